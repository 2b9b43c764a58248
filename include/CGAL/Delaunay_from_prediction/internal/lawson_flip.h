// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 4 of the pipeline (repair): Lawson's edge flips on a CGAL triangulation, seeded only
// with the edges certification found not locally Delaunay. The one flip engine of the
// package: delaunay_from_prediction runs it on the triangulation it exported, make_delaunay
// on the caller's own.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_LAWSON_FLIP_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_LAWSON_FLIP_H

#include <CGAL/Delaunay_from_prediction/internal/predicates.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Statistics::fallback_reason when Lawson's algorithm would need, or needed, more flips than
// the budget.
constexpr const char* flip_budget_exhausted = "the flip budget was exhausted";

// The edge (b, c) between the ccw triangle (a, b, c) and the triangle on its other side, whose
// third vertex is d, can be flipped to (a, d) keeping both faces counterclockwise: the
// quadrilateral a, b, d, c is strictly convex.
template <class Gt, class Point>
bool flip_makes_ccw_faces(const Gt& gt, const Point& a, const Point& b, const Point& c,
                          const Point& d)
{
  auto orientation = gt.orientation_2_object();
  return orientation(a, b, d) == LEFT_TURN && orientation(a, d, c) == LEFT_TURN;
}

// The default of flip_edges_while()'s `on_flip`: no log.
struct No_flip_log
{
  template <class Face_handle>
  void operator()(Face_handle, int) const
  {}
};

// A flip, as logged for undo_flip(): the face and index it was called with.
template <class Triangulation>
using Flip_log = std::vector<std::pair<typename Triangulation::Face_handle, int>>;

// Undoes tds.flip(f, i), given the same f and i right after it: every vertex and neighbour
// slot of f and g = the face across, and the slots of the four faces around them that point
// at f or g, are as they were before it (CGAL's flip of the new edge would bring back the
// same faces, but in each other's objects: a log of earlier flips names face objects and
// slots, so it must find them as they were). No edge lookup: exact even where the faces do
// not form a triangulation (two edges between the same vertices).
template <class Tds>
void undo_flip(Tds& /* the faces' data structure, for its types */, typename Tds::Face_handle f, int i)
{
  // After the flip: f = (a, b, d) in slots (i, ccw(i), cw(i)), g = (d, c, a) in slots
  // (j, ccw(j), cw(j)); before it f = (a, b, c), g = (d, c, b). See flip_edges_while().
  const typename Tds::Face_handle g = f->neighbor(ccw(i));
  const typename Tds::Vertex_handle a = f->vertex(i), b = f->vertex(ccw(i)), d = f->vertex(cw(i));
  const int j = g->index(d);
  const typename Tds::Vertex_handle c = g->vertex(ccw(j));
  const typename Tds::Face_handle across_bd = f->neighbor(i), across_ca = g->neighbor(j);
  const int at_bd = across_bd->index(f), at_ca = across_ca->index(g);
  f->set_vertex(cw(i), c);
  g->set_vertex(cw(j), b);
  f->set_neighbor(i, g);
  f->set_neighbor(ccw(i), across_ca);
  g->set_neighbor(j, f);
  g->set_neighbor(ccw(j), across_bd);
  across_ca->set_neighbor(at_ca, f);
  across_bd->set_neighbor(at_bd, g);
  a->set_face(f);
  b->set_face(f);
  c->set_face(g);
  d->set_face(g);
}

// The flip loop: pops candidate edges (face, index) from `stack` and flips each interior edge
// for which `wants_flip(f, i, a, b, c, d)` holds ((b, c) the edge, a opposite in f, d opposite
// in its neighbour) and whose quadrilateral is strictly convex, queueing the four edges around
// every flip; until the stack is empty (returns true) or `max_flips` flips have been made
// (returns false; the triangulation is still a valid triangulation of the same vertices). Any
// edge may be listed, stale or twice: each is tested when popped. If `touched` is not null it
// receives both faces of every flip, and `on_flip(f, i)` the face and index of every flip
// (a Flip_log entry for undo_flip()). With
// `Wanted_flips_are_convex` the caller guarantees that `wants_flip` implies a strictly convex
// quadrilateral, and the test is skipped.
template <bool Wanted_flips_are_convex = false, class Triangulation, class WantsFlip, class OnFlip = No_flip_log>
bool flip_edges_while(Triangulation& tr,
                      std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                      WantsFlip wants_flip, std::size_t max_flips, std::size_t& flips,
                      std::vector<typename Triangulation::Face_handle>* touched, OnFlip on_flip = OnFlip())
{
  using Face_handle = typename Triangulation::Face_handle;
  const auto& gt = tr.geom_traits();
  const auto infinite = tr.infinite_vertex();
  auto& tds = tr.tds();
  // The loop is bound by memory latency: the face across the popped edge and its opposite
  // vertex are cold two times in three. The stack is a pipeline: the faces across the edges
  // two pops ahead are prefetched, and the vertices of the face across the next edge, so
  // the misses of consecutive edges overlap. A flip also rewrites the faces across the far
  // edges of f and g, prefetched before the in-circle test decides. The four edges pushed by
  // a flip belong to its two faces, which are hot: the faces across them are prefetched at
  // once.
  auto prefetch_across = [](const std::pair<Face_handle, int>& e) {
#if defined(__GNUC__)
    __builtin_prefetch(e.first->neighbor(e.second).operator->());
#else
    (void)e;
#endif
  };
  auto prefetch_vertices_across = [](const std::pair<Face_handle, int>& e) {
#if defined(__GNUC__)
    const Face_handle g = e.first->neighbor(e.second);
    for(int k = 0; k < 3; ++k)
      __builtin_prefetch(g->vertex(k).operator->());
#else
    (void)e;
#endif
  };
  while(!stack.empty()) {
    const std::size_t size = stack.size();
    if(size > 2)
      prefetch_across(stack[size - 3]);
    if(size > 1)
      prefetch_vertices_across(stack[size - 2]);
    const Face_handle f = stack.back().first;
    const int i = stack.back().second;
    stack.pop_back();
    const Face_handle g = f->neighbor(i);
    if(f->has_vertex(infinite) || g->has_vertex(infinite))
      continue; // hull edges cannot be flipped
    const int j = tds.mirror_index(f, i);
    const auto& a = f->vertex(i)->point();
    const auto& b = f->vertex(ccw(i))->point();
    const auto& c = f->vertex(cw(i))->point();
    const auto& d = g->vertex(j)->point();
    prefetch_across(std::make_pair(f, ccw(i)));
    prefetch_across(std::make_pair(g, ccw(j)));
    if(!wants_flip(f, i, a, b, c, d))
      continue;
    if(!Wanted_flips_are_convex && !flip_makes_ccw_faces(gt, a, b, c, d))
      continue;
    CGAL_assertion(!Wanted_flips_are_convex || flip_makes_ccw_faces(gt, a, b, c, d));
    if(flips >= max_flips)
      return false;
    // After the flip f = (a, b, d) and g = (d, c, a), with the same slots: their four outer
    // edges are f's i and cw(i), g's j and cw(j).
    tds.flip(f, i);
    ++flips;
    on_flip(f, i);
    if(touched != nullptr) {
      touched->push_back(f);
      touched->push_back(g);
    }
    stack.emplace_back(f, i);
    stack.emplace_back(f, cw(i));
    stack.emplace_back(g, j);
    stack.emplace_back(g, cw(j));
    for(std::size_t k = stack.size() - 4; k < stack.size(); ++k)
      prefetch_across(stack[k]);
  }
  return true;
}

// Lawson's algorithm: flips until every edge is locally Delaunay, or until `max_flips` flips
// have been made (returns false then), starting from the candidate edges in `stack`.
// `touched` receives both faces of every flip.
//
// Termination: with exact predicates each flip strictly lowers the lifted (perturbed)
// surface, so no triangulation repeats; with an inexact kernel the budget stops a cycle.
// A flip is made only when both new faces are counterclockwise. With exact predicates an
// edge between two ccw faces that fails the in-circle test always has a strictly convex
// quadrilateral (the opposite vertex lies in the circumcircle's cap beyond the edge, or on
// its arc, strictly inside the angle of the other face at its apex), so the test is skipped
// for the kernels whose predicates are exact on doubles (with the prefetch of the faces a flip
// rewrites, a quarter off the flip loop's time at 1e6 points); every caller flips a
// triangulation whose finite faces are all ccw. With an inexact kernel the guard keeps every
// face ccw.
template <class Triangulation>
bool lawson_flip(Triangulation& tr,
                 std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                 std::size_t max_flips, std::size_t& flips,
                 std::vector<typename Triangulation::Face_handle>& touched)
{
  using Gt = typename Triangulation::Geom_traits;
  const Gt& gt = tr.geom_traits();
  auto not_locally_delaunay = [&gt](const auto&, int, const auto& a, const auto& b, const auto& c,
                                    const auto& d) { return !is_locally_delaunay(gt, a, b, c, d); };
  return flip_edges_while<has_exact_double_predicates<Gt>::value>(tr, stack, not_locally_delaunay, max_flips,
                                                                  flips, &touched);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_LAWSON_FLIP_H
