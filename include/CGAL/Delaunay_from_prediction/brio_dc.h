// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point: BrioDC (K. Buchin, W. Mulzer, "Linear-time Delaunay triangulations simplified"):
// the Delaunay triangulation by a biased randomized insertion order whose samples meet every
// component of the nearest-neighbour graph, each point inserted after a walk along its
// nearest-neighbour graph edges from a point already inserted.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H
#define CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/build/brio_dc_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt` by BrioDC (K. Buchin, W. Mulzer,
"Linear-time Delaunay triangulations simplified"): a randomized incremental construction whose
insertion order is a gradation of samples \f$P = S_0 \supseteq S_1 \supseteq \dots \supseteq S_\ell\f$.
On the cycle of every connected component of the nearest-neighbour graph \f$N(S_i)\f$ two
points are matched, and \f$S_{i+1}\f$ holds one of them, chosen at random (so it meets every
component), and every other point of \f$S_i\f$ with probability \f$q\f$ (named parameter
`sample_probability`). The points of \f$S_i \setminus S_{i+1}\f$ are inserted component by
component, each located by a walk that starts at the vertex of its neighbour in \f$N(S_i)\f$
inserted before it.

The paper samples with \f$q = 1/2\f$; the default here is \f$q = 1/8\f$, 10-24% less time on
every distribution measured (fewer levels, hence fewer graphs and fewer sweeps over the
triangulation), with walks as short (see the user manual). The paper's proof of Theorem 2
bounds the chance that a triangle with \f$s\f$ conflicting points appears by the chance that
none of them is sampled, \f$2^{-s}\f$; with \f$q\f$ it is at most \f$\max(1 - q, 1/2)^s\f$ (a
matched point is kept with probability 1/2), which keeps the sum over triangles linear for
any fixed \f$q > 0\f$, with a constant that grows as \f$q\f$ shrinks. That adaptation is ours,
not the paper's.
A sample that keeps more than 31/32 of the points of its level (\f$q\f$ near 1 on points whose
graph has few components: equal points, a geometric progression) is the last one, inserted by
\cgal's insertion: else the samples would number about one per point.

The nearest-neighbour graphs are computed with a uniform grid of about two points a cell,
crowded cells refined by grids of their own down to 6 levels (not \cgal's spatial searching,
and not the linear-time algorithm of Chan that the paper's Theorem 1 cites; the grid's cells
also order the insertion for locality), with distances in double precision (on coordinates
scaled by a power of two to their bounding box where squared distances would overflow or
underflow) and a search reading at most 512 points. The graph is exact (compared with a
brute-force search in the tests, on uniform, clustered, graded, grid, collinear and duplicate
points) unless a search runs out of its 512 points (hundreds of points at equal or nearly equal
positions) or points lie closer than \f$2^{-511}\f$ of the bounding box's size: then the
neighbour is approximate, which costs time, never correctness: every point is inserted. Each
point is located by a visibility walk from its neighbour's vertex; a walk longer than about
\f$\log_2 n + 8\f$ faces starts again, uncapped, from a vertex inserted near the point.

Complexity: the paper's Theorem 2 gives expected \f$O(n + f(n))\f$ time, \f$f(n)\f$ the time of
a nearest-neighbour graph, for its sampling probability 1/2 and straight walks along the graph's
edges. This function departs from that setting (grid graph, capped visibility walks with a grid
restart, \f$q = 1/8\f$ by default): no bound is proven for it. Its walks were measured at
1.75-2.24 faces per point at \f$10^5\f$ and \f$10^6\f$ points (see the user manual).

The result is exactly the triangulation \cgal's `Delaunay_triangulation_2` builds from the same
points (co-circular ties broken by \cgal's symbolic perturbation).

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: see \ref dfpParallel for what runs on several threads.
        The result is the same triangulation whatever the tag and the number of threads.
\tparam PointRange a random-access range of `DT::Point`.
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
        assignable from `std::size_t`, every vertex's `info()` is set to the index of its point
        (for duplicate points, the smallest of their indices). A `CGAL::Triangulation_hierarchy_2`
        of one is kept as in `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters.

\param points the points.
\param dt receives the result; cleared first.
\param np optional named parameters among the following ones:
\cgalNamedParamsBegin
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the samples}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{a fixed seed}
  \cgalParamNEnd
  \cgalParamNBegin{sample_probability}
    \cgalParamDescription{the probability \f$q\f$ that a point not matched on its component's cycle is
                          in the next sample (`Delaunay_from_prediction::parameters::sample_probability()`)}
    \cgalParamType{`double`, in \f$(0, 1]\f$}
    \cgalParamDefault{1/8 (the paper's value is 1/2)}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did: `points_located`, `faces_visited` (divided by `points_located`: the
         mean length of a walk), `walk_fallbacks`, `insertion_rounds` (the number of samples),
         `points_reinserted` (every point), `duplicate_points`.
\throws Invalid_prediction if a point has a non-finite coordinate, or there are \f$2^{32} - 1\f$
        points or more; `std::invalid_argument` if `sample_probability` is not in \f$(0, 1]\f$.
        Then `dt` is unchanged.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
is built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics brio_dc_delaunay(const PointRange& points, DT& dt, const NamedParameters& np = parameters::default_values())
{
  internal::check_point_range_type<PointRange, typename DT::Point>();
  constexpr bool parallel = internal::runs_in_parallel<ConcurrencyTag>();
  if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(dt, [&](auto& level0) { return brio_dc_delaunay<ConcurrencyTag>(points, level0, np); });
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto point_begin = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  internal::check_points_are_finite(point_begin, n);
  if(n >= std::size_t(internal::no_rank))
    throw Invalid_prediction("Delaunay_from_prediction: 2^32 - 1 points or more are not supported by brio_dc_delaunay");
  const std::uint64_t seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0xb410dcu);
  const double probability = double(choose_parameter(get_parameter(np, internal_np::sample_probability), 0.125));
  if(!(probability > 0 && probability <= 1)) {
    std::ostringstream message;
    message << "Delaunay_from_prediction: brio_dc_delaunay's sample_probability must be in (0, 1]; it is "
            << probability;
    throw std::invalid_argument(message.str());
  }
  Statistics stats;
  dt.clear();
  stats.points_reinserted = n;
  if(n == 0)
    return stats;
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    internal::build_with_exact_predicates(dt, point_begin, n, stats); // inexact predicates: decided by exact ones
    return stats;
  }
  internal::brio_dc_insert(dt, point_begin, n, seed, probability, stats, parallel);
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H
