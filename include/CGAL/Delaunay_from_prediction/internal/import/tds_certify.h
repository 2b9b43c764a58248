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
// `inverted_faces_sample` faces before the pass (In_place_stages::screen(), inverted_faces_exceed_early())
// and again in the pass from 65,536 faces on (Face_certifier::certify_block()).
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

// The certificate of Sections 1.2 and 1.5 read off a CGAL triangulation (dimension 2), one
// block of the face container at a time: every finite face counterclockwise, every interior
// edge tested with the perturbed in-circle test. Sequentially the container is one block; on
// TBB's threads it is cut into blocks that are only read, each with lists of its own, joined
// in block order, so that the lists are the same whatever the number of threads.
template <class Triangulation>
class Face_certifier
{
public:
  using Face_handle = typename Triangulation::Face_handle;
  using Edge = std::pair<Face_handle, int>;
  using Face_iterator = typename Triangulation::Triangulation_data_structure::Face_iterator;

  // What one block found: failing edges, faces not ccw, edges tested.
  struct Block_lists
  {
    std::vector<Edge>& non_delaunay;
    std::vector<Face_handle>& bad;
    std::size_t& edges_tested;
  };

  Face_certifier(Triangulation& tr, bool wants_bad_faces, std::size_t max_bad_faces,
                 Inline_flips<Triangulation>* inline_flips)
      : tr_(tr), gt_(tr.geom_traits()), infinite_(tr.infinite_vertex()),
        all_faces_(tr.tds().number_of_faces()), wants_bad_faces_(wants_bad_faces), max_bad_faces_(max_bad_faces),
        inline_flips_(inline_flips)
  {}

  // Why the blocks stopped, once they have all run: Outcome::ok if they did not.
  Outcome stopped() const
  {
    if(!stop_.load())
      return Outcome::ok;
    return wants_bad_faces_ ? Outcome::too_many_inverted_faces : Outcome::inverted_face;
  }
  Outcome flips_outcome() const { return flip_budget_exhausted_ ? Outcome::flip_budget_exhausted : Outcome::ok; }

  // The faces [first, last) of the container. A face not ccw goes to `out.bad`, or stops every
  // block when no bad faces are wanted, or when they are past `max_bad_faces` or heading past
  // it (inverted_faces_heading_past(), from 65,536 faces seen on). With inline flips (one
  // block only), failing edges between ccw faces are flipped as they are found (Inline_flips).
  void certify_block(Face_iterator first, Face_iterator last, Block_lists out)
  {
    if(stop_.load(std::memory_order_relaxed))
      return;
    auto orientation = gt_.orientation_2_object();
    const std::less<const void*> before;
    std::size_t visited = 0;
    Face_iterator ahead = first;
    for(int k = 0; k < 16 && ahead != last; ++k)
      ++ahead;
    for(Face_iterator f = first; f != last; ++f) {
      if(ahead != last)
        prefetch_around(ahead++);
      if(f->has_vertex(infinite_))
        continue;
      ++visited;
      const auto* p0 = &f->vertex(0)->point();
      const auto* p1 = &f->vertex(1)->point();
      const auto* p2 = &f->vertex(2)->point();
      if(orientation(*p0, *p1, *p2) != LEFT_TURN) {
        out.bad.push_back(f);
        if(!wants_bad_faces_ || bad_faces_heading_past(bad_total_.fetch_add(1) + 1, visited, inverted_faces_margin, 65536)) {
          stop_.store(true);
          return;
        }
        continue;
      }
      bool flipped = false;
      for(int i = 0; i < 3; ++i) {
        const Face_handle g = f->neighbor(i);
        if(!before(&*f, &*g) || g->has_vertex(infinite_))
          continue; // each interior edge once, from its face of lower address
        out.edges_tested += flipped ? 0 : 1;
        const auto& d = g->vertex(g->index(Face_handle(f)))->point();
        if(is_locally_delaunay(gt_, *p0, *p1, *p2, d))
          continue;
        if(inline_flips_ == nullptr) {
          out.non_delaunay.emplace_back(f, i);
          continue;
        }
        switch(flip_inline(f, i, d, flipped, visited, out)) {
        case Inline::listed:
          continue;
        case Inline::over_budget:
          return;
        case Inline::flipped:
          // f was flipped: its edges are tested again (they are locally Delaunay unless a
          // later flip changed the faces across them).
          p0 = &f->vertex(0)->point();
          p1 = &f->vertex(1)->point();
          p2 = &f->vertex(2)->point();
          flipped = true;
          i = -1;
        }
      }
    }
    visited_total_.fetch_add(visited);
  }

private:
  enum class Inline { listed, flipped, over_budget };

  // Whether, after at least `sample` faces, the faces not ccw (`bad`, of all blocks) head
  // past `times` the limit (or are past it), scaled from the faces seen (this block's
  // `visited` and the blocks done).
  bool bad_faces_heading_past(std::size_t bad, std::size_t visited, double times, std::size_t sample) const
  {
    if(bad > max_bad_faces_)
      return true;
    const std::size_t seen = visited_total_.load(std::memory_order_relaxed) + visited;
    return seen >= sample && inverted_faces_heading_past(bad, seen, all_faces_, max_bad_faces_, times);
  }

  // The failing edge (f, i), d across it: flipped with the cascade it starts when the face
  // across is ccw too (then its quadrilateral is strictly convex, see lawson_flip()), listed
  // otherwise. A pass heading past the limit of faces not ccw ends in a rebuild: flips made on
  // the way would be wasted, so they stop while it heads past the limit itself.
  template <class Point>
  Inline flip_inline(Face_iterator f, int i, const Point& d, bool flipped, std::size_t visited, Block_lists& out)
  {
    using Gt = typename Triangulation::Geom_traits;
    auto orientation = gt_.orientation_2_object();
    inline_flips_->edges_failing += flipped ? 0 : 1; // found before a flip reached it
    if(orientation(d, f->vertex(cw(i))->point(), f->vertex(ccw(i))->point()) != LEFT_TURN ||
       (wants_bad_faces_ && bad_faces_heading_past(out.bad.size(), visited, 1., 4096))) {
      out.non_delaunay.emplace_back(f, i);
      return Inline::listed;
    }
    cascade_.assign(1, Edge(f, i));
    auto wants_flip = [&](Face_handle h, int k, const auto& a, const auto& b, const auto& c, const auto& e) {
      if(is_locally_delaunay(gt_, a, b, c, e))
        return false;
      if(orientation(e, c, b) == LEFT_TURN)
        return true;
      out.non_delaunay.emplace_back(h, k);
      return false;
    };
    auto log_flip = [&](Face_handle h, int k) { inline_flips_->log.emplace_back(h, k); };
    const std::size_t flips_before = inline_flips_->flips;
    if(!flip_edges_while<has_exact_double_predicates<Gt>::value>(tr_, cascade_, wants_flip, inline_flips_->max_flips,
                                                                 inline_flips_->flips, &inline_flips_->touched,
                                                                 log_flip)) {
      flip_budget_exhausted_ = true;
      return Inline::over_budget;
    }
    return inline_flips_->flips == flips_before ? Inline::listed : Inline::flipped;
  }

  Triangulation& tr_;
  const typename Triangulation::Geom_traits& gt_;
  typename Triangulation::Vertex_handle infinite_;
  std::size_t all_faces_;
  bool wants_bad_faces_;
  std::size_t max_bad_faces_;
  Inline_flips<Triangulation>* inline_flips_;
  std::vector<Edge> cascade_; // the inline flips' stack
  std::atomic<std::size_t> bad_total_{0}, visited_total_{0};
  std::atomic<bool> stop_{false};
  bool flip_budget_exhausted_ = false;
};

// Returns Outcome::ok if every finite face of `tr` (dimension 2) is counterclockwise, after listing
// in `non_delaunay` every interior edge that fails the perturbed in-circle test; otherwise
// returns why not. If `bad_faces` is given, the faces that are not counterclockwise go there
// instead, and the pass goes on (Outcome::ok is returned; `hull_is_convex` is then only meaningful
// if `bad_faces` stays empty), unless more than `max_bad_faces` are found, or the rule of
// inverted_faces_heading_past() gives up: then the pass stops at once and returns why.
// `hull_is_convex` tells whether the hull is a convex polygon wound once: then the argument of
// import_prediction.h (the TDS providing the twin pairing) shows that `tr` is a geometric
// triangulation of its vertices; if not, convexify_hull() may make it one.
// Reads only, unless `inline_flips` is given (sequentially only): then the failing edges
// between counterclockwise faces are flipped as they are found (see Inline_flips), and the
// call returns Outcome::flip_budget_exhausted when the budget runs out.
// With `parallel`, blocks of faces are certified on TBB's threads (Face_certifier): a 64th of
// the faces each, at least 32 and at most 16384, so that even small triangulations are cut
// into several blocks and the tests cross block boundaries. Compact_container has no random
// access: one sequential walk notes where each block starts (one word of each face).
template <class Triangulation, class Parallel = bool>
Outcome certify_faces(Triangulation& tr, std::vector<std::pair<typename Triangulation::Face_handle, int>>& non_delaunay,
                      std::size_t& edges_tested, bool& hull_is_convex,
                      std::vector<typename Triangulation::Face_handle>* bad_faces = nullptr,
                      std::size_t max_bad_faces = 0, Inline_flips<Triangulation>* inline_flips = nullptr,
                      Parallel parallel = false)
{
  using Certifier = Face_certifier<Triangulation>;
  using Face_iterator = typename Certifier::Face_iterator;
  CGAL_precondition(inline_flips == nullptr || !parallel);
  hull_is_convex = false;
  if(tr.dimension() < 2)
    return Outcome::dimension_below_2;
  auto& tds = tr.tds();
  Certifier certifier(tr, bad_faces != nullptr, max_bad_faces, inline_flips);
  std::vector<typename Triangulation::Face_handle> unused_bad;
  if(!may_run_in_parallel<Parallel>() || !parallel) {
    certifier.certify_block(tds.faces_begin(), tds.faces_end(),
                            {non_delaunay, bad_faces != nullptr ? *bad_faces : unused_bad, edges_tested});
  } else if constexpr(may_run_in_parallel<Parallel>()) {
    const std::size_t block_faces =
        (std::min)((std::max)(tds.number_of_faces() / 64, std::size_t(32)), std::size_t(16384));
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
      std::vector<std::pair<typename Triangulation::Face_handle, int>> non_delaunay;
      std::vector<typename Triangulation::Face_handle> bad;
      std::size_t edges_tested = 0;
    };
    std::vector<Found> found(blocks);
    for_each_block(true, blocks, [&](std::size_t b) {
      certifier.certify_block(starts[b], starts[b + 1], {found[b].non_delaunay, found[b].bad, found[b].edges_tested});
    });
    if(certifier.stopped() == Outcome::ok) {
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
    }
  }
  if(certifier.stopped() != Outcome::ok)
    return certifier.stopped();
  if(certifier.flips_outcome() != Outcome::ok)
    return certifier.flips_outcome();
  hull_is_convex = hull_is_convex_and_wound_once(tr);
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_TDS_CERTIFY_H
