// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Named parameters (Epick): max_flips(n) is an exact budget (a prediction needing f flips
// succeeds with max_flips(f) and falls back with max_flips(f - 1), the result exact either
// way), max_flips(0) forces a fallback, for delaunay_from_prediction() and make_delaunay();
// screen_prediction(bool): good predictions pass the sampling screen at n >= 4096, random
// triples at n >= 5000 are rejected by it, and fall back without it with strategy(flips) (the
// default strategy may repair them locally instead); chaining with CGAL's parameters, and the
// package's chained as CGAL's are (`max_flips(0).strategy(s)`); visitor(v): every stage seen
// in begin/end pairs, in the pipeline's order; tuning(t): its thresholds are read;
// strategy<S>() (a strategy known at compile time): the strategies each form of the parameter
// compiles, and the same result and statistics as strategy(S), alone and chained.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <functional>
#include <list>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Points = std::vector<Point>;
using DT = DT_with_info<K>;
namespace NP = CGAL::Delaunay_from_prediction::parameters;

template <class FaceRange, class Parameters>
DFP::Statistics run(const Points& points, const FaceRange& faces, const Faces& as_indices,
                    const Parameters& np)
{
  DT dt;
  const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt, np);
  check_is_cgal_delaunay(dt, points);
  check_statistics(s, as_indices, points, dt);
  return s;
}

template <class Parameters>
DFP::Statistics run(const Points& points, const Faces& faces, const Parameters& np)
{
  return run(points, faces, faces, np);
}

void test_max_flips(CGAL::Random& rng)
{
  const Points points = to_points<K>(uniform_points(2000, rng));
  const Faces faces = flipped_delaunay_faces<K>(points, 40, rng);
  const std::size_t needed = [&] {
    Scope s("unlimited budget");
    const DFP::Statistics st = run(points, faces, NP::max_flips(std::size_t(-1)));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.flips > 0);
    DFP_CHECK(st.flips >= edges_not_in_delaunay<K>(faces, points));
    return st.flips;
  }();
  {
    Scope s("max_flips(0)");
    const DFP::Statistics st = run(points, faces, NP::max_flips(0));
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips == 0);
    DFP_CHECK(st.outcome != DFP::Outcome::ok);
    DFP_CHECK(st.faces_certified == 0);
  }
  {
    Scope s("max_flips(needed) (int)");
    const DFP::Statistics st = run(points, faces, NP::max_flips(int(needed)));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.flips == needed);
  }
  {
    Scope s("max_flips(needed - 1)");
    const DFP::Statistics st = run(points, faces, NP::max_flips(needed - 1));
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips <= needed - 1);
  }
  {
    Scope s("max_flips(0) on the DT itself: no flip needed, no fallback");
    const DFP::Statistics st = run(points, delaunay_faces<K>(points), NP::max_flips(0));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.faces_certified == st.faces_in);
  }
  {
    Scope s("max_flips(0, CGAL::parameters::verbose(false))");
    const DFP::Statistics st = run(points, faces, NP::max_flips(0, CGAL::parameters::verbose(false)));
    DFP_CHECK(st.fell_back);
  }
  {
    Scope s("max_flips(needed).verbose(false)");
    const DFP::Statistics st = run(points, faces, NP::max_flips(needed).verbose(false));
    DFP_CHECK(!st.fell_back);
  }
  // The chained form, as CGAL's own parameters chain: each value is read wherever it stands.
  {
    Scope s("max_flips(0).screen_prediction(false)");
    const DFP::Statistics st = run(points, faces, NP::max_flips(0).screen_prediction(false));
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips == 0);
  }
  {
    Scope s("screen_prediction(true).max_flips(needed - 1).strategy(Strategy::flips)");
    const DFP::Statistics st =
        run(points, faces, NP::screen_prediction(true).max_flips(needed - 1).strategy(DFP::Strategy::flips));
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips <= needed - 1);
  }
  {
    Scope s("strategy(Strategy::flips).max_flips(needed)");
    const DFP::Statistics st = run(points, faces, NP::strategy(DFP::Strategy::flips).max_flips(needed));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.flips == needed);
  }
  {
    Scope s("max_flips(needed, CGAL::parameters::verbose(false)).strategy(Strategy::rebuild)");
    const DFP::Statistics st =
        run(points, faces, NP::max_flips(needed, CGAL::parameters::verbose(false)).strategy(DFP::Strategy::rebuild));
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips == 0);
  }
  {
    Scope s("screen_prediction(false, max_flips(0))");
    const DFP::Statistics st = run(points, faces, NP::screen_prediction(false, NP::max_flips(0)));
    DFP_CHECK(st.fell_back);
  }
  {
    Scope s("max_flips(needed, screen_prediction(true))");
    const DFP::Statistics st = run(points, faces, NP::max_flips(needed, NP::screen_prediction(true)));
    DFP_CHECK(!st.fell_back);
  }
}

void test_make_delaunay_budget(CGAL::Random& rng)
{
  const Points points = to_points<K>(uniform_points(1000, rng));
  auto prepare = [&](DT& tr, Handles<DT>& handles) {
    build(tr, points, handles);
    flip_randomly(tr, 30, rng);
  };
  {
    Scope s("make_delaunay, unlimited budget");
    DT tr;
    Handles<DT> handles;
    prepare(tr, handles);
    const DFP::Statistics st = DFP::make_delaunay(tr, NP::max_flips(std::size_t(-1)));
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.flips > 0);
  }
  {
    Scope s("make_delaunay, max_flips(0) on a non-Delaunay triangulation");
    DT tr;
    Handles<DT> handles;
    build(tr, points, handles);
    DFP_CHECK(flip_randomly(tr, 10, rng) == 10);
    const DFP::Statistics st = DFP::make_delaunay(tr, NP::max_flips(0, CGAL::parameters::verbose(false)));
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
    DFP_CHECK(st.fell_back);
    DFP_CHECK(st.flips == 0);
  }
  {
    Scope s("make_delaunay, max_flips(0) on a Delaunay triangulation");
    DT tr;
    Handles<DT> handles;
    build(tr, points, handles);
    const DFP::Statistics st = DFP::make_delaunay(tr, NP::max_flips(0));
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
    DFP_CHECK(!st.fell_back);
  }
}

// The exact budget boundary for make_delaunay. The number of flips Lawson's algorithm makes
// can depend on the order in which edges are tested, and that order on where the faces lie in
// memory, which differs between two triangulations built alike. So the prediction is one where
// the count cannot depend on the order: a jittered grid (jitter 0.05, no four points
// co-circular) with the Delaunay diagonal of 25 unit squares flipped. The wrong diagonal's
// triangles have circumcircles of radius about 0.71 around the square's centre, the other
// neighbours' points are at least about 1.5 away, so each wrong diagonal is the only edge that
// fails around it and one flip fixes it: exactly 25 flips, whatever the order.
void test_make_delaunay_boundary()
{
  CGAL::Random rng(123);
  const int side = 30;
  XYs xy;
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j)
      xy.push_back({double(i), double(j)});
  const Points points = to_points<K>(jittered(xy, 0.05, rng));
  auto flipped = [&](DT& tr, Handles<DT>& handles) {
    build(tr, points, handles);
    std::size_t done = 0;
    for(int i = 1; i + 1 < side && done < 25; i += 4)
      for(int j = 1; j + 1 < side && done < 25; j += 4) {
        auto at = [&](int a, int b) { return handles[std::size_t(a * side + b)]; };
        DT::Face_handle f;
        int k;
        if(tr.is_edge(at(i, j), at(i + 1, j + 1), f, k) || tr.is_edge(at(i + 1, j), at(i, j + 1), f, k)) {
          tr.tds().flip(f, k);
          ++done;
        }
      }
    return done;
  };
  for(std::size_t budget : {std::size_t(25), std::size_t(24)}) {
    Scope s("make_delaunay, max_flips(", budget, "), 25 flips needed");
    DT tr;
    Handles<DT> handles;
    DFP_CHECK(flipped(tr, handles) == 25);
    const DFP::Statistics st = DFP::make_delaunay(tr, NP::max_flips(budget));
    DFP_CHECK(st.fell_back == (budget < 25));
    if(!st.fell_back)
      DFP_CHECK(st.flips == 25);
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
  }
}

void test_screen(CGAL::Random& rng)
{
  const std::size_t n = 5000;
  const XYs xy = uniform_points(n, rng);
  const Points points = to_points<K>(xy);
  const Faces dt_faces = delaunay_faces<K>(points);
  for(bool screen : {true, false}) {
    Scope s("screen_prediction(", screen, "), n = ", n);
    {
      Scope c("the DT itself");
      const DFP::Statistics st = run(points, shuffled(dt_faces, rng), NP::screen_prediction(screen));
      DFP_CHECK(!st.fell_back);
      DFP_CHECK(st.faces_certified == st.faces_in);
    }
    {
      Scope c("the DT after n/100 flips");
      const DFP::Statistics st =
          run(points, flipped_delaunay_faces<K>(points, n / 100, rng), NP::screen_prediction(screen));
      DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
      DFP_CHECK(st.flips > 0);
    }
    {
      Scope c("the DT of a subset (half the points)");
      const DFP::Statistics st =
          run(points, delaunay_faces<K>(Points(points.begin(), points.begin() + n / 2)),
              NP::screen_prediction(screen));
      DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
    }
    // With the local repair (the default strategy), random triples may be repaired rather
    // than rebuilt if the budgets allow it; with strategy(flips) they always fall back.
    {
      Scope c("random triples");
      const Faces triples = random_triples(n, 2 * n, rng);
      const DFP::Statistics st =
          run(points, triples, NP::strategy(DFP::Strategy::flips, NP::screen_prediction(screen)));
      DFP_CHECK(st.fell_back);
      if(screen)
        DFP_CHECK_MSG(reason_is(st, DFP::Outcome::screen_rejected),
                      to_string(st.outcome));
      const DFP::Statistics automatic = run(points, triples, NP::screen_prediction(screen));
      DFP_CHECK(repaired_or_rebuilt(automatic));
      if(screen)
        DFP_CHECK(automatic.fell_back);
    }
    {
      Scope c("random triples in a std::list (no random access)");
      const Faces triples = random_triples(n, 2 * n, rng);
      const std::list<Face> faces(triples.begin(), triples.end());
      const DFP::Statistics st =
          run(points, faces, triples, NP::strategy(DFP::Strategy::flips, NP::screen_prediction(screen)));
      DFP_CHECK(st.fell_back);
      // The screen draws from the faces once they are read, whatever the range.
      if(screen)
        DFP_CHECK_MSG(reason_is(st, DFP::Outcome::screen_rejected), to_string(st.outcome));
      const DFP::Statistics automatic = run(points, faces, triples, NP::screen_prediction(screen));
      DFP_CHECK(repaired_or_rebuilt(automatic));
    }
  }
  {
    Scope s("default parameters, random triples, n = ", n);
    const Faces triples = random_triples(n, 2 * n, rng);
    DT dt;
    const DFP::Statistics st = DFP::delaunay_from_prediction(points, triples, dt);
    check_is_cgal_delaunay(dt, points);
    check_statistics(st, triples, points, dt);
    // The screen (on by default) rejects random triples before any repair is tried.
    DFP_CHECK(st.fell_back);
    DFP_CHECK_MSG(reason_is(st, DFP::Outcome::screen_rejected),
                  to_string(st.outcome));
  }
  {
    Scope s("integer grid 70 x 70 (co-circular: on-circle points are not inside), screen on");
    const Points grid = to_points<K>(grid_points(70, 70, rng));
    const DFP::Statistics st = run(grid, delaunay_faces<K>(grid), NP::screen_prediction(true));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.faces_certified == st.faces_in);
  }
}

// A visitor that records each stage_begin (true) and stage_end (false), in order.
struct Stage_recorder
{
  std::vector<std::pair<bool, DFP::Stage>> events;
  void stage_begin(DFP::Stage s) { events.emplace_back(true, s); }
  void stage_end(DFP::Stage s) { events.emplace_back(false, s); }
};

std::string stage_names(const std::vector<DFP::Stage>& stages)
{
  std::string names;
  for(const DFP::Stage s : stages)
    names += std::string(names.empty() ? "" : " ") + DFP::to_string(s);
  return names;
}

// The stages `r` saw, checked to begin and end in matching pairs, one after the other.
std::vector<DFP::Stage> paired_stages(const Stage_recorder& r)
{
  std::vector<DFP::Stage> stages;
  DFP_CHECK_MSG(r.events.size() % 2 == 0, r.events.size() << " events");
  for(std::size_t k = 0; k < r.events.size(); ++k) {
    DFP_CHECK_MSG(r.events[k].first == (k % 2 == 0), "event " << k << " " << DFP::to_string(r.events[k].second));
    if(k % 2 == 0)
      stages.push_back(r.events[k].second);
    else
      DFP_CHECK_MSG(r.events[k].second == stages.back(), "stage_end(" << DFP::to_string(r.events[k].second)
                                                                      << ") after stage_begin(" << DFP::to_string(stages.back()) << ")");
  }
  return stages;
}

// A visitor sees every stage begin and end in pairs, in the order the pipeline runs them, for
// both entry points, sequential and parallel: a correct prediction (no rebuild), one that falls
// back (rebuild), make_delaunay with inverted faces (untangled, carved). Both entry points run
// the same driver: the screens come before the import or the certification in place.
void test_visitor(CGAL::Random& rng)
{
  using S = DFP::Stage;
  using Stages = std::vector<S>;
  const Points points = to_points<K>(uniform_points(2000, rng));
  const Faces delaunay = faces_by_info(indexed_delaunay<K>(points));
  const Faces flipped = flipped_delaunay_faces<K>(points, 40, rng);
  auto expect = [](const Stage_recorder& r, const Stages& expected) {
    const Stages got = paired_stages(r);
    DFP_CHECK_MSG(got == expected, "saw: " << stage_names(got) << "; expected: " << stage_names(expected));
  };
  for_each_concurrency([&] {
    auto dfp = [&](const Faces& faces, const auto& np) {
      DT dt;
      Stage_recorder r;
      const DFP::Statistics st = with_concurrency([&](auto tag) {
        return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt, np.visitor(std::ref(r)));
      });
      check_is_cgal_delaunay(dt, points);
      return std::make_pair(st, r);
    };
    {
      Scope s("delaunay_from_prediction, Delaunay faces");
      const auto [st, r] = dfp(delaunay, NP::max_flips(std::size_t(-1)));
      DFP_CHECK(!st.fell_back);
      expect(r, {S::check, S::screen, S::order, S::import, S::flips});
    }
    {
      Scope s("delaunay_from_prediction, max_flips(0): falls back");
      const auto [st, r] = dfp(flipped, NP::max_flips(0));
      DFP_CHECK(st.fell_back);
      expect(r, {S::check, S::screen, S::order, S::import, S::rebuild});
    }
    auto md = [&](DT& tr, const auto& np) {
      Stage_recorder r;
      const DFP::Statistics st =
          with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr, np.visitor(std::ref(r))); });
      return std::make_pair(st, r);
    };
    {
      Scope s("make_delaunay, 20 random flips");
      DT tr;
      Handles<DT> handles;
      build(tr, points, handles);
      flip_randomly(tr, 20, rng);
      const auto [st, r] = md(tr, NP::max_flips(std::size_t(-1)));
      check_is_cgal_delaunay(tr, points);
      DFP_CHECK(!st.fell_back);
      expect(r, {S::check, S::screen, S::certify, S::flips});
    }
    {
      Scope s("make_delaunay, max_flips(0) after 20 flips: falls back");
      DT tr;
      Handles<DT> handles;
      build(tr, points, handles);
      flip_randomly(tr, 20, rng);
      const auto [st, r] = md(tr, NP::max_flips(0));
      check_is_cgal_delaunay(tr, points);
      DFP_CHECK(st.fell_back);
      expect(r, {S::check, S::screen, S::certify, S::rebuild});
    }
    {
      Scope s("make_delaunay, 8 vertices moved by 3 mean spacings: inverted faces");
      DT tr;
      Handles<DT> handles;
      build(tr, points, handles);
      Points moved = points;
      for(std::size_t k = 0; k < 8; ++k) {
        const std::size_t i = std::size_t(rng.get_int(0, int(points.size())));
        moved[i] = Point(points[i].x() + rng.get_double(-0.06, 0.06), points[i].y() + rng.get_double(-0.06, 0.06));
        handles[i]->set_point(moved[i]);
      }
      const auto [st, r] = md(tr, NP::strategy(DFP::Strategy::carve));
      check_is_cgal_delaunay(tr, moved);
      DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
      const Stages got = paired_stages(r);
      DFP_CHECK_MSG(got == Stages({S::check, S::screen, S::certify, S::untangle, S::carve, S::flips}) ||
                        got == Stages({S::check, S::screen, S::certify, S::untangle, S::flips}),
                    stage_names(got));
      DFP_CHECK_MSG(st.faces_carved == 0 || got.size() == 6, stage_names(got) << ", " << st.faces_carved << " carved");
    }
  });
  {
    Scope s("a visitor given by value is copied");
    Stage_recorder r;
    DT dt;
    DFP::delaunay_from_prediction(points, delaunay, dt, NP::visitor(r));
    DFP_CHECK(r.events.empty());
  }
}

// The tuning parameter is read: Tuning::t_division_budget_factor decides whether the
// t-division divides (Statistics::regions), Tuning::min_points_per_block and
// min_threads_for_blocks whether a parallel rebuild is made by regions (the vertices come out
// block by block, another order than the sequential build's).
void test_tuning(CGAL::Random& rng)
{
  const Points points = to_points<K>(uniform_points(3000, rng));
  {
    Scope s("t_division_budget_factor");
    auto regions_with = [&](double factor) {
      DT tr;
      Handles<DT> handles;
      build(tr, points, handles);
      DFP::Tuning t;
      t.t_division_budget_factor = factor;
      CGAL::Random same(5);
      flip_randomly(tr, 30, same);
      const DFP::Statistics st = DFP::make_delaunay(tr, NP::strategy(DFP::Strategy::t_division).tuning(t));
      check_is_cgal_delaunay(tr, points);
      return st.regions;
    };
    DFP_CHECK(regions_with(0) == 0);
    DFP_CHECK(regions_with(1e9) > 0);
  }
  const Faces triples = random_triples(points.size(), 2 * points.size(), rng);
  DFP::Tuning blocks, no_blocks;
  blocks.min_points_per_block = 200;
  blocks.min_threads_for_blocks = 2;
  no_blocks.min_threads_for_blocks = 1000;
  for_each_concurrency([&] {
    auto vertex_order = [&](const DFP::Tuning& t) {
      DT dt;
      const DFP::Statistics st = with_concurrency([&](auto tag) {
        return DFP::delaunay_from_prediction<decltype(tag)>(points, triples, dt, NP::tuning(t));
      });
      DFP_CHECK(st.fell_back);
      check_is_cgal_delaunay(dt, points);
      std::vector<std::size_t> order;
      for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        order.push_back(v->info());
      return order;
    };
    const bool by_regions = current_concurrency() == Concurrency::parallel_2_threads;
#ifdef CGAL_LINKED_WITH_TBB
    DFP_CHECK((vertex_order(blocks) != vertex_order(no_blocks)) == by_regions);
#else
    (void)by_regions;
    DFP_CHECK(vertex_order(blocks) == vertex_order(no_blocks));
#endif
  });
}

// What each form of the named parameter `strategy` compiles (Compiled_paths), and strategy<S>()
// against strategy(S): the same triangulation (CGAL's) and the same statistics, for both
// entry points, alone and chained.
template <DFP::Strategy S>
void check_strategy_known_at_compile_time(const Points& points, const Faces& faces, CGAL::Random& rng)
{
  namespace I = DFP::internal;
  static_assert(I::strategies_compiled<decltype(NP::strategy<S>())>() == I::strategy_bit(S));
  static_assert(I::strategies_compiled<decltype(NP::max_flips(10).template strategy<S>())>() == I::strategy_bit(S));
  Scope s(std::string("strategy ") + std::to_string(int(S)));
  auto same = [](const DFP::Statistics& a, const DFP::Statistics& b) {
    DFP_CHECK_MSG(a.outcome == b.outcome && a.fell_back == b.fell_back && a.flips == b.flips &&
                      a.faces_certified == b.faces_certified && a.points_reinserted == b.points_reinserted,
                  to_string(a.outcome) << " / " << to_string(b.outcome) << ", flips " << a.flips << " / " << b.flips);
  };
  {
    DT known, given;
    const DFP::Statistics a = DFP::delaunay_from_prediction(points, faces, known, NP::strategy<S>());
    const DFP::Statistics b = DFP::delaunay_from_prediction(points, faces, given, NP::strategy(S));
    check_is_cgal_delaunay(known, points);
    same(a, b);
    DT chained;
    const DFP::Statistics c = DFP::delaunay_from_prediction(
        points, faces, chained, NP::strategy<S>(CGAL::parameters::verbose(false)).max_flips(std::size_t(-1)));
    check_is_cgal_delaunay(chained, points);
    const DFP::Statistics d = DFP::delaunay_from_prediction(
        points, faces, given, NP::max_flips(std::size_t(-1)).strategy(S));
    same(c, d);
  }
  {
    Points moved = points;
    DT known, given;
    Handles<DT> known_handles, given_handles;
    build(known, points, known_handles);
    build(given, points, given_handles);
    for(std::size_t i = 0; i < moved.size(); i += 7) {
      moved[i] = Point(points[i].x() + rng.get_double(-0.01, 0.01), points[i].y() + rng.get_double(-0.01, 0.01));
      known_handles[i]->set_point(moved[i]);
      given_handles[i]->set_point(moved[i]);
    }
    const DFP::Statistics a = DFP::make_delaunay(known, NP::strategy<S>());
    const DFP::Statistics b = DFP::make_delaunay(given, NP::strategy(S));
    check_is_cgal_delaunay(known, moved);
    check_is_cgal_delaunay(given, moved);
    // The order of the repair's work follows the face objects' addresses, which differ between
    // the two triangulations: the flips counted may differ, not the outcome.
    DFP_CHECK_MSG(a.outcome == b.outcome && a.fell_back == b.fell_back,
                  to_string(a.outcome) << " / " << to_string(b.outcome));
  }
}

void test_strategy_known_at_compile_time(CGAL::Random& rng)
{
  namespace I = DFP::internal;
  using Default = DFP::parameters::Default_named_parameters;
  static_assert(I::strategies_compiled<Default>() == I::strategy_bit(DFP::Strategy::automatic));
  static_assert(I::strategies_compiled<decltype(NP::max_flips(10))>() == I::strategy_bit(DFP::Strategy::automatic));
  static_assert(I::strategies_compiled<decltype(NP::strategy(DFP::Strategy::flips))>() == ~std::uint32_t(0));
  static_assert(I::strategies_compiled<decltype(NP::max_flips(10).strategy(DFP::Strategy::flips))>() ==
                ~std::uint32_t(0));
  static_assert(std::is_convertible<DFP::Strategy_constant<DFP::Strategy::section_3>, DFP::Strategy>::value);
  const Points points = to_points<K>(uniform_points(1500, rng));
  const Faces faces = flipped_delaunay_faces<K>(points, 30, rng);
  using St = DFP::Strategy;
  check_strategy_known_at_compile_time<St::automatic>(points, faces, rng);
  check_strategy_known_at_compile_time<St::flips>(points, faces, rng);
  check_strategy_known_at_compile_time<St::carve>(points, faces, rng);
  check_strategy_known_at_compile_time<St::t_division>(points, faces, rng);
  check_strategy_known_at_compile_time<St::regions>(points, faces, rng);
  check_strategy_known_at_compile_time<St::rebuild>(points, faces, rng);
  check_strategy_known_at_compile_time<St::spanning_tree>(points, faces, rng);
  check_strategy_known_at_compile_time<St::section_3>(points, faces, rng);
  check_strategy_known_at_compile_time<St::theorem_4_1>(points, faces, rng);
  check_strategy_known_at_compile_time<St::theorem_5_4>(points, faces, rng);
}

int main()
{
  CGAL::Random rng(8080);
  DFP_RUN(test_strategy_known_at_compile_time(rng));
  DFP_RUN(test_visitor(rng));
  DFP_RUN(test_tuning(rng));
  DFP_RUN(test_max_flips(rng));
  DFP_RUN(test_make_delaunay_budget(rng));
  DFP_RUN(test_make_delaunay_boundary());
  DFP_RUN(test_screen(rng));
  return finish("test_named_parameters");
}
