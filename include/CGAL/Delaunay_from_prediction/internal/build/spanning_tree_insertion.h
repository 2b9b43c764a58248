// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The insertion engine of Section 3 of the paper (Lemma 3.2, Theorem 3.3): the Delaunay
// triangulation of points built by rounds of random samples (a gradation), each point
// located by walking from the vertex of a tree neighbour already inserted. With a spanning
// tree whose edges are Delaunay edges the walks cross a few faces each, and the build needs
// no spatial sort (a third of CGAL's own build); a wrong edge costs a capped walk and a
// fallback location; a tree that does not help at all hands its points to the grid-order
// insertion of rebuild.h, so no input costs much more than a build from scratch.
//
// What differs from the paper, and why:
// - The rounds insert points one by one by incremental insertion (insertion.h; the
//   lower envelopes of the proof are that insertion's result); conflict lists are not kept: each
//   point is located when it is inserted, by a walk in the current triangulation from the
//   nearest ancestor in the tree already inserted (the paper walks along every tree edge in
//   every round; the walk from an ancestor is the same walk with the intermediate points
//   skipped).
// - The fallback point location is a jump to the last vertex inserted in the point's cell of
//   a uniform grid (two resolutions), then an uncapped walk: short on well-spread points
//   (measured, not proven), instead of the O(log n) point location structure of the proof.
// - The tree is the breadth-first tree of the given graph (the graph itself when it is a
//   tree); points are scanned in its depth-first preorder, so that consecutive insertions are
//   near each other in the plane and in memory.
// - The gradation has ratio 8 (see gradation_rounds()), and a graph whose edges are far too
//   long to help is told before any of this (edges_look_random()).
// So the paper's O((n + D_T log n) log* n) expected bound (Theorem 3.3) is not proven for this
// engine, and no other bound is: each walk from the tree is capped at about log2 n + 8 faces,
// but the grid restart after the cap and the insertions themselves are not bounded by a proof.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SPANNING_TREE_INSERTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SPANNING_TREE_INSERTION_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// An undirected graph on the point indices 0..n-1, in compressed adjacency form: the
// neighbours of v are targets[offsets[v]] .. targets[offsets[v + 1] - 1].
struct Adjacency
{
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> targets;
  std::size_t size() const { return offsets.empty() ? 0 : offsets.size() - 1; }
};

// The adjacency of the points 0..n-1 from edge ends listed in pairs (in range, different):
// degrees, prefix sums, then each edge written at both ends. (Counting the degrees while
// reading the caller's edges measured slower than this separate pass.)
inline Adjacency adjacency_of(const std::vector<std::uint32_t>& ends, std::size_t n)
{
  Adjacency g;
  g.offsets.assign(n + 1, 0);
  for(const std::uint32_t v : ends)
    ++g.offsets[v + 1];
  for(std::size_t v = 0; v < n; ++v)
    g.offsets[v + 1] += g.offsets[v];
  g.targets.resize(g.offsets[n]);
  std::vector<std::uint32_t> fill(g.offsets.begin(), g.offsets.end() - 1);
  for(std::size_t k = 0; k + 1 < ends.size(); k += 2) {
    const std::uint32_t a = ends[k], b = ends[k + 1];
    g.targets[fill[a]++] = b;
    g.targets[fill[b]++] = a;
  }
  return g;
}

constexpr std::uint32_t no_rank = 0xFFFFFFFFu;

// The BFS forest of `graph` (roots taken in index order; a graph that is a forest is its
// own), listed in depth-first preorder: order[r] is the point of rank r, parent[r] the rank
// of its parent (no_rank for a root; always below r), degree[r] its degree in the forest.
// The preorder keeps consecutive points near each other even where a wrong edge jumps (the
// subtree over there is listed whole), which BFS order does not: with 1% of the edges of a
// tree replaced by random ones, inserting in BFS order cost 1.4 times more. The input comes
// in any order, so a depth-first traversal would pay a cache miss or two per vertex, one
// after the other; instead the BFS (whose queue lets the neighbour lists be prefetched)
// gives the tree, and the preorder follows from subtree sizes in two passes over the BFS
// order (children are contiguous in it): 0.04 s at 1e6 points, a depth-first traversal 0.25 s.
struct Preorder_forest
{
  std::vector<std::uint32_t> order, parent, degree;
  std::size_t roots = 0;
};

inline Preorder_forest preorder_spanning_forest(const Adjacency& graph)
{
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> bfs, bfs_parent, first_child, size;
  bfs.reserve(n);
  bfs_parent.reserve(n);
  first_child.resize(n);
  std::vector<std::uint32_t> bfs_rank(n, no_rank);
  std::size_t roots = 0;
  for(std::size_t s = 0; s < n; ++s) {
    if(bfs_rank[s] != no_rank)
      continue;
    ++roots;
    std::size_t head = bfs.size();
    bfs_rank[s] = std::uint32_t(head);
    bfs.push_back(std::uint32_t(s));
    bfs_parent.push_back(no_rank);
    for(; head < bfs.size(); ++head) {
#if defined(__GNUC__)
      // Three stages ahead: the offsets, the neighbour list, the neighbours' ranks.
      if(head + 12 < bfs.size())
        __builtin_prefetch(&graph.offsets[bfs[head + 12]]);
      if(head + 6 < bfs.size())
        __builtin_prefetch(&graph.targets[graph.offsets[bfs[head + 6]]]);
      if(head + 3 < bfs.size()) {
        const std::uint32_t u = bfs[head + 3];
        for(std::uint32_t k = graph.offsets[u]; k < graph.offsets[u + 1]; ++k)
          __builtin_prefetch(&bfs_rank[graph.targets[k]]);
      }
#endif
      const std::uint32_t v = bfs[head];
      first_child[head] = std::uint32_t(bfs.size());
      for(std::uint32_t k = graph.offsets[v]; k < graph.offsets[v + 1]; ++k) {
        const std::uint32_t w = graph.targets[k];
        if(bfs_rank[w] != no_rank)
          continue;
        bfs_rank[w] = std::uint32_t(bfs.size());
        bfs.push_back(w);
        bfs_parent.push_back(std::uint32_t(head));
      }
    }
  }
  // Subtree sizes (children come after their parent), then preorder ranks: a root keeps its
  // BFS rank (its component occupies the same ranks in both orders), and the children of h,
  // bfs ranks first_child[h] .. first_child[h + 1] - 1, follow h one subtree after another.
  size.assign(n, 1);
  for(std::size_t h = n; h-- > 1;)
    if(bfs_parent[h] != no_rank)
      size[bfs_parent[h]] += size[h];
  std::vector<std::uint32_t>& pre = bfs_rank; // reused: BFS rank -> preorder rank
  for(std::size_t h = 0; h < n; ++h) {
    if(bfs_parent[h] == no_rank)
      pre[h] = std::uint32_t(h);
    std::uint32_t next = pre[h] + 1;
    const std::size_t end = h + 1 < n ? first_child[h + 1] : n;
    for(std::size_t c = first_child[h]; c < end && bfs_parent[c] == h; ++c) {
      pre[c] = next;
      next += size[c];
    }
  }
  Preorder_forest forest;
  forest.roots = roots;
  forest.order.resize(n);
  forest.parent.resize(n);
  forest.degree.assign(n, 0);
  for(std::size_t h = 0; h < n; ++h) {
    const std::uint32_t r = pre[h];
    forest.order[r] = bfs[h];
    const std::uint32_t p = bfs_parent[h] == no_rank ? no_rank : pre[bfs_parent[h]];
    forest.parent[r] = p;
    if(p != no_rank) {
      ++forest.degree[r];
      ++forest.degree[p];
    }
  }
  return forest;
}

// The rounds of the gradation (proof of Theorem 3.3): nested samples of the multiset where
// each point appears as often as its degree in the tree, of sizes |P|/s_i. A point's round
// is the round of its earliest copy; copies are drawn independently (the point is in sample
// i with probability 1 - (1 - 1/s_i)^degree). Roots are in round 0. The paper's sequence
// (s_1 = n, s_{i+1} = log2 s_i: 5 rounds at 1e6 points) makes every round a sweep over a
// large part of the triangulation; s_i = 8^(rounds - 1 - i), as in CGAL's biased
// randomized insertion order, leaves most points to one last sweep and measured faster
// (1e6 uniform points, exact EMST: 1.45 times faster than CGAL's build instead of 1.18, same
// process, glibc's default allocator policy).
inline std::vector<unsigned char> gradation_rounds(const Preorder_forest& forest, std::uint64_t seed,
                                                   std::size_t& number_of_rounds)
{
  const std::size_t n = forest.order.size();
  std::vector<double> threshold; // a copy is in round i iff its draw u < threshold[i]
  for(double s = 1; s < double(n); s *= 8)
    threshold.push_back(1 / s);
  std::reverse(threshold.begin(), threshold.end());
  if(threshold.empty())
    threshold.push_back(1);
  threshold.back() = 2; // the last round takes every point left
  number_of_rounds = threshold.size();
  // The same on 64-bit integers: u < threshold iff draw < threshold * 2^64.
  std::vector<std::uint64_t> below(threshold.size());
  for(std::size_t i = 0; i < threshold.size(); ++i)
    below[i] = threshold[i] >= 1 ? ~std::uint64_t(0) : std::uint64_t(std::ldexp(threshold[i], 64));
  std::vector<unsigned char> round(n);
  Splitmix64 random{seed};
  for(std::size_t r = 0; r < n; ++r) {
    if(forest.parent[r] == no_rank) {
      round[r] = 0;
      continue;
    }
    std::uint64_t u = ~std::uint64_t(0);
    for(std::uint32_t c = 0; c < forest.degree[r]; ++c)
      u = (std::min)(u, random());
    unsigned char i = 0;
    while(u >= below[i] && std::size_t(i) + 1 < below.size())
      ++i;
    round[r] = i;
  }
  return round;
}

// Whether the edges (ends listed in pairs) are much longer than the spacing of the points,
// judged on a sample of 255 edges: the median length above 32 times the side of the area
// per point in the bounding box. A random tree is (its edges span a fair part of the box), a
// proximity graph with a tenth of its edges wrong is not. Such a graph gives no useful hint,
// and its adjacency and preorder alone would cost a tenth of a build.
template <class PointIterator>
bool edges_look_random(PointIterator points, std::size_t n, const std::vector<std::uint32_t>& ends,
                       std::uint64_t seed)
{
  if(n < 4096 || ends.empty())
    return false;
  Splitmix64 random{seed};
  const Spacing_sample sample =
      sample_spacing(n, [&](std::size_t k) -> decltype(points[0]) { return points[k]; }, [&](std::size_t) {
        const std::size_t k = 2 * random.below(ends.size() / 2);
        return std::pair<std::size_t, std::size_t>(ends[k], ends[k + 1]);
      });
  return sample.area_per_point > 0 && sample.median_squared_distance > 32 * 32 * sample.area_per_point;
}

// Inserts the points (random access, n of them) into the empty Delaunay triangulation `dt`
// along the spanning forest of `graph`, setting info() to the point index (the smallest for
// duplicates). Fills the walk counters of `stats`, `points_reinserted` and
// `duplicate_points`; sets `fell_back` when the forest did not help and the remaining
// points went to the grid-order insertion.
template <class DT, class PointIterator>
void insert_along_spanning_forest(DT& dt, PointIterator points, std::size_t n, const Adjacency& graph,
                                  Statistics& stats, std::uint64_t seed = 0x5eed7ee5ull)
{
  using Point = typename DT::Point;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  stats.points_reinserted += n;
  if(n == 0)
    return;
  const Preorder_forest forest = preorder_spanning_forest(graph);
  // The points in preorder: every later pass reads them in order.
  std::vector<Point> point(n);
  for(std::size_t r = 0; r < n; ++r)
    point[r] = points[forest.order[r]];
  std::vector<Vertex_handle> vertex(n);
  auto on_vertex = [&](std::size_t r, Vertex_handle v, bool is_new) {
    vertex[r] = v;
    if(is_new) {
      set_index_info(v, forest.order[r]);
    } else {
      merge_index_info(v, forest.order[r]);
      ++stats.duplicate_points;
    }
  };
  // A graph with many components gives few hints: insert everything in grid order.
  if(forest.roots > n / 64 + 1) {
    std::vector<std::size_t> ranks(n);
    for(std::size_t r = 0; r < n; ++r)
      ranks[r] = r;
    insert_by_index(dt, point.begin(), ranks, on_vertex);
    stats.fell_back = true;
    stats.outcome = Outcome::graph_too_many_components;
    return;
  }
  std::size_t rounds = 0;
  const std::vector<unsigned char> round = gradation_rounds(forest, seed, rounds);
  stats.insertion_rounds = rounds;
  // Round 0 (the roots and a handful of points) in grid order.
  {
    std::vector<std::size_t> first;
    for(std::size_t r = 0; r < n; ++r)
      if(round[r] == 0)
        first.push_back(r);
    insert_by_index(dt, point.begin(), first, on_vertex);
  }
  Vertex_grid<Vertex_handle> grid(n, [&](std::size_t r) -> const Point& { return point[r]; });
  for(std::size_t r = 0; r < n; ++r)
    if(round[r] == 0)
      grid.record(point[r], vertex[r]);
  const std::size_t cap = walk_cap(n);
  std::vector<std::pair<Face_handle, int>> flip_stack;
  // near[r]: the rank of the nearest ancestor-or-self of r already inserted.
  std::vector<std::uint32_t> near(n, no_rank);
  for(unsigned char k = 1; k < rounds; ++k) {
    const std::size_t located_before = stats.points_located, fallbacks_before = stats.walk_fallbacks;
    for(std::size_t r = 0; r < n; ++r) {
      const std::uint32_t p = forest.parent[r];
      if(round[r] < k) {
        near[r] = std::uint32_t(r);
        continue;
      }
      near[r] = p == no_rank ? no_rank : near[p];
      if(round[r] != k)
        continue;
      // Insert point r, located from its nearest inserted ancestor (one exists: roots are in
      // round 0).
      const Point& q = point[r];
      const std::size_t count = dt.number_of_vertices();
      const Vertex_handle v = insert_walking_from(dt, q, vertex[near[r]], cap, grid, flip_stack, stats);
      on_vertex(r, v, dt.number_of_vertices() != count);
      grid.record(q, v);
      near[r] = std::uint32_t(r);
      // A forest whose edges keep missing (a random tree) only adds walks to a build in a
      // bad order: past a fair sample, the remaining points go to the grid-order insertion.
      const std::size_t located_in_round = stats.points_located - located_before;
      if((located_in_round & 1023) == 0 && located_in_round >= 4096 &&
         2 * (stats.walk_fallbacks - fallbacks_before) > located_in_round) {
        std::vector<std::size_t> rest;
        for(std::size_t s = 0; s < n; ++s)
          if(round[s] > k || (round[s] == k && s > r))
            rest.push_back(s);
        insert_by_index(dt, point.begin(), rest, on_vertex);
        stats.fell_back = true;
        stats.outcome = Outcome::tree_walks_missing;
        return;
      }
    }
  }
}

// Builds DT(points) into the empty `dt` from a graph on the points, given by its edge ends
// in pairs (in range, different; fewer than no_rank points): along its spanning forest, or in
// grid order when its edges are too long to help, with `fell_back` set.
// The engine's one entry, for delaunay_from_spanning_graph() and for
// delaunay_from_prediction() with Strategy::spanning_tree.
template <class DT, class PointIterator>
void build_along_edges(DT& dt, PointIterator points, std::size_t n, const std::vector<std::uint32_t>& ends,
                       Statistics& stats)
{
  if(edges_look_random(points, n, ends, 0x5eed7ee5ull)) {
    std::vector<std::size_t> indices(n);
    for(std::size_t i = 0; i < n; ++i)
      indices[i] = i;
    insert_points(dt, points, indices, stats);
    stats.fell_back = true;
    stats.outcome = Outcome::graph_edges_too_long;
    return;
  }
  insert_along_spanning_forest(dt, points, n, adjacency_of(ends, n), stats);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SPANNING_TREE_INSERTION_H
