// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// split_delaunay() against CGAL: DT(S1) and DT(S2) from DT(S), S = S1 u S2, by
//   - "2 builds": CGAL's range insert of S1, then of S2 (from the points);
//   - "removal": CGAL's vertex removal, a copy of DT(S) per part, the other part's vertices
//     removed one by one in the vertices' order (the copies timed);
//   - "default": split_delaunay() (Split_method::ordered);
//   - "randomized": split_delaunay() with Split_method::randomized (the paper's algorithm).
// Ratios are the time of "2 builds" over each. Points uniform in the unit square; DT(S) built
// by CGAL's range insert (vertices in spatial-sort order), or, in case "random order", by
// inserting the points one by one in random order (vertices in that order). Partitions: each
// point in S1 with probability 1/2 or 1/10, or S1 the points left of x = 1/2. Medians of --reps
// runs, the calls alternating; every result is checked against the two CGAL builds (face set
// signatures).
//
// Usage: bench_split [--n 1e5,1e6] [--reps 3] [--seed S] [--no-randomized]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/split.h>

using namespace dfp_bench;

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  int reps = 3;
  bool randomized = true;
  std::uint64_t seed = 20261127;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = sizes_of(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else if(a == "--no-randomized")
      randomized = false;
    else {
      std::printf("usage: %s [--n 1e5,1e6] [--reps 3] [--seed S] [--no-randomized]\n", argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_split, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::printf("%-8s %-13s %-9s | %8s %8s %8s %8s | %7s %7s %7s | %s\n", "n", "input", "S1", "2 builds", "removal",
              "default", "random.", "removal", "default", "random.", "faces/pt (random.)");
  bool all_same = true;
  for(const std::size_t n : sizes) {
    for(const std::string input : {"range", "random order"}) {
      for(const std::string partition : {"1/2", "1/10", "x < 1/2"}) {
        if(input == "random order" && partition != "1/2")
          continue;
        Rng rng{salted_seed(0x5911, seed, input + partition, n)};
        std::vector<Point> points = uniform_points(n, salted_seed(0x5912, seed, "points", n));
        std::vector<std::pair<Point, std::uint32_t>> indexed = with_indices(points);
        DTI dt;
        if(input == "range") {
          dt.insert(indexed.begin(), indexed.end());
        } else {
          shuffle(indexed, rng);
          DTI::Face_handle hint;
          for(const auto& p : indexed) {
            const DTI::Vertex_handle v = dt.insert(p.first, hint);
            v->info() = p.second;
            hint = v->face();
          }
        }
        std::vector<char> first(n);
        for(std::size_t i = 0; i < n; ++i)
          first[i] = partition == "1/2" ? (rng() & 1) : partition == "1/10" ? rng.below(10) == 0 : points[i].x() < 0.5;
        std::vector<Point> s1, s2;
        for(std::size_t i = 0; i < n; ++i)
          (first[i] ? s1 : s2).push_back(points[i]);
        auto in_first = [&](DTI::Vertex_handle v) { return first[v->info()] != 0; };
        std::vector<double> t_cgal, t_removal, t_default, t_random;
        DFP::Statistics s_random;
        for(int r = 0; r < reps; ++r) {
          CGAL::Real_timer timer;
          Signature ref1, ref2, sig1, sig2;
          {
            DT a, b;
            timer.start();
            a.insert(s1.begin(), s1.end());
            b.insert(s2.begin(), s2.end());
            timer.stop();
            t_cgal.push_back(timer.time());
            ref1 = signature(a);
            ref2 = signature(b);
          }
          {
            timer.reset();
            timer.start();
            DTI a(dt), b(dt);
            std::vector<DTI::Vertex_handle> out_a, out_b;
            for(auto v = a.finite_vertices_begin(); v != a.finite_vertices_end(); ++v)
              if(!first[v->info()])
                out_a.push_back(v);
            for(auto v = b.finite_vertices_begin(); v != b.finite_vertices_end(); ++v)
              if(first[v->info()])
                out_b.push_back(v);
            for(const auto& v : out_a)
              a.remove(v);
            for(const auto& v : out_b)
              b.remove(v);
            timer.stop();
            t_removal.push_back(timer.time());
            all_same = all_same && signature(a) == ref1 && signature(b) == ref2;
          }
          {
            DTI a, b;
            timer.reset();
            timer.start();
            DFP::split_delaunay(dt, in_first, a, b);
            timer.stop();
            t_default.push_back(timer.time());
            all_same = all_same && signature(a) == ref1 && signature(b) == ref2;
          }
          if(randomized) {
            DTI a, b;
            timer.reset();
            timer.start();
            s_random = DFP::split_delaunay(dt, in_first, a, b,
                                           DFP::parameters::split_method(DFP::Split_method::randomized));
            timer.stop();
            t_random.push_back(timer.time());
            all_same = all_same && signature(a) == ref1 && signature(b) == ref2;
          }
        }
        const double cgal = median(t_cgal), removal = median(t_removal), ours = median(t_default),
                     random = randomized ? median(t_random) : 0.0;
        std::printf("%-8zu %-13s %-9s | %8.3f %8.3f %8.3f %8.3f | %7.2f %7.2f %7.2f | %.2f\n", n, input.c_str(),
                    partition.c_str(), cgal, removal, ours, random, cgal / removal, cgal / ours,
                    randomized ? cgal / random : 0.0,
                    double(s_random.faces_visited) / double(std::max<std::size_t>(1, s_random.points_located)));
        std::fflush(stdout);
      }
    }
  }
  std::printf("# every result equal to CGAL's: %s\n", all_same ? "yes" : "NO");
  return all_same ? 0 : 1;
}
