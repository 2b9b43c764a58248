// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The insertion of BrioDC (brio_dc_delaunay(); K. Buchin, W. Mulzer, "Linear-time Delaunay
// triangulations simplified"): the gradation of samples that meet every component of the
// nearest-neighbour graph, and the walks along the graph's edges that locate each point.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BRIO_DC_INSERTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BRIO_DC_INSERTION_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/build/nearest_neighbour_graph.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// BrioDC on the finite points point_begin[0..n) into the empty `dt` (exact predicates): the
// gradation of samples S_0 = P, S_1, ... drawn from the nearest-neighbour graph of each
// level, the last sample inserted by CGAL's insertion, then each level's other points located
// by a walk from their graph neighbour's vertex. Fills `stats`; the caller checked the input.
// With `parallel`, the nearest-neighbour searches run on TBB's threads (the same graphs).
template <class DT, class PointIterator>
void brio_dc_insert(DT& dt, PointIterator point_begin, std::size_t n, std::uint64_t seed, double probability,
                    Statistics& stats, bool parallel = false)
{
  using Point = typename DT::Point;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  // The points, gathered (every later pass reads them by index).
  std::vector<Point> point(point_begin, point_begin + std::ptrdiff_t(n));

  // The gradation, from S_0 = P down: each level in grid order, with its nearest-neighbour
  // graph (positions within the level) and which of its points are in the next sample.
  struct Level
  {
    std::vector<std::uint32_t> members;     // point indices, in grid order
    std::vector<std::uint32_t> nn;          // nearest neighbour, by position
    std::vector<unsigned char> in_next;     // in S_{i+1}
  };
  std::vector<Level> levels;
  std::vector<std::uint32_t> original;   // the caller's index of each point (after renumbering)
  std::vector<Vertex_handle> vertex(n); // the vertex of each point, once inserted
  internal::Vertex_grid<Vertex_handle> vertex_grid(n, [&](std::size_t i) -> const Point& { return point[i]; });
  internal::Splitmix64 random{seed + 0xb410dcull};
  {
    std::vector<std::uint32_t> members(n);
    for(std::size_t i = 0; i < n; ++i)
      members[i] = std::uint32_t(i);
    std::vector<double> xy;
    std::vector<std::uint32_t> order;
    while(members.size() > 64) {
      Level level;
      const std::size_t m = members.size();
      xy.resize(2 * m);
      for(std::size_t k = 0; k < m; ++k) {
        xy[2 * k] = CGAL::to_double(point[members[k]].x());
        xy[2 * k + 1] = CGAL::to_double(point[members[k]].y());
      }
      internal::nearest_neighbour_graph(xy.data(), m, order, level.nn, parallel);
      level.members.resize(m);
      for(std::size_t k = 0; k < m; ++k)
        level.members[k] = members[order[k]];
      if(levels.empty()) {
        // Renumber the points in the grid order of the first level: every later pass then
        // reads `point` and `vertex` in nearly increasing order, where the input order would
        // make each read a cache miss.
        std::vector<Point> sorted(n);
        for(std::size_t k = 0; k < n; ++k)
          sorted[k] = point[level.members[k]];
        point.swap(sorted);
        original.swap(level.members);
        level.members.resize(n);
        for(std::size_t k = 0; k < n; ++k)
          level.members[k] = std::uint32_t(k);
      }
      members.clear();
      // A matching of two points on the cycle of each component of the graph (a functional
      // graph: each component is a tree hanging from one cycle, two mutual neighbours unless
      // neighbours were approximate); one point of each pair goes to the sample, every other
      // point with the sampling probability (1/8 by default).
      level.in_next.assign(m, 2); // 2: not decided
      std::vector<std::uint32_t> state(m, 0);
      for(std::uint32_t s = 0; s < m; ++s) {
        if(state[s] != 0)
          continue;
        // Follow the neighbours from s until a point seen before: on this path (a new cycle)
        // or in an earlier one (a tree hanging from a known component).
        std::uint32_t u = s;
        while(state[u] == 0) {
          state[u] = s + 1;
          u = level.nn[u];
        }
        if(state[u] == s + 1) { // a new cycle through u: match u with its neighbour
          // (A cycle of one point, which nearest_neighbour_graph() never gives, keeps it.)
          const std::uint32_t v = level.nn[u];
          const bool keep_u = v == u || (random() & 1) != 0;
          level.in_next[u] = keep_u ? 1 : 0;
          if(v != u)
            level.in_next[v] = keep_u ? 0 : 1;
        }
      }
      for(std::uint32_t k = 0; k < m; ++k) {
        if(level.in_next[k] == 2) // (uniform() < 1: probability 1 keeps every point)
          level.in_next[k] = random.uniform() < probability ? 1 : 0;
        if(level.in_next[k])
          members.push_back(level.members[k]);
      }
      levels.push_back(std::move(level));
      // A sample that barely shrinks (sample_probability near 1, whose graph has few
      // components: equal points, a geometric progression) would make one level per point or
      // so, quadratic time: it is the last sample instead.
      if(members.size() > m - m / 32)
        break;
    }
    // The last sample, small (or one that did not shrink): inserted first, by CGAL's insertion.
    stats.insertion_rounds = levels.size() + 1;
    Face_handle hint;
    for(std::uint32_t i : members) {
      const std::size_t count = dt.number_of_vertices();
      const Vertex_handle v = dt.insert(point[i], hint);
      hint = v->face();
      internal::record_index_info(v, original.empty() ? i : original[i], dt.number_of_vertices() != count,
                                  stats.duplicate_points);
      vertex[i] = v;
      vertex_grid.record(point[i], v);
    }
  }
  const std::size_t cap = internal::walk_cap(n);
  std::vector<std::pair<Face_handle, int>> flip_stack;
  // From the coarsest level down: the points not in the next sample, component by component
  // in grid order of their first sampled point, each from its graph neighbour (depth-first
  // along the graph's edges, both directions).
  std::vector<std::uint32_t> children_start, children, stack;
  std::vector<unsigned char> done;
  // Inserts point i, located by a walk from vertex `from` (or by CGAL's location without one).
  auto insert = [&](std::uint32_t i, Vertex_handle from) {
    const std::size_t count = dt.number_of_vertices();
    const Vertex_handle v = from != Vertex_handle()
                                ? internal::insert_walking_from(dt, point[i], from, cap, vertex_grid, flip_stack, stats)
                                : dt.insert(point[i]);
    internal::record_index_info(v, original[i], dt.number_of_vertices() != count, stats.duplicate_points);
    vertex[i] = v;
    vertex_grid.record(point[i], v);
  };
  for(std::size_t l = levels.size(); l-- > 0;) {
    const Level& level = levels[l];
    const std::size_t m = level.members.size();
    children_start.assign(m + 1, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      ++children_start[level.nn[k] + 1];
    for(std::size_t k = 0; k < m; ++k)
      children_start[k + 1] += children_start[k];
    children.resize(m);
    {
      std::vector<std::uint32_t> fill(children_start.begin(), children_start.end() - 1);
      for(std::uint32_t k = 0; k < m; ++k)
        children[fill[level.nn[k]]++] = k;
    }
    done.assign(m, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      done[k] = level.in_next[k];
    for(std::uint32_t s = 0; s < m; ++s) {
      if(!level.in_next[s] || done[s] == 2)
        continue;
      done[s] = 2; // 2: its neighbours were pushed
      stack.assign(1, s);
      while(!stack.empty()) {
        const std::uint32_t u = stack.back();
        stack.pop_back();
        auto visit = [&](std::uint32_t w) {
          if(done[w] == 2)
            return;
          if(done[w] == 0) // insert w, located from u
            insert(level.members[w], vertex[level.members[u]]);
          done[w] = 2;
          stack.push_back(w);
        };
        visit(level.nn[u]);
        for(std::uint32_t c = children_start[u]; c < children_start[u + 1]; ++c)
          visit(children[c]);
      }
    }
    // Every component of the graph has a point in the next sample (the matching on its
    // cycle), so the search above reached every point; whatever the graph, a point it did not
    // reach is inserted here, so that none is dropped.
    for(std::uint32_t w = 0; w < m; ++w)
      if(done[w] == 0)
        insert(level.members[w], vertex_grid.near(point[level.members[w]]));
  }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BRIO_DC_INSERTION_H
