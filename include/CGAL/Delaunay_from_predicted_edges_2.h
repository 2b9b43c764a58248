// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point for a prediction given as edges (a planar straight-line graph, Corollary 4.2 of
// the paper: a subgraph of DT(P) with edges missing): the triangles of the graph go through
// delaunay_from_prediction(), whose local repair fills the faces with more sides (holes) and
// corrects whatever the graph got wrong.

#ifndef CGAL_DELAUNAY_FROM_PREDICTED_EDGES_2_H
#define CGAL_DELAUNAY_FROM_PREDICTED_EDGES_2_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/graph_triangles.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt`, using `edges` as a prediction of
its edges (a planar straight-line graph, typically \f$DT(P)\f$ with edges missing,
Corollary 4.2 of the paper).

The triangles of the graph (three points pairwise joined by edges) are handed to
`delaunay_from_prediction()` as the predicted faces. Its local repair turns the faces of the
graph with more than three sides into holes and triangulates them (ear clipping, then flips),
leaves out triangles that overlap others (a separating triangle around a vertex of degree
three), and corrects whatever else the graph got wrong (crossing edges). The result is exactly
CGAL's Delaunay triangulation of the points. The graph costs \f$O(m \log m + m d)\f$ for
\f$m\f$ edges and maximum degree \f$d\f$ (a sort of the edges, then a merge of two neighbour
lists per edge), and uses no geometry. The paper's \f$O(n + D \log n)\f$ bound of Corollary 4.2
is not met: ear clipping is quadratic in the size of a hole, and Lawson's flips have no bound in
\f$D\f$ (a call whose damage exceeds the budgets rebuilds from scratch instead).

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: see \ref dfpParallel for what runs on several threads.
        The result is the same triangulation whatever the tag and the number of threads.
\tparam PointRange a random-access range of `DT::Point`.
\tparam EdgeRange a range whose elements `e` give two integer indices into `points`, as
        `e[0]`, `e[1]` or as `e.first`, `e.second` (for example `std::pair<int, int>`).
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`; vertex `info()`, if assignable from
        `std::size_t`, receives the point index as in `delaunay_from_prediction()`. A
        `CGAL::Triangulation_hierarchy_2` of one is kept as in `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters, passed on to
        `delaunay_from_prediction()`.

\param points the points.
\param edges the predicted edges, in any order and direction; repeated edges are allowed.
\param dt receives the result; cleared first.
\param np optional named parameters, see `delaunay_from_prediction()`.

\returns what the call did, see `Statistics`; `faces_in` is the number of triangles derived
         from the graph.
\throws Invalid_prediction if a point has a non-finite coordinate, or an edge has an index out
        of range or joins a point to itself. Then `dt` is unchanged.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class EdgeRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_predicted_edges(const PointRange& points, const EdgeRange& edges, DT& dt,
                                         const NamedParameters& np = parameters::default_values())
{
  internal::check_point_range_type<PointRange, typename DT::Point>();
  internal::check_edge_range_type<EdgeRange>();
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  internal::check_points_are_finite(point_at, n);
  std::vector<std::pair<std::size_t, std::size_t>> read;
  std::size_t k = 0;
  for(const auto& e : edges)
    read.push_back(internal::read_edge(e, k++, n));
  if(n >= (std::size_t(1) << 32))
    return delaunay_from_prediction<ConcurrencyTag>(points, std::vector<std::array<std::size_t, 3>>(), dt, np);
  const std::vector<std::array<std::size_t, 3>> triangles = internal::graph_triangles(n, read);
  return delaunay_from_prediction<ConcurrencyTag>(points, triangles, dt, np);
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTED_EDGES_2_H
