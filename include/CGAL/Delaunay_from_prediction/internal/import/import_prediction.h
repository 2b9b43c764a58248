// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 3 of the pipeline for a prediction given as index triples (read and validated into
// 32-bit triples by input_check.h): import, certify and export to CGAL's triangulation data
// structure, fused into one streaming pass.
//
// At 1e6 points the cost is memory traffic, not arithmetic (see PERFORMANCE_NOTES), so:
//  - if the points or the faces come in no spatial order (sampled), the points are renumbered
//    along a serpentine grid and the faces counting-sorted by their smallest new index, so
//    that everything later touches a narrow band of memory (spatial_order.h);
//  - one pass over the faces then orients each face, creates its CGAL vertices and face, and
//    pairs its half-edges with their twins through a small hash table holding the open
//    "frontier" edges; when a twin is found the two faces are linked and the edge gets its
//    in-circle test while both faces are in cache.
// Linear expected time; the hash table stays as small as the frontier (about sqrt(n) edges
// for spatially ordered faces).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_IMPORT_PREDICTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_IMPORT_PREDICTION_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/import/hole_tracing.h>
#include <CGAL/Delaunay_from_prediction/internal/import/open_halfedges.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// What Prediction_importer leaves behind besides the triangulation itself.
template <class Triangulation>
struct Imported_prediction
{
  using Face_handle = typename Triangulation::Face_handle;

  std::vector<std::size_t> unused_points;                         // used by no face
  std::vector<std::pair<Face_handle, int>> not_locally_delaunay; // one side of each such edge
  // Tolerant import (local repair): faces left out (degenerate, or on the same side of an
  // edge as an earlier face), and, when the faces kept are not a triangulation with a convex
  // hull, their half-edges without a twin (the TDS then has no infinite faces yet).
  std::size_t faces_dropped = 0;
  bool needs_repair = false;
  std::vector<std::pair<Face_handle, int>> open_halfedges;
  // Tolerant import: holes it filled itself (fill_small_holes()), and the faces it made for
  // them (addresses, sorted): those are not predicted faces.
  std::size_t holes_filled = 0;
  std::vector<const void*> filled_faces;
  std::size_t vertices_used = 0;
  std::size_t edges_tested = 0;
  bool reordered = false;        // whether the spatial reordering ran
  // The caller's point indices in the grid order of the reordering, when it renumbered the
  // points (else empty): a rebuild after the import starts from it.
  std::vector<std::uint32_t> points_in_grid_order;
  Outcome failure = Outcome::ok; // why the faces are not a triangulation
};

// When the import stops early, because what would follow it (the local repair, the flips)
// costs more than a rebuild. Each rule looks at a stretch of consecutive faces, all of them
// (Prediction_importer::build()) or one chunk's share (build_in_chunks()), after `done` of
// them, and extrapolates what it has seen to all the faces; the importer runs the rules every
// 4096 faces.
struct Import_limits
{
  // A stretch of faces, with its own terms of the rule for holes.
  struct Stretch
  {
    std::size_t faces;    // in the stretch
    std::size_t max_open; // open half-edges past which it stops at once
    std::size_t frontier; // open half-edges of its frontiers, not counted as holes
  };

  // `hole_halfedges`: the open half-edges of holes the caller's repair takes on (the
  // pipeline's max_open_halfedges(), n/4 + 64 by default).
  Import_limits(std::size_t n, std::size_t all_faces, std::size_t max_failing_edges, bool tolerant_import,
                bool faces_sorted_by_band, std::size_t hole_halfedges)
      : faces(all_faces), root(std::size_t(std::sqrt(double(n)))), max_hole_halfedges(hole_halfedges),
        max_open(hole_halfedges > std::size_t(-1) - 32 * root ? std::size_t(-1) : hole_halfedges + 32 * root), max_failing(max_failing_edges), max_dropped(all_faces / 64 + 64),
        tolerant(tolerant_import), faces_sorted(faces_sorted_by_band)
  {}

  // All the faces, with one frontier.
  Stretch all_faces() const { return Stretch{faces, max_open, 8 * root}; }
  // A chunk of `size` faces: its share of the fixed limit, and two frontiers (with the chunks
  // before and after it).
  Stretch chunk(std::size_t size) const
  {
    const double share = double(max_hole_halfedges) * double(size) / double(faces) + double(64 * root);
    return Stretch{size, share >= double(max_open) ? max_open : std::size_t(share), 16 * root};
  }

  // Tolerant import: the half-edges still open are the moving frontier when the faces come
  // sorted (spatial_order.h), plus the boundaries of holes; past n/4 of those the local
  // repair would cost more than a rebuild (see delaunay_from_prediction), so the import
  // stops as soon as it sees that many (with 32 sqrt(n) for the frontier), or, from a 32nd
  // of the faces on, as soon as the hole boundaries seen so far, extrapolated to all the
  // faces, exceed 1.25 times that. Measured at 1e6 points with 1% of the faces deleted, the
  // open half-edges grow linearly from a frontier of about sqrt(n) (8 sqrt(n) is
  // subtracted); with 10% deleted the import stops after about 5% of the faces, where the
  // fixed limit alone lets it run through half of them.
  Outcome too_many_holes(const Stretch& s, std::size_t done, std::size_t open) const
  {
    const bool stop = open > s.max_open ||
                      (32 * done >= s.faces && open > s.frontier &&
                       double(open - s.frontier) * double(faces) > 1.25 * double(max_open) * double(done));
    return stop ? Outcome::too_many_holes : Outcome::ok;
  }

  // The same extrapolation, from an eighth of the faces on, for the edges failing the
  // in-circle test against `max_failing` (the caller's flip budget over the flips a
  // failing edge costs): a prediction that would exhaust the flips is rebuilt after an
  // eighth of the import instead of after all of it and the flips (bench_d_cross: the rho
  // model's predictions cost 1.2 to 1.4 times the rebuild that way at 1e5 points).
  Outcome too_many_failing_edges(const Stretch& s, std::size_t done, std::size_t failing) const
  {
    const bool stop = 8 * done >= s.faces && double(failing) * double(faces) > double(max_failing) * double(done);
    return stop ? Outcome::too_many_failing_edges : Outcome::ok;
  }

  // The same extrapolation for the faces left out: with 1% of the points of 1e6
  // relabelled (faces crossing others) it stops after a 32nd of the faces, where the
  // fixed limit alone is passed near the end, 0.2 s in (the call 1.46 times CGAL's build).
  Outcome too_many_overlapping_faces(const Stretch& s, std::size_t done, std::size_t dropped) const
  {
    const bool stop = 32 * done >= s.faces &&
                      double(dropped) * double(faces) > 1.25 * double(max_dropped) * double(done);
    return stop ? Outcome::too_many_overlapping_faces : Outcome::ok;
  }

  // The rules that apply, in turn, after `done` faces of `s`: the first one that stops.
  Outcome check(const Stretch& s, std::size_t done, std::size_t open, std::size_t failing, std::size_t dropped) const
  {
    Outcome why = Outcome::ok;
    if(tolerant && faces_sorted)
      why = too_many_holes(s, done, open);
    if(why == Outcome::ok)
      why = too_many_failing_edges(s, done, failing);
    if(why == Outcome::ok && tolerant)
      why = too_many_overlapping_faces(s, done, dropped);
    return why;
  }

  std::size_t faces; // all of them
  std::size_t root;  // sqrt(n)
  // Open half-edges on hole boundaries past which the local repair costs more than a rebuild.
  std::size_t max_hole_halfedges;
  std::size_t max_open; // that, with the frontier of all the faces
  std::size_t max_failing; // failing edges past which the flips cost more than a rebuild
  // Faces the tolerant import may leave out before it gives up: each one usually costs the
  // local repair a carved star, and past 1.5% of the faces (measured: index triples of a
  // triangulation whose points then moved by 0.1 spacing, 5% of the faces inverted) the
  // repair costs more than a rebuild; stopping early saves the rest of the import.
  std::size_t max_dropped;
  bool tolerant, faces_sorted; // the rule for holes needs faces in band order (spatial_order.h)
};

template <class Triangulation>
class Prediction_importer
{
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Face_handle = typename Triangulation::Face_handle;
  using Face = typename Triangulation::Face;
  using Point = typename Triangulation::Point;
  // An open half-edge is stored as its face's address (faces hold pointers: 8-byte aligned)
  // with the half-edge's index (the vertex it faces) in bits 0-1 and, in bit 2, whether its
  // tail is the edge's smaller endpoint.
  static constexpr std::uintptr_t tail_is_smaller_bit = 4, index_bits = 3, flag_bits = 7;
  // An open half-edge by its endpoints, with its code.
  struct Boundary_halfedge
  {
    std::uint32_t tail, head;
    std::uintptr_t code;
    bool operator<(const Boundary_halfedge& other) const { return tail < other.tail; }
  };

  static std::uintptr_t halfedge_code(Face_handle f, int i, bool tail_is_smaller)
  {
    return reinterpret_cast<std::uintptr_t>(&*f) | std::uintptr_t(i) | (tail_is_smaller ? tail_is_smaller_bit : 0);
  }

  enum class Pairing { opened, twin_found, same_side };
  // Offers half-edge i of f, from `tail` to `head`, to `open`: either it opens, or the
  // half-edge waiting on the same edge is taken (`twin`), on the other side of the edge or,
  // for faces that overlap, on the same side.
  static Pairing offer_halfedge(Open_halfedges& open, Face_handle f, int i, std::uint32_t tail, std::uint32_t head,
                                std::uintptr_t& twin)
  {
    const bool tail_is_smaller = tail < head;
    const std::uintptr_t code = halfedge_code(f, i, tail_is_smaller);
    if(!open.take_or_open(tail_is_smaller ? tail : head, tail_is_smaller ? head : tail, code, twin))
      return Pairing::opened;
    return ((twin ^ code) & tail_is_smaller_bit) == 0 ? Pairing::same_side : Pairing::twin_found;
  }

  // Links half-edge i of f to its twin, half-edge j of g, and records the edge in `failing`
  // (as (f, i)) unless it is locally Delaunay: `opposite` is f's vertex i, `tail` and `head`
  // the edge's ends.
  static void link_and_test(const typename Triangulation::Geom_traits& gt, Face_handle f, int i, Face_handle g, int j,
                            const Point& opposite, const Point& tail, const Point& head, std::size_t& edges_tested,
                            std::vector<std::pair<Face_handle, int>>& failing)
  {
    f->set_neighbor(i, g);
    g->set_neighbor(j, f);
    ++edges_tested;
    if(!is_locally_delaunay(gt, opposite, tail, head, g->vertex(j)->point()))
      failing.emplace_back(f, i);
  }

  // Orients the face with vertices v counterclockwise, swapping v[1] and v[2] if needed; false
  // if it is flat.
  template <class Orientation_2, class PointIterator>
  static bool orient_face(Orientation_2& orientation, PointIterator points, std::uint32_t v[3])
  {
    const Orientation o = orientation(points[v[0]], points[v[1]], points[v[2]]);
    if(o == NEGATIVE)
      std::swap(v[1], v[2]);
    return o != COLLINEAR;
  }

  // The per-face step of build() and build_in_chunks(): offers the half-edges of face f
  // (vertices v, counterclockwise; half-edge i runs from v[ccw(i)] to v[cw(i)], the face on
  // its left) to `open`, and links and tests each one whose twin was waiting (in `faces`).
  // Returns 3, or the first half-edge that met one on the same side of its edge (taken from
  // `open`: `twin`), those before it linked and tested.
  template <class PointIterator, class Faces>
  static int pair_face(const typename Triangulation::Geom_traits& gt, PointIterator points, Faces& faces,
                       Open_halfedges& open, Face_handle f, const std::uint32_t v[3], std::uintptr_t& twin,
                       std::size_t& edges_tested, std::vector<std::pair<Face_handle, int>>& failing)
  {
    for(int i = 0; i < 3; ++i) {
      const std::uint32_t tail = v[ccw(i)], head = v[cw(i)];
      const Pairing pairing = offer_halfedge(open, f, i, tail, head, twin);
      if(pairing == Pairing::opened)
        continue;
      if(pairing == Pairing::same_side)
        return i;
      link_and_test(gt, f, i, faces.iterator_to(*reinterpret_cast<Face*>(twin & ~flag_bits)), int(twin & index_bits),
                    points[v[i]], points[tail], points[head], edges_tested, failing);
    }
    return 3;
  }

public:
  // Imports and certifies the prediction `triples` (validated 32-bit index triples of
  // points[0..n), input_check.h; reordered here) into `tr`, fresh from its constructor.
  //
  // Why the checks certify a triangulation. Orient every face counterclockwise (a flat face
  // fails). Pair each half-edge with one of opposite direction on the same edge if there is
  // one (two faces on the same side of an edge fail). For a point x on no edge let deg(x) be
  // the number of faces containing x. Summing the winding numbers of the face boundaries,
  // paired half-edges cancel, so deg(x) is the winding number around x of the chain of
  // unpaired half-edges. If that chain is a single convex polygon wound once counterclockwise,
  // deg is 1 inside it and 0 outside: the faces tile the polygon with disjoint interiors. Then
  // no edge has more than two faces, no vertex lies inside another face's edge and no two
  // vertices coincide (the faces at such a place would cover part of the plane twice), and
  // each vertex's link winds exactly once: the faces form a triangulation of their vertices
  // whose domain is convex, hence their convex hull. If every point is a vertex or equal to
  // one, it triangulates P; if moreover every interior edge is locally Delaunay under CGAL's
  // perturbed in-circle test, it is CGAL's DT(P) (Delaunay's lemma, applied to the
  // symbolically perturbed points, whose Delaunay triangulation is unique).
  //
  // With `tolerant`, a face that is degenerate or lies on the same side of an edge as an
  // earlier face is left out instead of failing the import, and a boundary that is not one
  // convex polygon is handed over (needs_repair, open_halfedges) for carve_repair.h.
  //
  // With `parallel`, the faces are oriented, paired and tested in chunks on TBB's threads
  // (build_in_chunks()); the certificate is the same.
  //
  // `visitor` is told of the two stages (visitor.h): Stage::order, the spatial reordering with
  // the copy of the points, and Stage::import, the import and certificate.
  template <class PointIterator, class Visitor = Default_visitor, class Parallel = bool>
  static void run(Triangulation& tr, PointIterator points, std::size_t n, std::vector<std::uint32_t>& triples,
                  Imported_prediction<Triangulation>& out, bool tolerant, Parallel parallel = false,
                  Visitor&& visitor = Visitor(), std::size_t max_failing = std::size_t(-1),
                  std::size_t max_hole_halfedges = 0)
  {
    Prediction_importer importer(tr, n, triples.size() / 3, out, tolerant);
    importer.max_failing_ = max_failing; // failing edges past which the import stops (extrapolated)
    // Open half-edges of holes past which the import stops (0: n/4 + 64, the pipeline's default).
    importer.max_hole_halfedges_ = max_hole_halfedges == 0 ? n / 4 + 64 : max_hole_halfedges;
    visitor.stage_begin(Stage::order);
    Spatial_order order;
    order.compute(tr.geom_traits(), points, n, triples, parallel);
    out.reordered = order.renumbered() || order.faces_sorted();
    auto import = [&](auto sorted_points) {
      visitor.stage_begin(Stage::import);
      bool built = false;
      if constexpr(may_run_in_parallel<Parallel>())
        built = parallel && importer.number_of_faces_ >= 2 * min_chunk &&
                importer.build_in_chunks(sorted_points, triples, order);
      if(!built)
        importer.build(sorted_points, triples, order);
      visitor.stage_end(Stage::import);
    };
    if(order.renumbered()) {
      // Default-initialized, not zero-filled: every entry is written below.
      const std::unique_ptr<Point[]> sorted_points(new Point[n]);
      for_each_range(parallel, n, 65536, [&](std::size_t first, std::size_t last) {
        for(std::size_t v = first; v < last; ++v)
          sorted_points[v] = points[order.old_index(std::uint32_t(v))];
      });
      visitor.stage_end(Stage::order);
      import(static_cast<const Point*>(sorted_points.get()));
      out.points_in_grid_order = order.take_old_indices();
    } else {
      visitor.stage_end(Stage::order);
      import(points);
    }
  }

private:
  Prediction_importer(Triangulation& tr, std::size_t n, std::size_t number_of_faces,
                      Imported_prediction<Triangulation>& out, bool tolerant)
      : tr_(tr), n_(n), number_of_faces_(number_of_faces), out_(out), tolerant_(tolerant)
  {}

  Import_limits import_limits(const Spatial_order& order) const
  {
    return Import_limits(n_, number_of_faces_, max_failing_, tolerant_, order.faces_sorted(), max_hole_halfedges_);
  }

  Face_handle face_of(std::uintptr_t code) const
  {
    return tr_.tds().faces().iterator_to(*reinterpret_cast<Face*>(code & ~flag_bits));
  }

  // The streaming pass, then the hull.
  template <class PointIterator>
  void build(PointIterator points, const std::vector<std::uint32_t>& triples,
             const Spatial_order& order)
  {
    auto& tds = tr_.tds();
    const auto& gt = tr_.geom_traits();
    auto orientation = gt.orientation_2_object();
    tds.faces().clear(); // the constructor's face of dimension -1
    tds.set_dimension(2);
    tds.vertices().reserve(n_ + 1);
    tds.faces().reserve(number_of_faces_ + 64);
    std::vector<Vertex_handle> vertex_of(n_);
    Open_halfedges open(n_);
    const Import_limits limits = import_limits(order);
    const Import_limits::Stretch all_faces = limits.all_faces();

    const std::uint32_t* t = triples.data();
    for(std::size_t k = 0; k < number_of_faces_; ++k, t += 3) {
      if((k & 4095) == 0) {
        const Outcome why = limits.check(all_faces, k, open.size(), out_.not_locally_delaunay.size(), out_.faces_dropped);
        if(why != Outcome::ok) {
          out_.failure = why;
          return;
        }
      }
      std::uint32_t v[3] = {t[0], t[1], t[2]};
      if(!orient_face(orientation, points, v)) {
        if(tolerant_ && ++out_.faces_dropped <= limits.max_dropped)
          continue;
        out_.failure = tolerant_ ? Outcome::too_many_degenerate_faces : Outcome::degenerate_face;
        return;
      }
      Vertex_handle w[3];
      bool created[3];
      for(int i = 0; i < 3; ++i) {
        Vertex_handle& slot = vertex_of[v[i]];
        created[i] = (slot == Vertex_handle());
        if(created[i]) {
          slot = tds.create_vertex();
          slot->set_point(points[v[i]]);
          set_index_info(slot, order.old_index(v[i]));
          ++out_.vertices_used;
        }
        w[i] = slot;
      }
      const Face_handle f = tds.create_face(w[0], w[1], w[2]);
      for(int i = 0; i < 3; ++i)
        if(created[i])
          w[i]->set_face(f);

      const std::size_t tests_before = out_.not_locally_delaunay.size();
      std::uintptr_t twin = 0;
      const int conflict =
          pair_face(gt, points, tds.faces(), open, f, v, twin, out_.edges_tested, out_.not_locally_delaunay);
      if(conflict == 3)
        continue;
      if(!tolerant_) {
        out_.failure = Outcome::overlapping_faces;
        return;
      }
      // Leave this face out: reopen the twin just taken, undo the half-edges done.
      const std::uint32_t tail = v[ccw(conflict)], head = v[cw(conflict)];
      std::uintptr_t ignored = 0;
      open.take_or_open((std::min)(tail, head), (std::max)(tail, head), twin, ignored);
      drop_face(f, v, conflict, created, w, open, tests_before);
      if(out_.faces_dropped > limits.max_dropped) {
        out_.failure = Outcome::too_many_overlapping_faces;
        return;
      }
      for(int i = 0; i < 3; ++i)
        if(created[i])
          vertex_of[v[i]] = Vertex_handle();
    }

    std::vector<Boundary_halfedge> boundary;
    boundary.reserve(open.size());
    open.for_each([&](std::uint32_t smaller, std::uint32_t larger, std::uintptr_t code) {
      boundary.push_back(boundary_halfedge(smaller, larger, code));
    });
    finish(points, vertex_of, order, boundary);
  }

  static Boundary_halfedge boundary_halfedge(std::uint32_t smaller, std::uint32_t larger, std::uintptr_t code)
  {
    return (code & tail_is_smaller_bit) ? Boundary_halfedge{smaller, larger, code}
                                        : Boundary_halfedge{larger, smaller, code};
  }

  // After the faces are imported and paired: the points no face uses, then the half-edges
  // still open (`boundary`: the hull's and the boundaries of holes), the small holes filled
  // (tolerant import) and the hull closed, or the boundary handed over for carve_repair.h.
  template <class PointIterator>
  void finish(PointIterator points, const std::vector<Vertex_handle>& vertex_of, const Spatial_order& order,
              std::vector<Boundary_halfedge>& boundary)
  {
    for(std::uint32_t v = 0; v < n_; ++v)
      if(vertex_of[v] == Vertex_handle())
        out_.unused_points.push_back(order.old_index(v));
    std::sort(out_.unused_points.begin(), out_.unused_points.end());
    std::sort(boundary.begin(), boundary.end());
    if(tolerant_ && out_.faces_dropped == 0)
      fill_small_holes(points, boundary);
    const std::size_t kept = number_of_faces_ - out_.faces_dropped + out_.filled_faces.size();
    const long long hull_size = 2 * (long long)(out_.vertices_used) - 2 - (long long)(kept);
    Outcome why = Outcome::ok;
    if(hull_size < 3 || boundary.size() != std::size_t(hull_size))
      why = Outcome::holes_or_not_a_triangulation;
    else
      why = close_hull(points, boundary);
    if(why == Outcome::ok)
      return;
    if(!tolerant_) {
      out_.failure = why;
      return;
    }
    out_.needs_repair = true;
    out_.open_halfedges.reserve(boundary.size());
    for(const Boundary_halfedge& h : boundary)
      out_.open_halfedges.emplace_back(face_of(h.code), int(h.code & index_bits));
  }

  // Faces per chunk of build_in_chunks(), at least: small, so that even small inputs (and the
  // tests) cross several chunk boundaries.
  static constexpr std::size_t min_chunk = 32;

  // build_in_chunks()'s chunks of consecutive faces: a 16th of them, at least min_chunk, so
  // at most 16 chunks.
  struct Chunks
  {
    explicit Chunks(std::size_t all_faces)
        : faces(all_faces), size((std::max)(min_chunk, (all_faces + 15) / 16)), count((all_faces + size - 1) / size)
    {}
    // body(c, first, last) for each chunk c, of faces [first, last), on TBB's threads.
    template <class Body>
    void for_each(const Body& body) const
    {
      for_each_block(true, count, [&](std::size_t c) { body(c, c * size, (std::min)(faces, (c + 1) * size)); });
    }
    std::size_t faces, size, count;
  };

  // What a chunk of build_in_chunks() makes: its own containers, since CGAL's are not
  // thread-safe, its failing edges and the half-edges it leaves open.
  struct Chunk
  {
    typename Triangulation::Triangulation_data_structure::Vertex_range vertices;
    typename Triangulation::Triangulation_data_structure::Face_range faces;
    std::vector<std::pair<Face_handle, int>> not_locally_delaunay;
    std::vector<Boundary_halfedge> open; // tail = smaller endpoint, head = larger
    std::size_t edges_tested = 0;
  };

  // Why the chunks stop: not, a face the tolerant import would leave out, or an Outcome.
  static constexpr int go_on = -1, face_left_out = -2;

  // build() in parallel, on chunks of consecutive faces (Chunks). Three passes over the
  // chunks on TBB's threads:
  //  1. each chunk marks the vertices it uses in a bitmap of its own (mark_chunk_vertices());
  //  2. each chunk creates, in index order, the vertices it uses and no earlier chunk does,
  //     in a Compact_container of its own (create_chunk_vertices());
  //  3. each chunk orients its faces and creates them in a container of its own, pairs their
  //     half-edges through its own Open_halfedges, links and tests the pairs; it writes only
  //     its own faces and vertices (import_chunk()).
  // Then the half-edges each chunk left open (its frontiers with the chunks before and after,
  // about sqrt(n) each for faces in band order, and the hull) are paired sequentially in chunk
  // order (pair_seams()), and the containers spliced, in chunk order, into the triangulation's
  // (Compact_container::merge(), constant time per block), so that faces come in the order
  // build() creates them (vertices in chunk order, by index within a chunk); the seams are
  // linked and tested last (splice_and_link()). The pairing is exact, so the faces, their
  // links and the failing edges are those of build(); only the order of the failing edges
  // differs.
  //
  // A face the tolerant import would leave out (flat, or on the same side of an edge as
  // another) stops every chunk and false is returned, the triangulation untouched: build()
  // then runs from the start, since which face it leaves out depends on the order of the
  // faces. Strict imports fail there as build() does.
  template <class PointIterator>
  bool build_in_chunks(PointIterator points, const std::vector<std::uint32_t>& triples, const Spatial_order& order)
  {
    const Chunks chunks(number_of_faces_);
    std::vector<Chunk> chunk(chunks.count);

    // 1 and 2. The vertices, each made by the first chunk that uses it (`owner`).
    std::vector<std::uint64_t> uses = mark_chunk_vertices(triples, chunks);
    std::vector<Vertex_handle> vertex_of(n_);
    std::vector<std::uint8_t> owner(n_); // chunks <= 16
    create_chunk_vertices(points, order, chunks, uses, chunk, vertex_of, owner);
    std::vector<std::uint64_t>().swap(uses);

    // 3. The faces, their pairs and tests.
    const Import_limits limits = import_limits(order);
    std::atomic<int> stop{go_on};
    chunks.for_each([&](std::size_t c, std::size_t first, std::size_t last) {
      import_chunk(points, triples, limits, c, first, last, vertex_of, owner, chunk[c], stop);
    });
    const int why = stop.load();
    if(why == face_left_out)
      return false; // the chunks' containers are released: build() starts again
    if(why != go_on) {
      out_.failure = Outcome(why);
      return true;
    }

    // The seams paired in chunk order before anything is spliced, so that a pair on the same
    // side leaves the triangulation as it was (the chunks' containers are released on return).
    std::size_t seams = 0;
    for(const Chunk& c : chunk)
      seams += c.open.size();
    Hash_map<std::uint64_t, std::uintptr_t> waiting(2 * seams + 2);
    std::vector<std::pair<std::uintptr_t, std::uintptr_t>> seam_pairs; // (half-edge, twin) codes
    seam_pairs.reserve(seams / 2);
    std::vector<std::size_t> pairs_end(chunks.count); // chunk c's pairs end there
    if(!pair_seams(chunk, waiting, seam_pairs, pairs_end)) {
      if(tolerant_)
        return false; // build() starts again
      out_.failure = Outcome::overlapping_faces;
      return true;
    }

    splice_and_link(chunk, seam_pairs, pairs_end);
    std::vector<Boundary_halfedge> boundary;
    boundary.reserve(waiting.size());
    waiting.for_each([&](std::uint64_t edge, std::uintptr_t code) {
      boundary.push_back(boundary_halfedge(std::uint32_t(edge >> 32), std::uint32_t(edge), code));
    });
    finish(points, vertex_of, order, boundary);
    return true;
  }

  // Stage 1 of build_in_chunks(): the vertices each chunk uses, a bitmap of n bits per chunk.
  std::vector<std::uint64_t> mark_chunk_vertices(const std::vector<std::uint32_t>& triples, const Chunks& chunks) const
  {
    const std::size_t words = (n_ + 63) / 64;
    std::vector<std::uint64_t> uses(chunks.count * words, 0);
    chunks.for_each([&](std::size_t c, std::size_t first, std::size_t last) {
      std::uint64_t* mine = uses.data() + c * words;
      for(const std::uint32_t *t = triples.data() + 3 * first, *end = triples.data() + 3 * last; t != end; ++t)
        mine[*t >> 6] |= std::uint64_t(1) << (*t & 63);
    });
    return uses;
  }

  // Stage 2 of build_in_chunks(): each chunk creates, in index order, the vertices it uses
  // (`uses`, from mark_chunk_vertices()) and no earlier chunk does, and is their `owner`.
  template <class PointIterator>
  void create_chunk_vertices(PointIterator points, const Spatial_order& order, const Chunks& chunks,
                             const std::vector<std::uint64_t>& uses, std::vector<Chunk>& chunk,
                             std::vector<Vertex_handle>& vertex_of, std::vector<std::uint8_t>& owner) const
  {
    const std::size_t words = (n_ + 63) / 64;
    chunks.for_each([&](std::size_t c, std::size_t, std::size_t) {
      for(std::size_t w = 0; w < words; ++w) {
        std::uint64_t own = uses[c * words + w];
        for(std::size_t earlier = 0; own != 0 && earlier < c; ++earlier)
          own &= ~uses[earlier * words + w];
        for(std::size_t bit = 0; own != 0; ++bit, own >>= 1) {
          if((own & 1) == 0)
            continue;
          const std::size_t v = 64 * w + bit;
          const Vertex_handle h = chunk[c].vertices.emplace();
          h->set_point(points[v]);
          set_index_info(h, order.old_index(std::uint32_t(v)));
          vertex_of[v] = h;
          owner[v] = std::uint8_t(c);
        }
      }
    });
  }

  // Stage 3 of build_in_chunks(), for chunk c, of faces [first, last): the faces oriented and
  // created in the chunk's container, their half-edges paired through an Open_halfedges of
  // its own, the pairs linked and tested. At a face the tolerant import would leave out, or
  // when a stop rule says so, it sets `stop`, which every chunk then obeys.
  template <class PointIterator>
  void import_chunk(PointIterator points, const std::vector<std::uint32_t>& triples, const Import_limits& limits,
                    std::size_t c, std::size_t first, std::size_t last, const std::vector<Vertex_handle>& vertex_of,
                    const std::vector<std::uint8_t>& owner, Chunk& out, std::atomic<int>& stop) const
  {
    const auto& gt = tr_.geom_traits();
    auto orientation = gt.orientation_2_object();
    auto& created = out.faces;
    created.reserve(last - first);
    Open_halfedges open(n_, true);
    const Import_limits::Stretch share = limits.chunk(last - first);
    for(std::size_t k = first; k < last; ++k) {
      const std::size_t done = k - first;
      if((done & 1023) == 0 && stop.load(std::memory_order_relaxed) != go_on)
        return;
      // The stop rules on this chunk's share of the faces; a chunk leaves no face out (it
      // stops instead), hence none dropped.
      if((done & 4095) == 0) {
        const Outcome why = limits.check(share, done, open.size(), out.not_locally_delaunay.size(), 0);
        if(why != Outcome::ok) {
          stop.store(int(why));
          return;
        }
      }
      const std::uint32_t* t = triples.data() + 3 * k;
      std::uint32_t v[3] = {t[0], t[1], t[2]};
      if(!orient_face(orientation, points, v)) {
        stop.store(tolerant_ ? face_left_out : int(Outcome::degenerate_face));
        return;
      }
      const Face_handle f = created.emplace(vertex_of[v[0]], vertex_of[v[1]], vertex_of[v[2]]);
      // A vertex's first face in the chunk that made it becomes its face().
      for(int i = 0; i < 3; ++i)
        if(owner[v[i]] == c && vertex_of[v[i]]->face() == Face_handle())
          vertex_of[v[i]]->set_face(f);
      std::uintptr_t twin = 0;
      if(pair_face(gt, points, created, open, f, v, twin, out.edges_tested, out.not_locally_delaunay) != 3) {
        stop.store(tolerant_ ? face_left_out : int(Outcome::overlapping_faces));
        return;
      }
    }
    out.open.reserve(open.size());
    open.for_each([&](std::uint32_t smaller, std::uint32_t larger, std::uintptr_t code) {
      out.open.push_back(Boundary_halfedge{smaller, larger, code});
    });
  }

  // The half-edges the chunks left open, paired in chunk order through `waiting` (those left
  // there are the boundary): the (half-edge, twin) codes go to `seam_pairs`, chunk c's ending
  // at pairs_end[c]. False at a pair on the same side of its edge.
  bool pair_seams(const std::vector<Chunk>& chunk, Hash_map<std::uint64_t, std::uintptr_t>& waiting,
                  std::vector<std::pair<std::uintptr_t, std::uintptr_t>>& seam_pairs,
                  std::vector<std::size_t>& pairs_end) const
  {
    for(std::size_t c = 0; c < chunk.size(); ++c) {
      for(const Boundary_halfedge& h : chunk[c].open) {
        const std::uint64_t edge = std::uint64_t(h.tail) << 32 | h.head;
        std::uintptr_t twin = 0;
        if(!waiting.take(edge, twin)) {
          waiting.insert(edge, h.code);
          continue;
        }
        if(((twin ^ h.code) & tail_is_smaller_bit) == 0)
          return false;
        seam_pairs.emplace_back(h.code, twin);
      }
      pairs_end[c] = seam_pairs.size();
    }
    return true;
  }

  // The chunks' containers spliced, in chunk order, into the triangulation's; then their
  // failing edges, followed by those of the seams paired after them, linked and tested in
  // the same order.
  void splice_and_link(std::vector<Chunk>& chunk, const std::vector<std::pair<std::uintptr_t, std::uintptr_t>>& seam_pairs,
                       const std::vector<std::size_t>& pairs_end)
  {
    auto& tds = tr_.tds();
    const auto& gt = tr_.geom_traits();
    tds.faces().clear(); // the constructor's face of dimension -1
    tds.set_dimension(2);
    for(Chunk& c : chunk) {
      out_.vertices_used += c.vertices.size();
      tds.vertices().merge(c.vertices);
      tds.faces().merge(c.faces);
    }
    for(std::size_t c = 0, k = 0; c < chunk.size(); ++c) {
      out_.edges_tested += chunk[c].edges_tested;
      out_.not_locally_delaunay.insert(out_.not_locally_delaunay.end(), chunk[c].not_locally_delaunay.begin(),
                                       chunk[c].not_locally_delaunay.end());
      for(; k < pairs_end[c]; ++k) {
        const Face_handle f = face_of(seam_pairs[k].first);
        const int i = int(seam_pairs[k].first & index_bits);
        link_and_test(gt, f, i, face_of(seam_pairs[k].second), int(seam_pairs[k].second & index_bits),
                      f->vertex(i)->point(), f->vertex(ccw(i))->point(), f->vertex(cw(i))->point(),
                      out_.edges_tested, out_.not_locally_delaunay);
      }
    }
  }

  // Leaves face f (vertices v, vertex handles w, `created` those it created) out of the
  // import after its half-edge `conflict` met a twin on the same side: its half-edges before
  // `conflict` are unlinked (their twins reopened) or closed, the in-circle results on them
  // dropped, and the face and the vertices it created deleted.
  CGAL_DFP_RARELY_RUN void drop_face(Face_handle f, const std::uint32_t v[3], int conflict, const bool created[3],
                 const Vertex_handle w[3], Open_halfedges& open, std::size_t tests_before)
  {
    auto& tds = tr_.tds();
    for(int i = 0; i < conflict; ++i) {
      const std::uint32_t tail = v[ccw(i)], head = v[cw(i)];
      const std::uint32_t smaller = (std::min)(tail, head), larger = (std::max)(tail, head);
      std::uintptr_t twin = 0;
      const Face_handle g = f->neighbor(i);
      if(g == Face_handle()) {
        open.take_or_open(smaller, larger, 0, twin); // closes f's own open half-edge
        continue;
      }
      const int j = g->index(f);
      g->set_neighbor(j, Face_handle());
      --out_.edges_tested;
      // g's half-edge j runs from head to tail.
      const std::uintptr_t code = halfedge_code(g, j, head < tail);
      open.take_or_open(smaller, larger, code, twin);
    }
    out_.not_locally_delaunay.resize(tests_before);
    for(int i = 0; i < 3; ++i)
      if(created[i]) {
        tds.delete_vertex(w[i]);
        --out_.vertices_used;
      }
    tds.delete_face(f);
    ++out_.faces_dropped;
  }

  // Tolerant import, when no face was left out: fills the small holes here instead of handing
  // them to carve_repair.h, whose store of open half-edges (hash tables of half-edges and
  // vertices, incremental rounds) is built for carving. Measured with 1% of the faces of a DT of 1e6
  // points deleted (19,549 holes, nearly all single triangles): 0.026 s here against 0.045 s
  // for the tracing, filling and commit there, and the whole call 5-6% faster (in-process
  // A/B; the lookups of the kept faces around the holes are most of what is left).
  // The tracing is the carve's (hole_tracing.h), on a sorted array of index pairs: the open
  // half-edges are traced into cycles of at most max_fill edges, split at repeated vertices
  // into loops; a loop is filled when ear clipping triangulates it, reversed, as a
  // counterclockwise polygon (so the hull's
  // cycle, clockwise once reversed, and islands are never taken), and when it shares no vertex
  // with a loop left open. The ears are paired like imported faces, with their in-circle
  // tests; everything else is left open for carve_repair.h. Nothing here needs the holes to
  // be what they seem: the ears are counterclockwise and paired, so the certificate stays the
  // one of run() (every face counterclockwise, every half-edge paired but those of one convex
  // cycle wound once).
  template <class PointIterator>
  void fill_small_holes(PointIterator points, std::vector<Boundary_halfedge>& halfedges)
  {
    const std::size_t m = halfedges.size();
    std::vector<char> done(m, 0);
    Hole_plan plan;
    plan_hole_fills(points, halfedges, done, plan);
    std::vector<char>& closed_by_fill = done; // reused: every entry is 1 after the planning
    std::fill(closed_by_fill.begin(), closed_by_fill.end(), 0);
    fill_planned_holes(points, halfedges, plan, closed_by_fill);
    sort_by_address(out_.filled_faces);
    std::size_t left = 0;
    for(std::size_t k = 0; k < m; ++k)
      if(!closed_by_fill[k])
        halfedges[left++] = halfedges[k];
    halfedges.resize(left);
  }

  // Open half-edges in a cycle that fill_small_holes() may fill, at most.
  static constexpr std::size_t max_fill = 32;
  // Turning around a vertex through more linked faces than this (a vertex's degree is
  // about 6) means faces winding around it: left to carve_repair.h.
  static constexpr std::size_t longest_turn = 64;

  // The loops fill_small_holes() may fill, each given by positions in its sorted half-edges:
  // loop l is loop_halfedges[loop_start[l], loop_start[l + 1]), its ears
  // loop_ears[loop_ears_start[l], loop_ears_start[l + 1]). Half-edge loop[q] runs from t_q to
  // t_(q+1); reversed, the polygon has vertex p = t_(m-1-p), and its edge from p to p+1 is the
  // twin of loop[m-2-p] (indices mod m).
  struct Hole_plan
  {
    std::vector<std::size_t> loop_halfedges, loop_start = std::vector<std::size_t>(1, 0),
                                             loop_ears_start = std::vector<std::size_t>(1, 0);
    std::vector<Hole_ear> loop_ears;
    std::vector<std::uint32_t> left_open; // vertices of the cycles and loops not filled, sorted
  };

  // The open half-edge after halfedges[k] (sorted by tail), or halfedges.size() if none: the
  // only one leaving its head, or, when several do (holes that touch there), the one that ends
  // the fan of linked faces turning around the head from halfedges[k]'s face, as next_open()
  // of carve_repair.h does (the cycle then passes through the head twice and is split).
  std::size_t next_open_halfedge(const std::vector<Boundary_halfedge>& halfedges, std::size_t k) const
  {
    const std::size_t no_successor = halfedges.size();
    const std::uint32_t head = halfedges[k].head;
    const auto first = std::lower_bound(halfedges.begin(), halfedges.end(), Boundary_halfedge{head, 0, 0});
    if(first == halfedges.end() || first->tail != head)
      return no_successor;
    if(first + 1 == halfedges.end() || (first + 1)->tail != head)
      return std::size_t(first - halfedges.begin());
    Face_handle f = face_of(halfedges[k].code);
    const Vertex_handle v = f->vertex(cw(int(halfedges[k].code & index_bits)));
    int leaving = ccw(int(halfedges[k].code & index_bits)); // f's half-edge that leaves v
    if(!turn_to_open_halfedge(f, v, leaving, [](Face_handle g, int i) { return g->neighbor(i) == Face_handle(); },
                              longest_turn))
      return no_successor; // faces winding around v: not a hole to fill here
    for(auto it = first; it != halfedges.end() && it->tail == head; ++it)
      if((it->code & ~flag_bits) == reinterpret_cast<std::uintptr_t>(&*f) && int(it->code & index_bits) == leaving)
        return std::size_t(it - halfedges.begin());
    return no_successor;
  }

  // Pass 1 of fill_small_holes(): traces the open half-edges into cycles (`done` marks those
  // traced), splits them into loops and clips every loop; the loops clipped go to `plan`, the
  // vertices of what stays open to plan.left_open.
  template <class PointIterator>
  void plan_hole_fills(PointIterator points, const std::vector<Boundary_halfedge>& halfedges, std::vector<char>& done,
                       Hole_plan& plan) const
  {
    const auto& gt = tr_.geom_traits();
    const std::size_t m = halfedges.size();
    std::vector<std::size_t> cycle, loop;
    Hole_clipper clipper;
    std::vector<Hole_ear> ears;
    auto plan_loop = [&](std::vector<std::size_t>::const_iterator first, std::vector<std::size_t>::const_iterator last) {
      const std::size_t size = std::size_t(last - first);
      if(size < 3 ||
         !clipper.clip(gt, size, [&](std::size_t q) -> decltype(auto) { return points[halfedges[first[std::ptrdiff_t(q)]].tail]; },
                       ears)) {
        for(auto h = first; h != last; ++h)
          plan.left_open.push_back(halfedges[*h].tail);
        return;
      }
      plan.loop_halfedges.insert(plan.loop_halfedges.end(), first, last);
      plan.loop_start.push_back(plan.loop_halfedges.size());
      plan.loop_ears.insert(plan.loop_ears.end(), ears.begin(), ears.end());
      plan.loop_ears_start.push_back(plan.loop_ears.size());
    };
    for(std::size_t start = 0; start < m; ++start) {
      if(done[start])
        continue;
      cycle.clear();
      bool closed = false;
      for(std::size_t at = start; !done[at] && cycle.size() < max_fill;) {
        done[at] = 1;
        cycle.push_back(at);
        at = next_open_halfedge(halfedges, at);
        if(at == m)
          break;
        if(at == start) {
          closed = true;
          break;
        }
      }
      if(!closed) {
        for(const std::size_t h : cycle)
          plan.left_open.push_back(halfedges[h].tail);
        continue;
      }
      // A cycle through a vertex twice (holes that touch there, the successor having turned
      // through the faces between them) is split there into loops, each through distinct
      // vertices.
      split_at_repeated_vertices(cycle, [&](std::size_t h) { return halfedges[h].tail; }, loop, plan_loop);
    }
    std::sort(plan.left_open.begin(), plan.left_open.end());
  }

  // Pass 2 of fill_small_holes(): fills the loops of `plan` that share no vertex with one left
  // open, and marks their half-edges in `closed_by_fill`. A loop left open may be
  // an island of kept faces inside a hole that touches it at a vertex (a kept face whose
  // three neighbours are missing): the hole's loop around it would be filled over it.
  // Leaving the whole region to carve_repair.h keeps the faces from overlapping.
  template <class PointIterator>
  void fill_planned_holes(PointIterator points, const std::vector<Boundary_halfedge>& halfedges, const Hole_plan& plan,
                          std::vector<char>& closed_by_fill)
  {
    auto& tds = tr_.tds();
    const auto& gt = tr_.geom_traits();
    // Links half-edge i of f (from `tail` to `head`) to half-edge j of g, with the in-circle test.
    auto link = [&](Face_handle f, int i, std::uint32_t tail, std::uint32_t head, Face_handle g, int j) {
      link_and_test(gt, f, i, g, j, f->vertex(i)->point(), points[tail], points[head], out_.edges_tested,
                    out_.not_locally_delaunay);
    };
    struct Diagonal
    {
      std::size_t from, to;
      Face_handle face;
      int index;
    };
    std::vector<Diagonal> diagonals;
    std::vector<std::size_t> polygon;
    for(std::size_t l = 0; l + 1 < plan.loop_start.size(); ++l) {
      const std::size_t* first = plan.loop_halfedges.data() + plan.loop_start[l];
      const std::size_t size = plan.loop_start[l + 1] - plan.loop_start[l];
      polygon.resize(size);
      bool touches_open = false;
      for(std::size_t p = 0; p < size; ++p) {
        polygon[p] = halfedges[first[hole_corner(p, size)]].tail;
        touches_open = touches_open || std::binary_search(plan.left_open.begin(), plan.left_open.end(), polygon[p]);
      }
      if(touches_open)
        continue;
      diagonals.clear();
      for(std::size_t e = plan.loop_ears_start[l]; e < plan.loop_ears_start[l + 1]; ++e) {
        const Hole_ear& t = plan.loop_ears[e];
        Vertex_handle corner[3];
        for(int c = 0; c < 3; ++c) {
          const std::uintptr_t code = halfedges[first[hole_corner(t.corner[c], size)]].code;
          corner[c] = face_of(code)->vertex(ccw(int(code & index_bits)));
        }
        const Face_handle f = tds.create_face(corner[0], corner[1], corner[2]);
        out_.filled_faces.push_back(&*f);
        // The edge opposite slot i runs from polygon vertex `from` to `to`.
        for(int i = 0; i < 3; ++i) {
          const std::size_t from = t.corner[ccw(i)], to = t.corner[cw(i)];
          const std::uint32_t tail = std::uint32_t(polygon[from]), head = std::uint32_t(polygon[to]);
          if(t.closes[i] != Hole_ear::diagonal) { // a side of the hole: its open half-edge is the twin
            const std::uintptr_t twin = halfedges[first[t.closes[i]]].code;
            link(f, i, tail, head, face_of(twin), int(twin & index_bits));
            continue;
          }
          const auto other = std::find_if(diagonals.begin(), diagonals.end(),
                                          [&](const Diagonal& d) { return d.from == to && d.to == from; });
          if(other == diagonals.end())
            diagonals.push_back(Diagonal{from, to, f, i});
          else
            link(f, i, tail, head, other->face, other->index);
        }
      }
      for(std::size_t q = 0; q < size; ++q)
        closed_by_fill[first[q]] = 1;
      ++out_.holes_filled;
    }
  }

  // Links the unpaired half-edges into one cycle, checks that it is a convex polygon wound
  // once counterclockwise, and closes the triangulation with the infinite faces.
  template <class PointIterator>
  Outcome close_hull(PointIterator points, const std::vector<Boundary_halfedge>& hull)
  {
    const std::size_t m = hull.size();
    for(std::size_t k = 1; k < m; ++k)
      if(hull[k].tail == hull[k - 1].tail) {
        return Outcome::boundary_pinched;
      }
    std::vector<std::size_t> cycle; // positions in `hull`, in ccw order
    cycle.reserve(m);
    std::size_t at = 0;
    for(std::size_t k = 0; k < m; ++k) {
      cycle.push_back(at);
      const Boundary_halfedge probe{hull[at].head, 0, 0};
      const auto next = std::lower_bound(hull.begin(), hull.end(), probe);
      if(next == hull.end() || next->tail != probe.tail) {
        return Outcome::boundary_not_closed;
      }
      at = std::size_t(next - hull.begin());
      if(at == 0 && k + 1 < m) {
        return Outcome::boundary_with_holes;
      }
    }
    if(at != 0 || !is_convex_ccw_cycle(tr_.geom_traits(), m, [&](std::size_t k) -> const Point& {
         return points[hull[cycle[k]].tail];
       })) {
      return Outcome::boundary_not_convex;
    }
    // The face outside hull half-edge u->v is (v, u, infinite); consecutive ones share the
    // edge (v, infinite), opposite u in the first and opposite w in the second.
    auto& tds = tr_.tds();
    const Vertex_handle infinite = tr_.infinite_vertex();
    std::vector<Face_handle> outside(m);
    for(std::size_t k = 0; k < m; ++k) {
      const std::uintptr_t code = hull[cycle[k]].code;
      const Face_handle inside = face_of(code);
      const int i = int(code & index_bits);
      outside[k] = tds.create_face(inside->vertex(cw(i)), inside->vertex(ccw(i)), infinite);
      tds.set_adjacency(outside[k], 2, inside, i);
    }
    for(std::size_t k = 0; k < m; ++k)
      tds.set_adjacency(outside[k], 1, outside[(k + 1) % m], 0);
    infinite->set_face(outside[0]);
    return Outcome::ok;
  }

  Triangulation& tr_;
  const std::size_t n_, number_of_faces_;
  Imported_prediction<Triangulation>& out_;
  const bool tolerant_;
  std::size_t max_failing_ = std::size_t(-1); // see run()
  std::size_t max_hole_halfedges_ = 0;         // see run()
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_IMPORT_PREDICTION_H
