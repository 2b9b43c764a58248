// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point: the Delaunay triangulation of points from a predicted graph on them (a
// spanning tree, a neighbour graph, the edges of a triangulation, crossing or not), by the
// spanning-tree insertion of Section 3 of the paper (internal/build/spanning_tree_insertion.h).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_SPANNING_GRAPH_H
#define CGAL_DELAUNAY_FROM_PREDICTION_SPANNING_GRAPH_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/build/conflict_list_rounds.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Checks `edges` against n points and returns their ends, in pairs (throws before anything
// else is done).
template <class EdgeRange>
std::vector<std::uint32_t> checked_edge_ends(const EdgeRange& edges, std::size_t n)
{
  std::vector<std::uint32_t> ends;
  ends.reserve(2 * std::size_t(std::distance(std::begin(edges), std::end(edges))));
  std::size_t k = 0;
  for(const auto& e : edges) {
    const auto ab = read_edge(e, k++, n);
    ends.push_back(std::uint32_t(ab.first));
    ends.push_back(std::uint32_t(ab.second));
  }
  return ends;
}

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
Builds the Delaunay triangulation of `points` into `dt`, using a graph on the points as a
prediction: a spanning tree (for example a guessed Euclidean minimum spanning tree), a
neighbour graph, or the edges of a predicted triangulation. Edges may cross, repeat, and need
not be Delaunay edges: a wrong edge only costs time.

A spanning tree of the graph is taken (breadth-first), the points are dealt into the rounds
of a gradation of random samples weighted by their degree in the tree, and each point is
located by a walk in the current triangulation from the vertex of its nearest tree ancestor
already inserted, then inserted by the package's insertion (a split and flips for a point
strictly inside a face, \cgal's insertion otherwise). This is the insertion order and the
walks along tree edges of the paper's Theorem 3.3 and Lemma 3.2, with a gradation of ratio 8
instead of the paper's \f$\log^*\f$ sequence and without the paper's conflict lists: points
are inserted one by one. The paper's \f$O((n + D_T \log n) \log^* n)\f$ expected bound
(\f$D_T\f$ the number of tree edges that are not Delaunay edges) is therefore not proven for
this function, and no other bound is: a walk from the tree crosses at most about
\f$\log_2 n + 8\f$ faces, then starts again, uncapped, from a vertex inserted in the point's
cell of a grid. With a tree of Delaunay edges the build needs no spatial sort. A graph whose edges are much longer than the spacing of the points (the
median of 255 sampled edges over 32 times the side of the area per point: a random tree) or
that has more than \f$n/64\f$ connected components is not used at all, and when the walks keep
missing in a round (more than half of them past their cap), the remaining points are
inserted in a spatial order, as a build from scratch would (`Statistics::fell_back` in all
three cases).

The result is exactly the triangulation CGAL's `Delaunay_triangulation_2` builds from the same
points (co-circular ties broken by CGAL's symbolic perturbation), whatever the graph.

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: see \ref dfpParallel for what runs on several threads.
        The result is the same triangulation whatever the tag and the number of threads.
\tparam PointRange a random-access range of `DT::Point`.
\tparam EdgeRange a range of edges, each a `std::pair`, `std::tuple` or `std::array` of two
        integer indices into `points`, or anything with `operator[](0..1)` returning one.
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
        assignable from `std::size_t`, every vertex's `info()` is set to the index of its point
        (for duplicate points, the smallest of their indices). A `CGAL::Triangulation_hierarchy_2`
        of one is kept as in `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters: `parameters::strategy(Strategy::section_3)`
        builds by the paper's Section 3 as written instead (below); every other strategy means
        the engine described above.

\param points the points.
\param edges the predicted graph.
\param dt receives the result; cleared first.
\param np optional named parameters: `strategy`.

\returns what the call did: `edges_in`, `points_located`, `faces_visited` (divided by
         `points_located`: the mean length of a walk), `walk_fallbacks`, `insertion_rounds`,
         `duplicate_points`, `fell_back`.
\throws Invalid_prediction if a point has a non-finite coordinate, or an edge has an end out of
        range or joins a point to itself. Then `dt` is unchanged.

With `parameters::strategy(Strategy::section_3)`, the build is Section 3 of the paper as
written (Lemma 3.2 and the rounds of Theorem 3.3; \ref dfpSection3): samples
\f$R_1 \subset \dots \subset R_\ell = P\f$ of the points weighted by tree degree, sizes
\f$|\widehat P|/s_i\f$ with \f$s_1 = n\f$, \f$s_{i+1} = \lfloor\log_2 s_i\rfloor\f$; each
round locates every point in \f$DT(R_i)\f$ by walks along the tree capped at \f$\log_2 n\f$
faces, lists each point's conflicting faces by graph search, and builds \f$DT(R_{i+1})\f$ by
randomized incremental construction with these conflict lists. No heuristic fallback; two
substitutions (a grid and a walk for the \f$O(\log n)\f$ point location; the incremental
construction for the per-cell lower envelopes) keep Theorem 3.3's bound from being proven for
the code as it is. It also fills `conflict_list_entries`, `largest_conflict_list` and
`points_relocated`.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
is built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class EdgeRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_spanning_graph(const PointRange& points, const EdgeRange& edges, DT& dt,
                                        const NamedParameters& np = parameters::default_values())
{
  internal::check_point_range_type<PointRange, typename DT::Point>();
  internal::check_edge_range_type<EdgeRange>();
  (void)internal::runs_in_parallel<ConcurrencyTag>(); // checks the tag; runs sequentially (manual, "Parallel Mode")
  if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(
        dt, [&](auto& level0) { return delaunay_from_spanning_graph<ConcurrencyTag>(points, edges, level0, np); });
  } else { // the body below, not instantiated for a hierarchy
  const Strategy strategy =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::strategy), Strategy::automatic);
  Statistics stats;
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  internal::check_points_are_finite(point_at, n);
  if(n >= std::size_t(internal::no_rank))
    throw Invalid_prediction("Delaunay_from_prediction: 2^32 - 1 points or more are not supported by "
                             "delaunay_from_spanning_graph");
  const std::vector<std::uint32_t> ends = internal::checked_edge_ends(edges, n);
  stats.edges_in = ends.size() / 2;
  dt.clear();
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value)
    internal::build_with_exact_predicates(dt, point_at, n, stats); // inexact predicates: decided by exact ones
  else if(strategy == Strategy::section_3)
    internal::build_by_conflict_list_rounds(dt, point_at, n, ends, stats);
  else
    internal::build_along_edges(dt, point_at, n, ends, stats);
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_SPANNING_GRAPH_H
