// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// make_delaunay()'s local repair stage by stage, on one thread and with CGAL::Parallel_tag in
// a TBB arena of --threads threads: what limits its parallel speed-up (the call split into
// the stages it runs one after the other). The input is CGAL's Delaunay triangulation of
// uniform points with every vertex moved by Gaussian noise of scale sigma x mean spacing (the
// kinetic case of bench_delaunay_from_prediction). The stages are those of its carve path,
// timed in one call by a visitor (Stage_timer, benchmark_util.h; DFP::Stage):
//   certify   the certification pass (sequential: with Lawson's flips of the failing edges
//             found as it goes; parallel: in blocks, and the hull test);
//   untangle  the flips that undo a vertex crossing an edge (parallel: in cells);
//   carve     carving, hole filling and reinsertion; one thread in both modes;
//   flips     Lawson's flips (parallel: in cells).
// A last column times another whole make_delaunay() call of each mode, without a visitor, on a
// fresh copy (alone where the damage is past the local repair's limits and the call
// rebuilds). Times are
// medians of --reps repetitions, the two modes alternating; each result is checked against
// CGAL's build of the moved points.
//
// Usage: bench_repair_stages [--n 1e6] [--reps 5] [--threads 2] [--sigmas 0.01,0.1] [--seed S]

#include "benchmark_util.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

namespace {

constexpr int stage_count = 5; // certify, untangle, carve, flips, whole call
const DFP::Stage stages[stage_count - 1] = {DFP::Stage::certify, DFP::Stage::untangle, DFP::Stage::carve,
                                           DFP::Stage::flips};

// make_delaunay() on `tr` with a Stage_timer: its stages' times into `seconds[0..3]`, the faces
// it carved in `carved`. False if the input does not take the carve path (no face left
// inverted after the untangling, or the call rebuilt).
bool run_stages(DTI& tr, bool parallel, double* seconds, std::size_t& carved)
{
  Stage_timer timer;
  const auto np = DFP::parameters::visitor(std::ref(timer));
  const DFP::Statistics stats =
      parallel ? DFP::make_delaunay<CGAL::Parallel_tag>(tr, np) : DFP::make_delaunay(tr, np);
  for(int k = 0; k < stage_count - 1; ++k)
    seconds[k] = timer.seconds(stages[k]);
  carved = stats.faces_carved;
  return timer.saw(DFP::Stage::carve) && !timer.saw(DFP::Stage::rebuild);
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
  for(const DFP::Stage stage : stages)
    std::printf(" %9s", DFP::to_string(stage));
  std::printf(" %9s", "call");
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
    bool ok = true, local = true; // local: the carve ran (else make_delaunay rebuilds, or only flips)
    std::size_t carved = 0;        // faces carved
    for(int r = 0; r < reps; ++r)
      for(int mode = 0; mode < 2; ++mode) {
        const bool parallel = mode == 1;
        double stage[stage_count] = {0, 0, 0, 0, 0};
        Signature got;
        {
          DTI tr = moved; // untimed copy
          const bool ran = arena.execute([&] { return run_stages(tr, parallel, stage, carved); });
          local = local && ran;
          got = signature(tr);
          ok = ok && got == expected;
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
                              : local ? "ok, " + std::to_string(carved) + " faces carved"
                                      : "ok (no carve: the call rebuilds, or untangles and flips)";
    print_stage_rows(label, seconds[0], seconds[1], stage_count, local, check);
  }
  std::printf("(seconds, medians; certify + untangle + carve + flips are the stages of one call, timed by a\n"
              " visitor (sequentially, certify includes the flips made as it goes); call: another whole\n"
              " make_delaunay() on a fresh copy; the carve runs on one thread in both modes)\n");
  return all_ok ? 0 : 1;
#endif
}
