// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Which build from scratch delaunay_from_prediction() should fall back to: on predictions that
// do fall back, the spatial-order build (Strategy::rebuild) against the build along a spanning
// tree of the faces' edges (Strategy::spanning_tree), both reading and checking the faces as
// the fallback does, with CGAL's range insert and the default call in the same run.
//
// Predictions (faces by point index): the Delaunay faces of the points before they moved by
// Gaussian noise of 0.3, 0.5 and 1 spacing sqrt(1/n) per coordinate; the Delaunay faces with 1%
// of the points relabelled among themselves (self-crossing); 2n random triples. Uniform points
// in the unit square, or clustered ones (64 Gaussian blobs of standard deviation 0.005 to
// 0.035). Times are medians of --reps repetitions, the four calls alternating; every result is
// checked against CGAL's (face set signature).
//
// Usage: bench_fallback [--n 1e6] [--reps 5] [--seed S]

#include "benchmark_util.h"

#include <cmath>

using namespace dfp_bench;

int main(int argc, char** argv)
{
  std::size_t n = 1000000;
  int reps = 5;
  std::uint64_t seed = 20261127;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      n = std::size_t(std::atof(option_value(argc, argv, i).c_str()));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e6] [--reps 5] [--seed S]\n", argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_fallback, %s, %s, malloc policy %s, n = %zu, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", n, reps);
  std::printf("%-9s %-20s | %8s %8s %8s %8s | %9s %9s | %s\n", "dist", "prediction", "CGAL s", "rebuild", "tree",
              "default", "tree/rb", "CGAL/def", "check (default path)");
  bool all_same = true;
  for(const std::string dist : {"uniform", "clustered"}) {
    Rng rng{salted_seed(0xfa11, seed, dist, n)};
    std::vector<Point> points;
    points.reserve(n);
    std::vector<Point> centres;
    std::vector<double> sigma;
    for(int b = 0; b < 64; ++b) {
      const double x = 0.1 + 0.8 * rng.uniform();
      centres.emplace_back(x, 0.1 + 0.8 * rng.uniform());
      sigma.push_back(0.005 + 0.03 * rng.uniform());
    }
    for(std::size_t i = 0; i < n; ++i) {
      if(dist == "uniform") {
        const double x = rng.uniform();
        points.emplace_back(x, rng.uniform());
      } else {
        const std::size_t b = rng.below(64);
        const double x = centres[b].x() + sigma[b] * rng.normal();
        points.emplace_back(x, centres[b].y() + sigma[b] * rng.normal());
      }
    }
    const std::vector<Face> delaunay_faces = export_faces(build_indexed(points));
    const double spacing = std::sqrt(1.0 / double(n));
    for(const std::string prediction : {"moved 0.3", "moved 0.5", "moved 1", "relabelled 1%", "random triples"}) {
      std::vector<Point> q = points;
      std::vector<Face> faces = delaunay_faces;
      if(prediction.compare(0, 5, "moved") == 0) {
        const double s = std::atof(prediction.c_str() + 6) * spacing;
        for(Point& p : q) {
          const double x = p.x() + s * rng.normal();
          p = Point(x, p.y() + s * rng.normal());
        }
      } else if(prediction == "relabelled 1%") {
        std::vector<std::uint32_t> chosen;
        for(std::uint32_t k = 0; k < n; ++k)
          if(rng.below(100) == 0)
            chosen.push_back(k);
        const std::vector<std::uint32_t> label = permuted_among(n, chosen, rng);
        for(Face& f : faces)
          f = {label[f[0]], label[f[1]], label[f[2]]};
      } else {
        for(Face& f : faces) {
          do
            f = {std::uint32_t(rng.below(n)), std::uint32_t(rng.below(n)), std::uint32_t(rng.below(n))};
          while(f[0] == f[1] || f[0] == f[2] || f[1] == f[2]);
        }
      }
      shuffle_faces(faces, rng);
      Signature cgal_sig;
      std::vector<double> t_cgal, t_rebuild, t_tree, t_default;
      DFP::Statistics st_default;
      bool same = true;
      for(int r = 0; r < reps; ++r) {
        t_cgal.push_back(time_cgal(q, cgal_sig));
        Signature sig;
        DFP::Statistics st;
        t_rebuild.push_back(time_prediction(q, faces, st, sig, DFP::parameters::strategy(DFP::Strategy::rebuild)));
        same = same && sig == cgal_sig;
        t_tree.push_back(time_prediction(q, faces, st, sig, DFP::parameters::strategy(DFP::Strategy::spanning_tree)));
        same = same && sig == cgal_sig;
        t_default.push_back(time_prediction(q, faces, st_default, sig));
        same = same && sig == cgal_sig;
      }
      all_same = all_same && same;
      const double tc = median(t_cgal), trb = median(t_rebuild), ttr = median(t_tree), td = median(t_default);
      std::printf("%-9s %-20s | %8.3f %8.3f %8.3f %8.3f | %9.3f %9.2f | %s (%s)\n", dist.c_str(), prediction.c_str(), tc,
                  trb, ttr, td, ttr / trb, tc / td, same ? "same as CGAL" : "DIFFERENT",
                  st_default.fell_back ? to_string(st_default.outcome) : "repaired");
      std::fflush(stdout);
    }
  }
  std::printf("# rebuild = Strategy::rebuild (spatial order), tree = Strategy::spanning_tree (along the faces' "
              "edges), default = the default strategy; tree/rb > 1: the spatial order is faster\n");
  return all_same ? 0 : 1;
}
