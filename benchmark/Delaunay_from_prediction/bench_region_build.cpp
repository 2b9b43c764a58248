// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The region-parallel build (internal/build/block_parallel_build.h) against the package's sequential
// build from scratch and CGAL's range insert, in the same run, for 2, 4 and 8 blocks in a TBB
// arena of --threads threads; also the seams' share (points triangulated again) and the walls
// that failed the in-circle test. These times decide from how many threads the entry points
// build by regions (DFP::Tuning::min_threads_for_blocks, min_points_per_block). (The time of
// each of the region build's own steps, split, blocks, seams and join, is no longer reported:
// they are steps inside Stage::rebuild, not stages a visitor sees.) Times are medians of --reps repetitions, the
// calls alternating; every result is checked against CGAL's (face set signature).
//
// Usage: bench_region_build [--n 1e6] [--reps 5] [--threads 2] [--seed S]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

int main(int argc, char** argv)
{
  std::size_t n = 1000000;
  int reps = 5, threads = 2;
  std::uint64_t seed = 20261202;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      n = std::size_t(std::atof(option_value(argc, argv, i).c_str()));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--threads")
      threads = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e6] [--reps 5] [--threads 2] [--seed S]\n", argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
#ifndef CGAL_LINKED_WITH_TBB
  std::printf("bench_region_build needs TBB\n");
  return 0;
#else
  namespace internal = DFP::internal;
  const bool keep = keep_freed_memory();
  tbb::task_arena arena(threads);
  std::printf("# bench_region_build, %s, %s, malloc policy %s, n = %zu, %d threads, medians of %d\n",
              local_date_time().c_str(), build_description().c_str(), keep ? "keep" : "default", n, threads, reps);
  std::printf("%-9s %-6s | %8s %8s %8s | %9s %9s %9s | %7s %7s | %s\n", "dist", "blocks", "CGAL s", "seq s",
              "regions", "CGAL/seq", "CGAL/reg", "seq/reg", "seams", "failing", "check");
  bool all_same = true;
  for(const std::string dist : {"uniform", "clustered"}) {
    const std::vector<Point> points = distribution_points(dist, n, salted_seed(0x4e61, seed, dist, n));
    const std::size_t block_counts[] = {2, 4, 8};
    std::vector<double> cgal, sequential, regions[3];
    internal::Block_build_counts report[3];
    bool same = true;
    for(int r = 0; r < reps; ++r) {
      Signature expected, got;
      cgal.push_back(time_cgal(points, expected));
      {
        DT dt;
        DFP::Statistics st;
        sequential.push_back(time_call(dt, [&] { internal::build_from_scratch(dt, points.begin(), n, st); }, got));
        same = same && got == expected;
      }
      for(int b = 0; b < 3; ++b) {
        DT dt;
        bool built = false;
        regions[b].push_back(time_call(dt, [&] {
          arena.execute([&] {
            DFP::Statistics st;
            built = internal::build_in_blocks(dt, points.begin(), n, st, block_counts[b], true, &report[b]);
          });
        }, got));
        same = same && built && got == expected;
      }
    }
    all_same = all_same && same;
    for(int b = 0; b < 3; ++b) {
      std::vector<double> cgal_seq, cgal_reg, seq_reg;
      for(std::size_t r = 0; r < std::size_t(reps); ++r) {
        cgal_seq.push_back(cgal[r] / sequential[r]);
        cgal_reg.push_back(cgal[r] / regions[b][r]);
        seq_reg.push_back(sequential[r] / regions[b][r]);
      }
      std::printf("%-9s %-6zu | %8.4f %8.4f %8.4f | %9.2f %9.2f %9.2f | %6.2f%% %7zu | %s\n", dist.c_str(),
                  block_counts[b], median(cgal), median(sequential), median(regions[b]), median(cgal_seq),
                  median(cgal_reg), median(seq_reg), 100.0 * double(report[b].seam_points) / double(n),
                  report[b].walls_failing, same ? "ok" : "DIFFERENT");
    }
  }
  std::printf("(seams: the points triangulated again for the seams; failing: walls repaired by flips;\n"
              " times are medians, ratios medians of the ratios of each repetition)\n");
  return all_same ? 0 : 1;
#endif
}
