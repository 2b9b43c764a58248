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
// Usage: bench_brio_dc [--n 1e5,1e6] [--dists uniform,clustered,graded] [--reps 5] [--seed S]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/brio_dc.h>

using namespace dfp_bench;

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  std::vector<std::string> dists = {"uniform", "clustered", "graded"};
  int reps = 5;
  std::uint64_t seed = 20261127;
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
    else {
      std::printf("usage: %s [--n 1e5,1e6] [--dists uniform,clustered,graded] [--reps 5] [--seed S]\n", argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_brio_dc, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::printf("%-8s %-10s | %8s %8s %6s | %8s %6s | %8s %8s %7s\n", "n", "dist", "CGAL s", "BrioDC", "ratio",
              "p=1/2", "ratio", "faces/pt", "fallback", "samples");
  bool all_same = true;
  for(const std::size_t n : sizes) {
    for(const std::string& dist : dists) {
      const std::vector<Point> points = distribution_points(dist, n, salted_seed(0xb410, seed, dist, n));
      std::vector<double> t_cgal, t_brio, t_half;
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
      }
      const double cgal = median(t_cgal), ours = median(t_brio), half = median(t_half);
      std::printf("%-8zu %-10s | %8.3f %8.3f %6.2f | %8.3f %6.2f | %8.2f %8zu %7zu\n", n, dist.c_str(), cgal, ours,
                  cgal / ours, half, cgal / half,
                  double(stats.faces_visited) / double(std::max<std::size_t>(1, stats.points_located)),
                  stats.walk_fallbacks, stats.insertion_rounds);
      std::fflush(stdout);
    }
  }
  std::printf("# every result equal to CGAL's: %s\n", all_same ? "yes" : "NO");
  return all_same ? 0 : 1;
}
