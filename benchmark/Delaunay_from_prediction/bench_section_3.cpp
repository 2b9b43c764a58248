// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Benchmark of Section 3 and Theorem 4.1 of the paper as written (Strategy::section_3,
// Strategy::theorem_4_1): how their time (and Section 3's counted work) grow with the
// prediction's error D and with n, against n + D log2 n, next to the default strategy, the
// package's build from scratch (Strategy::rebuild) and CGAL's, on the same inputs.
//
// Rows (uniform points in the unit square):
//   part D: at each n of --n, predictions with growing D:
//     flips K    DT(P) after K random flips (k_flip_prediction), K = 0, n/1000, n/100, n/10, n/3;
//     rho R      the rho model of Section 1.3 (rho_model_prediction, random completion),
//                R = 0.9, 0.5, 0.1;
//     relabel X  DT(P) with X of the points exchanging their labels (a random permutation
//                among them, X = 0.1%, 1%, 10%): wrong edges across the whole domain, the
//                ones Lemma 3.2 charges log n each (self-crossing faces, Corollary 3.5);
//   part n: at each n of --growth, D = 0 (flips 0) and D ~ n/100 (flips n/100).
// D is counted exactly: the distinct predicted edges that are not edges of DT(P).
// Columns: D; the seconds of CGAL's range insert, of section_3, of theorem_4_1, of the default
// strategy and of Strategy::rebuild (the package's build from scratch, the prediction
// unused), medians of --reps repetitions in which the five calls alternate; CGAL / section_3
// and CGAL / theorem_4_1; section_3's counters (faces visited by its walks, conflict-list
// entries over all rounds, points relocated by the incremental construction, walks past their
// cap); theorem_4_1's supercells, bad supercells and cells computed; then the fits.
// The fits: least squares against a * n + b * D * log2(n) of the counted work (the sum of the
// three counters) over all rows, and of each strategy's seconds over the rows of each n; each
// row then shows measured / fitted, which stays near 1 where the model n + D log n describes
// the growth, and the seconds per point and per unit of work.
// Every result is checked against CGAL's (face set signature); the exit status says whether all
// were equal.

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/prediction_models.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace dfp_bench;

namespace {

struct Row
{
  std::string part, model;
  std::size_t n = 0, D = 0;
  double cgal = 0, section_3 = 0, theorem_4_1 = 0, automatic = 0, rebuild = 0;
  std::size_t faces_visited = 0, conflict_entries = 0, relocated = 0, capped = 0;
  std::size_t supercells = 0, bad_supercells = 0, cells_computed = 0;
  bool same = true;
  double work() const { return double(faces_visited + conflict_entries + relocated); }
  double x() const { return double(n); }
  double y() const { return double(D) * std::log2(double(n)); }
};

// Least squares of v = a x + b y (no intercept): returns (a, b).
template <class Value>
std::pair<double, double> fit(const std::vector<Row>& rows, const Value& value)
{
  double sxx = 0, sxy = 0, syy = 0, sxv = 0, syv = 0;
  for(const Row& r : rows) {
    sxx += r.x() * r.x();
    sxy += r.x() * r.y();
    syy += r.y() * r.y();
    sxv += r.x() * value(r);
    syv += r.y() * value(r);
  }
  const double det = sxx * syy - sxy * sxy;
  if(std::abs(det) < 1e-12 * sxx * syy || syy == 0)
    return {sxv / sxx, 0.0};
  return {(sxv * syy - syv * sxy) / det, (syv * sxx - sxv * sxy) / det};
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> sizes = {"1e5", "1e6"}, growth = {"1e4", "3e4", "1e5", "3e5", "1e6"};
  int reps = 3;
  std::string csv_file;
  std::uint64_t seed = 20261206;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = split(option_value(argc, argv, i));
    else if(a == "--growth")
      growth = split(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--csv")
      csv_file = option_value(argc, argv, i);
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e5,1e6] [--growth 1e4,3e4,1e5,3e5,1e6] [--reps 3] [--csv FILE] [--seed S]\n"
                  "  --n lists the sizes of part D, --growth those of part n; an empty list (\"\") skips a part\n",
                  argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_section_3, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::vector<Row> rows;
  bool all_same = true;
  auto run = [&](const std::string& part, std::size_t n, const std::string& model) {
    const std::vector<Point> points = uniform_points(n, salted_seed(0x5ec3, seed, "uniform", n));
    const DTI reference = build_indexed(points);
    Signature cgal_sig;
    {
      DT d(points.begin(), points.end());
      cgal_sig = signature(d);
    }
    std::vector<DFP::Indexed_triangle> predicted;
    const std::uint64_t model_seed = salted_seed(0x3ed1, seed, model, n);
    if(model.compare(0, 6, "flips ") == 0) {
      const std::string k = model.substr(6);
      const std::size_t flips = k == "0" ? 0 : n / std::size_t(std::atof(k.substr(2).c_str()));
      predicted = DFP::k_flip_prediction(points, flips, model_seed);
    } else if(model.compare(0, 8, "relabel ") == 0) {
      // A fraction of the points exchange their labels (a random permutation among them):
      // their edges reach across the domain, so the tree's walks along them hit their cap.
      predicted = DFP::delaunay_triangles(points);
      const double fraction = std::atof(model.substr(8).c_str()) / 100.0;
      Rng pick{model_seed};
      std::vector<std::uint32_t> chosen;
      for(std::uint32_t k = 0; k < n; ++k)
        if(double(pick.below(1u << 30)) < fraction * double(1u << 30))
          chosen.push_back(k);
      const std::vector<std::uint32_t> label = permuted_among(n, chosen, pick);
      for(auto& f : predicted)
        for(auto& v : f)
          v = label[v];
    } else
      predicted = DFP::rho_model_prediction(points, std::atof(model.substr(4).c_str()), model_seed,
                                             DFP::Completion::random);
    std::vector<Face> faces;
    for(const auto& f : predicted)
      faces.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    Rng rng{model_seed};
    shuffle_faces(faces, rng);
    Row row;
    row.part = part;
    row.model = model;
    row.n = n;
    row.D = wrong_edges(edges_of(faces), edges_of(export_faces(reference)));
    std::vector<double> t_cgal, t_s3, t_t41, t_auto, t_rebuild;
    for(int r = 0; r < reps; ++r) {
      Signature sig;
      DFP::Statistics stats;
      t_cgal.push_back(time_cgal(points, sig));
      t_s3.push_back(time_prediction(points, faces, stats, sig,
                                     DFP::parameters::strategy(DFP::Strategy::section_3)));
      // section_3 goes through the pipeline's rebuild stage, so fell_back is set; the outcome
      // says that the strategy itself ran.
      row.same = row.same && sig == cgal_sig && stats.outcome == DFP::Outcome::section_3_requested;
      row.faces_visited = stats.faces_visited;
      row.conflict_entries = stats.conflict_list_entries;
      row.relocated = stats.points_relocated;
      row.capped = stats.walk_fallbacks;
      t_t41.push_back(time_prediction(points, faces, stats, sig,
                                      DFP::parameters::strategy(DFP::Strategy::theorem_4_1)));
      row.same = row.same && sig == cgal_sig && !stats.fell_back;
      row.supercells = stats.supercells;
      row.bad_supercells = stats.bad_supercells;
      row.cells_computed = stats.cells_computed;
      t_auto.push_back(time_prediction(points, faces, stats, sig));
      row.same = row.same && sig == cgal_sig;
      t_rebuild.push_back(time_prediction(points, faces, stats, sig, DFP::parameters::strategy(DFP::Strategy::rebuild)));
      row.same = row.same && sig == cgal_sig;
    }
    row.cgal = median(t_cgal);
    row.section_3 = median(t_s3);
    row.theorem_4_1 = median(t_t41);
    row.automatic = median(t_auto);
    row.rebuild = median(t_rebuild);
    all_same = all_same && row.same;
    std::printf("%-6s %-8zu %-11s %8zu | %7.3f %7.3f %7.3f %7.3f %7.3f | %5.2f %5.2f | %10zu %10zu %10zu %6zu | "
                "%5zu %5zu %7zu | %s\n",
                part.c_str(), n, model.c_str(), row.D, row.cgal, row.section_3, row.theorem_4_1, row.automatic,
                row.rebuild, row.cgal / row.section_3, row.cgal / row.theorem_4_1, row.faces_visited,
                row.conflict_entries, row.relocated, row.capped, row.supercells, row.bad_supercells,
                row.cells_computed, row.same ? "same as CGAL" : "DIFFERENT");
    std::fflush(stdout);
    rows.push_back(row);
  };
  std::printf("%-6s %-8s %-11s %8s | %7s %7s %7s %7s %7s | %5s %5s | %10s %10s %10s %6s | %5s %5s %7s | %s\n",
              "part", "n", "prediction", "D", "CGAL s", "sec3 s", "t4.1 s", "auto s", "rebld s", "C/s3", "C/t41",
              "walk faces", "conflicts", "relocated", "capped", "super", "bad", "cells", "check");
  for(const std::string& size : sizes) {
    const std::size_t n = std::size_t(std::atof(size.c_str()));
    for(const char* model : {"flips 0", "flips n/1000", "flips n/100", "flips n/10", "flips n/3", "rho 0.9", "rho 0.5",
                             "rho 0.1", "relabel 0.1%", "relabel 1%", "relabel 10%"})
      run("D", n, model);
  }
  for(const std::string& size : growth) {
    const std::size_t n = std::size_t(std::atof(size.c_str()));
    for(const char* model : {"flips 0", "flips n/100"}) {
      const bool done = std::any_of(rows.begin(), rows.end(), [&](const Row& r) { return r.n == n && r.model == model; });
      if(!done)
        run("n", n, model);
    }
  }
  // The counted work is fitted over all rows; the seconds for each n apart, since the cost of
  // a unit of work grows with n (the rounds visit the points in random order: cache misses).
  const auto work_fit = fit(rows, [](const Row& r) { return r.work(); });
  std::printf("# fit over all rows: counted work = %.3g * n + %.3g * D log2 n\n", work_fit.first, work_fit.second);
  std::map<std::size_t, std::pair<double, double>> time_fits, t41_fits;
  for(const Row& r : rows)
    if(time_fits.count(r.n) == 0) {
      std::vector<Row> same_n;
      std::copy_if(rows.begin(), rows.end(), std::back_inserter(same_n), [&](const Row& o) { return o.n == r.n; });
      time_fits[r.n] = fit(same_n, [](const Row& o) { return o.section_3; });
      t41_fits[r.n] = fit(same_n, [](const Row& o) { return o.theorem_4_1; });
      std::printf("# fit at n = %zu: section_3 seconds = %.3g * n + %.3g * D log2 n; theorem_4_1 seconds = %.3g * n + "
                  "%.3g * D log2 n\n",
                  r.n, time_fits[r.n].first, time_fits[r.n].second, t41_fits[r.n].first, t41_fits[r.n].second);
    }
  std::printf("%-8s %-11s %8s | %8s %8s %8s | %9s %9s %9s\n", "n", "prediction", "D", "s3/fit", "work/fit",
              "t41/fit", "ns/point", "ns/work", "D log n/n");
  std::FILE* csv = csv_file.empty() ? nullptr : std::fopen(csv_file.c_str(), "w");
  if(csv != nullptr)
    std::fprintf(csv, "part,n,prediction,D,cgal_s,section_3_s,theorem_4_1_s,automatic_s,rebuild_s,cgal_over_section_3,"
                      "cgal_over_theorem_4_1,walk_faces,conflict_list_entries,points_relocated,walks_capped,supercells,"
                      "bad_supercells,cells_computed,time_over_fit,work_over_fit,theorem_4_1_time_over_fit,"
                      "same_as_cgal\n");
  for(const Row& r : rows) {
    const double t_fit = time_fits[r.n].first * r.x() + time_fits[r.n].second * r.y();
    const double w_fit = work_fit.first * r.x() + work_fit.second * r.y();
    const double t41_fit = t41_fits[r.n].first * r.x() + t41_fits[r.n].second * r.y();
    std::printf("%-8zu %-11s %8zu | %8.2f %8.2f %8.2f | %9.0f %9.1f %9.3f\n", r.n, r.model.c_str(), r.D,
                r.section_3 / t_fit, r.work() / w_fit, r.theorem_4_1 / t41_fit, 1e9 * r.section_3 / double(r.n),
                1e9 * r.section_3 / r.work(), r.y() / r.x());
    if(csv != nullptr)
      std::fprintf(csv, "%s,%zu,%s,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.3f,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%.3f,%.3f,%.3f,%d\n",
                   r.part.c_str(), r.n, r.model.c_str(), r.D, r.cgal, r.section_3, r.theorem_4_1, r.automatic,
                   r.rebuild, r.cgal / r.section_3, r.cgal / r.theorem_4_1, r.faces_visited, r.conflict_entries,
                   r.relocated, r.capped, r.supercells, r.bad_supercells, r.cells_computed, r.section_3 / t_fit,
                   r.work() / w_fit, r.theorem_4_1 / t41_fit, int(r.same));
  }
  if(csv != nullptr)
    std::fclose(csv);
  std::printf("# C/s3 = CGAL / section_3, C/t41 = CGAL / theorem_4_1; s3/fit, work/fit and t41/fit = measured / "
              "fitted; ns/point and ns/work = section_3's time per point and per unit of counted work\n");
  return all_same ? 0 : 1;
}
