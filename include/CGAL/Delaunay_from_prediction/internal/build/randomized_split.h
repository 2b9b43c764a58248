// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The randomized split of a Delaunay triangulation (Section 3.3 of the paper;
// Split_method::randomized of split_delaunay()): the points removed in random order, each paired
// with its nearest neighbour in its part by a growing-circle search along Delaunay edges.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_RANDOMIZED_SPLIT_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_RANDOMIZED_SPLIT_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The paper's algorithm on the finite vertices of `dt` (dimension 2), indexed 0..n-1 in
// container order: `part[k]` is 0 or 1. Returns, for k = 0..n-1, the point removed k-th and the
// index of its nearest neighbour in its part among the points left (no_rank if none).
template <class DT>
void randomized_removal_order(const DT& dt, const std::vector<unsigned char>& part,
                              std::vector<std::uint32_t>& removed, std::vector<std::uint32_t>& neighbour,
                              std::uint64_t seed)
{
  using Gt = typename DT::Geom_traits;
  using Vb = Triangulation_vertex_base_with_info_2<std::uint32_t, Gt>;
  using Tds = Triangulation_data_structure_2<Vb>;
  using Work = Delaunay_triangulation_2<Gt, Tds>;
  using Work_vertex = typename Work::Vertex_handle;
  using Point = typename DT::Point;
  const std::size_t n = part.size();
  // A copy of dt whose vertices carry their index (the infinite vertex: no_rank).
  Work work(dt.geom_traits());
  {
    std::uint32_t next = 0;
    const void* infinite = &*dt.infinite_vertex();
    struct Convert_vertex
    {
      std::uint32_t* next;
      const void* infinite;
      typename Tds::Vertex operator()(const typename DT::Vertex& v) const
      {
        typename Tds::Vertex w;
        w.set_point(v.point());
        return w;
      }
      void operator()(const typename DT::Vertex& v, typename Tds::Vertex& w) const
      {
        w.info() = static_cast<const void*>(&v) == infinite ? no_rank : (*next)++;
      }
    };
    struct Convert_face
    {
      typename Tds::Face operator()(const typename DT::Face&) const { return typename Tds::Face(); }
      void operator()(const typename DT::Face&, typename Tds::Face&) const {}
    };
    const Work_vertex infinite_copy =
        work.tds().copy_tds(dt.tds(), dt.infinite_vertex(), Convert_vertex{&next, infinite}, Convert_face{});
    work.set_infinite_vertex(infinite_copy);
  }
  std::vector<Work_vertex> vertex(n);
  for(auto v = work.finite_vertices_begin(); v != work.finite_vertices_end(); ++v)
    vertex[v->info()] = v;
  std::vector<std::uint32_t> alive(n), position(n);
  for(std::size_t k = 0; k < n; ++k)
    alive[k] = position[k] = std::uint32_t(k);
  std::size_t left_in_part[2] = {0, 0};
  for(unsigned char c : part)
    ++left_in_part[c];
  // A nearest-neighbour search by a growing circle (Section 3.3, step 2): the points of the
  // current triangulation by increasing distance to p, each popped point's neighbours pushed;
  // a point of p's part is not pushed but kept as the best candidate, and the search ends when
  // no pushed point is nearer than the candidate (then no point of the part is: the paper's
  // "Fact", points in a disk reach any point on its circle along Delaunay edges inside it).
  // Distances are compared in double, on coordinates scaled to the box of the points
  // (squared_distance_in_double()): the neighbour only chooses where a walk starts.
  const double scale = unit_scale(bounding_box(n, [&](std::size_t k) -> const Point& { return vertex[k]->point(); }));
  using Entry = std::pair<double, std::uint32_t>;
  struct Search
  {
    std::vector<std::uint64_t> seen; // the number of the last search that pushed each vertex
    std::vector<Entry> heap;         // a min-heap by distance
    std::uint32_t p = no_rank, found = no_rank;
    double best = 0; // distance to `found`
    bool done = false;
  };
  std::uint64_t stamp = 0; // numbers the searches
  auto push_neighbours = [&](Search& s, std::uint32_t u, std::uint64_t mark) {
    auto w = work.incident_vertices(vertex[u]), end = w;
    if(w == nullptr)
      return;
    const Point& centre = vertex[s.p]->point();
    do {
      const std::uint32_t x = w->info();
      if(x != no_rank && s.seen[x] != mark) {
        s.seen[x] = mark;
        const double d = squared_distance_in_double(w->point(), centre, scale);
        if(part[x] == part[s.p]) {
          if(d < s.best) {
            s.best = d;
            s.found = x;
          }
        } else if(d < s.best) {
          s.heap.emplace_back(d, x);
          std::push_heap(s.heap.begin(), s.heap.end(), std::greater<Entry>());
        }
      }
    } while(++w != end);
  };
  auto start = [&](Search& s, std::uint32_t p, std::uint64_t mark) {
    s.p = p;
    s.heap.clear();
    s.found = no_rank;
    s.best = std::numeric_limits<double>::infinity();
    s.done = left_in_part[part[p]] == 1; // alone in its part: nothing to find
    s.seen[p] = mark;
    if(!s.done)
      push_neighbours(s, p, mark);
  };
  auto step = [&](Search& s, std::uint64_t mark) {
    if(s.heap.empty() || !(s.heap.front().first < s.best)) {
      s.done = true;
      return;
    }
    std::pop_heap(s.heap.begin(), s.heap.end(), std::greater<Entry>());
    const std::uint32_t u = s.heap.back().second;
    s.heap.pop_back();
    push_neighbours(s, u, mark);
  };
  Splitmix64 random{seed};
  Search a, b; // two searches at a time, each with its own marks
  a.seen.assign(n, 0);
  b.seen.assign(n, 0);
  removed.clear();
  neighbour.clear();
  for(std::size_t left = n; left > 0; --left) {
    // Step 1: two random points; step 2: both searches in turn, the first to finish wins.
    const std::uint32_t pa = alive[random.below(left)], pb = alive[random.below(left)];
    start(a, pa, ++stamp);
    Search* winner = &a;
    if(pb != pa && !a.done) {
      start(b, pb, ++stamp);
      while(!a.done && !b.done) {
        step(a, stamp - 1);
        if(!a.done)
          step(b, stamp);
      }
      winner = a.done ? &a : &b;
    } else {
      while(!a.done)
        step(a, stamp);
    }
    const std::uint32_t p = winner->p;
    removed.push_back(p);
    neighbour.push_back(winner->found);
    // Step 3: remove p (CGAL's removal from a Delaunay triangulation).
    work.remove(vertex[p]);
    --left_in_part[part[p]];
    const std::uint32_t last = alive[left - 1];
    alive[position[p]] = last;
    position[last] = position[p];
  }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_RANDOMIZED_SPLIT_H
