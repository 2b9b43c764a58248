// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points: the Euclidean minimum spanning tree, the relative neighbourhood graph and
// the Gabriel graph of points from a predicted graph on them (Corollaries 3.6 and 3.7 of the
// paper and the remark after them): the Delaunay triangulation is built from the prediction
// by delaunay_from_spanning_graph(), then each graph is read off it. All three are subgraphs
// of every Delaunay triangulation of the points under the tie rules below, so reading them
// off CGAL's triangulation is exact.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_PROXIMITY_GRAPHS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_PROXIMITY_GRAPHS_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/proximity_graph_extraction.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/union_find.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
Computes the Euclidean minimum spanning tree of `points` from a predicted spanning tree (or
any graph) on them: Corollary 3.6 of the paper. The Delaunay triangulation is built by
`delaunay_from_spanning_graph()` (the insertion order and walks of the paper's Theorem 3.3,
without its conflict lists: the paper's \f$O((n + D \log n) \log^* n)\f$ bound is not proven
for it; an exact EMST is a subgraph of the Delaunay triangulation, so every walk starts next
to its point), then Kruskal's algorithm runs on its edges.

Tie rule: edges are ordered by exact length, then by their pair of indices (smaller index
first, then larger); the tree returned is the unique minimum spanning tree for that order.
Points at equal positions are joined by zero-length edges to the smallest index among them,
so the tree spans every index.

\tparam PointRange a random-access range of points of a CGAL kernel.
\tparam EdgeRange as for `delaunay_from_spanning_graph()`.
\tparam OutputIterator an output iterator accepting `std::pair<std::size_t, std::size_t>`.

\param points the points.
\param tree_edges the predicted tree (any graph on the points is accepted).
\param out receives the \f$n - 1\f$ edges (for \f$n \geq 1\f$) as pairs `(i, j)`, `i < j`, in
       increasing lexicographic order.
\returns the output iterator past the last edge written.
\throws Invalid_prediction as `delaunay_from_spanning_graph()`.
*/
template <class PointRange, class EdgeRange, class OutputIterator>
OutputIterator euclidean_minimum_spanning_tree_from_prediction(const PointRange& points, const EdgeRange& tree_edges,
                                                               OutputIterator out)
{
  internal::check_edge_range_type<EdgeRange>();
  return internal::minimum_spanning_tree_of(internal::Indexed_delaunay<PointRange>(points, tree_edges), points, out);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
Computes the Euclidean minimum spanning tree of `points` from a predicted triangulation (any
faces on the points): Theorem 5.5 of the paper, in practical form. The Delaunay triangulation
is built by `delaunay_from_prediction()` with the named parameters `np` (with
`Strategy::regions`, by the division into regions of Theorem 5.4), then Kruskal's algorithm
runs on its edges. The paper's Theorem 5.5 runs the recursion of Theorem 5.4 on spanning trees
and obtains the Delaunay triangulation from the tree; here the tree is read off the Delaunay
triangulation, so the cost is that of `delaunay_from_prediction()` plus a sort of its edges,
and the paper's \f$O(n (\log^* n)^2 + n \log d_{cross-emst})\f$ bound is not claimed.

Tie rule and output: as `euclidean_minimum_spanning_tree_from_prediction()`.

\tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`, as for `delaunay_from_prediction()`.
\tparam PointRange a random-access range of points of a CGAL kernel.
\tparam FaceRange as for `delaunay_from_prediction()`.
\tparam OutputIterator an output iterator accepting `std::pair<std::size_t, std::size_t>`.
\tparam NamedParameters named parameters of `delaunay_from_prediction()`.

\param points the points.
\param faces the predicted faces (orientation free; need not form a triangulation).
\param out receives the \f$n - 1\f$ edges (for \f$n \geq 1\f$) as pairs `(i, j)`, `i < j`, in
       increasing lexicographic order.
\param np the named parameters of `delaunay_from_prediction()`.
\returns the output iterator past the last edge written.
\throws Invalid_prediction as `delaunay_from_prediction()`.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class FaceRange, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters>
OutputIterator euclidean_minimum_spanning_tree_from_predicted_faces(const PointRange& points, const FaceRange& faces,
                                                                    OutputIterator out,
                                                                    const NamedParameters& np = parameters::default_values())
{
  internal::check_face_range_type<FaceRange>();
  return internal::minimum_spanning_tree_of(
      internal::Indexed_delaunay<PointRange>(points, faces, ConcurrencyTag(), np), points, out);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
Computes the relative neighbourhood graph of `points` from a predicted connected graph on
them (for example a guess of that graph): Corollary 3.7 of the paper. `p q` is an edge iff no
point `r` has both \f$|pr| < |pq|\f$ and \f$|qr| < |pq|\f$ (the open lune is empty); such an edge
is a Delaunay edge. The Delaunay triangulation is built by `delaunay_from_spanning_graph()`;
then for each of its edges, the points in the open disk of radius \f$|pq|\f$ around `p` are
visited along Delaunay edges from `p` (they are connected through that disk) and tested.

Points at equal positions count as one, the smallest of their indices: the graph joins those
representatives.

\tparam PointRange a random-access range of points of a CGAL kernel.
\tparam EdgeRange as for `delaunay_from_spanning_graph()`.
\tparam OutputIterator an output iterator accepting `std::pair<std::size_t, std::size_t>`.

\param points the points.
\param edges the predicted graph.
\param out receives the edges as pairs `(i, j)`, `i < j`, in increasing lexicographic order.
\returns the output iterator past the last edge written.
\throws Invalid_prediction as `delaunay_from_spanning_graph()`.
*/
template <class PointRange, class EdgeRange, class OutputIterator>
OutputIterator relative_neighborhood_graph_from_prediction(const PointRange& points, const EdgeRange& edges,
                                                           OutputIterator out)
{
  internal::check_edge_range_type<EdgeRange>();
  internal::Indexed_delaunay<PointRange> del(points, edges);
  using Vertex_handle = typename internal::Indexed_delaunay<PointRange>::DT::Vertex_handle;
  auto compare_distance = del.dt.geom_traits().compare_distance_2_object();
  const std::size_t n = del.representative.size();
  std::vector<std::size_t> visited_by(n, std::size_t(-1)); // by info: the edge number last visiting
  std::vector<Vertex_handle> stack;
  std::vector<std::pair<std::size_t, std::size_t>> graph;
  std::size_t edge_number = 0;
  del.for_each_edge([&](auto f, int i) {
    const Vertex_handle p = f->vertex(del.dt.ccw(i)), q = f->vertex(del.dt.cw(i));
    const auto& pp = p->point();
    const auto& qp = q->point();
    // r blocks pq iff |pr| < |pq| and |qr| < |pq|.
    auto blocks = [&](Vertex_handle r) {
      return compare_distance(pp, r->point(), pp, qp) == SMALLER &&
             compare_distance(qp, r->point(), qp, pp) == SMALLER;
    };
    bool empty = true;
    // Depth-first search from p over the vertices in the open disk of radius |pq| around p:
    // for any vertex r in it, the segment rp crosses Voronoi cells of sites no farther from
    // p than r, which are joined by Delaunay edges, so all of them are reached.
    ++edge_number;
    stack.assign(1, p);
    visited_by[p->info()] = edge_number;
    while(empty && !stack.empty()) {
      const Vertex_handle v = stack.back();
      stack.pop_back();
      auto c = del.dt.incident_vertices(v), done = c;
      do {
        const Vertex_handle r = c;
        if(del.dt.is_infinite(r) || visited_by[r->info()] == edge_number)
          continue;
        visited_by[r->info()] = edge_number;
        if(compare_distance(pp, r->point(), pp, qp) != SMALLER)
          continue; // outside the disk
        if(r != q && blocks(r)) {
          empty = false;
          break;
        }
        stack.push_back(r);
      } while(++c != done);
    }
    if(empty) {
      const std::size_t a = p->info(), b = q->info();
      graph.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  });
  return internal::write_sorted(graph, out);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
Computes the Gabriel graph of `points` from a predicted connected graph on them (the remark
after Corollary 3.7 of the paper). `p q` is an edge iff the closed disk with diameter `p q`
holds no other point; such an edge is an edge of every Delaunay triangulation of the points,
and is found by testing the (at most two) vertices opposite it in CGAL's triangulation: a
Delaunay edge is a Gabriel edge iff neither of them sees `p q` at a right or obtuse angle.
The triangulation is built by `delaunay_from_spanning_graph()`.

Tie rule: a point on the circle with diameter `p q` removes the edge (closed disk). Points at
equal positions count as one, the smallest of their indices.

\tparam PointRange a random-access range of points of a CGAL kernel.
\tparam EdgeRange as for `delaunay_from_spanning_graph()`.
\tparam OutputIterator an output iterator accepting `std::pair<std::size_t, std::size_t>`.

\param points the points.
\param edges the predicted graph.
\param out receives the edges as pairs `(i, j)`, `i < j`, in increasing lexicographic order.
\returns the output iterator past the last edge written.
\throws Invalid_prediction as `delaunay_from_spanning_graph()`.
*/
template <class PointRange, class EdgeRange, class OutputIterator>
OutputIterator gabriel_graph_from_prediction(const PointRange& points, const EdgeRange& edges, OutputIterator out)
{
  internal::check_edge_range_type<EdgeRange>();
  internal::Indexed_delaunay<PointRange> del(points, edges);
  auto angle = del.dt.geom_traits().angle_2_object();
  std::vector<std::pair<std::size_t, std::size_t>> graph;
  del.for_each_edge([&](auto f, int i) {
    const auto p = f->vertex(del.dt.ccw(i)), q = f->vertex(del.dt.cw(i));
    // The angle at r of p r q is acute iff r is outside the closed diametral disk.
    auto outside = [&](auto r) { return del.dt.is_infinite(r) || angle(p->point(), r->point(), q->point()) == ACUTE; };
    // In dimension 1 the edges join consecutive points of a line: all are Gabriel edges.
    const bool gabriel = del.dt.dimension() < 2 || (outside(f->vertex(i)) && outside(del.dt.mirror_vertex(f, i)));
    if(gabriel) {
      const std::size_t a = p->info(), b = q->info();
      graph.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  });
  return internal::write_sorted(graph, out);
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_PROXIMITY_GRAPHS_H
