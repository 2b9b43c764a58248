// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The package's one random source: splitmix64, with uniform and normal draws written out
// here rather than taken from <random>, whose distributions differ between standard
// libraries. A seed gives the same numbers everywhere, so sampled screens and generated
// predictions are reproducible.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_RANDOM_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_RANDOM_H

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

struct Splitmix64
{
  std::uint64_t state;
  std::uint64_t operator()()
  {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// uniform in [0, 1), 53 random bits.
  double uniform() { return double((*this)() >> 11) * 0x1.0p-53; }
  /// uniform in [0, bound); bound > 0. (The modulo bias, below 2^-40 for bound < 2^24, does
  /// not matter for sampling.)
  std::size_t below(std::size_t bound) { return std::size_t((*this)() % bound); }
  /// standard normal, by the Box-Muller transform.
  double normal()
  {
    const double u = 1.0 - uniform(); // in (0, 1]
    const double v = uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
  }
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_RANDOM_H
