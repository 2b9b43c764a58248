// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Every edge flip of the package, and the loops that drive them:
// - flip_edges_while() and lawson_flip(): Lawson's algorithm (stage 4 of the pipeline,
//   repair), seeded only with the edges certification found not locally Delaunay;
//   delaunay_from_prediction runs it on the triangulation it exported, make_delaunay on the
//   caller's own, certification (tds_certify.h) on the fly; on TBB's threads, in the cells of
//   a grid (make_flip_cells()), flip_in_cells();
// - flip_around_new_vertex(): the flips of one incremental insertion (insertion.h);
// - untangle_by_flips(): the flips that undo a vertex crossing an edge (make_delaunay after
//   moves, before any carving), on TBB's threads in the same cells;
// - convexify_hull(): flips of infinite edges that make a hull convex again;
// - undo_flip() and undo_flips(): the log that lets make_delaunay restore the caller's
//   triangulation exactly.
//
// Hull flips. A hull that is no longer convex (make_delaunay after moves: a hull vertex that
// moved inwards, or nearly collinear hull points that moved a little) is repaired by flips of
// infinite edges. Each flip turns a reflex hull vertex b, between hull neighbours a and c,
// into an interior vertex: the infinite faces around the edge (b, infinite) become the finite
// face (a, c, b), counterclockwise because b turned right, and the infinite face of the new
// hull edge a->c.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_FLIPS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_FLIPS_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/counting_sort.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Default flip budget. Lawson's algorithm needs about as many flips as the prediction has
// wrong edges, and falls back at once when the failing edges alone exceed the budget. A flip
// with its re-tests costs about 0.4 of a point insertion of a rebuild (measured: 0.42 us per
// flip against about 1 us per point at 1e6 points), so 3n/4 wasted flips add at most about
// 0.3 of a rebuild; moves of 0.1 spacing need 0.44n (1e6 points) to 0.5n (5000 points), a
// plain Triangulation_2 of random points ~6n, which is cheaper to rebuild.
inline std::size_t default_max_flips(std::size_t n) { return 3 * n / 4 + 64; }

// The edge (b, c) between the ccw triangle (a, b, c) and the triangle on its other side, whose
// third vertex is d, can be flipped to (a, d) keeping both faces counterclockwise: the
// quadrilateral a, b, d, c is strictly convex.
template <class Gt, class Point>
bool flip_makes_ccw_faces(const Gt& gt, const Point& a, const Point& b, const Point& c,
                          const Point& d)
{
  auto orientation = orientation_called_out_of_line(gt);
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

// The cells of the tasks that flip on TBB's threads (flip_in_cells(), untangle_by_flips()),
// for the faces face_at(0..m-1) they start from: a grid of side x side cells over the box of
// the finite vertices of a sample of the faces, about `per_cell` faces a cell, 4 to 256
// cells: few enough that most flips are inside a cell, enough for TBB to balance the threads.
// Which cell a point is in only steers: the tasks' results do not depend on it. False when
// the sample has no finite vertex.
template <class Vertex_handle, class FaceAt>
bool make_flip_cells(std::size_t m, const FaceAt& face_at, Vertex_handle infinite, std::size_t per_cell,
                     Cell_grid& out)
{
  Box box;
  const std::size_t stride = (std::max)(std::size_t(1), m / 4096);
  for(std::size_t k = 0; k < m; k += stride)
    for(int v = 0; v < 3; ++v) {
      const Vertex_handle u = face_at(k)->vertex(v);
      if(u == infinite)
        continue;
      box.add(CGAL::to_double(u->point().x()), CGAL::to_double(u->point().y()));
    }
  if(box.is_empty())
    return false;
  const std::size_t side =
      (std::min)(std::size_t(16), (std::max)(std::size_t(2), std::size_t(std::sqrt(double(m) / double(per_cell)))));
  out = Cell_grid(box, side, side);
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
//
// With `parallel` (CGAL::Parallel_tag), and at least min_edges_to_flip_in_cells candidate
// edges, the flips run in cells on TBB's threads first (flip_in_cells() below); the loop on
// this thread then ends the work, from the edges the cells left.
constexpr std::size_t min_edges_to_flip_in_cells = 64;

template <class Triangulation>
bool flip_in_cells(Triangulation& tr, std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                   std::size_t max_flips, std::size_t& flips,
                   std::vector<typename Triangulation::Face_handle>& touched);

template <class Triangulation, class Parallel = bool>
bool lawson_flip(Triangulation& tr,
                 std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                 std::size_t max_flips, std::size_t& flips,
                 std::vector<typename Triangulation::Face_handle>& touched, Parallel parallel = false)
{
  if constexpr(may_run_in_parallel<Parallel>()) {
    if(parallel && stack.size() >= min_edges_to_flip_in_cells && !flip_in_cells(tr, stack, max_flips, flips, touched))
      return false;
  } else {
    CGAL_USE(parallel);
  }
  using Gt = typename Triangulation::Geom_traits;
  const Gt& gt = tr.geom_traits();
  auto not_locally_delaunay = [&gt](const auto&, int, const auto& a, const auto& b, const auto& c,
                                    const auto& d) { return !is_locally_delaunay(gt, a, b, c, d); };
  return flip_edges_while<has_exact_double_predicates<Gt>::value>(tr, stack, not_locally_delaunay, max_flips,
                                                                  flips, &touched);
}

// Lawson's algorithm on TBB's threads. The vertices are given to the cells of a grid over the
// box of the candidate edges' faces, by their points (which flips never change); the task of
// a cell flips only the edges whose four quadrilateral vertices lie in it, and leaves the
// others on `stack`, for lawson_flip()'s loop on this thread, which ends the work in order.
// Returns false when the budget ran out.
//
// Why the tasks do not race. A face keeps its vertices until it is flipped, and a task flips
// only faces with all three vertices in its cell; so a face with two vertices in cell c keeps
// them while the tasks run, and only c's task writes it: a flip writes the two faces flipped
// (three vertices in c, before and after), the slots of the four faces around them that
// point back (two vertices in c: an edge of the quadrilateral) and the face slots of the
// four vertices (in c). c's task reads only such faces (those on its stack have three
// vertices in c, those across their edges two), points, which nothing writes, and, to sort
// the candidate edges it starts from, the vertex slots of faces with a vertex in c, which
// only c's task may change.
//
// Why the result is the same. Every flip queues the four edges around it, so every edge
// that is not locally Delaunay is always on a task's stack, a deferred list or the final
// stack, and a triangulation of the same vertices is valid after every flip: Lawson's
// algorithm, in another order, ends at the same triangulation (the Delaunay triangulation,
// unique under the perturbation). Only the number of flips may differ. The budget: the tasks
// add their flips to a shared count every 256 flips and stop when it passes `max_flips`.

template <class Triangulation>
bool flip_in_cells(Triangulation& tr, std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                   std::size_t max_flips, std::size_t& flips,
                   std::vector<typename Triangulation::Face_handle>& touched)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Edge = std::pair<Face_handle, int>;
  using Gt = typename Triangulation::Geom_traits;
  const Gt& gt = tr.geom_traits();
  const Vertex_handle infinite = tr.infinite_vertex();
  const std::size_t m = stack.size();

  // Cells of about 1024 candidate edges.
  Cell_grid grid;
  if(!make_flip_cells(m, [&](std::size_t k) { return stack[k].first; }, infinite, 1024, grid))
    return true; // no finite vertex in the sample: all left to the loop on this thread
  const std::size_t cells = grid.cells();
  const auto cell_of = [&grid](const auto& p) { return grid.cell_of(p); };
  // Each candidate edge goes to the cell of its face's first vertex, or, if the face is
  // infinite, to the last bucket, `cells` (hull edges are never flipped). Its task keeps it
  // if the face's other vertices and the vertex across the edge are in the cell too, and
  // leaves it to the final pass otherwise. (Reading the vertices of a face with a vertex in
  // the cell is safe: only that cell's task may flip it. Its neighbours are read only once
  // all three vertices are known to be in the cell.)
  std::vector<Edge> sorted(m);
  std::vector<std::uint32_t> end;
  counting_sort(
      m, cells + 1,
      [&](std::size_t k) {
#if defined(__GNUC__)
        // Called in order within a block: the face, then its first vertex, fetched ahead.
        if(k + 16 < m)
          __builtin_prefetch(stack[k + 16].first.operator->());
        if(k + 8 < m)
          __builtin_prefetch(stack[k + 8].first->vertex(0).operator->());
#endif
        const Face_handle f = stack[k].first;
        return f->has_vertex(infinite) ? cells : cell_of(f->vertex(0)->point());
      },
      [&](std::size_t k) { return stack[k]; }, [&](std::size_t position, const Edge& e) { sorted[position] = e; },
      true, end);

  // Each task keeps its flips, its deferred edges and the faces it touched to itself until
  // it ends (no false sharing), then moves them to its cell's slot.
  std::vector<std::vector<Edge>> deferred(cells);
  std::vector<std::vector<Face_handle>> touched_in(cells);
  std::vector<std::size_t> flips_in(cells, 0);
  std::atomic<std::size_t> total_flips{flips};
  std::atomic<bool> over_budget{false};
  for_each_block(true, cells, [&](std::size_t cell) {
    std::vector<Edge> cell_stack, cell_deferred;
    const std::size_t first = cell == 0 ? 0 : end[cell - 1], last = end[cell];
    for(std::size_t k = first; k < last; ++k) {
#if defined(__GNUC__)
      // Two loads per edge miss the cache: the face, then its vertices. Pipelined.
      if(k + 16 < last)
        __builtin_prefetch(sorted[k + 16].first.operator->());
      if(k + 8 < last) {
        __builtin_prefetch(sorted[k + 8].first->vertex(1).operator->());
        __builtin_prefetch(sorted[k + 8].first->vertex(2).operator->());
      }
#endif
      const Face_handle f = sorted[k].first;
      if(cell_of(f->vertex(1)->point()) == cell && cell_of(f->vertex(2)->point()) == cell)
        cell_stack.push_back(sorted[k]);
      else
        cell_deferred.push_back(sorted[k]);
    }
    std::vector<Face_handle> cell_touched;
    std::size_t cell_flips = 0, published = 0;
    // (b, c) the edge, a opposite in f (a, b, c in the cell), d opposite across it.
    auto wants_flip = [&](Face_handle f, int i, const auto& a, const auto& b, const auto& c, const auto& d) {
      CGAL_assertion(cell_of(a) == cell && cell_of(b) == cell && cell_of(c) == cell);
      if(cell_of(d) != cell) {
        cell_deferred.emplace_back(f, i);
        return false;
      }
      if(is_locally_delaunay(gt, a, b, c, d))
        return false;
      if(cell_flips - published >= 256) {
        if(total_flips.fetch_add(cell_flips - published) + (cell_flips - published) > max_flips)
          over_budget = true;
        published = cell_flips;
      }
      return !over_budget.load(std::memory_order_relaxed);
    };
    // A task that reaches the budget on its own leaves edges unflipped: the call fails.
    if(!flip_edges_while<has_exact_double_predicates<Gt>::value>(tr, cell_stack, wants_flip, max_flips, cell_flips,
                                                                 &cell_touched))
      over_budget = true;
    deferred[cell] = std::move(cell_deferred);
    touched_in[cell] = std::move(cell_touched);
    flips_in[cell] = cell_flips;
  });
  for(std::size_t c = 0; c < cells; ++c) {
    flips += flips_in[c];
    touched.insert(touched.end(), touched_in[c].begin(), touched_in[c].end());
  }
  if(over_budget || flips > max_flips)
    return false;
  stack.assign(sorted.begin() + end[cells - 1], sorted.end());
  for(const std::vector<Edge>& d : deferred)
    stack.insert(stack.end(), d.begin(), d.end());
  return true;
}

// Undoes the logged flips (certification's, untangle_by_flips()'s), latest first.
template <class Triangulation>
CGAL_DFP_RARELY_RUN void undo_flips(Triangulation& tr, Flip_log<Triangulation>& log)
{
  for(auto it = log.rbegin(); it != log.rend(); ++it)
    undo_flip(tr.tds(), it->first, it->second);
  log.clear();
}

// The flips that make a new vertex's star Delaunay (one insertion, Lawson's argument): `v`
// was just inserted strictly inside a face of a Delaunay triangulation; the edges opposite
// it are flipped while v is inside the circumcircle of the face beyond them (the perturbed
// test, so the result is CGAL's). Only those edges can fail, so only they are queued; a face
// beyond a hull edge is never flipped, v being strictly inside the hull. `stack` is scratch
// space.
template <class Triangulation>
void flip_around_new_vertex(Triangulation& tr, typename Triangulation::Vertex_handle v,
                            std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack)
{
  const auto& gt = tr.geom_traits();
  auto& tds = tr.tds();
  const auto infinite = tr.infinite_vertex();
  const auto& q = v->point();
  stack.clear();
  auto g = v->face();
  for(int k = 0; k < 3; ++k) {
    const int i = g->index(v);
    stack.emplace_back(g, i);
    g = g->neighbor(ccw(i));
  }
  while(!stack.empty()) {
    const auto face = stack.back().first;
    const int i = stack.back().second;
    stack.pop_back();
    const auto n = face->neighbor(i);
    if(n->has_vertex(infinite) ||
       side_of_oriented_circle_perturbed(gt, n->vertex(0)->point(), n->vertex(1)->point(), n->vertex(2)->point(), q) !=
           ON_POSITIVE_SIDE)
      continue;
    // After the flip face = (v, b, d) keeps v at slot i, and n = (d, c, v).
    tds.flip(face, i);
    stack.emplace_back(face, i);
    stack.emplace_back(n, n->index(v));
  }
}

// Untangling by flips, before any carving (make_delaunay). A face inverted by small moves is
// most often a vertex a that crossed the opposite edge (b, c) into the neighbour (c, b, d):
// then a lies inside that neighbour, and flipping (b, c) to (a, d) gives two faces that are
// both counterclockwise. Each bad face whose flip does that is flipped (the neighbour is
// finite, the new edge not already there); the faces still bad afterwards are returned in
// `bad`. The flips are combinatorial: nothing here assumes the faces tile the plane; the
// certificate stays the one at the top of this file (every face ccw, hull convex and wound
// once). Each flip made is logged, so undo_flips() can restore `tr`.
//
// With `parallel` (CGAL::Parallel_tag) and at least min_faces_to_untangle_in_cells bad faces,
// the faces are untangled in cells on TBB's threads first, as Lawson's flips are
// (flip_in_cells()): a cell's task takes a bad face when its three vertices and the
// vertices across its finite edges are in the cell, and leaves the others to a final pass in
// order. The argument of flip_in_cells() says why the tasks do not race (the test for
// an existing edge (a, d) turns around a, in the cell, through the faces' slots across edges
// at a, which no other task writes). The logs of the cells are joined in cell order: flips of
// different cells write disjoint slots, so undoing them latest first restores `tr` as well.
// Only which faces stay bad, and so how much is carved, may depend on the order; the
// triangulation make_delaunay() returns does not.
constexpr std::size_t min_faces_to_untangle_in_cells = 64;

// The scope of a task that may take every face (untangle_faces()).
struct Every_vertex
{
  template <class Vertex_handle>
  bool operator()(const Vertex_handle&) const
  {
    return true;
  }
};

// The untangling of the faces bad[first, last), as described above, by one task (`alone`:
// no other task runs): a face is taken when in_scope() holds for its vertices and those
// across its finite edges, and appended to `deferred` otherwise.
template <class Triangulation, class InScope>
void untangle_faces(Triangulation& tr, const std::vector<typename Triangulation::Face_handle>& bad,
                    std::size_t first, std::size_t last, bool alone, const InScope& in_scope,
                    std::vector<typename Triangulation::Face_handle>& deferred,
                    std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                    Flip_log<Triangulation>& log, std::vector<typename Triangulation::Face_handle>& touched)
{
  using Face_handle = typename Triangulation::Face_handle;
  auto orientation = orientation_called_out_of_line(tr.geom_traits());
  auto& tds = tr.tds();
  const auto infinite = tr.infinite_vertex();
  for(std::size_t k = first; k < last; ++k) {
    const Face_handle f = bad[k];
#if defined(__GNUC__)
    // The faces are far apart: fetch the neighbourhood of one ahead. In a cell, its neighbour
    // slots are read only once its vertices are known to be in the cell (else they may be
    // another task's): the vertices 8 ahead, the neighbours 4 ahead.
    if(k + 8 < last)
      for(int i = 0; i < 3; ++i) {
        __builtin_prefetch(bad[k + 8]->vertex(i).operator->());
        if(alone)
          __builtin_prefetch(bad[k + 8]->neighbor(i).operator->());
      }
    if(!alone && k + 4 < last) {
      const Face_handle h = bad[k + 4];
      if(in_scope(h->vertex(0)) && in_scope(h->vertex(1)) && in_scope(h->vertex(2)))
        for(int i = 0; i < 3; ++i)
          __builtin_prefetch(h->neighbor(i).operator->());
    }
#endif
    if(!in_scope(f->vertex(0)) || !in_scope(f->vertex(1)) || !in_scope(f->vertex(2))) {
      deferred.push_back(f);
      continue;
    }
    const auto& p0 = f->vertex(0)->point();
    if(orientation(p0, f->vertex(1)->point(), f->vertex(2)->point()) == LEFT_TURN)
      continue; // made ccw by an earlier flip
    bool across_in_scope = true;
    for(int i = 0; i < 3 && across_in_scope; ++i) {
      const Face_handle g = f->neighbor(i);
      across_in_scope = g->has_vertex(infinite) || in_scope(g->vertex(tds.mirror_index(f, i)));
    }
    if(!across_in_scope) {
      deferred.push_back(f);
      continue;
    }
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      if(g->has_vertex(infinite))
        continue;
      const auto a = f->vertex(i), b = f->vertex(ccw(i)), c = f->vertex(cw(i));
      const auto d = g->vertex(tds.mirror_index(f, i));
      if(orientation(a->point(), b->point(), d->point()) != LEFT_TURN ||
         orientation(a->point(), d->point(), c->point()) != LEFT_TURN || tds.is_edge(a, d))
        continue;
      tds.flip(f, i); // f = (a, b, d), g = (d, c, a): see flip_edges_while()
      log.emplace_back(f, i);
      touched.push_back(f);
      touched.push_back(g);
      for(int j = 0; j < 3; ++j) {
        stack.emplace_back(f, j);
        stack.emplace_back(g, j);
      }
      break;
    }
  }
}

template <class Triangulation>
bool untangle_in_cells(Triangulation& tr, std::vector<typename Triangulation::Face_handle>& bad,
                       std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                       Flip_log<Triangulation>& log, std::vector<typename Triangulation::Face_handle>& touched);

template <class Triangulation, class Parallel = bool>
void untangle_by_flips(Triangulation& tr, std::vector<typename Triangulation::Face_handle>& bad,
                       std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                       Flip_log<Triangulation>& log,
                       std::vector<typename Triangulation::Face_handle>& touched, Parallel parallel = false)
{
  using Face_handle = typename Triangulation::Face_handle;
  bool in_cells = false;
  if constexpr(may_run_in_parallel<Parallel>())
    in_cells = parallel && bad.size() >= min_faces_to_untangle_in_cells && untangle_in_cells(tr, bad, stack, log, touched);
  else
    CGAL_USE(parallel);
  if(!in_cells) {
    std::vector<Face_handle> deferred;
    untangle_faces(tr, bad, 0, bad.size(), true, Every_vertex(), deferred, stack, log, touched);
  }
  auto orientation = orientation_called_out_of_line(tr.geom_traits());
  bad.erase(std::remove_if(bad.begin(), bad.end(),
                           [&](Face_handle f) {
                             return orientation(f->vertex(0)->point(), f->vertex(1)->point(),
                                                f->vertex(2)->point()) == LEFT_TURN;
                           }),
            bad.end());
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
}

// untangle_by_flips() on TBB's threads: the bad faces dealt to the cells of a grid, each
// cell's task untangling the faces whose vertices it holds (as flip_in_cells() does), then
// the faces deferred at the cells' borders on this thread. False when no grid fits.
template <class Triangulation>
bool untangle_in_cells(Triangulation& tr, std::vector<typename Triangulation::Face_handle>& bad,
                       std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                       Flip_log<Triangulation>& log, std::vector<typename Triangulation::Face_handle>& touched)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Edge = std::pair<Face_handle, int>;
  Cell_grid grid;
  if(!make_flip_cells(bad.size(), [&](std::size_t k) { return bad[k]; }, tr.infinite_vertex(), 256, grid))
    return false;
  const auto cell_of = [&grid](const auto& p) { return grid.cell_of(p); };
  // Bad faces are finite: each goes to the cell of its first vertex.
  std::vector<Face_handle> sorted(bad.size());
  std::vector<std::uint32_t> end;
  counting_sort(
      bad.size(), grid.cells(), [&](std::size_t k) { return cell_of(bad[k]->vertex(0)->point()); },
      [&](std::size_t k) { return bad[k]; },
      [&](std::size_t position, Face_handle f) { sorted[position] = f; }, true, end);
  struct Cell_output
  {
    std::vector<Face_handle> deferred, touched;
    std::vector<Edge> stack;
    Flip_log<Triangulation> log;
  };
  std::vector<Face_handle> deferred;
  std::vector<Cell_output> out(grid.cells());
  for_each_block(true, grid.cells(), [&](std::size_t cell) {
    Cell_output& o = out[cell];
    untangle_faces(tr, sorted, cell == 0 ? 0 : end[cell - 1], end[cell], false,
                   [&](Vertex_handle v) { return v != tr.infinite_vertex() && cell_of(v->point()) == cell; },
                   o.deferred, o.stack, o.log, o.touched);
  });
  for(Cell_output& o : out) {
    deferred.insert(deferred.end(), o.deferred.begin(), o.deferred.end());
    touched.insert(touched.end(), o.touched.begin(), o.touched.end());
    stack.insert(stack.end(), o.stack.begin(), o.stack.end());
    log.insert(log.end(), o.log.begin(), o.log.end());
  }
  std::vector<Face_handle> unused;
  untangle_faces(tr, deferred, 0, deferred.size(), true, Every_vertex(), unused, stack, log, touched);
  return true;
}

// Walks the hull of `tr` (dimension 2, every finite face ccw) and flips away reflex vertices
// until the hull is convex. Why the result is a triangulation although the hull before may
// not have been a simple polygon: every face is still ccw, so by the argument of
// import_prediction.h the faces tile the plane with multiplicity equal to the winding number
// of the hull; the final check that the hull is a convex polygon wound once makes that 1.
// On success the new finite faces' edges are pushed on `stack` (they may not be locally
// Delaunay), their addresses into `created`, and true is returned; otherwise every flip is
// undone and false returned (the caller's triangulation is as it was).
template <class Triangulation>
bool convexify_hull(Triangulation& tr,
                    std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                    std::vector<const void*>& created, std::size_t& flips)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  auto& tds = tr.tds();
  auto orientation = orientation_called_out_of_line(tr.geom_traits());
  const Vertex_handle infinite = tr.infinite_vertex();

  std::size_t hull_size = 0;
  {
    Face_handle f = infinite->face();
    do {
      ++hull_size;
      f = f->neighbor(cw(f->index(infinite)));
    } while(f != infinite->face());
  }

  // Infinite face f holds hull edge a->b with a = f->vertex(cw(i)), b = f->vertex(ccw(i)),
  // i the index of the infinite vertex; f->neighbor(cw(i)) holds the next hull edge b->c and
  // f->neighbor(ccw(i)) the previous one.
  std::vector<std::pair<Face_handle, Vertex_handle>> done; // (finite face made, its b)
  Face_handle f = infinite->face();
  // Whether no hull vertex near b but a, b, c lies in the closed triangle (a, c, b): then the
  // face (a, c, b) is an ear of the pocket between the hull and its convex hull, and adding
  // it overlaps no face. A pocket of a simple polygon always has such an ear at a reflex
  // vertex (two-ears theorem: of two disjoint ears, one is not at the lid), so the flips go
  // on until the hull is convex. Only the 32 hull vertices on either side of b are tested:
  // a pocket's ear is tested against its own pocket; a far part of the hull reaching into
  // the ear would make the hull wind twice, which the final check rejects (correctness never
  // rests on this test, only the chance that the flips succeed).
  auto is_empty_ear = [&](Face_handle from, Vertex_handle a, Vertex_handle b, Vertex_handle c) {
    auto inside = [&](Vertex_handle v) {
      return v != a && v != b && v != c && orientation(a->point(), c->point(), v->point()) != RIGHT_TURN &&
             orientation(c->point(), b->point(), v->point()) != RIGHT_TURN &&
             orientation(b->point(), a->point(), v->point()) != RIGHT_TURN;
    };
    Face_handle ahead = from, behind = from;
    for(int k = 0; k < 32; ++k) {
      ahead = ahead->neighbor(cw(ahead->index(infinite)));   // hull edges after a->b
      behind = behind->neighbor(ccw(behind->index(infinite))); // and before it
      if(inside(ahead->vertex(ccw(ahead->index(infinite)))) ||
         inside(behind->vertex(cw(behind->index(infinite)))))
        return false;
      if(ahead == behind)
        break;
    }
    return true;
  };
  std::size_t unchanged = 0;
  // Each step passes a vertex (at most hull_size in a row) or flips one away: at most about
  // hull_size^2 steps.
  const std::size_t max_steps = (hull_size + 2) * (hull_size + 2);
  for(std::size_t steps = 0; unchanged < hull_size && steps < max_steps; ++steps) {
    const int i = f->index(infinite);
    const Face_handle g = f->neighbor(cw(i));
    const Vertex_handle a = f->vertex(cw(i)), b = f->vertex(ccw(i));
    const Vertex_handle c = g->vertex(ccw(g->index(infinite)));
    if(hull_size <= 3 || orientation(a->point(), b->point(), c->point()) != RIGHT_TURN ||
       tds.is_edge(a, c) || !is_empty_ear(f, a, b, c)) {
      f = g;
      ++unchanged;
      continue;
    }
    tds.flip(f, cw(i)); // the edge (b, infinite)
    const Face_handle inside = f->has_vertex(infinite) ? g : f;
    const Face_handle outside = inside == f ? g : f;
    done.emplace_back(inside, b);
    --hull_size;
    unchanged = 0;
    // Step back: a may have become reflex.
    f = outside->neighbor(ccw(outside->index(infinite)));
  }

  if(!hull_is_convex_and_wound_once(tr)) {
    for(auto it = done.rbegin(); it != done.rend(); ++it)
      tds.flip(it->first, it->first->index(it->second)); // the edge (a, c) back to (b, infinite)
    return false;
  }
  for(const auto& made : done) {
    created.push_back(&*made.first);
    for(int k = 0; k < 3; ++k)
      stack.emplace_back(made.first, k);
  }
  flips += done.size();
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_FLIPS_H
