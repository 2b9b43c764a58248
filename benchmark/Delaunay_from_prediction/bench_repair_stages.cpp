// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// make_delaunay()'s local repair stage by stage, on one thread and with CGAL::Parallel_tag in
// a TBB arena of --threads threads: what limits its parallel speed-up (an ablation of the
// call into the stages it runs one after the other). The input is CGAL's Delaunay
// triangulation of uniform points with every vertex moved by Gaussian noise of scale
// sigma x mean spacing (the kinetic case of bench_delaunay_from_prediction). The stages are
// called as make_delaunay() calls them on its carve path:
//   certify   the certification pass (sequential: certify_triangulation() without its
//             inline flips; parallel: certify_faces_in_blocks(), and the hull test);
//   untangle  the flips that undo a vertex crossing an edge (parallel: in cells);
//   carve     carving, hole filling and reinsertion (carve_and_reinsert()), and the hull made
//             convex again (convexify_hull()); one thread in both modes;
//   flips     Lawson's flips (parallel: in cells, lawson_flip_in_cells()).
// A last column times the whole make_delaunay() call of each mode on a fresh copy (alone where
// the damage is past the local repair's limits and the call rebuilds). Times are
// medians of --reps repetitions, the two modes alternating; each result is checked against
// CGAL's build of the moved points.
//
// Usage: bench_repair_stages [--n 1e6] [--reps 5] [--threads 2] [--sigmas 0.01,0.1] [--seed S]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/internal/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/tds_certify.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

namespace {

constexpr int stage_count = 5; // certify, untangle, carve, flips, whole call
const char* const stage_names[stage_count] = {"certify", "untangle", "carve", "flips", "call"};

// The stages of make_delaunay's carve path on `tr`, timed into `seconds[0..3]`. False if the
// input does not take that path (no face inverted, or the carve gave up).
bool run_stages(DTI& tr, bool parallel, double* seconds, std::size_t& not_ccw)
{
  namespace internal = DFP::internal;
  using Face_handle = DTI::Face_handle;
  const std::size_t n = tr.number_of_vertices();
  std::vector<std::pair<Face_handle, int>> stack;
  std::vector<Face_handle> bad, touched;
  std::size_t tested = 0, flips = 0;
  bool hull_is_convex = false;
  const std::size_t max_bad = internal::default_carve_limits(n).max_bad_faces;
  CGAL::Real_timer clock;
  clock.start();
  double last = 0;
  auto lap = [&](int stage) {
    const double now = clock.time();
    seconds[stage] = now - last;
    last = now;
  };
  internal::Outcome why;
  if(parallel) {
    why = internal::certify_faces_in_blocks(tr, stack, tested, &bad, max_bad);
    hull_is_convex = why == internal::Outcome::ok && internal::hull_is_convex_and_wound_once(tr);
  } else {
    why = internal::certify_triangulation(tr, stack, tested, hull_is_convex, &bad, max_bad);
  }
  lap(0);
  not_ccw = bad.size();
  if(why != internal::Outcome::ok || bad.empty())
    return false;
  internal::Flip_log<DTI> log;
  internal::untangle_by_flips(tr, bad, stack, log, touched, parallel);
  lap(1);
  DFP::Statistics stats;
  internal::Carve_repair<DTI> carve(tr, true);
  std::vector<const void*> modified;
  if(!bad.empty() && internal::carve_and_reinsert(carve, tr, bad, stack, log, modified, stats) != internal::Outcome::ok)
    return false;
  std::vector<const void*> hull_faces;
  if(!hull_is_convex && !internal::convexify_hull(tr, stack, hull_faces, flips))
    return false;
  lap(2);
  const bool flipped = internal::lawson_flip(tr, stack, std::size_t(-1), flips, touched, parallel);
  lap(3);
  return flipped;
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t n = 1000000;
  int reps = 5, threads = 2;
  std::uint64_t seed = 20261203;
  std::vector<double> sigmas{0.01, 0.1};
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      n = std::size_t(std::atof(option_value(argc, argv, i).c_str()));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--threads")
      threads = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--sigmas") {
      sigmas.clear();
      for(const std::string& s : split(option_value(argc, argv, i)))
        sigmas.push_back(std::atof(s.c_str()));
    } else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e6] [--reps 5] [--threads 2] [--sigmas 0.01,0.1] [--seed S]\n", argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
#ifndef CGAL_LINKED_WITH_TBB
  std::printf("bench_repair_stages needs TBB\n");
  return 0;
#else
  const bool keep = keep_freed_memory();
  tbb::task_arena arena(threads);
  std::printf("# bench_repair_stages, %s, %s, malloc policy %s, n = %zu uniform, Gaussian moves, %d threads, "
              "medians of %d\n",
              local_date_time().c_str(), build_description().c_str(), keep ? "keep" : "default", n, threads, reps);
  std::printf("%-9s %-10s |", "sigma", "mode");
  for(const char* name : stage_names)
    std::printf(" %9s", name);
  std::printf(" | %s\n", "check");
  const std::vector<Point> points = distribution_points("uniform", n, salted_seed(0x5354, seed, "uniform", n));
  const DTI base = build_indexed(points);
  bool all_ok = true;
  for(const double sigma : sigmas) {
    const std::vector<Point> moved_points =
        noisy_points(points, "gaussian", sigma * mean_spacing(points), salted_seed(0x4d4f, seed, "moves", n));
    DTI moved = base;
    for(auto v = moved.finite_vertices_begin(); v != moved.finite_vertices_end(); ++v)
      v->set_point(moved_points[v->info()]);
    Signature expected;
    time_cgal(moved_points, expected);
    std::vector<double> seconds[2][stage_count];
    bool ok = true, local = true; // local: the stages ran (else make_delaunay rebuilds)
    std::size_t not_ccw = 0;       // faces found not counterclockwise by the certification
    for(int r = 0; r < reps; ++r)
      for(int mode = 0; mode < 2; ++mode) {
        const bool parallel = mode == 1;
        double stage[stage_count] = {0, 0, 0, 0, 0};
        Signature got;
        {
          DTI tr = moved; // untimed copy
          const bool ran = arena.execute([&] { return run_stages(tr, parallel, stage, not_ccw); });
          local = local && ran;
          got = signature(tr);
          ok = ok && (!ran || got == expected);
        }
        {
          DTI tr = moved;
          stage[4] = time_call(tr, [&] {
            arena.execute([&] {
              if(parallel)
                DFP::make_delaunay<CGAL::Parallel_tag>(tr);
              else
                DFP::make_delaunay(tr);
            });
          }, got);
          ok = ok && got == expected;
        }
        for(int k = 0; k < stage_count; ++k)
          seconds[mode][k].push_back(stage[k]);
      }
    all_ok = all_ok && ok;
    char label[32];
    std::snprintf(label, sizeof label, "%g", sigma);
    const std::string check = !ok      ? "DIFFERENT"
                              : local ? "ok, " + std::to_string(not_ccw) + " faces not ccw"
                                      : "ok (no local repair: the call rebuilds)";
    print_stage_rows(label, seconds[0], seconds[1], stage_count, local, check);
  }
  std::printf("(seconds, medians; certify + untangle + carve + flips are the stages called one by one, call\n"
              " the whole make_delaunay() on a fresh copy: sequentially it flips during certification, so\n"
              " its stages overlap; the carve runs on one thread in both modes)\n");
  return all_ok ? 0 : 1;
#endif
}
