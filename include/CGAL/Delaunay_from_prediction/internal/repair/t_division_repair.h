// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The repair of Theorem 2.1 of the paper (Strategy::t_division), on a CGAL triangulation
// whose faces may be inverted or not locally Delaunay, in place:
//   1. divide the faces into regions of at most t faces, connected in the dual graph;
//   2. B = the faces with a neighbour in another region or outside the hull, V_B their
//      vertices; build DT(V_B) with CGAL's insertion;
//   3. a region is good if it has no face that is not counterclockwise, no edge failing the
//      in-circle test, every face of it in B is a face of DT(V_B), and every hull edge of it
//      a hull edge of DT(V_B); bad otherwise;
//   4. delete the faces of the bad regions; the holes they leave are bounded by edges of good
//      faces of B, hence by edges of DT(V_B): fill each with the faces of DT(V_B) inside it
//      (a flood fill in DT(V_B) that stops at the images of the kept faces);
//   5. insert the vertices left without a face (V_bad) back, keeping the vertex objects, and
//      flip (the merge of DT(V_B u V_good) with V_bad).
//
// How this differs from the paper. A true t-division bounds every region's boundary by
// O(sqrt t); breadth-first region growing gives compact regions on well-shaped meshes but no
// bound (regions squeezed between others come out as small fragments, all boundary). Step 5
// inserts V_bad one point at a time instead of merging DT(V_bad) in linear time
// (Kirkpatrick); with the insertion order of the rebuilds it costs about as much per point.
//
// Why the result is Delaunay. Before step 5 the triangulation is the union of the good
// regions and faces of DT(V_B). An edge between two faces of DT(V_B) is locally Delaunay
// (both are faces of one Delaunay triangulation); an edge with a good face on one side was
// tested by certification (the perturbed in-circle test, every failing edge made both its
// regions bad); the hull is DT(V_B)'s, convex. So every edge is locally Delaunay: this is
// DT(V_B u V_good) (the paper's step 4). The insertions then leave only the edges around
// inserted vertices to flip, and every edge of a filled hole is queued as well, so Lawson's
// algorithm ends at DT(P) whatever the kernel did. Why it is a triangulation: every check of
// plan() below is made before anything is modified (each hole edge must meet exactly one
// face of the fill, every vertex of the fill must have lost all its faces or be on a hole's
// boundary), so commit() cannot fail; all faces are then counterclockwise (good ones were
// tested, DT(V_B)'s are) and the hull is DT(V_B)'s, a convex polygon wound once: by the
// winding-number argument of import_prediction.h the faces tile the hull exactly once.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_T_DIVISION_REPAIR_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_T_DIVISION_REPAIR_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/dense_index.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/duplicate_vertices.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/region_growing.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Default region size t for n vertices: n/32 clamped to [64, 4096] (at least 64 regions). The proof of Theorem 2.1
// takes t = log2(n)^2 (400 at 1e6 points); measured at 1e6 points with one bad region, a
// region of 400 faces puts 35% of the vertices in V_B and the repair takes 1.06 s (a rebuild:
// 0.85 s), 1024 faces 24% and 0.67 s, 4096 faces 13% and 0.54 s; beyond, V_B shrinks but
// each bad region costs more (16384: 0.55 s).
inline std::size_t default_region_size(std::size_t n)
{
  return (std::min)(std::size_t(4096), (std::max)(std::size_t(64), n / 32));
}

template <class Triangulation>
class T_division_repair
{
public:
  using Gt = typename Triangulation::Geom_traits;
  using Tds = typename Triangulation::Triangulation_data_structure;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  using Edge = std::pair<Face_handle, int>;

  // Divides the faces of `tr` (dimension 2, a valid TDS) into regions of at most
  // `region_size` faces.
  T_division_repair(Triangulation& tr, std::size_t region_size)
      : tr_(tr), tds_(tr.tds()), infinite_(tr.infinite_vertex()), face_index_(tds_.faces()),
        vertex_index_(tds_.vertices()), boundary_dt_(tr.geom_traits())
  {
    divide((std::max)(std::size_t(1), region_size));
  }

  // --- Marking: what certification found. ------------------------------------------------
  void mark_bad_face(Face_handle f) { mark_region_of(f); }
  void mark_failing_edge(Face_handle f, int i)
  {
    mark_region_of(f);
    mark_region_of(f->neighbor(i));
  }

  // The hull is not a convex polygon wound once: marks the regions at its reflex vertices,
  // or, if it has none (it winds more than once), every region on it.
  void mark_hull_if_not_convex()
  {
    auto orientation = tr_.geom_traits().orientation_2_object();
    std::vector<Face_handle> hull;
    auto h = tds_.incident_faces(infinite_), end = h;
    do
      hull.push_back(h);
    while(++h != end);
    bool marked = false;
    auto inside = [&](Face_handle f) { return f->neighbor(f->index(infinite_)); };
    for(std::size_t k = 0; k < hull.size(); ++k) {
      // The infinite face (infinite, p, q) lies outside hull edge q->p; the next one around
      // the infinite vertex, (infinite, r, p), outside p->r.
      const Face_handle f = hull[k];
      const int i = f->index(infinite_);
      const Face_handle g = f->neighbor(cw(i));
      const int j = g->index(infinite_);
      CGAL_assertion(g->vertex(cw(j)) == f->vertex(ccw(i)));
      if(orientation(f->vertex(cw(i))->point(), f->vertex(ccw(i))->point(), g->vertex(ccw(j))->point()) == LEFT_TURN)
        continue;
      mark_region_of(inside(f));
      mark_region_of(inside(g));
      marked = true;
    }
    if(!marked)
      for(const Face_handle f : hull)
        mark_region_of(inside(f));
  }

  // --- Planning: reads `tr` only. ---------------------------------------------------------

  // Builds DT(V_B), finds the good regions and the fill of every hole, and checks that the
  // fill fits. `max_cost` bounds |V_B| plus the faces of the bad regions, then |V_B| plus
  // four times the vertices to reinsert (a reinsertion and its flips cost about four point
  // insertions of a rebuild: measured at 1e6 points, 222,422 points reinserted into the
  // fills with 4.8 flips each, about 3 us per point against 0.85 us for a rebuild). Returns
  // null when commit() can run, otherwise why not (then `tr` is untouched).
  Outcome plan(std::size_t max_cost)
  {
    const std::size_t faces_in_bad_regions = count_faces_in_bad_regions();
    if(faces_in_bad_regions == 0)
      return Outcome::ok; // nothing marked (a hull that is not convex was): nothing to repair
    collect_boundary();
    if(vb_.size() + faces_in_bad_regions > max_cost)
      return Outcome::bad_regions_too_large;
    const Outcome built = build_boundary_dt();
    if(built != Outcome::ok)
      return built;
    certify_boundary_faces();
    // 1: a vertex of a kept face, 2: a vertex of removed faces only, listed.
    std::vector<char> kept_vertex(vertex_index_.size(), 0);
    if(!mark_removed_faces(kept_vertex))
      return Outcome::every_region_bad;
    const std::size_t removed_boundary_vertices = list_detached_vertices(kept_vertex);
    if(vb_.size() + 4 * detached_.size() > max_cost)
      return Outcome::bad_regions_too_large;
    std::vector<std::pair<std::uint32_t, Dt_face>> border;
    Outcome why = mark_kept_images(border);
    if(why == Outcome::ok)
      why = flood_fill(border);
    if(why == Outcome::ok)
      why = check_fill_vertices(kept_vertex, removed_boundary_vertices);
    if(why != Outcome::ok)
      return why;
    planned_ = true;
    return Outcome::ok;
  }

  std::size_t regions() const { return bad_region_.size(); }
  std::size_t bad_regions() const
  {
    return std::size_t(std::count(bad_region_.begin(), bad_region_.end(), char(1)));
  }
  std::size_t boundary_vertices() const { return vb_.size(); }
  std::size_t faces_removed() const { return removed_finite_; }
  // The finite faces to remove whose address satisfies `pred` (before commit()).
  template <class Pred>
  std::size_t faces_removed_if(Pred pred) const
  {
    std::size_t count = 0;
    for(std::size_t k = 0; k < removed_.size(); ++k) // empty when nothing was marked
      count += (removed_[k] && region_[k] != outside && pred(static_cast<const void*>(&*faces_[k]))) ? 1 : 0;
    return count;
  }
  std::size_t holes() const { return holes_; }
  // The vertices left without a face (V_bad), reinserted by reinsert().
  const std::vector<Vertex_handle>& detached() const { return detached_; }
  bool is_removed(Face_handle f) const { return planned_ && removed_[face_index_.of(f)]; }
  // Whether `f` was made by this repair (the fill, insertions).
  bool is_created(const void* f) const { return created_.contains(f); }

  // --- Modifying. --------------------------------------------------------------------------

  // Replaces the faces of the bad regions by the fill (after a successful plan()). The
  // entries of `stack` on removed faces are dropped; every edge of the fill goes on it.
  void commit(std::vector<Edge>& stack)
  {
    if(!planned_ || fill_.empty())
      return;
    const Dt_index& dt_index = *dt_index_;
    stack.erase(std::remove_if(stack.begin(), stack.end(), [&](const Edge& e) { return is_removed(e.first); }),
                stack.end());
    std::vector<Face_handle> made(fill_.size());
    for(std::size_t p = 0; p < fill_.size(); ++p) {
      const Dt_face d = fill_[p];
      made[p] = tds_.create_face(vertex_of(d->vertex(0)), vertex_of(d->vertex(1)), vertex_of(d->vertex(2)));
      created_.insert(&*made[p], 0);
    }
    for(std::size_t p = 0; p < fill_.size(); ++p) {
      const Dt_face d = fill_[p];
      for(int i = 0; i < 3; ++i) {
        const Dt_face g = d->neighbor(i);
        const std::size_t gi = dt_index.of(g);
        if(in_fill_[gi] != none) {
          made[p]->set_neighbor(i, made[in_fill_[gi]]);
        } else {
          // A hole edge: the kept face across it, and the slot of the shared edge there.
          const Face_handle kept = faces_[owner_[gi]];
          const int j = kept->index(vertex_of(g->vertex(g->index(d))));
          tds_.set_adjacency(made[p], i, kept, j);
        }
        stack.emplace_back(made[p], i);
        made[p]->vertex(i)->set_face(made[p]);
      }
    }
    for(std::size_t k = 0; k < faces_.size(); ++k)
      if(removed_[k])
        tds_.delete_face(faces_[k]);
    for(const Vertex_handle v : detached_)
      v->set_face(Face_handle());
  }

  // Reinserts V_bad keeping the vertex objects (reinsert_vertex_objects()); faces of the
  // prediction that insertion modifies go to `modified`.
  template <class OnDuplicate>
  void reinsert(std::vector<Edge>& stack, std::vector<const void*>& modified, OnDuplicate on_duplicate)
  {
    reinsert_vertex_objects(
        tr_, detached_, stack,
        [&](Face_handle f) {
          if(!f->has_vertex(infinite_) && !created_.contains(&*f))
            modified.push_back(&*f);
        },
        [&](Face_handle f) { created_.insert(&*f, 0); }, on_duplicate);
  }

private:
  static constexpr std::uint32_t none = std::uint32_t(-1);
  static constexpr std::uint32_t outside = outside_regions; // the region of infinite faces
  using Dt_vertex_base = Triangulation_vertex_base_with_info_2<std::uint32_t, Gt>;
  using Dt = Delaunay_triangulation_2<Gt, Triangulation_data_structure_2<Dt_vertex_base>>;
  using Dt_vertex = typename Dt::Vertex_handle;
  using Dt_face = typename Dt::Face_handle;
  using Dt_index = Dense_index<typename Dt::Triangulation_data_structure::Face_range>;

  // The finite faces divided into regions connected in the dual graph (grow_regions(), seeds
  // in container order); infinite faces belong to no region. The neighbours' dense indices
  // are kept for plan().
  void divide(std::size_t t)
  {
    const std::size_t F = face_index_.size();
    faces_.reserve(F);
    for(auto f = tds_.faces().begin(); f != tds_.faces().end(); ++f)
      faces_.push_back(f);
    neighbor_.resize(3 * F);
    for(std::size_t k = 0; k < F; ++k)
      for(int i = 0; i < 3; ++i)
        neighbor_[3 * k + i] = std::uint32_t(face_index_.of(faces_[k]->neighbor(i)));
    region_.assign(F, no_region);
    {
      auto h = tds_.incident_faces(infinite_), end = h;
      do
        region_[face_index_.of(h)] = outside;
      while(++h != end);
    }
    const std::uint32_t regions = grow_regions(region_, t, [&](std::uint32_t k, auto&& f) {
      for(int i = 0; i < 3; ++i)
        f(neighbor_[3 * k + i]);
    });
    bad_region_.assign(regions, 0);
  }

  // --- Stages of plan(). -------------------------------------------------------------------

  // The finite faces of the bad regions: none means nothing to repair.
  std::size_t count_faces_in_bad_regions() const
  {
    std::size_t count = 0;
    for(std::size_t k = 0; k < faces_.size(); ++k)
      count += region_[k] != outside ? bad_region_[region_[k]] : 0;
    return count;
  }

  // B (the faces with a neighbour in another region or outside the hull) and V_B, its
  // vertices in the order of B's faces.
  void collect_boundary()
  {
    const std::size_t F = faces_.size();
    is_boundary_.assign(F, 0);
    for(std::size_t k = 0; k < F; ++k) {
      if(region_[k] == outside)
        continue;
      for(int i = 0; i < 3; ++i)
        if(region_[neighbor_[3 * k + i]] != region_[k]) {
          is_boundary_[k] = 1;
          break;
        }
    }
    vb_of_.assign(vertex_index_.size(), none);
    for(std::size_t k = 0; k < F; ++k)
      if(is_boundary_[k])
        for(int i = 0; i < 3; ++i) {
          const Vertex_handle v = faces_[k]->vertex(i);
          std::uint32_t& at = vb_of_[vertex_index_.of(v)];
          if(at == none) {
            at = std::uint32_t(vb_.size());
            vb_.push_back(v);
          }
        }
  }

  // DT(V_B) by CGAL's insertion (spatially sorted); fails on repeated or collinear points.
  Outcome build_boundary_dt()
  {
    {
      std::vector<std::pair<Point, std::uint32_t>> points;
      points.reserve(vb_.size());
      for(std::size_t k = 0; k < vb_.size(); ++k)
        points.emplace_back(vb_[k]->point(), std::uint32_t(k));
      boundary_dt_.insert(points.begin(), points.end());
    }
    if(boundary_dt_.number_of_vertices() != vb_.size())
      return Outcome::duplicate_points;
    if(boundary_dt_.dimension() != 2)
      return Outcome::boundary_vertices_collinear;
    dt_vertex_.assign(vb_.size(), Dt_vertex());
    for(auto v = boundary_dt_.finite_vertices_begin(); v != boundary_dt_.finite_vertices_end(); ++v)
      dt_vertex_[v->info()] = v;
    return Outcome::ok;
  }

  // Good regions: their faces in B are faces of DT(V_B), their hull edges hull edges; a
  // region failing either is bad. Records the image of each face of B in a good region.
  void certify_boundary_faces()
  {
    const std::size_t F = faces_.size();
    image_.assign(F, Dt_face());
    for(std::size_t k = 0; k < F; ++k) {
      if(!is_boundary_[k] || bad_region_[region_[k]])
        continue;
      const Face_handle f = faces_[k];
      Dt_face image;
      if(!boundary_dt_.is_face(dt_of(f->vertex(0)), dt_of(f->vertex(1)), dt_of(f->vertex(2)), image)) {
        bad_region_[region_[k]] = 1;
        continue;
      }
      image_[k] = image;
      for(int i = 0; i < 3; ++i)
        if(f->neighbor(i)->has_vertex(infinite_) &&
           !boundary_dt_.is_infinite(image->neighbor(image->index(dt_of(f->vertex(i))))))
          bad_region_[region_[k]] = 1;
    }
  }

  // What goes: the faces of bad regions, and the infinite faces outside them. Marks the
  // vertices of kept faces in `kept_vertex`; returns whether any finite face is kept.
  bool mark_removed_faces(std::vector<char>& kept_vertex)
  {
    const std::size_t F = faces_.size();
    removed_.assign(F, 0);
    std::size_t kept_faces = 0;
    for(std::size_t k = 0; k < F; ++k) {
      const Face_handle f = faces_[k];
      if(region_[k] == outside) {
        removed_[k] = bad_region_[region_[neighbor_[3 * k + f->index(infinite_)]]];
        continue;
      }
      removed_[k] = bad_region_[region_[k]];
      if(!removed_[k]) {
        ++kept_faces;
        for(int i = 0; i < 3; ++i)
          kept_vertex[vertex_index_.of(f->vertex(i))] = 1;
      }
    }
    return kept_faces != 0;
  }

  // Lists the vertices of removed faces that keep no face: outside V_B they are V_bad
  // (detached_), in V_B they must reappear in the fill. Returns how many are in V_B.
  std::size_t list_detached_vertices(std::vector<char>& kept_vertex)
  {
    std::size_t removed_boundary_vertices = 0;
    for(std::size_t k = 0; k < faces_.size(); ++k) {
      if(!removed_[k])
        continue;
      if(region_[k] != outside)
        ++removed_finite_;
      for(int i = 0; i < 3; ++i) {
        const Vertex_handle v = faces_[k]->vertex(i);
        if(v == infinite_)
          continue;
        char& kept = kept_vertex[vertex_index_.of(v)];
        if(kept)
          continue;
        kept = 2; // listed
        if(vb_of_[vertex_index_.of(v)] == none)
          detached_.push_back(v);
        else
          ++removed_boundary_vertices;
      }
    }
    return removed_boundary_vertices;
  }

  // Marks the images of the kept faces of B and of the kept infinite faces (`border`, the
  // kept faces that may border a hole) as owned by them; two on one image cannot both stay.
  Outcome mark_kept_images(std::vector<std::pair<std::uint32_t, Dt_face>>& border)
  {
    dt_index_.reset(new Dt_index(boundary_dt_.tds().faces()));
    const Dt_index& dt_index = *dt_index_;
    for(std::size_t k = 0; k < faces_.size(); ++k)
      if(!removed_[k] && (region_[k] == outside || is_boundary_[k]))
        border.emplace_back(std::uint32_t(k), image_of(k));
    owner_.assign(dt_index.size(), none);
    for(const auto& b : border) {
      std::uint32_t& owner = owner_[dt_index.of(b.second)];
      if(owner != none)
        return Outcome::kept_faces_repeated;
      owner = b.first;
    }
    return Outcome::ok;
  }

  // The fill: floods DT(V_B) from across every hole edge, never entering a marked face, one
  // hole per flood; fails unless the fill meets the kept faces exactly at the hole edges.
  Outcome flood_fill(const std::vector<std::pair<std::uint32_t, Dt_face>>& border)
  {
    const Dt_index& dt_index = *dt_index_;
    in_fill_.assign(dt_index.size(), none);
    std::size_t hole_edges = 0, contacts = 0;
    for(const auto& b : border) {
      const Face_handle f = faces_[b.first];
      for(int i = 0; i < 3; ++i) {
        if(!removed_[neighbor_[3 * b.first + i]])
          continue;
        ++hole_edges;
        const Dt_face across = b.second->neighbor(b.second->index(dt_of(f->vertex(i))));
        const std::size_t ai = dt_index.of(across);
        if(owner_[ai] != none)
          return Outcome::kept_faces_do_not_fit;
        if(in_fill_[ai] != none)
          continue;
        ++holes_;
        in_fill_[ai] = std::uint32_t(fill_.size());
        fill_.push_back(across);
        for(std::size_t head = fill_.size() - 1; head < fill_.size(); ++head)
          for(int j = 0; j < 3; ++j) {
            const Dt_face g = fill_[head]->neighbor(j);
            const std::size_t gi = dt_index.of(g);
            if(owner_[gi] != none)
              ++contacts;
            else if(in_fill_[gi] == none) {
              in_fill_[gi] = std::uint32_t(fill_.size());
              fill_.push_back(g);
            }
          }
      }
    }
    // Every hole edge leads to a contact, distinct ones to distinct contacts: equal counts
    // mean the fill meets the kept faces only at hole edges.
    if(contacts != hole_edges)
      return Outcome::kept_faces_do_not_fit;
    return Outcome::ok;
  }

  // Vertices of the fill: one that lost all its faces must have its whole star in DT(V_B)
  // in the fill; one that kept faces must touch a kept face there (be on a hole's boundary);
  // and every boundary vertex that lost its faces must be in the fill.
  Outcome check_fill_vertices(const std::vector<char>& kept_vertex, std::size_t removed_boundary_vertices) const
  {
    const Dt_index& dt_index = *dt_index_;
    std::vector<char> seen(vb_.size(), 0);
    std::size_t removed_seen = 0;
    for(const Dt_face d : fill_)
      for(int i = 0; i < 3; ++i) {
        const Dt_vertex w = d->vertex(i);
        if(boundary_dt_.is_infinite(w) || seen[w->info()])
          continue;
        seen[w->info()] = 1;
        const bool kept = kept_vertex[vertex_index_.of(vb_[w->info()])] == 1;
        bool touches_kept = false, star_in_fill = true;
        auto g = boundary_dt_.incident_faces(w), end = g;
        do {
          const std::size_t gi = dt_index.of(g);
          touches_kept = touches_kept || owner_[gi] != none;
          star_in_fill = star_in_fill && in_fill_[gi] != none;
        } while(++g != end);
        if(kept ? !touches_kept : !star_in_fill)
          return Outcome::kept_faces_do_not_fit;
        removed_seen += kept ? 0 : 1;
      }
    if(removed_seen != removed_boundary_vertices)
      return Outcome::kept_faces_do_not_fit;
    return Outcome::ok;
  }

  void mark_region_of(Face_handle f)
  {
    const std::uint32_t r = region_[face_index_.of(f)];
    if(r != outside)
      bad_region_[r] = 1;
  }

  Dt_vertex dt_of(Vertex_handle v) const
  {
    return v == infinite_ ? boundary_dt_.infinite_vertex() : dt_vertex_[vb_of_[vertex_index_.of(v)]];
  }
  Vertex_handle vertex_of(Dt_vertex w) const { return boundary_dt_.is_infinite(w) ? infinite_ : vb_[w->info()]; }

  // The face of DT(V_B) a kept face of B, or a kept infinite face, corresponds to.
  Dt_face image_of(std::size_t k) const
  {
    if(region_[k] != outside)
      return image_[k];
    const Face_handle h = faces_[k];
    const Face_handle inside = h->neighbor(h->index(infinite_));
    const Dt_face image = image_[face_index_.of(inside)];
    return image->neighbor(image->index(dt_of(inside->vertex(inside->index(h)))));
  }

  Triangulation& tr_;
  Tds& tds_;
  const Vertex_handle infinite_;
  const Dense_index<typename Tds::Face_range> face_index_;
  const Dense_index<typename Tds::Vertex_range> vertex_index_;
  std::vector<Face_handle> faces_;       // by dense index
  std::vector<std::uint32_t> neighbor_;  // dense index of neighbour i of face k at 3k + i
  std::vector<std::uint32_t> region_;    // region of each face; outside for infinite faces
  std::vector<char> bad_region_;
  std::vector<char> is_boundary_, removed_;
  std::vector<std::uint32_t> vb_of_;     // vertex -> index in vb_, or none
  std::vector<Vertex_handle> vb_;        // V_B
  Dt boundary_dt_;                       // DT(V_B), info() = index in vb_
  std::vector<Dt_vertex> dt_vertex_;
  std::vector<Dt_face> image_;           // for the faces of B in good regions
  std::unique_ptr<Dt_index> dt_index_;   // dense indices of DT(V_B)'s faces
  std::vector<std::uint32_t> owner_;     // DT(V_B) face -> the kept face it is the image of
  std::vector<std::uint32_t> in_fill_;   // DT(V_B) face -> its position in fill_
  std::vector<Dt_face> fill_;
  std::vector<Vertex_handle> detached_;
  Address_table<std::size_t> created_;
  std::size_t removed_finite_ = 0, holes_ = 0;
  bool planned_ = false;
};

// Strategy::t_division of delaunay_from_prediction() and make_delaunay() (Theorem 2.1 of the
// paper): the bad regions of a t-division replaced and their inner vertices reinserted, when that
// costs less than a rebuild.

// Budget of Strategy::t_division for n vertices, in point insertions (|V_B| plus four times
// the vertices to reinsert, see T_division_repair::plan()): about a rebuild, n times `factor`
// (Tuning::t_division_budget_factor, 1 by default; tests raise it to reach the repair on
// small, badly damaged inputs).
inline std::size_t t_division_budget(std::size_t n, double factor)
{
  const double budget = factor * double(n);
  const double most = double(std::size_t(-1) / 4);
  return budget < most ? std::size_t(budget) : std::size_t(-1) / 4;
}

// Strategy::t_division on the valid triangulation `tr`: the faces in `bad`
// are not counterclockwise; the failing edges are those of `stack` (when `stack_fails`), or
// those of its edges that fail the in-circle test. Replaces the bad regions and reinserts
// their inner vertices, leaving the flips to the caller; returns Outcome::ok then, otherwise why not
// with `tr` untouched. With `check_duplicates`, returns first if a vertex to reinsert is at
// the point of another; otherwise `on_duplicate(v, w)` handles it as in reinsert_vertex_objects().
// `budget_factor`: see t_division_budget().
template <class Triangulation, class OnDuplicate, class MadeEarlier = bool (*)(const void*)>
Outcome repair_by_t_division(Triangulation& tr, std::unique_ptr<T_division_repair<Triangulation>>& regions,
                              const std::vector<typename Triangulation::Face_handle>& bad, bool hull_is_convex,
                              std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                              bool stack_fails, std::size_t region_size, double budget_factor,
                              std::vector<const void*>& modified,
                              Statistics& stats, bool check_duplicates, OnDuplicate on_duplicate,
                              MadeEarlier made_earlier = [](const void*) { return false; })
{
  const std::size_t n = tr.number_of_vertices();
  const auto& gt = tr.geom_traits();
  const auto infinite = tr.infinite_vertex();
  std::vector<std::pair<typename Triangulation::Face_handle, int>> failing;
  for(const auto& e : stack) {
    const auto f = e.first;
    const int i = e.second;
    const auto g = f->neighbor(i);
    if(f->has_vertex(infinite) || g->has_vertex(infinite))
      continue;
    if(stack_fails || !is_locally_delaunay(gt, f->vertex(i)->point(), f->vertex(ccw(i))->point(),
                                           f->vertex(cw(i))->point(), g->vertex(tr.tds().mirror_index(f, i))->point()))
      failing.push_back(e);
  }
  // m marks spread over the 2n/t regions spoil about m t / 2 faces and reinsert about 0.3 to
  // 0.45 m t points (measured at 1e5 and 1e6). Measured on top of the carve's own cost: about
  // 0.28 us per point for the division itself (regions, DT(V_B)) and 4.3 us per reinserted
  // point (1e5: 13,581 reinserted, 0.087 s more than the carve; 1e6: 13,134 reinserted, 0.34 s
  // more), against 0.75-0.86 us per point for a rebuild. Past m t = 0.15 n the division alone
  // would take the call past 1.1 times a rebuild (with the import of index triples, about 0.35
  // us per point, before it): say so before dividing, and let the carve finish.
  const std::size_t budget = t_division_budget(n, budget_factor);
  if(double(bad.size() + failing.size()) * double(region_size) > 0.15 * double(budget))
    return Outcome::t_division_over_budget;
  regions.reset(new T_division_repair<Triangulation>(tr, region_size));
  for(const auto f : bad)
    regions->mark_bad_face(f);
  for(const auto& e : failing)
    regions->mark_failing_edge(e.first, e.second);
  if(!hull_is_convex)
    regions->mark_hull_if_not_convex();
  const Outcome why = regions->plan(budget);
  stats.regions = regions->regions();
  stats.bad_regions = regions->bad_regions();
  stats.boundary_vertices = regions->boundary_vertices();
  if(why != Outcome::ok)
    return why;
  if(check_duplicates && has_duplicate_of(tr, regions->detached()))
    return Outcome::duplicate_points;
  // Faces an earlier stage made (the carve's fill, the import's) are not predicted faces:
  // not counted as carved.
  stats.faces_carved += regions->faces_removed_if([&](const void* f) { return !made_earlier(f); });
  regions->commit(stack);
  regions->reinsert(stack, modified, on_duplicate);
  stats.holes_refilled += regions->holes();
  stats.points_reinserted += regions->detached().size();
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_T_DIVISION_REPAIR_H
