// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Reading the proximity graphs of proximity_graphs.h off the Delaunay triangulation: DT(P)
// built from the predicted graph or faces with point indices as info, index pairs sorted by the
// exact length of their segments, Kruskal's algorithm, sorted pairs written out.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PROXIMITY_GRAPH_EXTRACTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PROXIMITY_GRAPH_EXTRACTION_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/union_find.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The Delaunay triangulation of the points, from the predicted graph, with the index of
// each vertex's point as info (the smallest one for duplicates), and `representative[i]`:
// the smallest index of a point equal to point i.
template <class PointRange>
struct Indexed_delaunay
{
  using Point = std::decay_t<decltype(*std::begin(std::declval<const PointRange&>()))>;
  using Kernel = typename Kernel_traits<Point>::Kernel;
  using Vb = Triangulation_vertex_base_with_info_2<std::size_t, Kernel>;
  using Tds = Triangulation_data_structure_2<Vb>;
  using DT = Delaunay_triangulation_2<Kernel, Tds>;

  DT dt;
  std::vector<std::size_t> representative;

  // From a predicted graph (delaunay_from_spanning_graph()).
  template <class EdgeRange>
  Indexed_delaunay(const PointRange& points, const EdgeRange& edges)
  {
    find_representatives(points, delaunay_from_spanning_graph(points, edges, dt));
  }
  // From predicted faces (delaunay_from_prediction() with the named parameters `np`).
  template <class ConcurrencyTag, class FaceRange, class NamedParameters>
  Indexed_delaunay(const PointRange& points, const FaceRange& faces, ConcurrencyTag, const NamedParameters& np)
  {
    find_representatives(points, delaunay_from_prediction<ConcurrencyTag>(points, faces, dt, np));
  }

  // Calls `visit(f, i)` for every finite edge (f, i) of the triangulation (dimension 1: the
  // edges of the chain; below: none).
  template <class Visit>
  void for_each_edge(Visit visit) const
  {
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
      visit(e->first, e->second);
  }

private:
  void find_representatives(const PointRange& points, const Statistics& stats)
  {
    const auto point_at = std::begin(points);
    const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
    representative.resize(n);
    std::iota(representative.begin(), representative.end(), std::size_t(0));
    if(stats.duplicate_points == 0)
      return;
    // Equal points are found by an exact sort; only when there are any.
    auto compare_xy = dt.geom_traits().compare_xy_2_object();
    std::vector<std::size_t> sorted(representative);
    std::sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) {
      const Comparison_result c = compare_xy(point_at[a], point_at[b]);
      return c == SMALLER || (c == EQUAL && a < b);
    });
    for(std::size_t k = 1; k < n; ++k)
      if(compare_xy(point_at[sorted[k - 1]], point_at[sorted[k]]) == EQUAL)
        representative[sorted[k]] = representative[sorted[k - 1]];
  }
};

// Sorts index pairs by the exact length of the segment between their points, equal lengths
// by the pair. Exact at the cost of a sort of doubles: each squared length is bounded by
// interval arithmetic on the coordinates' intervals, the pairs are sorted by lower bound,
// and only runs of overlapping intervals (ties, or lengths too close for doubles) are sorted
// again with the kernel's exact comparison. Pairs of different runs are strictly ordered: a
// run ends where the next lower bound exceeds every upper bound in it. (Sorting with the
// exact comparison throughout cost 0.25 s for the 300,000 edges of 1e5 points.)
template <class Pair, class PointIterator, class Gt>
void sort_by_exact_length(std::vector<Pair>& pairs, PointIterator point_at, const Gt& gt)
{
  struct Keyed
  {
    double low, high;
    Pair pair;
  };
  std::vector<Keyed> keyed(pairs.size());
  {
    Protect_FPU_rounding<true> upward; // Interval_nt<false> needs it
    using I = Interval_nt<false>;
    for(std::size_t k = 0; k < pairs.size(); ++k) {
      const auto& p = point_at[pairs[k].first];
      const auto& q = point_at[pairs[k].second];
      const I dx = I(CGAL::to_interval(p.x())) - I(CGAL::to_interval(q.x()));
      const I dy = I(CGAL::to_interval(p.y())) - I(CGAL::to_interval(q.y()));
      const I length = CGAL::square(dx) + CGAL::square(dy);
      keyed[k] = Keyed{length.inf(), length.sup(), pairs[k]};
    }
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    return a.low < b.low || (a.low == b.low && a.pair < b.pair);
  });
  auto compare_distance = gt.compare_distance_2_object();
  auto exactly_shorter = [&](const Keyed& e, const Keyed& g) {
    const Comparison_result c = compare_distance(point_at[e.pair.first], point_at[e.pair.second],
                                                 point_at[g.pair.first], point_at[g.pair.second]);
    return c == SMALLER || (c == EQUAL && e.pair < g.pair);
  };
  for(std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    double high = keyed[i].high;
    for(; j < keyed.size() && !(keyed[j].low > high); ++j)
      high = (std::max)(high, keyed[j].high);
    if(j - i > 1)
      std::sort(keyed.begin() + std::ptrdiff_t(i), keyed.begin() + std::ptrdiff_t(j), exactly_shorter);
    i = j;
  }
  for(std::size_t k = 0; k < pairs.size(); ++k)
    pairs[k] = keyed[k].pair;
}

// Writes the pairs in increasing lexicographic order.
template <class OutputIterator>
OutputIterator write_sorted(std::vector<std::pair<std::size_t, std::size_t>>& edges, OutputIterator out)
{
  std::sort(edges.begin(), edges.end());
  for(const auto& e : edges)
    *out++ = e;
  return out;
}

// The Euclidean minimum spanning tree read off `del` (an Indexed_delaunay) by Kruskal's
// algorithm on its edges, written to `out` in increasing lexicographic order: duplicates first
// (zero length, joined to their representative), then the edges by exact length (ties by the
// pair).
template <class Indexed, class PointRange, class OutputIterator>
OutputIterator minimum_spanning_tree_of(const Indexed& del, const PointRange& points, OutputIterator out)
{
  const std::size_t n = del.representative.size();
  std::vector<std::pair<std::size_t, std::size_t>> candidates, tree;
  del.for_each_edge([&](auto f, int i) {
    const std::size_t a = f->vertex(del.dt.ccw(i))->info(), b = f->vertex(del.dt.cw(i))->info();
    candidates.emplace_back((std::min)(a, b), (std::max)(a, b));
  });
  sort_by_exact_length(candidates, std::begin(points), del.dt.geom_traits());
  Union_find sets(n);
  for(std::size_t i = 0; i < n; ++i)
    if(del.representative[i] != i && sets.join(i, del.representative[i]))
      tree.emplace_back(del.representative[i], i);
  for(const auto& e : candidates)
    if(sets.join(e.first, e.second))
      tree.push_back(e);
  return write_sorted(tree, out);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PROXIMITY_GRAPH_EXTRACTION_H
