// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The hole tracer shared by the importer's small-hole filler (import_prediction.h) and the
// carve (carve_repair.h). A hole is bounded by open half-edges of kept faces, the kept faces
// on their left. The tracer's three steps:
// - the successor of an open half-edge ending at v: turn around v through kept faces, away
//   from the hole, to the first open half-edge leaving v (turn_to_open_halfedge());
// - a cycle of successors that passes a vertex twice (holes touching there) is split there
//   into loops through distinct vertices (split_at_repeated_vertices());
// - a loop is filled by ear clipping of its polygon: the loop reversed, counterclockwise
//   (Hole_clipper); every side of an ear is a side of the hole, closing one open half-edge,
//   or a diagonal shared with another ear.
// The two callers keep their own stores of open half-edges (the importer a sorted array of
// index pairs, the carve hash tables that follow incremental rounds) and link the ears
// themselves.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_HOLE_TRACING_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_HOLE_TRACING_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/enum.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Ear clipping of a polygon: the one polygon triangulator of the package, used to fill the
// holes of a carved prediction (carve_repair.h) and the faces of a predicted planar graph
// (Delaunay_from_predicted_edges_2.h).

// Triangulates the polygon with vertices point(0), ..., point(m-1), counterclockwise, into
// m - 2 ears (a, b, c) of positions, each counterclockwise. An ear is cut at b when (a, b, c)
// is counterclockwise and no other vertex of the remaining polygon lies in it or on its
// boundary; a simple polygon always has one (two-ears theorem), so the clipping succeeds on
// every simple counterclockwise polygon. Returns false, with no ears, when it gets stuck (the
// polygon is not simple, or not counterclockwise). Robust: exact orientation tests only, so a
// returned ear is truly counterclockwise. O(m^2) tests in the worst case; callers bound m.
// `prev` and `next` are scratch space (reused across calls to spare allocations).
template <class Gt, class PointOf>
bool clip_ears(const Gt& gt, std::size_t m, PointOf point, std::vector<std::array<std::size_t, 3>>& ears,
               std::vector<std::size_t>& prev, std::vector<std::size_t>& next)
{
  ears.clear();
  if(m < 3)
    return false;
  auto orientation = orientation_called_out_of_line(gt);
  prev.resize(m);
  next.resize(m);
  for(std::size_t p = 0; p < m; ++p) {
    prev[p] = (p + m - 1) % m;
    next[p] = (p + 1) % m;
  }
  std::size_t remaining = m, b = 0, tried = 0;
  while(remaining >= 3) {
    const std::size_t a = prev[b], c = next[b];
    const auto& pa = point(a);
    const auto& pb = point(b);
    const auto& pc = point(c);
    bool ear = orientation(pa, pb, pc) == LEFT_TURN;
    if(ear && remaining > 3)
      for(std::size_t q = next[c]; q != a; q = next[q]) {
        const auto& pq = point(q);
        if(orientation(pa, pb, pq) != RIGHT_TURN && orientation(pb, pc, pq) != RIGHT_TURN &&
           orientation(pc, pa, pq) != RIGHT_TURN) {
          ear = false;
          break;
        }
      }
    if(!ear) {
      b = c;
      if(++tried > remaining) {
        ears.clear();
        return false;
      }
      continue;
    }
    ears.push_back({a, b, c});
    next[a] = c;
    prev[c] = a;
    --remaining;
    tried = 0;
    b = a; // a may have become an ear
  }
  return true;
}

// Turns around vertex v, starting at face f whose half-edge `leaving` leaves v, through the
// faces across each half-edge leaving v until `is_open(f, leaving)`: returns true with f and
// `leaving` on that open half-edge, or false after `max_turns` faces (faces winding around
// v, or a fan too large for the caller).
template <class Face_handle, class Vertex_handle, class IsOpen>
bool turn_to_open_halfedge(Face_handle& f, const Vertex_handle& v, int& leaving, IsOpen is_open,
                           std::size_t max_turns)
{
  for(std::size_t turns = 0; turns < max_turns; ++turns) {
    if(is_open(f, leaving))
      return true;
    const Face_handle g = f->neighbor(leaving);
    leaving = cw(g->index(v));
    f = g;
  }
  return false;
}

// Splits the closed cycle of half-edges `cycle` at every vertex it passes twice into loops
// that pass each vertex once, in one pass: a stack of the half-edges since the last split.
// `tail(h)` is h's tail vertex as a key (a pointer or an unsigned index); `on_loop(first,
// last)` receives each loop as a range of `stack` (scratch space), the inner ones first.
// Short cycles search the stack; long ones remember where each tail sits in it (an entry is
// current if the stack still holds that vertex there).
template <class TailOf, class OnLoop>
void split_at_repeated_vertices(const std::vector<std::size_t>& cycle, TailOf tail, std::vector<std::size_t>& stack,
                                OnLoop on_loop)
{
  constexpr std::size_t short_cycle = 32; // up to this, a search is cheaper than a table
  stack.clear();
  if(cycle.size() <= short_cycle) {
    for(const std::size_t h : cycle) {
      const auto v = tail(h);
      std::size_t seen = 0;
      while(seen < stack.size() && tail(stack[seen]) != v)
        ++seen;
      if(seen < stack.size()) {
        on_loop(stack.cbegin() + std::ptrdiff_t(seen), stack.cend());
        stack.resize(seen);
      }
      stack.push_back(h);
    }
  } else {
    // Integer tails keyed as 64-bit integers: one table type with the importer's (code_size.h).
    using Tail = decltype(tail(cycle[0]));
    Hash_map<std::conditional_t<std::is_pointer<Tail>::value, Tail, std::uint64_t>, std::size_t> at;
    for(const std::size_t h : cycle) {
      const auto v = tail(h);
      std::size_t* seen = at.insert(v, stack.size()).first;
      if(*seen < stack.size() && tail(stack[*seen]) == v) {
        on_loop(stack.cbegin() + std::ptrdiff_t(*seen), stack.cend());
        stack.resize(*seen);
      }
      *seen = stack.size();
      stack.push_back(h);
    }
  }
  on_loop(stack.cbegin(), stack.cend());
}

// An ear of a hole's fill, in positions of its loop: corner c is the tail of the loop's
// half-edge hole_corner(corner[c], m); the side opposite corner c closes the loop's
// half-edge at position closes[c], or is a diagonal (closes[c] == Hole_ear::diagonal) from
// corner c+1 to corner c+2.
struct Hole_ear
{
  static constexpr std::size_t diagonal = std::size_t(-1);
  std::array<std::size_t, 3> corner;
  std::array<std::size_t, 3> closes;
};

// Where polygon vertex p of a loop of m half-edges sits in the loop: half-edge q runs from
// tail t_q to t_(q+1); reversed, the polygon has vertex p = t_(m-1-p), and its side from p to
// p+1 is half-edge (2m-2-p) mod m, reversed.
inline std::size_t hole_corner(std::size_t p, std::size_t m) { return m - 1 - p; }
inline std::size_t hole_side(std::size_t p, std::size_t m) { return (2 * m - 2 - p) % m; }

// Ear clipping of holes (triangulate_polygon() above), with its scratch space reused across holes.
class Hole_clipper
{
public:
  // Fills the loop of m half-edges whose tails' points are tail_point(0..m-1), in loop
  // order; false if ear clipping fails on its polygon (not simple, or not counterclockwise:
  // not a hole).
  template <class Gt, class TailPoint>
  bool clip(const Gt& gt, std::size_t m, TailPoint tail_point, std::vector<Hole_ear>& ears)
  {
    ears.clear();
    if(!clip_ears(gt, m, [&](std::size_t p) -> decltype(auto) { return tail_point(hole_corner(p, m)); }, cut_,
                  prev_, next_))
      return false;
    ears.reserve(cut_.size());
    for(const auto& t : cut_) {
      Hole_ear e;
      for(int c = 0; c < 3; ++c) {
        e.corner[c] = t[c];
        const std::size_t from = t[ccw(c)], to = t[cw(c)];
        e.closes[c] = (from + 1) % m == to ? hole_side(from, m) : Hole_ear::diagonal;
      }
      ears.push_back(e);
    }
    return true;
  }

private:
  std::vector<std::array<std::size_t, 3>> cut_;
  std::vector<std::size_t> prev_, next_;
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_HOLE_TRACING_H
