// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Local repair of a prediction that is not a triangulation (Appendix A of the paper, in the
// practical form this package uses): carve out what is geometrically wrong, retriangulate the
// holes, reinsert the vertices left without a face, and let Lawson's flips (flips.h)
// finish. Used by make_delaunay (inverted or flat faces after moves, in place, vertex objects
// kept) and by delaunay_from_prediction (holes, repeated, overlapping or degenerate faces,
// missing hull faces: the importer hands over the faces it could pair, with open half-edges).
//
// Why the result is a triangulation. Every face kept is counterclockwise: make_delaunay
// carves the star of every vertex of a face that is not, and the importer never creates one.
// Each hole, a cycle of open half-edges of the kept faces, is filled by ear clipping with
// counterclockwise ears only, and the outer cycle is closed with infinite faces and made
// convex by hull flips that add counterclockwise faces (flips.h). Then every finite
// face is counterclockwise and the hull is checked to be a convex polygon wound once; by the
// winding-number argument of import_prediction.h the faces tile the hull exactly once: a
// triangulation of its vertices, whatever the holes looked like. If the final check fails,
// make_delaunay rolls every change back (then rebuilds), so the caller's triangulation is
// never left half-repaired. The reinserted vertices go in by CGAL's point location and
// insertion into this valid triangulation; the flips then need no trust in the prediction:
// Lawson's algorithm reaches the Delaunay triangulation from any triangulation.
//
// Why ear clipping and not a Delaunay triangulation of each hole, or Chan's structures:
// holes are small (measured at 1e6 points moved by 0.1 spacing: 48,861 carved faces in 7,757
// holes, about 6 faces each; 1% of a DT's faces deleted: single triangles and quadrilaterals),
// where ear clipping takes 0.25 us per hole and no allocation, an auxiliary CGAL triangulation
// of the hole's points 1.16 us before it is glued in (bench_hole_filling.cpp, 1e6 points); the
// flips that follow make each hole Delaunay.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_CARVE_REPAIR_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_CARVE_REPAIR_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/duplicate_vertices.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/function_ref.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/import/hole_tracing.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/import/tds_certify.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>

#include <CGAL/Triangulation_2.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Limits of the local repair; past them the caller rebuilds (a damage that large is cheaper
// to rebuild, and the ear clipping is quadratic in a hole's size).
struct Carve_limits
{
  std::size_t max_removed_faces = 0; // faces carved in all
  std::size_t max_bad_faces = 0;     // faces found wrong before any carving
  // Rounds of widening the holes that cannot be filled, each by a ring of stars. The face
  // budget above bounds the work; this bounds the passes, so that a hole that keeps failing
  // is given up after 24 rings instead of the whole budget in small steps.
  std::size_t max_rounds = 24;
  // Boundary edges of one hole: the ear clipping is quadratic in it. The pairing of
  // diagonals in commit() needs fewer than 2^32.
  std::size_t max_hole_size = 1024;
};

// Limits of the local repair for `n` points. Measured at 1e6 points (moves of 0.1 spacing:
// 4.6% of the faces inverted, 0.19 n faces carved), the repair as a whole cost about a
// rebuild, the planning alone about 1.5 us per carved face; past n/8 carved faces a rebuild is
// cheaper.
inline Carve_limits default_carve_limits(std::size_t n)
{
  Carve_limits limits;
  limits.max_removed_faces = n / 8 + 64;
  limits.max_bad_faces = n / 16 + 16;
  return limits;
}

template <class Triangulation>
class Carve_repair
{
public:
  using Tds = typename Triangulation::Triangulation_data_structure;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  using Edge = std::pair<Face_handle, int>;

  // `keep_undo_log`: record what commit() removes, so that rollback() can restore it.
  Carve_repair(Triangulation& tr, bool keep_undo_log)
      : tr_(tr), tds_(tr.tds()), infinite_(tr.infinite_vertex()), keep_undo_log_(keep_undo_log)
  {}

  // --- Planning: reads the triangulation only. -------------------------------------------

  // Carves every face around `v` and reinserts `v` later.
  void carve_star(Vertex_handle v)
  {
    if(v != infinite_ && detached_set_.insert(&*v, 0).second)
      pending_.push_back(v);
  }

  // A half-edge (f, i) of a kept face with no neighbour (importer only).
  void add_open_halfedge(Face_handle f, int i) { given_open_.emplace_back(f, i); }

  // The importer's TDS has no infinite faces yet: the outer boundary is a cycle to close.
  void expect_outer_cycle() { outer_open_ = true; }

  // The faces may meet at a vertex in several fans (the importer: overlapping faces, left
  // out or not): checked by one pass at commit().
  void expect_several_fans() { may_have_several_fans_ = true; }

  // Carves, traces the holes, and widens the holes that cannot be filled, round after round.
  // Returns Outcome::ok when every hole has a fill; otherwise why the repair gives up.
  Outcome plan(const Carve_limits& limits)
  {
    // A star has about 6 faces, each carved face opens about one half-edge.
    removed_.reserve(6 * pending_.size());
    position_.reserve(6 * pending_.size() + given_open_.size());
    leaving_.reserve(6 * pending_.size() + given_open_.size());
    for(rounds_ = 1; rounds_ <= limits.max_rounds; ++rounds_) {
      for(std::size_t k = 0; k < pending_.size(); ++k) {
#if defined(__GNUC__)
        // The stars are far apart: fetch a vertex 8 ahead, then its face 4 ahead.
        if(k + 8 < pending_.size())
          __builtin_prefetch(&*pending_[k + 8]);
        if(k + 4 < pending_.size() && pending_[k + 4]->face() != Face_handle())
          __builtin_prefetch(pending_[k + 4]->face().operator->());
#endif
        carve_faces_around(pending_[k]);
      }
      pending_.clear();
      if(removed_list_.size() > limits.max_removed_faces)
        return Outcome::damage_over_budget;
      const std::size_t before_trace = removed_list_.size();
      const Outcome why = trace_and_fill(limits);
      if(why != Outcome::ok)
        return why;
      if(pending_.empty() && removed_list_.size() == before_trace) {
        collect_isolated_vertices();
        return Outcome::ok;
      }
    }
    return Outcome::holes_kept_growing;
  }

  std::size_t rounds() const { return rounds_ > 0 ? rounds_ : 0; }
  std::size_t faces_removed() const { return removed_finite_; }
  std::size_t holes() const
  {
    std::size_t count = 0;
    for(std::size_t l = 0; l < loops_.size(); ++l)
      count += !loops_[l].dead && l != outer_ ? 1 : 0;
    return count;
  }
  const std::vector<Vertex_handle>& detached() const { return detached_; }
  bool is_removed(Face_handle f) const { return is_removed(&*f); }
  bool is_removed(const void* f) const { return carved_bitmap_ ? carved_bitmap_->contains(f) : removed_.contains(f); }

  // --- Modifying. ------------------------------------------------------------------------

  // Deletes the carved faces (the entries of `stack` on them first), fills the holes, and
  // closes the outer cycle with infinite faces. Every new face's edges go on `stack`.
  void commit(std::vector<Edge>& stack)
  {
    drop_carved_edges(stack);
    delete_carved_faces();
    // Ears. Polygon edges pair with their open half-edge, diagonals with each other.
    // `linked` marks the open half-edges that get a neighbour: all of them, when the plan is
    // complete (every live loop filled, paired, or the outer one).
    std::vector<char> linked(open_.size(), 0);
    fill_holes(stack, linked);
    close_outer_cycle(linked);
    for(std::size_t k = 0; k < open_.size(); ++k)
      if(alive_[k] && !linked[k])
        complete_ = false;
    committed_ = true;
  }

  // After commit(): makes the hull convex if it is not (hull flips); returns whether the
  // result is a triangulation (see the argument at the top of this file).
  bool finish_hull(std::vector<Edge>& stack, std::size_t& flips)
  {
    // An open half-edge left without a neighbour (a loop the plan neither filled nor carved)
    // leaves a fan open: no walk around its vertices may start, and no triangulation is there.
    if(!complete_)
      return false;
    if(hull_is_convex_and_wound_once(tr_))
      return true;
    std::vector<const void*> made;
    if(!convexify_hull(tr_, stack, made, flips)) {
      return false;
    }
    for(const void* f : made)
      created_set_.insert(f, 0);
    return true;
  }

  // After commit() (and a failed finish_hull()): restores the triangulation as it was before
  // commit(): same vertices, same connectivity (new face objects: the faces of `log` that
  // were carved are replaced by the new objects, which have the same slots).
  CGAL_DFP_RARELY_RUN void rollback(Flip_log<Triangulation>& log)
  {
    CGAL_precondition(keep_undo_log_ && committed_);
    for(const Face_handle f : created_)
      tds_.delete_face(f);
    created_.clear();
    const std::size_t m = undo_.size();
    std::vector<Face_handle> again(m);
    for(std::size_t k = 0; k < m; ++k)
      again[k] = tds_.create_face(undo_[k].v[0], undo_[k].v[1], undo_[k].v[2]);
    for(std::size_t k = 0; k < m; ++k) {
      for(int i = 0; i < 3; ++i) {
        undo_[k].v[i]->set_face(again[k]);
        const void* old = undo_[k].neighbor[i];
        if(const std::size_t* at = old_index_.find(old)) {
          again[k]->set_neighbor(i, again[*at]);
          continue;
        }
        // A kept face: find the slot of the shared edge there.
        const Face_handle g = tds_.faces().iterator_to(*static_cast<typename Tds::Face*>(const_cast<void*>(old)));
        const Vertex_handle a = undo_[k].v[ccw(i)], b = undo_[k].v[cw(i)];
        for(int j = 0; j < 3; ++j)
          if(g->vertex(j) != a && g->vertex(j) != b)
            tds_.set_adjacency(again[k], i, g, j);
      }
    }
    for(auto& flip : log)
      if(const std::size_t* at = old_index_.find(&*flip.first))
        flip.first = again[*at];
    carved_bitmap_.reset();
    committed_ = false;
  }

  // Reinserts the carved vertices, keeping each vertex object (reinsert_vertex_objects()).
  // `on_duplicate(v, w)` is called when v's point is already the point of vertex w (v is
  // then deleted by the callee or left detached: it is not reinserted). Faces of the
  // prediction that insertion modifies go to `modified`. (`on_duplicate` is a Function_ref:
  // it is rarely called, and each caller's lambda would compile the reinsertion again.)
  void reinsert(std::vector<Edge>& stack, std::vector<const void*>& modified,
                Function_ref<void(Vertex_handle, Vertex_handle)> on_duplicate)
  {
    created_set_.reserve(created_set_.size() + 6 * detached_.size()); // about 6 faces around each
    reinsert_vertex_objects(
        tr_, detached_, stack, [&](Face_handle f) { note_modified(f, modified); },
        [&](Face_handle f) { created_set_.insert(&*f, 0); }, on_duplicate, &near_);
  }

  // Whether `f` was made by this repair (ears, infinite faces, hull flips, insertions).
  bool is_created(const void* f) const { return created_set_.contains(f); }

private:
  static constexpr std::size_t none = std::size_t(-1);
  static constexpr std::size_t unknown = std::size_t(-2);
  // A turn around a vertex through more faces than this is taken for a broken fan: the hole
  // is widened (a vertex of that degree, such as the centre of 2^16 co-circular points, then
  // costs a rebuild, never a wrong result).
  static constexpr std::size_t longest_fan = std::size_t(1) << 16;
  // A stack of failing edges longer than this is filtered through a bitmap of the carved
  // faces (commit()); a shorter one is filtered through the hash table as cheaply.
  static constexpr std::size_t long_stack = 4096;

  struct Ear
  {
    Vertex_handle v[3];
    std::size_t open[3];         // index into open_ of the polygon edge opposite v[i], or none
    std::uint64_t diagonal[3];   // else its ends in the hole, shared by the two ears on it
  };
  struct Loop
  {
    std::vector<std::size_t> halfedges; // open half-edges in order, kept faces on their left
    std::vector<Ear> ears;              // the fill of a hole
    std::size_t lowest = 0;             // position of the lowest-leftmost tail
    Orientation turn = COLLINEAR;       // the turn there: the loop's winding if it is simple
    bool dead = false;                  // traced again since
    std::size_t group = 0;              // loops split from one cycle share it
  };
  struct Undo_entry
  {
    Vertex_handle v[3];
    const void* neighbor[3];
  };

  // --- Stages of commit(). ---------------------------------------------------------------

  // Drops the entries of `stack` on carved faces. The stack is long (every failing edge): a
  // bitmap of the carved faces' slots answers from the cache where the hash table would miss it.
  void drop_carved_edges(std::vector<Edge>& stack)
  {
    using Bitmap = Slot_bitmap<typename Tds::Face>;
    std::uint64_t low = ~std::uint64_t(0), high = 0;
    for(const Face_handle f : removed_list_) {
      low = (std::min)(low, Bitmap::value(&*f));
      high = (std::max)(high, Bitmap::value(&*f));
    }
    if(stack.size() > long_stack && Bitmap::fits(low, high, removed_list_.size() + stack.size())) {
      // Kept for is_removed(), asked about every face flipped before the carve.
      carved_bitmap_.reset(new Bitmap(low, high));
      for(const Face_handle f : removed_list_)
        carved_bitmap_->insert(&*f);
      stack.erase(std::remove_if(stack.begin(), stack.end(),
                                 [&](const Edge& e) { return carved_bitmap_->contains(&*e.first); }),
                  stack.end());
    } else {
      stack.erase(std::remove_if(stack.begin(), stack.end(),
                                 [&](const Edge& e) { return removed_.contains(&*e.first); }),
                  stack.end());
    }
  }

  // Deletes the carved faces (logged first for rollback() when asked) and points every vertex
  // that keeps a face at one: a cycle vertex at the face of an outgoing open half-edge.
  void delete_carved_faces()
  {
    created_set_.reserve(created_set_.size() + removed_list_.size());
    if(keep_undo_log_)
      record_undo_log();
    for(const Face_handle f : removed_list_)
      tds_.delete_face(f);
    if(may_have_several_fans_)
      keep_vertices_with_other_fans();
    for(const Vertex_handle v : detached_)
      v->set_face(Face_handle());
    // Every vertex on a cycle keeps the face of an outgoing open half-edge.
    for(std::size_t k = 0; k < open_.size(); ++k)
      if(alive_[k])
        open_[k].first->vertex(ccw(open_[k].second))->set_face(open_[k].first);
  }

  // Creates the ears of every live hole and links them: polygon edges to their open
  // half-edge (marked in `linked`), diagonals to each other; a loop of two half-edges is
  // linked directly.
  void fill_holes(std::vector<Edge>& stack, std::vector<char>& linked)
  {
    // (the loop, the diagonal's ends in it) -> the ear's edge on it
    std::vector<std::pair<std::pair<std::size_t, std::uint64_t>, Edge>> diagonals;
    for(std::size_t l = 0; l < loops_.size(); ++l) {
      const Loop& loop = loops_[l];
      if(loop.dead)
        continue;
      if(loop.halfedges.size() == 2) { // two kept faces on one edge, not linked (importer only)
        const Edge& a = open_[loop.halfedges[0]];
        const Edge& b = open_[loop.halfedges[1]];
        tds_.set_adjacency(a.first, a.second, b.first, b.second);
        linked[loop.halfedges[0]] = linked[loop.halfedges[1]] = 1;
        stack.push_back(a);
        continue;
      }
      for(const Ear& ear : loop.ears) {
        const Face_handle f = tds_.create_face(ear.v[0], ear.v[1], ear.v[2]);
        created_.push_back(f);
        created_set_.insert(&*f, 0);
        for(int i = 0; i < 3; ++i) {
          stack.emplace_back(f, i);
          if(ear.open[i] != none) {
            const Edge& e = open_[ear.open[i]];
            tds_.set_adjacency(f, i, e.first, e.second);
            linked[ear.open[i]] = 1;
          } else {
            diagonals.emplace_back(std::make_pair(l, ear.diagonal[i]), Edge(f, i));
          }
        }
      }
    }
    std::sort(diagonals.begin(), diagonals.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for(std::size_t k = 0; k + 1 < diagonals.size(); k += 2) {
      CGAL_assertion(diagonals[k].first == diagonals[k + 1].first);
      if(diagonals[k].first != diagonals[k + 1].first)
        complete_ = false;
      tds_.set_adjacency(diagonals[k].second.first, diagonals[k].second.second,
                         diagonals[k + 1].second.first, diagonals[k + 1].second.second);
    }
  }

  // The outer cycle: the face outside half-edge u->v is (v, u, infinite), as in the importer.
  void close_outer_cycle(std::vector<char>& linked)
  {
    if(outer_ == none)
      return;
    const std::vector<std::size_t>& outer_cycle = loops_[outer_].halfedges;
    const std::size_t m = outer_cycle.size();
    std::vector<Face_handle> outside(m);
    for(std::size_t k = 0; k < m; ++k) {
      const Edge& e = open_[outer_cycle[k]];
      outside[k] = tds_.create_face(e.first->vertex(cw(e.second)), e.first->vertex(ccw(e.second)),
                                    infinite_);
      created_.push_back(outside[k]);
      created_set_.insert(&*outside[k], 0);
      tds_.set_adjacency(outside[k], 2, e.first, e.second);
      linked[outer_cycle[k]] = 1;
    }
    for(std::size_t k = 0; k < m; ++k)
      tds_.set_adjacency(outside[k], 1, outside[(k + 1) % m], 0);
    infinite_->set_face(outside[0]);
  }

  void note_modified(Face_handle f, std::vector<const void*>& modified) const
  {
    if(!f->has_vertex(infinite_) && !created_set_.contains(&*f))
      modified.push_back(&*f);
  }

  // The faces around `v`, which may have open (null) neighbours in the importer's TDS.
  CGAL_DFP_OUT_OF_LINE void faces_around(Vertex_handle v, std::vector<Face_handle>& out) const
  {
    out.clear();
    const Face_handle start = v->face();
    if(start == Face_handle())
      return;
    Face_handle f = start;
    do {
      out.push_back(f);
      f = f->neighbor(ccw(f->index(v)));
    } while(f != Face_handle() && f != start);
    if(f == start)
      return;
    for(f = start->neighbor(cw(start->index(v))); f != Face_handle(); f = f->neighbor(cw(f->index(v))))
      out.push_back(f);
  }

  void carve_faces_around(Vertex_handle v)
  {
    std::vector<Face_handle>& faces = scratch_faces_;
    faces_around(v, faces);
    for(const Face_handle f : faces)
      remove(f);
  }

  CGAL_DFP_OUT_OF_LINE void remove(Face_handle f)
  {
    if(!removed_.insert(&*f, removed_list_.size()).second)
      return;
    removed_list_.push_back(f);
    if(!f->has_vertex(infinite_)) {
      ++removed_finite_;
      return;
    }
    if(outer_open_)
      return;
    // One infinite face carved: carve them all, the outer boundary becomes a cycle to close.
    outer_open_ = true;
    std::vector<Face_handle> faces;
    faces_around(infinite_, faces);
    for(const Face_handle g : faces)
      remove(g);
  }

  // One round of tracing, incremental: the faces carved since the last round (from
  // removed_list_[traced_] on) open new half-edges and close those on them, and only the
  // loops through a vertex of such a face can change (the successor of a half-edge depends
  // only on the faces around its head). Those loops are traced again from scratch: split at
  // repeated vertices, classified, and filled; the others keep their fill.
  Outcome trace_and_fill(const Carve_limits& limits)
  {
    const std::size_t first_new = traced_;
    traced_ = removed_list_.size();
    const bool outer_is_open = outer_open_; // widening below may open it: traced next round

    Address_table<std::size_t> changed; // vertices of faces carved this round
    std::vector<std::size_t> to_trace;
    open_halfedges_of_carved(first_new, changed, to_trace);
    retire_changed_loops(changed, to_trace);
    std::vector<std::vector<std::size_t>> cycles;
    std::vector<std::size_t> group_of_cycle;
    trace_cycles(to_trace, cycles, group_of_cycle);
    const Outcome why = classify_loops(cycles, group_of_cycle, limits);
    if(why != Outcome::ok)
      return why;

    outer_ = none;
    if(outer_is_open) {
      if(!choose_outer_loop())
        return Outcome::outer_boundary_not_ccw;
      // A flap of faces folded over others and glued to them edge by edge shows only in the
      // outer loop, which then winds twice: it must be a simple polygon (every other loop
      // winds at most once, so the faces then cover each point at most once).
      if(carve_crossings(loops_[outer_].halfedges))
        return Outcome::ok; // widened: traced again next round
    }
    carve_islands();
    return Outcome::ok;
  }

  // --- Stages of trace_and_fill(). -------------------------------------------------------

  // Registers the half-edge (g, j) of a kept face as open, and as one to trace.
  void open_halfedge(Face_handle g, int j, std::vector<std::size_t>& to_trace)
  {
    to_trace.push_back(open_.size());
    Leaving* leaving = leaving_.insert(&*g->vertex(ccw(j)), Leaving()).first;
    leaving->last = open_.size();
    ++leaving->alive;
    position_.insert(halfedge_key(Edge(g, j)), open_.size());
    open_.emplace_back(g, j);
    alive_.push_back(1);
    loop_of_.push_back(none);
  }

  // The faces carved from removed_list_[first_new] on: their half-edges that were open
  // close, those of kept neighbours open (and, in the first round, the importer's). Their
  // vertices go to `changed` when there are loops they may change.
  void open_halfedges_of_carved(std::size_t first_new, Address_table<std::size_t>& changed,
                                std::vector<std::size_t>& to_trace)
  {
    const bool loops_may_change = !loops_.empty(); // none in the first round
    for(std::size_t k = first_new; k < traced_; ++k) {
      const Face_handle f = removed_list_[k];
#if defined(__GNUC__)
      if(k + 8 < traced_)
        for(int i = 0; i < 3; ++i)
          __builtin_prefetch(removed_list_[k + 8]->neighbor(i).operator->());
#endif
      for(int i = 0; i < 3; ++i) {
        if(loops_may_change)
          changed.insert(&*f->vertex(i), 0);
        if(const std::size_t* at = position_.find(halfedge_key(Edge(f, i)))) {
          if(alive_[*at])
            --leaving_.insert(&*f->vertex(ccw(i)), Leaving()).first->alive; // registered: found
          alive_[*at] = 0;
        }
        const Face_handle g = f->neighbor(i);
        if(g != Face_handle() && !removed_.contains(&*g))
          open_halfedge(g, g->index(f), to_trace);
      }
    }
    if(rounds_ == 1)
      for(const Edge& e : given_open_)
        if(!removed_.contains(&*e.first))
          open_halfedge(e.first, e.second, to_trace);
  }

  // Loops to trace again: those through a changed vertex, with every loop split from the
  // same cycle (at a split vertex the loops' successors are not next_open()'s). They die,
  // and their live half-edges go to `to_trace`.
  void retire_changed_loops(const Address_table<std::size_t>& changed, std::vector<std::size_t>& to_trace)
  {
    std::vector<char> dirty_group(groups_, 0);
    for(const Loop& loop : loops_) {
      if(loop.dead || dirty_group[loop.group])
        continue;
      for(const std::size_t h : loop.halfedges)
        if(!alive_[h] || changed.contains(&*tail_vertex(h))) {
          dirty_group[loop.group] = 1;
          break;
        }
    }
    for(Loop& loop : loops_) {
      if(loop.dead || !dirty_group[loop.group])
        continue;
      loop.dead = true;
      for(const std::size_t h : loop.halfedges)
        if(alive_[h]) {
          loop_of_[h] = none;
          to_trace.push_back(h);
        }
    }
  }

  // Cycles. The open half-edge after h, which ends at v, is found by turning around v
  // through kept faces, away from the hole, to the first open half-edge leaving v. So two
  // holes may touch at a vertex; a cycle that passes twice through a vertex is split there
  // into loops, appended to `cycles` with their group. A chain that does not close widens.
  void trace_cycles(const std::vector<std::size_t>& to_trace, std::vector<std::vector<std::size_t>>& cycles,
                    std::vector<std::size_t>& group_of_cycle)
  {
    std::vector<std::size_t> cycle;
    // The successors first, each independent of the others, so that the cache misses of
    // their walks overlap (following a cycle makes each walk wait for the one before); a
    // half-edge not listed, on a loop left as it was, is looked up on the way.
    std::vector<std::size_t> successor(open_.size(), unknown);
    for(const std::size_t k : to_trace)
      if(alive_[k] && loop_of_[k] == none)
        successor[k] = next_open_by_vertex(k);
    auto next = [&](std::size_t k) { return successor[k] != unknown ? successor[k] : next_open(k); };
    for(const std::size_t k : to_trace) {
      if(!alive_[k] || loop_of_[k] != none)
        continue;
      cycle.clear();
      std::size_t at = k;
      bool closed = true;
      do {
        loop_of_[at] = loops_.size(); // provisional: marks it seen
        cycle.push_back(at);
        at = next(at);
        if(at == none) {
          closed = false;
          break;
        }
      } while(at != k && loop_of_[at] == none);
      if(!closed || at != k) {
        for(const std::size_t h : cycle)
          loop_of_[h] = none;
        widen(cycle); // not a closed cycle: the faces around are inconsistent
        continue;
      }
      split_at_repeated_vertices(cycle, [&](std::size_t h) -> const void* { return &*tail_vertex(h); },
                                 scratch_loop_, [&](auto first, auto last) { cycles.emplace_back(first, last); });
      group_of_cycle.resize(cycles.size(), groups_++);
    }
  }

  // Each loop is classified at its lowest-leftmost vertex, where a simple loop turns the
  // way it winds: clockwise loops are holes, filled by ear clipping; counterclockwise ones
  // are the outer boundary (when it is open) or islands, kept faces hanging by one vertex
  // or lying over others, carved. A misjudged non-simple loop only fails the final check.
  Outcome classify_loops(std::vector<std::vector<std::size_t>>& cycles, const std::vector<std::size_t>& group_of_cycle,
                         const Carve_limits& limits)
  {
    auto orientation = orientation_called_out_of_line(tr_.geom_traits());
    for(std::size_t c = 0; c < cycles.size(); ++c) {
      Loop loop;
      loop.halfedges = std::move(cycles[c]);
      loop.group = group_of_cycle[c];
      const std::size_t m = loop.halfedges.size();
      loop.lowest = lowest(loop.halfedges);
      loop.turn = m < 3 ? COLLINEAR
                        : orientation(tail_point(loop.halfedges[(loop.lowest + m - 1) % m]),
                                      tail_point(loop.halfedges[loop.lowest]),
                                      tail_point(loop.halfedges[(loop.lowest + 1) % m]));
      if(m > limits.max_hole_size && loop.turn != LEFT_TURN)
        return Outcome::hole_over_budget;
      if(m != 2 && loop.turn == RIGHT_TURN && !fill(loop.halfedges, loop.ears))
        widen(loop.halfedges);
      if(m != 2 && loop.turn == COLLINEAR)
        widen(loop.halfedges);
      for(const std::size_t h : loop.halfedges)
        loop_of_[h] = loops_.size();
      loops_.push_back(std::move(loop));
    }
    return Outcome::ok;
  }

  // The outer loop (outer_): the counterclockwise loop with the lowest-leftmost vertex of
  // all; returns whether there is one. An island may hang at that very vertex: then the
  // outer loop is the one enclosing the larger area (the island lies inside it). Taken by
  // the order of the loops (of face addresses), an island could pass for the outer loop and
  // make the real one an island, carved layer by layer past the budget.
  CGAL_DFP_RARELY_RUN bool choose_outer_loop()
  {
    auto compare_xy = compare_xy_called_out_of_line(tr_.geom_traits());
    for(std::size_t l = 0; l < loops_.size(); ++l) {
      const Loop& loop = loops_[l];
      if(loop.dead || loop.turn != LEFT_TURN)
        continue;
      if(outer_ == none) {
        outer_ = l;
        continue;
      }
      const Comparison_result c = compare_xy(tail_point(loop.halfedges[loop.lowest]),
                                             tail_point(loops_[outer_].halfedges[loops_[outer_].lowest]));
      if(c == SMALLER ||
         (c == EQUAL && encloses_more(loop.halfedges, loops_[outer_].halfedges, tail_point(loop.halfedges[loop.lowest]))))
        outer_ = l;
    }
    return outer_ != none;
  }

  // The counterclockwise loops other than the outer one are islands: their faces go, layer
  // by layer (the importer's faces may then meet at a vertex in several fans).
  CGAL_DFP_RARELY_RUN void carve_islands()
  {
    for(std::size_t l = 0; l < loops_.size(); ++l)
      if(!loops_[l].dead && l != outer_ && loops_[l].turn == LEFT_TURN) {
        widen(loops_[l].halfedges, false); // an island: its faces go, layer by layer
        if(given_open_.size() > 0)
          may_have_several_fans_ = true;
      }
  }

  // Finds the pairs of edges of a loop that meet other than at a shared end (the loop is not
  // a simple polygon) and carves the stars of their ends; returns whether it found any.
  // Edges are bucketed in a grid of about one edge per cell over the loop's bounding box (by
  // their approximate bounding boxes, widened so that no meeting pair is missed), and only
  // edges sharing a cell are tested, exactly.
  CGAL_DFP_RARELY_RUN bool carve_crossings(const std::vector<std::size_t>& loop)
  {
    const std::size_t m = loop.size();
    if(m < 4)
      return false;
    auto orientation = orientation_called_out_of_line(tr_.geom_traits());
    auto compare_xy = compare_xy_called_out_of_line(tr_.geom_traits());
    std::vector<const Point*> p(m);
    for(std::size_t k = 0; k < m; ++k)
      p[k] = &tail_point(loop[k]);
    const Box box = bounding_box(m, [&](std::size_t k) -> const Point& { return *p[k]; });
    const std::size_t side = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(m))));
    // Boxes widened by far more than the rounding of to_double (relative to the coordinates,
    // plus the smallest subnormal); cells by Cell_grid, finite at any scale. Only which pairs
    // are tested depends on this: a pair that meets shares a cell, the tests are exact.
    const double largest = (std::max)((std::max)(std::fabs(box.xmin), std::fabs(box.xmax)),
                                      (std::max)(std::fabs(box.ymin), std::fabs(box.ymax)));
    const double margin = 1e-9 * (box.xmax / 2 - box.xmin / 2 + box.ymax / 2 - box.ymin / 2) + 1e-15 * largest +
                          std::numeric_limits<double>::denorm_min();
    const Cell_grid cells(box, side, side);
    std::vector<std::vector<std::size_t>> grid(cells.cells());
    for(std::size_t k = 0; k < m; ++k) {
      const Point& a = *p[k];
      const Point& b = *p[(k + 1) % m];
      const double x0 = (std::min)(CGAL::to_double(a.x()), CGAL::to_double(b.x())) - margin;
      const double x1 = (std::max)(CGAL::to_double(a.x()), CGAL::to_double(b.x())) + margin;
      const double y0 = (std::min)(CGAL::to_double(a.y()), CGAL::to_double(b.y())) - margin;
      const double y1 = (std::max)(CGAL::to_double(a.y()), CGAL::to_double(b.y())) + margin;
      for(std::size_t cx = cells.column(x0); cx <= cells.column(x1); ++cx)
        for(std::size_t cy = cells.row(y0); cy <= cells.row(y1); ++cy)
          grid[cy * side + cx].push_back(k);
    }
    // Closed segments [a, b] and [c, d] meet.
    auto meet = [&](const Point& a, const Point& b, const Point& c, const Point& d) {
      const Orientation o1 = orientation(a, b, c), o2 = orientation(a, b, d);
      const Orientation o3 = orientation(c, d, a), o4 = orientation(c, d, b);
      if(o1 != o2 && o3 != o4 && o1 != COLLINEAR && o2 != COLLINEAR && o3 != COLLINEAR && o4 != COLLINEAR)
        return true;
      auto on = [&](const Point& q, const Point& u, const Point& v, Orientation o) { // q on [u, v]
        return o == COLLINEAR && compare_xy(q, (std::min)(u, v, [&](const Point& x, const Point& y) { return compare_xy(x, y) == SMALLER; })) != SMALLER &&
               compare_xy(q, (std::max)(u, v, [&](const Point& x, const Point& y) { return compare_xy(x, y) == SMALLER; })) != LARGER;
      };
      return on(c, a, b, o1) || on(d, a, b, o2) || on(a, c, d, o3) || on(b, c, d, o4);
    };
    bool found = false;
    for(const std::vector<std::size_t>& bucket : grid)
      for(std::size_t i = 0; i < bucket.size(); ++i)
        for(std::size_t j = i + 1; j < bucket.size(); ++j) {
          std::size_t e = bucket[i], f = bucket[j];
          if(e > f)
            std::swap(e, f);
          const bool adjacent = f == e + 1 || (e == 0 && f == m - 1);
          const Point& a = *p[e];
          const Point& b = *p[(e + 1) % m];
          const Point& c = *p[f];
          const Point& d = *p[(f + 1) % m];
          bool bad = false;
          if(!adjacent) {
            bad = meet(a, b, c, d);
          } else { // consecutive edges share one end; they must not fold back on each other
            const Point& shared = (f == e + 1) ? b : a;
            const Point& u = (f == e + 1) ? a : b;
            const Point& w = (f == e + 1) ? d : c;
            bad = orientation(u, shared, w) == COLLINEAR &&
                  compare_xy(u, shared) != compare_xy(shared, w);
          }
          if(bad) {
            // The faces on both edges go too: the stars may have been carved already (a vertex
            // with several fans keeps the others), and the next round must see a change.
            remove(open_[loop[e]].first);
            remove(open_[loop[f]].first);
            for(const std::size_t k : {e, (e + 1) % m, f, (f + 1) % m})
              carve_star(tail_vertex(loop[k]));
            found = true;
          }
        }
    return found;
  }

  // Whether loop `a` encloses a larger area than loop `b`, both through the point `o`, in
  // double (only to tell an island from the outer loop). The coordinates are taken relative
  // to `o` (halves: no overflow) and scaled by a power of two that brings the largest to
  // about 1, so that the cross products neither overflow (coordinates near 1e154 and beyond)
  // nor vanish (near the smallest normal double).
  CGAL_DFP_RARELY_RUN bool encloses_more(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b, const Point& o) const
  {
    const double ox = CGAL::to_double(o.x()) / 2, oy = CGAL::to_double(o.y()) / 2;
    double largest = 0;
    for(const std::vector<std::size_t>* loop : {&a, &b})
      for(const std::size_t h : *loop) {
        const Point& p = tail_point(h);
        largest = (std::max)({largest, std::fabs(CGAL::to_double(p.x()) / 2 - ox),
                              std::fabs(CGAL::to_double(p.y()) / 2 - oy)});
      }
    const int e = largest > 0 && std::isfinite(largest) ? -std::ilogb(largest) : 0;
    const double u = std::ldexp(1.0, e / 2), v = std::ldexp(1.0, e - e / 2);
    auto area = [&](const std::vector<std::size_t>& loop) {
      double sum = 0;
      for(std::size_t k = 0; k < loop.size(); ++k) {
        const Point& p = tail_point(loop[k]);
        const Point& q = tail_point(loop[(k + 1) % loop.size()]);
        const double px = (CGAL::to_double(p.x()) / 2 - ox) * u * v, py = (CGAL::to_double(p.y()) / 2 - oy) * u * v;
        const double qx = (CGAL::to_double(q.x()) / 2 - ox) * u * v, qy = (CGAL::to_double(q.y()) / 2 - oy) * u * v;
        sum += px * qy - qx * py;
      }
      return sum;
    };
    return area(a) > area(b);
  }

  std::size_t lowest(const std::vector<std::size_t>& loop) const
  {
    auto compare_xy = compare_xy_called_out_of_line(tr_.geom_traits());
    std::size_t best = 0;
    for(std::size_t p = 1; p < loop.size(); ++p)
      if(compare_xy(tail_point(loop[p]), tail_point(loop[best])) == SMALLER)
        best = p;
    return best;
  }

  static const void* halfedge_key(const Edge& e)
  {
    return static_cast<const char*>(static_cast<const void*>(&*e.first)) + e.second;
  }

  bool is_open(Face_handle f, int i) const
  {
    const Face_handle g = f->neighbor(i);
    return g == Face_handle() || removed_.contains(&*g);
  }

  // The open half-edge that follows open_[k] on its cycle, or none.
  std::size_t next_open(std::size_t k) const
  {
    Face_handle f = open_[k].first;
    const Vertex_handle v = f->vertex(cw(open_[k].second));
    int out = ccw(open_[k].second); // the half-edge of f leaving v
    if(!turn_to_open_halfedge(f, v, out, [&](Face_handle g, int i) { return is_open(g, i); }, longest_fan))
      return none;
    const std::size_t* at = position_.find(halfedge_key(Edge(f, out)));
    return at == nullptr || !alive_[*at] ? none : *at;
  }

  // next_open(), from the open half-edges leaving the head: when it has only one, that one
  // (the turn around the head from open_[k] through kept faces stays in one fan, which ends
  // at an open half-edge leaving the head); otherwise by the turn.
  std::size_t next_open_by_vertex(std::size_t k) const
  {
    const Leaving* leaving = leaving_.find(&*open_[k].first->vertex(cw(open_[k].second)));
    if(leaving != nullptr && leaving->alive == 1 && alive_[leaving->last])
      return leaving->last;
    return next_open(k);
  }

  Vertex_handle tail_vertex(std::size_t k) const { return open_[k].first->vertex(ccw(open_[k].second)); }

  const Point& tail_point(std::size_t k) const
  {
    return open_[k].first->vertex(ccw(open_[k].second))->point();
  }

  // Carves the faces along a loop that cannot stay (a hole ear clipping cannot fill, an
  // island) and, for a hole, the stars of its vertices: the faces along it too, since a
  // vertex where faces meet only at that vertex has several fans and its star reaches only
  // one. An island (a face dropped over others, a piece hanging by a vertex) loses only the
  // faces along it: its vertices usually keep their own fans.
  CGAL_DFP_RARELY_RUN void widen(const std::vector<std::size_t>& cycle, bool with_stars = true)
  {
    for(const std::size_t k : cycle) {
      remove(open_[k].first);
      if(with_stars)
        carve_star(tail_vertex(k));
    }
  }


  // Fills one hole by ear clipping (hole_tracing.h).
  bool fill(const std::vector<std::size_t>& cycle, std::vector<Ear>& ears)
  {
    const std::size_t m = cycle.size();
    ears.clear();
    std::vector<Hole_ear>& cut = scratch_ears_;
    if(!clipper_.clip(tr_.geom_traits(), m, [&](std::size_t q) -> const Point& { return tail_point(cycle[q]); }, cut))
      return false;
    ears.reserve(cut.size());
    for(const Hole_ear& t : cut) {
      // A side of the hole pairs with its open half-edge, a diagonal with the other ear on it
      // through its ends, unique in this hole.
      Ear e;
      for(int i = 0; i < 3; ++i) {
        e.v[i] = tail_vertex(cycle[hole_corner(t.corner[i], m)]);
        e.open[i] = t.closes[i] == Hole_ear::diagonal ? none : cycle[t.closes[i]];
        const std::uint64_t from = t.corner[ccw(i)], to = t.corner[cw(i)];
        e.diagonal[i] = (std::min)(from, to) << 32 | (std::max)(from, to);
      }
      ears.push_back(e);
    }
    return true;
  }

  // The vertices left without a kept face: those whose star was carved, and those all of
  // whose faces went with their neighbours' stars. Each is reinserted, located from a vertex
  // on a cycle that shared a carved face with it, if there is one (near_).
  void collect_isolated_vertices()
  {
    Address_table<std::size_t> listed; // 1: on a cycle, 0: detached
    for(std::size_t k = 0; k < open_.size(); ++k)
      if(alive_[k])
        listed.insert(&*tail_vertex(k), 1); // cycle vertices keep faces
    detached_.clear();
    near_.clear();
    for(const Face_handle f : removed_list_)
      for(int i = 0; i < 3; ++i) {
        const Vertex_handle v = f->vertex(i);
        if(v == infinite_ || !listed.insert(&*v, 0).second)
          continue;
        detached_.push_back(v);
        near_.push_back(Vertex_handle());
        for(const int j : {ccw(i), cw(i)}) {
          const std::size_t* on_cycle = listed.find(&*f->vertex(j));
          if(on_cycle != nullptr && *on_cycle == 1) {
            near_.back() = f->vertex(j);
            break;
          }
        }
      }
  }

  // The importer's faces may meet at a vertex in several fans (overlapping predictions): a
  // vertex of carved faces may keep a whole fan elsewhere, out of reach of its open
  // half-edges. One pass over the faces left (after the carved ones are deleted) finds
  // them; they stay, pointing at a face they keep.
  CGAL_DFP_RARELY_RUN void keep_vertices_with_other_fans()
  {
    if(detached_.empty())
      return;
    Address_table<std::size_t> candidates;
    for(const Vertex_handle v : detached_)
      candidates.insert(&*v, 0);
    Address_table<std::size_t> kept;
    for(auto f = tds_.faces().begin(); f != tds_.faces().end(); ++f)
      for(int i = 0; i < 3; ++i) {
        const Vertex_handle v = f->vertex(i);
        if(candidates.contains(&*v) && kept.insert(&*v, 0).second)
          v->set_face(f);
      }
    std::size_t left = 0;
    for(std::size_t k = 0; k < detached_.size(); ++k)
      if(!kept.contains(&*detached_[k])) {
        detached_[left] = detached_[k];
        near_[left++] = near_[k];
      }
    detached_.resize(left);
    near_.resize(left);
  }

  void record_undo_log()
  {
    undo_.resize(removed_list_.size());
    old_index_.reserve(removed_list_.size());
    for(std::size_t k = 0; k < removed_list_.size(); ++k) {
      const Face_handle f = removed_list_[k];
      old_index_.insert(&*f, k);
      for(int i = 0; i < 3; ++i) {
        undo_[k].v[i] = f->vertex(i);
        undo_[k].neighbor[i] = &*f->neighbor(i);
      }
    }
  }

  Triangulation& tr_;
  Tds& tds_;
  const Vertex_handle infinite_;
  const bool keep_undo_log_;
  bool outer_open_ = false, committed_ = false, may_have_several_fans_ = false, complete_ = true;
  std::size_t rounds_ = 0, removed_finite_ = 0, outer_ = none, groups_ = 0, traced_ = 0;

  Address_table<std::size_t> removed_;   // carved face -> position in removed_list_
  std::unique_ptr<Slot_bitmap<typename Tds::Face>> carved_bitmap_; // the same set, from commit() on
  std::vector<Face_handle> removed_list_;
  Address_table<std::size_t> detached_set_;     // vertices queued for carving their star
  std::vector<Vertex_handle> pending_, detached_;
  std::vector<Vertex_handle> near_;       // per detached vertex: a cycle vertex near it, or null
  std::vector<Edge> given_open_;
  std::vector<Edge> open_;                // every half-edge ever found open, in order
  std::vector<char> alive_;               // whether it still is (its face not carved since)
  std::vector<std::size_t> loop_of_;      // its loop, or none
  Address_table<std::size_t> position_;   // open half-edge -> its position in open_
  struct Leaving
  {
    std::size_t last = 0;  // the open half-edge registered last with this tail
    std::size_t alive = 0; // how many with this tail are alive
  };
  Address_table<Leaving> leaving_;        // tail vertex -> its open half-edges
  std::vector<Loop> loops_;               // the current ones are not dead

  std::vector<Face_handle> created_;
  Address_table<std::size_t> created_set_;
  std::vector<Undo_entry> undo_;
  // Scratch space, reused across holes.
  Hole_clipper clipper_;
  std::vector<Hole_ear> scratch_ears_;
  std::vector<std::size_t> scratch_loop_;   // of split_at_repeated_vertices()
  std::vector<Face_handle> scratch_faces_;  // of carve_faces_around()
  Address_table<std::size_t> old_index_;
};

// Overlaps that edge pairing cannot see (the importer, after it left out faces on the same
// side of an edge as others: a flap of faces folded over the mesh but linked to it edge by
// edge): around a vertex whose faces close up, counterclockwise faces each turn by less than
// pi, so the fan winds around the vertex as many times as it passes the direction 0, counted
// exactly as in is_convex_ccw_cycle(). A vertex whose closed fan winds more than once has
// faces covering its neighbourhood twice: its star is carved. One pass over the vertices,
// about two orientation and coordinate tests per face.
// Fans of more faces are not followed (taken as open): a vertex of higher degree is never
// carved for winding twice. No result depends on it: faces that overlap there fail the final
// check, and the caller rebuilds.
constexpr std::size_t wound_twice_max_degree = 4096;

template <class Triangulation>
CGAL_DFP_RARELY_RUN void carve_vertices_wound_twice(const Triangulation& tr, Carve_repair<Triangulation>& carve)
{
  using Face_handle = typename Triangulation::Face_handle;
  const auto& gt = tr.geom_traits();
  auto compare_x = gt.compare_x_2_object();
  auto compare_y = gt.compare_y_2_object();
  for(auto v = tr.tds().vertices().begin(); v != tr.tds().vertices().end(); ++v) {
    const Face_handle start = v->face();
    if(start == Face_handle() || v == tr.infinite_vertex())
      continue;
    const auto& c = v->point();
    auto upper = [&](const auto& p) {
      const Comparison_result cy = compare_y(p, c);
      return cy == LARGER || (cy == EQUAL && compare_x(p, c) == LARGER);
    };
    std::size_t wraps = 0, steps = 0;
    Face_handle f = start;
    bool closed = true;
    do {
      const int i = f->index(v);
      // Around v counterclockwise, f turns from vertex ccw(i) to vertex cw(i).
      if(!upper(f->vertex(ccw(i))->point()) && upper(f->vertex(cw(i))->point()))
        ++wraps;
      f = f->neighbor(ccw(i));
      if(f == Face_handle() || ++steps > wound_twice_max_degree) {
        closed = false;
        break;
      }
    } while(f != start);
    if(closed && wraps != 1)
      carve.carve_star(typename Triangulation::Vertex_handle(v));
  }
}

// make_delaunay's local repair of a triangulation with faces that are not counterclockwise
// (`bad`), up to the flips: carves the stars of their vertices, fills the holes and reinserts
// those vertices (same objects); the edges to test are pushed on `stack`, the faces insertion
// split on `modified`. Returns Outcome::ok on success; otherwise why not, with `tr` as it was
// (the carve did not fit the budget, or the result would not be a triangulation: rolled back,
// the flips in `flip_log` still undoable). Never throws for duplicates: it returns first, and
// the caller's rebuild names them.
template <class Triangulation>
Outcome carve_and_reinsert(Carve_repair<Triangulation>& carve, Triangulation& tr,
                           const std::vector<typename Triangulation::Face_handle>& bad,
                           std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                           Flip_log<Triangulation>& flip_log, std::vector<const void*>& modified,
                           Statistics& stats)
{
  using Face_handle = typename Triangulation::Face_handle;
  // A face inverted by moves usually has one vertex that crossed the opposite edge, the
  // longest one: carving that vertex's star leaves a simple hole (its old link) in most
  // cases, at a third of the faces of carving all three stars. Holes that are not simple are
  // widened by the rounds of plan(). Only the amount carved depends on this choice.
  for(const Face_handle f : bad) {
    int crossing = 0;
    double longest = -1;
    for(int i = 0; i < 3; ++i) {
      const auto& p = f->vertex(ccw(i))->point();
      const auto& q = f->vertex(cw(i))->point();
      // Halves and hypot: no overflow near 1e308, no underflow to 0 near the smallest
      // normal double (only the amount carved depends on it).
      const double length = std::hypot(CGAL::to_double(p.x()) / 2 - CGAL::to_double(q.x()) / 2,
                                       CGAL::to_double(p.y()) / 2 - CGAL::to_double(q.y()) / 2);
      if(length > longest) {
        longest = length;
        crossing = i;
      }
    }
    carve.carve_star(f->vertex(crossing));
  }
  Outcome why = carve.plan(default_carve_limits(tr.number_of_vertices()));
  stats.carve_rounds = carve.rounds();
  if(why != Outcome::ok)
    return why;
  if(has_duplicate_of(tr, carve.detached()))
    return Outcome::duplicate_points;
  carve.commit(stack);
  if(!carve.finish_hull(stack, stats.flips)) {
    carve.rollback(flip_log); // the flips before the carve can still be undone
    return Outcome::carve_not_a_triangulation;
  }
  carve.reinsert(stack, modified, [](auto, auto) {
    CGAL_assertion_msg(false, "duplicates were ruled out before the carve");
  });
  stats.faces_carved = carve.faces_removed();
  stats.holes_refilled = carve.holes();
  stats.points_reinserted = carve.detached().size();
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_CARVE_REPAIR_H
