// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// delaunay_from_prediction() on index triples stage by stage, on one thread and with
// CGAL::Parallel_tag in a TBB arena of --threads threads: what limits its parallel speed-up
// (the call split into the stages it runs one after the other). The stages are those of its
// default path, timed in one call by a visitor (Stage_timer, benchmark_util.h; DFP::Stage):
//   check    the points checked finite, the faces validated into 32-bit triples;
//   screen   the sampling screen, the failing edges estimated, the missing faces counted;
//   order    the spatial reordering of points and faces, with the copy of the points;
//   import   the import with its certificate (orientation, pairing, in-circle tests);
//   flips    Lawson's flips of the edges that failed;
// and a last column times another whole call, without a visitor, on a fresh triangulation;
// what it spends beyond the stages is the construction and swap of the result and the count of
// certified faces. Cases
// (1e6 uniform points by default):
//   shuffled  D = 0: the Delaunay faces in random order, each triple as CGAL lists it;
//   hilbert   D = 0: points Hilbert-sorted, faces in the order of CGAL's DT of them;
//   flips     CGAL's DT after 1% of n random flips, faces in random order.
// Times are medians of --reps repetitions, the two modes alternating; each result is checked
// against CGAL's build of the points.
//
// Usage: bench_import_stages [--n 1e6] [--reps 5] [--threads 2] [--cases shuffled,hilbert,flips]
//                            [--seed S]

#include "benchmark_util.h"

#include <CGAL/hilbert_sort.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

namespace {

constexpr int stage_count = 6;
const DFP::Stage stages[stage_count - 1] = {DFP::Stage::check, DFP::Stage::screen, DFP::Stage::order,
                                           DFP::Stage::import, DFP::Stage::flips};

// delaunay_from_prediction() with a Stage_timer: its stages' times into `seconds[0..4]`, the
// result in `dt`. False if the prediction does not take the default path (a screen or the
// import failed, holes to repair, points to insert).
bool run_stages(const std::vector<Point>& points, const std::vector<Face>& faces, DT& dt, bool parallel,
                double* seconds)
{
  Stage_timer timer;
  const auto np = DFP::parameters::visitor(std::ref(timer));
  if(parallel)
    DFP::delaunay_from_prediction<CGAL::Parallel_tag>(points, faces, dt, np);
  else
    DFP::delaunay_from_prediction(points, faces, dt, np);
  for(int k = 0; k < stage_count - 1; ++k)
    seconds[k] = timer.seconds(stages[k]);
  return !timer.saw(DFP::Stage::rebuild) && !timer.saw(DFP::Stage::carve) && !timer.saw(DFP::Stage::insert);
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t n = 1000000;
  int reps = 5, threads = 2;
  std::uint64_t seed = 20261203;
  std::vector<std::string> cases{"shuffled", "hilbert", "flips"};
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      n = std::size_t(std::atof(option_value(argc, argv, i).c_str()));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--threads")
      threads = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--cases")
      cases = split(option_value(argc, argv, i));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e6] [--reps 5] [--threads 2] [--cases shuffled,hilbert,flips] [--seed S]\n",
                  argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  for(const std::string& c : cases)
    if(c != "shuffled" && c != "hilbert" && c != "flips") {
      std::printf("unknown case %s\n", c.c_str());
      return 2;
    }
#ifndef CGAL_LINKED_WITH_TBB
  std::printf("bench_import_stages needs TBB\n");
  return 0;
#else
  const bool keep = keep_freed_memory();
  tbb::task_arena arena(threads);
  std::printf("# bench_import_stages, %s, %s, malloc policy %s, n = %zu uniform, %d threads, medians of %d\n",
              local_date_time().c_str(), build_description().c_str(), keep ? "keep" : "default", n, threads, reps);
  std::printf("%-9s %-10s |", "case", "mode");
  for(const DFP::Stage stage : stages)
    std::printf(" %9s", DFP::to_string(stage));
  std::printf(" %9s", "call");
  std::printf(" | %s\n", "check");
  const std::vector<Point> uniform = distribution_points("uniform", n, salted_seed(0x5354, seed, "uniform", n));
  bool all_ok = true;
  for(const std::string& kase : cases) {
    std::vector<Point> points = uniform;
    std::vector<Face> faces;
    Rng rng{salted_seed(0x494d, seed, kase, n)};
    if(kase == "hilbert") {
      CGAL::hilbert_sort(points.begin(), points.end());
      faces = export_faces(build_indexed(points));
    } else {
      DTI indexed = build_indexed(points);
      if(kase == "flips")
        random_flips(indexed, n / 100, rng);
      faces = export_faces(indexed);
      shuffle_faces(faces, rng);
    }
    Signature expected;
    time_cgal(points, expected);
    std::vector<double> seconds[2][stage_count];
    bool ok = true, staged = true; // staged: the default path ran to its end
    for(int r = 0; r < reps; ++r)
      for(int mode = 0; mode < 2; ++mode) {
        const bool parallel = mode == 1;
        double stage[stage_count] = {0, 0, 0, 0, 0, 0};
        Signature got;
        {
          DT dt;
          const bool ran = arena.execute([&] { return run_stages(points, faces, dt, parallel, stage); });
          staged = staged && ran;
          got = signature(dt);
          ok = ok && got == expected;
        }
        {
          DT dt;
          stage[5] = time_call(dt, [&] {
            arena.execute([&] {
              if(parallel)
                DFP::delaunay_from_prediction<CGAL::Parallel_tag>(points, faces, dt);
              else
                DFP::delaunay_from_prediction(points, faces, dt);
            });
          }, got);
          ok = ok && got == expected;
        }
        for(int k = 0; k < stage_count; ++k)
          seconds[mode][k].push_back(stage[k]);
      }
    all_ok = all_ok && ok;
    print_stage_rows(kase, seconds[0], seconds[1], stage_count, staged,
                     std::string(ok ? "ok" : "DIFFERENT") + (staged ? "" : " (the call left the default path)"));
  }
  std::printf("(seconds, medians; check + screen + order + import + flips are the stages of one call, timed\n"
              " by a visitor; call: another whole delaunay_from_prediction() on a fresh triangulation)\n");
  return all_ok ? 0 : 1;
#endif
}
