// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Defaults shared by delaunay_from_prediction() and make_delaunay(): the flip budget, the
// limits of the local repair, and the fallback reasons of the strategies that skip the repair.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_STRATEGY_DEFAULTS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_STRATEGY_DEFAULTS_H

#include <CGAL/Delaunay_from_prediction/internal/carve_repair.h>

#include <cstddef>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Default flip budget. Lawson's algorithm needs about as many flips as the prediction has
// wrong edges, and falls back at once when the failing edges alone exceed the budget. A flip
// with its re-tests costs about 0.4 of a point insertion of a rebuild (measured: 0.42 us per
// flip against about 1 us per point at 1e6 points), so 3n/4 wasted flips add at most about
// 0.3 of a rebuild; moves of 0.1 spacing need 0.44n (1e6 points) to 0.5n (5000 points), a
// plain Triangulation_2 of random points ~6n, which is cheaper to rebuild.
inline std::size_t default_max_flips(std::size_t n) { return 3 * n / 4 + 64; }

// Statistics::fallback_reason for Strategy::rebuild.
constexpr const char* rebuild_requested = "the rebuild strategy was chosen";
// Statistics::fallback_reason for Strategy::spanning_tree.
constexpr const char* spanning_tree_requested = "the spanning_tree strategy was chosen";

// Limits of the local repair for `n` points. Measured at 1e6 points (moves of 0.1 spacing:
// 4.6% of the faces inverted, 0.19 n faces carved), the repair as a whole cost about a
// rebuild, the planning alone about 1.5 us per carved face; past n/8 carved faces a rebuild is
// cheaper.
inline Carve_limits default_carve_limits(std::size_t n)
{
  Carve_limits limits;
  limits.max_removed_faces = n / 8 + 64;
  limits.max_bad_faces = n / 16 + 16;
  return limits;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_STRATEGY_DEFAULTS_H
