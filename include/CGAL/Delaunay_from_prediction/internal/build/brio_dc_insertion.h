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

// One level of the gradation S_0 = P, S_1, ...: its points in grid order, with its
// nearest-neighbour graph (positions within the level) and which of its points are in the
// next sample.
struct Brio_dc_level
{
  std::vector<std::uint32_t> members;     // point indices, in grid order
  std::vector<std::uint32_t> nn;          // nearest neighbour, by position
  std::vector<unsigned char> in_next;     // in S_{i+1}
};

// Draws the next sample from `level`: a matching of two points on the cycle of each component
// of the graph (a functional graph: each component is a tree hanging from one cycle, two mutual
// neighbours unless neighbours were approximate); one point of each pair goes to the sample,
// every other point with the sampling probability (1/8 by default). Sets level.in_next and
// appends the sample's points to `sample`, in grid order.
inline void draw_next_sample(Brio_dc_level& level, Splitmix64& random, double probability,
                             std::vector<std::uint32_t>& sample)
{
  const std::size_t m = level.members.size();
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
      sample.push_back(level.members[k]);
  }
}

// BrioDC's insertion into the empty `dt` (see brio_dc_insert()), its stages sharing the
// gathered points, the vertex of each point and the grid of vertices the walks start from.
template <class DT, class PointIterator>
class Brio_dc_insertion
{
  using Point = typename DT::Point;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;

public:
  // The points gathered from point_begin[0..n) (every later pass reads them by index).
  Brio_dc_insertion(DT& dt, PointIterator point_begin, std::size_t n, Statistics& stats)
      : dt_(dt), stats_(stats), n_(n), point_(point_begin, point_begin + std::ptrdiff_t(n)), vertex_(n),
        vertex_grid_(n, [this](std::size_t i) -> const Point& { return point_[i]; }), cap_(internal::walk_cap(n))
  {}

  // The gradation, its last sample inserted by CGAL's insertion, then the levels from the
  // coarsest down.
  void run(std::uint64_t seed, double probability, bool parallel)
  {
    {
      const std::vector<std::uint32_t> last_sample = build_gradation(seed, probability, parallel);
      stats_.insertion_rounds = levels_.size() + 1;
      insert_last_sample(last_sample);
    }
    for(std::size_t l = levels_.size(); l-- > 0;)
      insert_level(levels_[l]);
  }

private:
  // The gradation, from S_0 = P down, until a sample of at most 64 points (or one that barely
  // shrinks); returns that last sample.
  std::vector<std::uint32_t> build_gradation(std::uint64_t seed, double probability, bool parallel)
  {
    internal::Splitmix64 random{seed + 0xb410dcull};
    std::vector<std::uint32_t> members(n_);
    for(std::size_t i = 0; i < n_; ++i)
      members[i] = std::uint32_t(i);
    std::vector<double> xy;
    std::vector<std::uint32_t> order;
    while(members.size() > 64) {
      Brio_dc_level level;
      const std::size_t m = members.size();
      graph_of_sample(members, xy, order, level, parallel);
      if(levels_.empty())
        renumber_in_grid_order(level);
      members.clear();
      draw_next_sample(level, random, probability, members);
      levels_.push_back(std::move(level));
      // A sample that barely shrinks (sample_probability near 1, whose graph has few
      // components: equal points, a geometric progression) would make one level per point or
      // so, quadratic time: it is the last sample instead.
      if(members.size() > m - m / 32)
        break;
    }
    return members;
  }

  // The level of the sample `members`: its points in grid order and their nearest-neighbour
  // graph (`xy` and `order` are scratch space kept from level to level).
  void graph_of_sample(const std::vector<std::uint32_t>& members, std::vector<double>& xy,
                       std::vector<std::uint32_t>& order, Brio_dc_level& level, bool parallel)
  {
    const std::size_t m = members.size();
    xy.resize(2 * m);
    for(std::size_t k = 0; k < m; ++k) {
      xy[2 * k] = CGAL::to_double(point_[members[k]].x());
      xy[2 * k + 1] = CGAL::to_double(point_[members[k]].y());
    }
    internal::nearest_neighbour_graph(xy.data(), m, order, level.nn, parallel);
    level.members.resize(m);
    for(std::size_t k = 0; k < m; ++k)
      level.members[k] = members[order[k]];
  }

  // Renumbers the points in the grid order of the first level: every later pass then reads
  // `point_` and `vertex_` in nearly increasing order, where the input order would make each
  // read a cache miss.
  void renumber_in_grid_order(Brio_dc_level& first_level)
  {
    std::vector<Point> sorted(n_);
    for(std::size_t k = 0; k < n_; ++k)
      sorted[k] = point_[first_level.members[k]];
    point_.swap(sorted);
    original_.swap(first_level.members);
    first_level.members.resize(n_);
    for(std::size_t k = 0; k < n_; ++k)
      first_level.members[k] = std::uint32_t(k);
  }

  // The last sample, small (or one that did not shrink): inserted first, by CGAL's insertion.
  void insert_last_sample(const std::vector<std::uint32_t>& members)
  {
    Face_handle hint;
    for(std::uint32_t i : members) {
      const std::size_t count = dt_.number_of_vertices();
      const Vertex_handle v = dt_.insert(point_[i], hint);
      hint = v->face();
      internal::record_index_info(v, original_.empty() ? i : original_[i], dt_.number_of_vertices() != count,
                        stats_.duplicate_points);
      vertex_[i] = v;
      vertex_grid_.record(point_[i], v);
    }
  }

  // The points of `level` not in the next sample, component by component in grid order of
  // their first sampled point, each from its graph neighbour (depth-first along the graph's
  // edges, both directions).
  void insert_level(const Brio_dc_level& level)
  {
    const std::size_t m = level.members.size();
    graph_children(level);
    done_.assign(m, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      done_[k] = level.in_next[k];
    for(std::uint32_t s = 0; s < m; ++s) {
      if(!level.in_next[s] || done_[s] == 2)
        continue;
      done_[s] = 2; // 2: its neighbours were pushed
      stack_.assign(1, s);
      while(!stack_.empty()) {
        const std::uint32_t u = stack_.back();
        stack_.pop_back();
        auto visit = [&](std::uint32_t w) {
          if(done_[w] == 2)
            return;
          if(done_[w] == 0) // insert w, located from u
            insert(level.members[w], vertex_[level.members[u]]);
          done_[w] = 2;
          stack_.push_back(w);
        };
        visit(level.nn[u]);
        for(std::uint32_t c = children_start_[u]; c < children_start_[u + 1]; ++c)
          visit(children_[c]);
      }
    }
    // Every component of the graph has a point in the next sample (the matching on its
    // cycle), so the search above reached every point; whatever the graph, a point it did not
    // reach is inserted here, so that none is dropped.
    for(std::uint32_t w = 0; w < m; ++w)
      if(done_[w] == 0)
        insert(level.members[w], vertex_grid_.near(point_[level.members[w]]));
  }

  // The graph's edges in reverse: the points whose neighbour is k are
  // children_[children_start_[k] .. children_start_[k + 1]), in increasing position.
  void graph_children(const Brio_dc_level& level)
  {
    const std::size_t m = level.members.size();
    children_start_.assign(m + 1, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      ++children_start_[level.nn[k] + 1];
    for(std::size_t k = 0; k < m; ++k)
      children_start_[k + 1] += children_start_[k];
    children_.resize(m);
    std::vector<std::uint32_t> fill(children_start_.begin(), children_start_.end() - 1);
    for(std::uint32_t k = 0; k < m; ++k)
      children_[fill[level.nn[k]]++] = k;
  }

  // Inserts point i, located by a walk from vertex `from` (or by CGAL's location without one).
  void insert(std::uint32_t i, Vertex_handle from)
  {
    const std::size_t count = dt_.number_of_vertices();
    const Vertex_handle v =
        from != Vertex_handle()
            ? internal::insert_walking_from(dt_, point_[i], from, cap_, vertex_grid_, flip_stack_, stats_)
            : dt_.insert(point_[i]);
    internal::record_index_info(v, original_[i], dt_.number_of_vertices() != count, stats_.duplicate_points);
    vertex_[i] = v;
    vertex_grid_.record(point_[i], v);
  }

  DT& dt_;
  Statistics& stats_;
  const std::size_t n_;
  std::vector<Point> point_;             // the points, renumbered in the first level's grid order
  std::vector<Brio_dc_level> levels_;
  std::vector<std::uint32_t> original_;  // the caller's index of each point (after renumbering)
  std::vector<Vertex_handle> vertex_;    // the vertex of each point, once inserted
  internal::Vertex_grid<Vertex_handle> vertex_grid_;
  const std::size_t cap_;
  std::vector<std::pair<Face_handle, int>> flip_stack_;
  // Scratch space of insert_level(), kept from level to level.
  std::vector<std::uint32_t> children_start_, children_, stack_;
  std::vector<unsigned char> done_;
};

// BrioDC on the finite points point_begin[0..n) into the empty `dt` (exact predicates): the
// gradation of samples S_0 = P, S_1, ... drawn from the nearest-neighbour graph of each
// level, the last sample inserted by CGAL's insertion, then each level's other points located
// by a walk from their graph neighbour's vertex. Fills `stats`; the caller checked the input.
// With `parallel`, the nearest-neighbour searches run on TBB's threads (the same graphs).
template <class DT, class PointIterator>
void brio_dc_insert(DT& dt, PointIterator point_begin, std::size_t n, std::uint64_t seed, double probability,
                    Statistics& stats, bool parallel = false)
{
  Brio_dc_insertion<DT, PointIterator>(dt, point_begin, n, stats).run(seed, probability, parallel);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BRIO_DC_INSERTION_H
