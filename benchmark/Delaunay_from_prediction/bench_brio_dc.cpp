// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// brio_dc_delaunay() (BrioDC) against CGAL's range insert of the same points, in the same run:
// uniform, clustered and graded points (distribution_points()), medians of --reps runs with
// the calls alternating, every result checked against CGAL's (face set signature). BrioDC runs
// with the default sampling probability (1/8) and with the paper's (1/2). Also the mean walk
// length along the nearest-neighbour graph and the number of samples (default probability).
//
// With --threads T (a build with TBB), also brio_dc_delaunay<CGAL::Parallel_tag> (default
// probability) in a TBB arena of T threads, in the same repetitions, and its speed-up over the
// sequential call.
//
// Usage: bench_brio_dc [--n 1e5,1e6] [--dists uniform,clustered,graded] [--reps 5] [--seed S]
//                      [--threads T]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/brio_dc.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::vector<std::string> dists = {"uniform", "clustered", "graded"};
  int reps = 5;
  std::uint64_t seed = 20261127;
  int threads = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = sizes_of(option_value(argc, argv, i));
    else if(a == "--dists")
      dists = split(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
#ifdef CGAL_LINKED_WITH_TBB
    else if(a == "--threads")
      threads = std::max(0, std::atoi(option_value(argc, argv, i).c_str()));
#endif
    else {
      std::printf("usage: %s [--n 1e5,1e6] [--dists uniform,clustered,graded] [--reps 5] [--seed S] [--threads T]\n",
                  argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_brio_dc, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  if(threads > 0)
    std::printf("# par: brio_dc_delaunay<CGAL::Parallel_tag> in a TBB arena of %d threads; x seq: its speed-up\n",
                threads);
  std::printf("%-8s %-10s | %8s %8s %6s | %8s %6s | %8s %8s %7s", "n", "dist", "CGAL s", "BrioDC", "ratio",
              "p=1/2", "ratio", "faces/pt", "fallback", "samples");
  if(threads > 0)
    std::printf(" | %8s %6s %6s", "par", "ratio", "x seq");
  std::printf("\n");
  bool all_same = true;
  for(const std::size_t n : sizes) {
    for(const std::string& dist : dists) {
      const std::vector<Point> points = distribution_points(dist, n, salted_seed(0xb410, seed, dist, n));
      std::vector<double> t_cgal, t_brio, t_half, t_par;
      DFP::Statistics stats;
      for(int r = 0; r < reps; ++r) {
        Signature reference, sig, sig_half;
        t_cgal.push_back(time_cgal(points, reference));
        DT dt;
        t_brio.push_back(time_call(dt, [&] { stats = DFP::brio_dc_delaunay(points, dt); }, sig));
        DT dt_half;
        t_half.push_back(time_call(
            dt_half, [&] { DFP::brio_dc_delaunay(points, dt_half, DFP::parameters::sample_probability(0.5)); },
            sig_half));
        all_same = all_same && sig == reference && sig_half == reference;
#ifdef CGAL_LINKED_WITH_TBB
        if(threads > 0) {
          Signature sig_par;
          DT dt_par;
          tbb::task_arena arena(threads);
          t_par.push_back(arena.execute([&] {
            return time_call(dt_par, [&] { DFP::brio_dc_delaunay<CGAL::Parallel_tag>(points, dt_par); }, sig_par);
          }));
          all_same = all_same && sig_par == reference;
        }
#endif
      }
      const double cgal = median(t_cgal), ours = median(t_brio), half = median(t_half);
      std::printf("%-8zu %-10s | %8.3f %8.3f %6.2f | %8.3f %6.2f | %8.2f %8zu %7zu", n, dist.c_str(), cgal, ours,
                  cgal / ours, half, cgal / half,
                  double(stats.faces_visited) / double(std::max<std::size_t>(1, stats.points_located)),
                  stats.walk_fallbacks, stats.insertion_rounds);
      if(!t_par.empty())
        std::printf(" | %8.3f %6.2f %6.2f", median(t_par), cgal / median(t_par), ours / median(t_par));
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  std::printf("# every result equal to CGAL's: %s\n", all_same ? "yes" : "NO");
  return all_same ? 0 : 1;
}
