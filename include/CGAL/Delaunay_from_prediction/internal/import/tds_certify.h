// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 3 of the pipeline (certify) for a prediction that is already a CGAL triangulation
// (make_delaunay): the same certificate as for index triples, read off CGAL's TDS, whose
// combinatorics are a sphere by construction, so only the geometry is checked.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_TDS_CERTIFY_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_TDS_CERTIFY_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Lawson's flips made during certification (make_delaunay), where the pass finds a failing
// edge between two counterclockwise faces: the faces and vertices it just read are in the
// cache, where the flips after the pass would find them cold (1e6 points moved by 0.1
// spacing: the pass and the flips took 0.26-0.30 s instead of 0.30-0.32 s, the whole call
// 0.89-0.93 of its time before, medians of in-process runs of both versions). Flips are made
// only between counterclockwise faces (an edge next to a face that is not is listed for
// later), so the faces that are not stay as they are; each flip is logged for undo_flip().
// No test that the new edge is not already there (the faces may overlap where some are
// inverted, and then two edges may join the same vertices): it cost as much as it saved, and
// the undo does not look edges up; the final certificate of the repair rules such edges out
// of any result. Every edge that fails and is not flipped is listed: with the pass over the
// faces still to come, the list covers every edge that may fail, as Lawson's algorithm needs.
template <class Triangulation>
struct Inline_flips
{
  std::size_t max_flips;
  std::size_t& flips;
  std::vector<typename Triangulation::Face_handle>& touched;
  Flip_log<Triangulation>& log;
  std::size_t edges_failing = 0; // edges the pass found failing, flipped or listed
};

// The certification passes are bound by memory latency (a face, its three vertices and up to
// three neighbours each): they prefetch the vertices and neighbours of the face 16 ahead.
template <class Face_iterator>
inline void prefetch_around(Face_iterator face)
{
#if defined(__GNUC__)
  for(int k = 0; k < 3; ++k) {
    __builtin_prefetch(face->vertex(k).operator->());
    __builtin_prefetch(face->neighbor(k).operator->());
  }
#else
  (void)face;
#endif
}

// The one rule by which make_delaunay gives up on a triangulation with too many faces that are
// not counterclockwise for the local repair (more than `max_bad_faces`, default_carve_limits()
// in carve_repair.h): past the limit the call rebuilds, so every test and flip made on the
// way there is wasted. It gives up as soon as the faces found not ccw among the first `seen`
// faces, scaled to all faces, exceed `times` the limit: 1.5 by default, from a sample of
// `inverted_faces_sample` faces before the pass (make_delaunay, inverted_faces_exceed_early())
// and again in the pass from 65,536 faces on (certify_triangulation(), certify_faces_in_blocks()).
// Rationale: a margin of 1.5 keeps the moves that the repair beats a rebuild on (0.1 of the
// mean spacing at 10^6 points: 2.3% of the faces, 0.72 times the limit) many standard
// deviations below it, while moves of 0.5 (24%, 7.7 times the limit) are told from the sample
// and rebuilt before a single in-circle test (results/make_delaunay_kinetic_gaussian_sparse_1e6.txt,
// bench_delaunay_from_prediction --cases kinetic).
constexpr double inverted_faces_margin = 1.5;
constexpr std::size_t inverted_faces_sample = 2048;

inline bool inverted_faces_heading_past(std::size_t not_ccw, std::size_t seen, std::size_t all_faces,
                                        std::size_t max_bad_faces, double times = inverted_faces_margin)
{
  return seen > 0 && double(not_ccw) * double(all_faces) > times * double(max_bad_faces) * double(seen);
}

// make_delaunay's early decision: whether the first inverted_faces_sample finite faces of `tr`
// (dimension 2), in the order of its face container, have so many faces that are not
// counterclockwise that the rule above gives up. Reads only. The container's first faces are
// spread over the whole domain in a triangulation built incrementally (by CGAL or by this
// package: their slots are freed and reused all through the build), so that move noise of one
// scale everywhere is estimated well (at 10^6 points, 0.7 to 1 times the fraction of all
// faces for moves of 0.1 to 0.5 spacing); in a container ordered by region, damage confined to the
// first region may steer the call to a rebuild a repair would have beaten. Only the time
// depends on it, never the result: a rebuild gives the same triangulation, and damage the
// sample misses is caught by the pass. Not used below 4 samples' worth of faces (the pass
// itself is then as cheap).
template <class Triangulation>
bool inverted_faces_exceed_early(const Triangulation& tr, std::size_t max_bad_faces)
{
  const std::size_t all_faces = tr.tds().number_of_faces(); // the infinite ones too, as in the pass
  if(tr.dimension() < 2 || all_faces < 4 * inverted_faces_sample)
    return false;
  auto orientation = tr.geom_traits().orientation_2_object();
  std::size_t seen = 0, not_ccw = 0;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end() && seen < inverted_faces_sample; ++f, ++seen)
    if(orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) != LEFT_TURN)
      ++not_ccw;
  return inverted_faces_heading_past(not_ccw, seen, all_faces, max_bad_faces);
}

// Returns Outcome::ok if every finite face of `tr` (dimension 2) is counterclockwise, after listing
// in `non_delaunay` every interior edge that fails the perturbed in-circle test; otherwise
// returns why not. If `bad_faces` is given, the faces that are not counterclockwise go there
// instead, and the pass goes on (Outcome::ok is returned; `hull_is_convex` is then only meaningful
// if `bad_faces` stays empty), unless more than `max_bad_faces` are found: then the pass
// stops at once and returns why. `hull_is_convex` tells whether the hull is a convex polygon wound once:
// then the argument of import_prediction.h (the TDS providing the twin pairing) shows that
// `tr` is a geometric triangulation of its vertices; if not, convexify_hull() may make it one.
// Reads only, unless `inline_flips` is given: then the failing edges between counterclockwise
// faces are flipped as they are found (see Inline_flips), and the call returns
// Outcome::flip_budget_exhausted when the budget runs out.
template <class Triangulation>
Outcome certify_triangulation(
    Triangulation& tr,
    std::vector<std::pair<typename Triangulation::Face_handle, int>>& non_delaunay,
    std::size_t& edges_tested, bool& hull_is_convex,
    std::vector<typename Triangulation::Face_handle>* bad_faces = nullptr,
    std::size_t max_bad_faces = 0, Inline_flips<Triangulation>* inline_flips = nullptr)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  using Gt = typename Triangulation::Geom_traits;
  hull_is_convex = false;
  if(tr.dimension() < 2)
    return Outcome::dimension_below_2;
  const Gt& gt = tr.geom_traits();
  auto orientation = gt.orientation_2_object();
  const auto infinite = tr.infinite_vertex();
  const std::less<const void*> before;
  // The inline flips: the face across (f, i) must be ccw too (then a failing edge has a
  // strictly convex quadrilateral, see lawson_flip()); one that is not waits in the list.
  std::vector<std::pair<Face_handle, int>> cascade;
  auto wants_flip = [&](Face_handle f, int i, const Point& a, const Point& b, const Point& c, const Point& d) {
    if(is_locally_delaunay(gt, a, b, c, d))
      return false;
    if(orientation(d, c, b) == LEFT_TURN)
      return true;
    non_delaunay.emplace_back(f, i);
    return false;
  };
  auto log_flip = [&](Face_handle f, int i) { inline_flips->log.emplace_back(f, i); };
  // Whether, after a sample of at least `sample` faces, the rule of inverted_faces_heading_past()
  // gives up at `times` the limit. A pass heading past the limit ends in a rebuild: flips made
  // on the way are wasted, so the inline flips stop while it heads past the limit itself.
  const std::size_t all_faces = tr.tds().number_of_faces();
  std::size_t visited = 0;
  auto bad_faces_heading_past = [&](double times, std::size_t sample) {
    return bad_faces != nullptr && visited >= sample &&
           inverted_faces_heading_past(bad_faces->size(), visited, all_faces, max_bad_faces, times);
  };
  auto ahead = tr.finite_faces_begin();
  for(int k = 0; k < 16 && ahead != tr.finite_faces_end(); ++k)
    ++ahead;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f) {
    if(ahead != tr.finite_faces_end())
      prefetch_around(ahead++);
    ++visited;
    const Point* p0 = &f->vertex(0)->point();
    const Point* p1 = &f->vertex(1)->point();
    const Point* p2 = &f->vertex(2)->point();
    if(orientation(*p0, *p1, *p2) != LEFT_TURN) {
      if(bad_faces == nullptr)
        return Outcome::inverted_face;
      bad_faces->push_back(f);
      // Past the limit, or heading past it (inverted_faces_heading_past()) after a fair
      // sample: damage that inverted_faces_exceed_early() did not see in its sample.
      if(bad_faces->size() > max_bad_faces || bad_faces_heading_past(inverted_faces_margin, 65536))
        return Outcome::too_many_inverted_faces;
      continue;
    }
    bool flipped = false;
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      if(!before(&*f, &*g) || g->has_vertex(infinite))
        continue; // each interior edge once, from its face of lower address
      edges_tested += flipped ? 0 : 1;
      const Point& d = g->vertex(g->index(Face_handle(f)))->point();
      if(is_locally_delaunay(gt, *p0, *p1, *p2, d))
        continue;
      if(inline_flips == nullptr) {
        non_delaunay.emplace_back(f, i);
        continue;
      }
      inline_flips->edges_failing += flipped ? 0 : 1; // found before a flip reached it
      if(orientation(d, f->vertex(cw(i))->point(), f->vertex(ccw(i))->point()) != LEFT_TURN ||
         bad_faces_heading_past(1., 4096)) {
        non_delaunay.emplace_back(f, i);
        continue;
      }
      cascade.assign(1, std::make_pair(Face_handle(f), i));
      const std::size_t flips_before = inline_flips->flips;
      if(!flip_edges_while<has_exact_double_predicates<Gt>::value>(
             tr, cascade, wants_flip, inline_flips->max_flips, inline_flips->flips, &inline_flips->touched, log_flip))
        return Outcome::flip_budget_exhausted;
      if(inline_flips->flips == flips_before)
        continue; // not flipped: listed
      // f was flipped: its edges are tested again (they are locally Delaunay unless a later
      // flip changed the faces across them).
      p0 = &f->vertex(0)->point();
      p1 = &f->vertex(1)->point();
      p2 = &f->vertex(2)->point();
      flipped = true;
      i = -1;
    }
  }
  hull_is_convex = hull_is_convex_and_wound_once(tr);
  return Outcome::ok;
}

// The certification pass of certify_triangulation() without the inline flips, on TBB's
// threads: the face set is only read, so blocks of faces are tested independently, each into
// lists of its own, joined in block order (the same lists whatever the number of threads).
// Compact_container has no random access: one sequential walk notes where each block of faces
// starts (it reads one word of each face). Blocks are a 64th of the faces, at least 32 and at
// most 16384 faces: even small triangulations are cut into several blocks, so that the tests
// cross block boundaries. Returns as certify_triangulation() does without `inline_flips`
// (`hull_is_convex` aside); stops early when a block sees that the faces not ccw are past
// `max_bad_faces`.
template <class Triangulation>
Outcome certify_faces_in_blocks(
    const Triangulation& tr,
    std::vector<std::pair<typename Triangulation::Face_handle, int>>& non_delaunay,
    std::size_t& edges_tested, std::vector<typename Triangulation::Face_handle>* bad_faces = nullptr,
    std::size_t max_bad_faces = 0)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Face_iterator = typename Triangulation::Triangulation_data_structure::Face_iterator;
  if(tr.dimension() < 2)
    return Outcome::dimension_below_2;
  const auto& tds = tr.tds();
  const auto& gt = tr.geom_traits();
  const auto infinite = tr.infinite_vertex();
  const std::size_t block_faces = (std::min)((std::max)(tds.number_of_faces() / 64, std::size_t(32)), std::size_t(16384));
  std::vector<Face_iterator> starts;
  starts.reserve(tds.number_of_faces() / block_faces + 2);
  std::size_t k = 0;
  for(Face_iterator f = tds.faces_begin(); f != tds.faces_end(); ++f, ++k)
    if(k % block_faces == 0)
      starts.push_back(f);
  const std::size_t blocks = starts.size();
  starts.push_back(tds.faces_end());
  struct Found
  {
    std::vector<std::pair<Face_handle, int>> non_delaunay;
    std::vector<Face_handle> bad;
    std::size_t edges_tested = 0;
  };
  std::vector<Found> found(blocks);
  std::atomic<std::size_t> bad_total{0}, visited_total{0};
  std::atomic<bool> stop{false};
  const std::size_t all_faces = tds.number_of_faces();
  const std::less<const void*> before;
  for_each_block(true, blocks, [&](std::size_t b) {
    if(stop.load(std::memory_order_relaxed))
      return;
    auto orientation = gt.orientation_2_object();
    Found& out = found[b];
    std::size_t visited = 0;
    Face_iterator ahead = starts[b];
    for(int j = 0; j < 16 && ahead != starts[b + 1]; ++j)
      ++ahead;
    for(Face_iterator f = starts[b]; f != starts[b + 1]; ++f) {
      if(ahead != starts[b + 1])
        prefetch_around(ahead++);
      if(f->has_vertex(infinite))
        continue;
      ++visited;
      const auto& p0 = f->vertex(0)->point();
      const auto& p1 = f->vertex(1)->point();
      const auto& p2 = f->vertex(2)->point();
      if(orientation(p0, p1, p2) != LEFT_TURN) {
        out.bad.push_back(f);
        if(bad_faces == nullptr || bad_total.fetch_add(1, std::memory_order_relaxed) + 1 > max_bad_faces) {
          stop.store(true, std::memory_order_relaxed);
          return;
        }
        continue;
      }
      for(int i = 0; i < 3; ++i) {
        const Face_handle g = f->neighbor(i);
        if(!before(&*f, &*g) || g->has_vertex(infinite))
          continue; // each interior edge once, from its face of lower address
        ++out.edges_tested;
        if(!is_locally_delaunay(gt, p0, p1, p2, g->vertex(g->index(Face_handle(f)))->point()))
          out.non_delaunay.emplace_back(f, i);
      }
    }
    // Heading past the limit after a fair sample, as in certify_triangulation().
    const std::size_t seen = visited_total.fetch_add(visited, std::memory_order_relaxed) + visited;
    if(bad_faces != nullptr && seen >= 65536 &&
       inverted_faces_heading_past(bad_total.load(std::memory_order_relaxed), seen, all_faces, max_bad_faces))
      stop.store(true, std::memory_order_relaxed);
  });
  if(stop.load())
    return bad_faces == nullptr ? Outcome::inverted_face : Outcome::too_many_inverted_faces;
  std::size_t listed = 0;
  for(const Found& out : found)
    listed += out.non_delaunay.size();
  non_delaunay.reserve(non_delaunay.size() + listed);
  for(Found& out : found) {
    non_delaunay.insert(non_delaunay.end(), out.non_delaunay.begin(), out.non_delaunay.end());
    edges_tested += out.edges_tested;
    if(bad_faces != nullptr)
      bad_faces->insert(bad_faces->end(), out.bad.begin(), out.bad.end());
  }
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_TDS_CERTIFY_H
