// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Experiments on how the quality of the prediction drives the running time, and on the
// closeness measures of Table 1 of "Delaunay Triangulations with Predictions" (Cabello, Chan,
// Giannopoulos). Writes one CSV file per experiment; scripts/experiments.sh builds this
// program, runs it and draws the figures (scripts/plot_experiments.gnuplot).
//
//   (a) exp_a_time_vs_n.csv      D = 0: time against n of delaunay_from_prediction() (the
//                                Delaunay faces, shuffled and rotated, points in random order),
//                                of make_delaunay() on a CGAL triangulation that already is
//                                Delaunay, and of CGAL's from-scratch build.
//   (b) exp_b_time_vs_D.csv      fixed n, k_flip_prediction() for k = 0 ... 2n: time against the
//                                measured D, with the default flip budget (n/2 + 64, then a
//                                rebuild), with no budget and no sampling screen (pure Lawson),
//                                and CGAL's build.
//   (c) exp_c_time_vs_rho.csv    fixed n, rho in {0.05, ..., 1}: rho model (adversarial and
//                                random completion) and random-flip model; time of the
//                                computation only (not of the generation), both budgets, CGAL,
//                                and the shape c (n log2 log2 n + n log2(1/rho)) of Corollaries
//                                6.2 and 6.6 with c fitted (least squares of the logarithms) to
//                                the pure-Lawson times (minimum of the repetitions) of each model.
//   (d) exp_d_measures.csv       every measure of prediction_measures() on every model, on
//                                uniform points and on a jittered grid, at small n; the program
//                                checks D_local <= D <= Lawson flips <= D_cross and D = D_missing
//                                on every triangulation and prints any violation.
//
// Timing conventions are those of bench_delaunay_from_prediction.cpp: Epick, plain
// CGAL::Delaunay_triangulation_2<Epick> for CGAL and for us, one thread, CGAL::Real_timer (wall
// clock), repetitions interleaved (the order of the algorithms rotates), median and minimum
// reported, mallopt "keep" policy (no heap trimming, no mmap'd blocks), every result of ours
// compared with CGAL's (counts and a hash of the face set) outside the timers. "CGAL with info"
// is the range insert of (point, index) pairs into a triangulation whose vertices carry the
// index: what a user who needs the indices back pays.
//
// Usage: experiment_prediction_quality [--experiments a,b,c,d] [--large] [--reps R]
//          [--out DIR] [--seed S] [--na LIST] [--nb N] [--nc N] [--nd LIST]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/measures.h>
#include <CGAL/Delaunay_from_prediction/prediction_models.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace dfp_bench;

using Triangle = DFP::Indexed_triangle; // what the generators return

// The seed of one input of this program (its own salt: the inputs of the recorded results).
std::uint64_t seed_for(std::uint64_t base, const std::string& what, std::uint64_t n)
{
  return salted_seed(0x5eedull, base, what, n);
}

// ---------------------------------------------------------------------------------------------
// Inputs (uniform_points() is in benchmark_util.h).

// s x s cells (s = round(sqrt(n))), one point per cell at a uniform position in the middle
// `jitter` fraction of the cell: a point set whose hull edges are about one cell long, so no
// Delaunay triangle is skinny near the hull. With jitter 0.1 every cell is nearly a square, so
// a flip of a Delaunay edge makes two fat triangles (small circumcircles); with 0.8, nearly
// flat convex quadrilaterals are common.
std::vector<Point> jittered_grid(std::size_t n, double jitter, std::uint64_t seed)
{
  Rng rng{seed};
  const std::size_t s = std::max<std::size_t>(2, std::size_t(std::llround(std::sqrt(double(n)))));
  std::vector<Point> points;
  points.reserve(s * s);
  for(std::size_t i = 0; i < s; ++i)
    for(std::size_t j = 0; j < s; ++j) {
      const double lo = 0.5 - 0.5 * jitter;
      const double x = (double(i) + lo + jitter * rng.uniform()) / double(s);
      points.emplace_back(x, (double(j) + lo + jitter * rng.uniform()) / double(s));
    }
  shuffle(points, rng); // random order, as for the uniform points
  return points;
}

std::vector<Point> make_points(const std::string& set, std::size_t n, std::uint64_t seed)
{
  if(set == "jgrid80")
    return jittered_grid(n, 0.8, seed);
  if(set == "jgrid10")
    return jittered_grid(n, 0.1, seed);
  return uniform_points(n, seed);
}

// The faces as a file would give them: list in random order, each triple rotated at random.
std::vector<Face> shuffled(const std::vector<Triangle>& in, std::uint64_t seed)
{
  std::vector<Face> faces(in.size());
  for(std::size_t i = 0; i < in.size(); ++i)
    faces[i] = {std::uint32_t(in[i][0]), std::uint32_t(in[i][1]), std::uint32_t(in[i][2])};
  Rng rng{seed};
  shuffle_faces(faces, rng);
  return faces;
}

// ---------------------------------------------------------------------------------------------
// Checks (the signature of a result is in benchmark_util.h).
int check_failures = 0;
void check(bool ok, const std::string& what)
{
  if(ok)
    return;
  ++check_failures;
  std::printf("!!!!!!!! CHECK FAILED: %s !!!!!!!!\n", what.c_str());
  std::fprintf(stderr, "!!!!!!!! CHECK FAILED: %s !!!!!!!!\n", what.c_str());
  std::fflush(stdout);
}

// ---------------------------------------------------------------------------------------------
// Timing (the timed calls, time_cgal(), time_prediction() and time_call(), are in
// benchmark_util.h).
struct Times
{
  std::vector<double> all;
  double median() const { return dfp_bench::median(all); }
  double min() const
  {
    return all.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::min_element(all.begin(), all.end());
  }
};

// One timed algorithm: returns its time; builds and destroys its triangulation outside its
// timer; leaves the signature of its result.
using Timed = std::function<double(Signature&)>;

// Runs `reps` rounds of all algorithms, the order rotating from one round to the next; checks
// every result against the first result of algorithm 0 (CGAL's build).
std::vector<Times> measure(int reps, const std::vector<Timed>& algorithms, const std::string& what)
{
  std::vector<Times> times(algorithms.size());
  Signature reference;
  bool have_reference = false;
  std::vector<std::pair<std::size_t, Signature>> results;
  for(int r = 0; r < reps; ++r)
    for(std::size_t t = 0; t < algorithms.size(); ++t) {
      const std::size_t a = (t + std::size_t(r)) % algorithms.size();
      Signature s;
      times[a].all.push_back(algorithms[a](s));
      if(a == 0 && !have_reference) {
        reference = s;
        have_reference = true;
      }
      results.emplace_back(a, s);
    }
  for(const auto& [a, s] : results)
    check(s == reference, what + ": result of algorithm " + std::to_string(a) + " differs from CGAL's");
  return times;
}

auto unlimited() { return DFP::parameters::max_flips((std::numeric_limits<std::size_t>::max)(), DFP::parameters::screen_prediction(false)); }

// (b) and (c): CGAL's build, the call with the default flip budget (statistics in `def`) and the
// one with no budget and no sampling screen (pure Lawson, in `unl`, which must not fall back).
std::vector<Times> measure_budgets(int reps, const std::vector<Point>& points, const std::vector<Face>& faces,
                                   DFP::Statistics& def, DFP::Statistics& unl, const std::string& what)
{
  const std::vector<Times> t = measure(
      reps,
      {[&](Signature& s) { return time_cgal(points, s); },
       [&](Signature& s) { return time_prediction(points, faces, def, s); },
       [&](Signature& s) { return time_prediction(points, faces, unl, s, unlimited()); }},
      what);
  check(!unl.fell_back, what + ": the unlimited call fell back");
  return t;
}

// The prediction of `model`: "rho_adversarial", "rho_random" (the rho model, with that
// completion) or "random_flip".
std::vector<Triangle> model_prediction(const std::string& model, const std::vector<Point>& points, double rho,
                                       std::uint64_t seed)
{
  if(model == "rho_adversarial")
    return DFP::rho_model_prediction(points, rho, seed, DFP::Completion::adversarial);
  if(model == "rho_random")
    return DFP::rho_model_prediction(points, rho, seed, DFP::Completion::random);
  return DFP::random_flip_prediction(points, rho, seed);
}

// ---------------------------------------------------------------------------------------------
// Options.
struct Options
{
  std::vector<std::string> experiments{"a", "b", "c", "d"};
  bool large = false;
  int reps = 3;
  std::string out = "benchmark/Delaunay_from_prediction/results";
  std::uint64_t seed = 20260301;
  std::vector<std::size_t> na, nd;
  std::size_t nb = 0, nc = 0;
  bool wants(const std::string& e) const
  {
    return std::find(experiments.begin(), experiments.end(), e) != experiments.end();
  }
};

std::size_t parse_n(const std::string& s)
{
  const double d = std::stod(s);
  if(!(d >= 16) || d > 4e9) {
    std::fprintf(stderr, "bad n %s\n", s.c_str());
    std::exit(2);
  }
  return std::size_t(std::llround(d));
}

void usage(const char* program)
{
  std::printf(
      "usage: %s [options]\n"
      "  --experiments L  subset of a,b,c,d (default all)\n"
      "  --large          larger n: (a) up to 5e6, (b) n = 1e6, (c) n = 5e5, (d) up to 3e4\n"
      "  --reps R         repetitions of each timing, median and min reported (default 3;\n"
      "                   2R+1 for n <= 1e5, R+2 for n <= 5e5)\n"
      "  --out DIR        where the CSV files go (default benchmark/Delaunay_from_prediction/results)\n"
      "  --seed S         base seed (default 20260301)\n"
      "  --na LIST        n of (a), comma separated, 1e6 notation allowed\n"
      "  --nb N, --nc N   n of (b), of (c)\n"
      "  --nd LIST        n of the rho models in (d) (the other models use the middle value)\n",
      program);
}

Options parse(int argc, char** argv)
{
  Options o;
  auto value = [&](int& i) { return option_value(argc, argv, i); };
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--experiments") {
      o.experiments = split(value(i));
      for(const auto& e : o.experiments)
        if(e != "a" && e != "b" && e != "c" && e != "d") {
          std::fprintf(stderr, "unknown experiment %s\n", e.c_str());
          std::exit(2);
        }
    } else if(a == "--large") {
      o.large = true;
    } else if(a == "--reps") {
      o.reps = std::max(1, std::atoi(value(i).c_str()));
    } else if(a == "--out") {
      o.out = value(i);
    } else if(a == "--seed") {
      o.seed = std::strtoull(value(i).c_str(), nullptr, 10);
    } else if(a == "--na") {
      for(const auto& s : split(value(i)))
        o.na.push_back(parse_n(s));
    } else if(a == "--nd") {
      for(const auto& s : split(value(i)))
        o.nd.push_back(parse_n(s));
    } else if(a == "--nb") {
      o.nb = parse_n(value(i));
    } else if(a == "--nc") {
      o.nc = parse_n(value(i));
    } else {
      help_or_unknown(a, argv[0], usage);
    }
  }
  if(o.na.empty()) {
    // 65000 and 70000 straddle 2^16, the threshold below which the import did not reorder
    // shuffled input when this program was written (see Statistics::input_reordered in the CSV).
    o.na = std::vector<std::size_t>{10000, 20000, 30000, 50000, 65000, 70000, 100000, 200000, 500000, 1000000};
    if(o.large)
      o.na.insert(o.na.end(), {2000000, 5000000});
  }
  if(o.nb == 0)
    o.nb = o.large ? 1000000 : 200000;
  if(o.nc == 0)
    o.nc = o.large ? 500000 : 100000;
  if(o.nd.empty())
    o.nd = o.large ? std::vector<std::size_t>{1000, 3000, 10000, 30000} : std::vector<std::size_t>{1000, 3000, 10000};
  return o;
}

int reps_for(const Options& o, std::size_t n)
{
  return n <= 100000 ? 2 * o.reps + 1 : n <= 500000 ? o.reps + 2 : o.reps;
}

std::ofstream open_csv(const Options& o, const std::string& name)
{
  const std::string path = o.out + "/" + name;
  std::ofstream f(path);
  if(!f) {
    std::fprintf(stderr, "cannot write %s (does the directory exist?)\n", path.c_str());
    std::exit(2);
  }
  f.precision(6);
  std::printf("# writing %s\n", path.c_str());
  return f;
}

// ---------------------------------------------------------------------------------------------
// (a) D = 0: time against n.
void experiment_a(const Options& o)
{
  std::printf("\n(a) D = 0, time against n: delaunay_from_prediction (shuffled faces), make_delaunay "
              "(on a Delaunay CGAL triangulation), CGAL's build\n");
  std::printf("%9s %10s %10s %10s %10s  %7s %7s  %s\n", "n", "CGAL[s]", "CGALinfo", "ours[s]",
              "make_del", "C/ours", "C/make", "path");
  std::ofstream csv = open_csv(o, "exp_a_time_vs_n.csv");
  csv << "n,reps,cgal_s,cgal_min_s,cgal_info_s,cgal_info_min_s,ours_s,ours_min_s,make_delaunay_s,"
         "make_delaunay_min_s,ratio_cgal_over_ours,ratio_cgal_over_make_delaunay,ours_fell_back,"
         "ours_flips,ours_input_reordered,make_delaunay_fell_back,make_delaunay_flips\n";
  for(const std::size_t n : o.na) {
    const std::vector<Point> points = uniform_points(n, seed_for(o.seed, "a/points", n));
    const std::vector<Face> faces = shuffled(DFP::delaunay_triangles(points), seed_for(o.seed, "a/shuffle", n));
    const std::vector<std::pair<Point, std::uint32_t>> with_index = with_indices(points);
    const DT base(points.begin(), points.end());
    DFP::Statistics ours, made;
    const int reps = reps_for(o, n);
    const std::vector<Times> t = measure(
        reps,
        {[&](Signature& s) { return time_cgal(points, s); },
         [&](Signature& s) { return time_cgal<DTI>(with_index, s); },
         [&](Signature& s) { return time_prediction(points, faces, ours, s); },
         [&](Signature& s) {
           DT tr = base; // copy, untimed
           return time_call(tr, [&] { made = DFP::make_delaunay(tr); }, s);
         }},
        "(a) n=" + std::to_string(n));
    check(!ours.fell_back && ours.flips == 0, "(a) delaunay_from_prediction at D = 0 flipped or fell back");
    check(!made.fell_back && made.flips == 0, "(a) make_delaunay on a Delaunay triangulation flipped or fell back");
    const double c = t[0].median(), ci = t[1].median(), d = t[2].median(), m = t[3].median();
    std::printf("%9zu %10.4f %10.4f %10.4f %10.4f  %7.2f %7.2f  %s%s\n", n, c, ci, d, m, c / d, c / m,
                ours.fell_back ? "FALLBACK" : "predict", ours.input_reordered ? " (reordered)" : "");
    std::fflush(stdout);
    csv << n << ',' << reps << ',' << c << ',' << t[0].min() << ',' << ci << ',' << t[1].min() << ','
        << d << ',' << t[2].min() << ',' << m << ',' << t[3].min() << ',' << c / d << ',' << c / m
        << ',' << int(ours.fell_back) << ',' << ours.flips << ',' << int(ours.input_reordered) << ','
        << int(made.fell_back) << ',' << made.flips << '\n';
  }
}

// ---------------------------------------------------------------------------------------------
// (b) time against D at fixed n: k random flips.
void experiment_b(const Options& o)
{
  const std::size_t n = o.nb;
  const std::size_t budget = DFP::internal::default_max_flips(n);
  std::printf("\n(b) n = %zu, k_flip_prediction: time against D; default flip budget n/2+64 = %zu\n", n, budget);
  std::printf("%9s %9s %9s %9s %9s  %9s %9s %9s  %s\n", "k", "D", "D_local", "Lawson", "", "CGAL[s]",
              "default", "no-limit", "default path");
  std::ofstream csv = open_csv(o, "exp_b_time_vs_D.csv");
  csv << "n,k,D,D_over_n,D_local,lawson_flips,flip_budget,reps,cgal_s,cgal_min_s,default_s,default_min_s,"
         "unlimited_s,unlimited_min_s,default_fell_back,default_reason,default_flips,ratio_cgal_over_default,"
         "ratio_cgal_over_unlimited\n";
  const std::vector<Point> points = uniform_points(n, seed_for(o.seed, "b/points", n));
  const std::vector<std::uint64_t> dt_edges = edges_of(DFP::delaunay_triangles(points));
  const double fractions[] = {0, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.25,
                              0.3, 0.4, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0};
  bool reported_fallback = false;
  for(const double fraction : fractions) {
    const std::size_t k = std::size_t(std::llround(fraction * double(n)));
    const std::vector<Triangle> predicted = DFP::k_flip_prediction(points, k, seed_for(o.seed, "b/flips", k));
    const std::size_t D = wrong_edges(edges_of(predicted), dt_edges);
    const std::vector<Face> faces = shuffled(predicted, seed_for(o.seed, "b/shuffle", k));
    DFP::Statistics def, unl;
    const int reps = reps_for(o, n);
    const std::vector<Times> t = measure_budgets(reps, points, faces, def, unl, "(b) k=" + std::to_string(k));
    check(unl.edges_not_locally_delaunay <= D && D <= unl.flips,
          "(b) k=" + std::to_string(k) + ": D_local <= D <= Lawson flips violated");
    const double c = t[0].median(), d = t[1].median(), u = t[2].median();
    std::printf("%9zu %9zu %9zu %9zu %9s  %9.4f %9.4f %9.4f  %s\n", k, D, unl.edges_not_locally_delaunay,
                unl.flips, "", c, d, u, def.fell_back ? (std::string("FALLBACK: ") + to_string(def.outcome)).c_str() : "predict");
    std::fflush(stdout);
    if(def.fell_back && !reported_fallback) {
      reported_fallback = true;
      std::printf("    -> first fallback of the default call at k = %zu, D = %zu (%.3f n), Lawson flips %zu > budget %zu\n",
                  k, D, double(D) / double(n), unl.flips, budget);
    }
    csv << n << ',' << k << ',' << D << ',' << double(D) / double(n) << ',' << unl.edges_not_locally_delaunay
        << ',' << unl.flips << ',' << budget << ',' << reps << ',' << c << ',' << t[0].min() << ',' << d << ','
        << t[1].min() << ',' << u << ',' << t[2].min() << ',' << int(def.fell_back) << ','
        << csv_quote(to_string(def.outcome)) << ',' << def.flips << ',' << c / d << ',' << c / u << '\n';
  }
}

// ---------------------------------------------------------------------------------------------
// (c) time against rho.
double paper_shape(std::size_t n, double rho)
{
  const double nn = double(n);
  return nn * std::log2(std::log2(nn)) + nn * std::log2(1.0 / rho);
}

void experiment_c(const Options& o)
{
  const std::size_t n = o.nc;
  std::printf("\n(c) n = %zu, time against rho (generation not timed)\n", n);
  std::printf("%-14s %5s %8s %9s %9s  %8s %8s %8s %8s  %s\n", "model", "rho", "D/n", "Lawson", "D_local",
              "gen[s]", "CGAL[s]", "default", "no-limit", "default path");
  const double rhos[] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95, 1.0};
  const char* models[] = {"rho_adversarial", "rho_random", "random_flip"};
  const std::vector<Point> points = uniform_points(n, seed_for(o.seed, "c/points", n));
  const std::vector<std::uint64_t> dt_edges = edges_of(DFP::delaunay_triangles(points));
  struct Row
  {
    std::string model;
    double rho;
    std::size_t D, D_local, lawson, default_flips;
    int reps;
    double gen, cgal, cgal_min, def, def_min, unl, unl_min;
    bool fell_back;
    std::string reason;
  };
  std::vector<Row> rows;
  for(const char* model : models)
    for(const double rho : rhos) {
      const std::uint64_t seed = seed_for(o.seed, std::string("c/") + model, std::uint64_t(rho * 1000));
      CGAL::Real_timer gen;
      gen.start();
      std::vector<Triangle> predicted = model_prediction(model, points, rho, seed);
      gen.stop();
      const std::size_t D = wrong_edges(edges_of(predicted), dt_edges);
      const std::vector<Face> faces = shuffled(predicted, seed ^ 0xabcdefull);
      predicted.clear();
      predicted.shrink_to_fit();
      DFP::Statistics def, unl;
      const int reps = reps_for(o, n);
      const std::vector<Times> t =
          measure_budgets(reps, points, faces, def, unl, std::string("(c) ") + model + " rho=" + std::to_string(rho));
      Row r{model, rho, D, unl.edges_not_locally_delaunay, unl.flips, def.flips, reps, gen.time(),
            t[0].median(), t[0].min(), t[1].median(), t[1].min(), t[2].median(), t[2].min(),
            def.fell_back, to_string(def.outcome)};
      std::printf("%-14s %5.2f %8.3f %9zu %9zu  %8.3f %8.4f %8.4f %8.4f  %s\n", model, rho,
                  double(D) / double(n), r.lawson, r.D_local, r.gen, r.cgal, r.def, r.unl,
                  def.fell_back ? (std::string("FALLBACK: ") + to_string(def.outcome)).c_str() : "predict");
      std::fflush(stdout);
      rows.push_back(r);
    }
  // One constant per model: c = exp(mean(log(t / shape))), the least-squares fit of log t, t the
  // minimum time of the pure-Lawson call.
  std::ofstream csv = open_csv(o, "exp_c_time_vs_rho.csv");
  csv << "model,n,rho,inv_rho,D,D_over_n,D_local,lawson_flips,flip_budget,reps,generation_s,cgal_s,"
         "cgal_min_s,default_s,default_min_s,unlimited_s,unlimited_min_s,default_fell_back,default_reason,"
         "default_flips,paper_shape,fit_constant,paper_fit_s\n";
  for(const char* model : models) {
    double sum = 0;
    int count = 0;
    for(const Row& r : rows)
      if(r.model == model) {
        sum += std::log(r.unl_min / paper_shape(n, r.rho));
        ++count;
      }
    const double c = std::exp(sum / count);
    double worst = 1;
    for(const Row& r : rows)
      if(r.model == model) {
        const double fit = c * paper_shape(n, r.rho);
        worst = std::max(worst, std::max(r.unl_min / fit, fit / r.unl_min));
        csv << r.model << ',' << n << ',' << r.rho << ',' << 1.0 / r.rho << ',' << r.D << ','
            << double(r.D) / double(n) << ',' << r.D_local << ',' << r.lawson << ','
            << DFP::internal::default_max_flips(n) << ',' << r.reps << ',' << r.gen << ',' << r.cgal << ','
            << r.cgal_min << ',' << r.def << ',' << r.def_min << ',' << r.unl << ',' << r.unl_min << ','
            << int(r.fell_back) << ',' << csv_quote(r.reason) << ',' << r.default_flips << ','
            << paper_shape(n, r.rho) << ',' << c << ',' << fit << '\n';
      }
    const Row* lo = nullptr;
    const Row* hi = nullptr;
    for(const Row& r : rows)
      if(r.model == model) {
        if(r.rho == 0.05)
          lo = &r;
        if(r.rho == 1.0)
          hi = &r;
      }
    std::printf("    %-15s fit c = %.3g ns per unit of n log2 log2 n + n log2(1/rho); worst factor "
                "between fit and no-limit time (min) %.2f",
                model, c * 1e9, worst);
    if(lo && hi)
      std::printf("; no-limit time rho=0.05 / rho=1: %.1f (Lawson flips %.2f n)", lo->unl_min / hi->unl_min,
                  double(lo->lawson) / double(n));
    std::printf("\n");
  }
}

// ---------------------------------------------------------------------------------------------
// (d) relations between the measures.

// A prediction model of this program (not of the package) with a small d_vio: up to k flips of
// uniformly drawn edges of DT(P), each made only if the quadrilateral is strictly convex and
// both new triangles have a circumradius of at most `cap` mean spacings (sqrt(area / n), the
// points' bounding box). Every face of the result has a small circumcircle, so on well-spread
// points few points lie inside it. Returns the number of flips made in `made`.
std::vector<Triangle> capped_flip_prediction(const std::vector<Point>& points, std::size_t k, double cap,
                                             std::uint64_t seed, std::size_t& made)
{
  DTI dt = build_indexed(points);
  const CGAL::Bbox_2 box = CGAL::bbox_2(points.begin(), points.end());
  const double spacing = std::sqrt((box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) / double(points.size()));
  const double r2 = cap * cap * spacing * spacing;
  const std::vector<DTI::Face_handle> faces = finite_face_handles(dt);
  const auto small_circles = [&](const Point& p, const Point& q, const Point& r, const Point& s) {
    return CGAL::squared_radius(p, q, r) <= r2 && CGAL::squared_radius(p, r, s) <= r2;
  };
  Rng rng{seed};
  made = 0;
  for(std::size_t draws = 64 * (k + faces.size()); made < k && draws > 0; --draws)
    if(try_random_flip(dt, faces, rng, small_circles))
      ++made;
  return export_faces<Triangle>(dt);
}
struct Instance
{
  std::string set, model;
  double param = 0;     // rho, k/n, noise, lists, ...
  double rho = -1;      // for the rho models, else negative
  std::size_t k = 0;    // flips asked for (k_flips, capped_flips)
  std::vector<Point> points;
  std::vector<Triangle> faces;
};

void experiment_d(const Options& o)
{
  std::printf("\n(d) measures on every model (checks D_local <= D <= Lawson flips <= D_cross, D = D_missing)\n");
  std::ofstream csv = open_csv(o, "exp_d_measures.csv");
  csv << "set,model,param,rho,k,n,faces,is_triangulation,not_a_triangulation,D,D_missing,D_local,D_cross,"
         "d_cross,D_vio,d_vio,D_flip_lower,lawson_flips,d_vio_squared,inv_rho_ln_n,measure_s,violation\n";
  const double rhos[] = {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 0.95};
  const std::size_t n_mid = o.nd[o.nd.size() / 2];
  std::size_t instances = 0, triangulations = 0, violations = 0;
  std::vector<std::string> set_names{"uniform", "jgrid80", "jgrid10"};
  // Per (set, model): least-squares slope through the origin of d_cross against (1/rho) ln n.
  // Also the power law d_cross = a x^b fitted to the logarithms (instances with d_cross > 0).
  struct Fit
  {
    double xy = 0, xx = 0;
    int count = 0;
    double max_ratio = 0;
    double lx = 0, ly = 0, lxx = 0, lxy = 0;
    int logs = 0;
  };
  std::vector<std::pair<std::string, Fit>> fits;
  auto fit_of = [&](const std::string& key) -> Fit& {
    for(auto& f : fits)
      if(f.first == key)
        return f.second;
    fits.emplace_back(key, Fit());
    return fits.back().second;
  };
  double max_dcross_over_dvio2 = 0;
  std::string max_dcross_over_dvio2_at;
  CGAL::Real_timer total;
  total.start();

  auto run = [&](Instance& in) {
    CGAL::Real_timer timer;
    timer.start();
    const DFP::Prediction_measures m = DFP::prediction_measures(in.points, in.faces);
    timer.stop();
    ++instances;
    const std::size_t n = in.points.size();
    std::string violation;
    if(m.is_triangulation) {
      ++triangulations;
      if(!(m.D_local <= m.D))
        violation += "D_local>D;";
      if(m.D != m.D_missing)
        violation += "D!=D_missing;";
      if(!m.D_flip_upper)
        violation += "no_Lawson_count;";
      else {
        if(!(m.D <= *m.D_flip_upper))
          violation += "D>Lawson;";
        if(!(*m.D_flip_upper <= m.D_cross))
          violation += "Lawson>D_cross;";
      }
      if(!(m.d_cross <= m.D_cross) || !(m.d_vio <= m.D_vio))
        violation += "max>sum;";
      if((m.D == 0) != (m.D_cross == 0) || (m.D == 0) != (m.D_vio == 0))
        violation += "zero_mismatch;";
      if(m.d_vio > 0) {
        const double r = double(m.d_cross) / (double(m.d_vio) * double(m.d_vio));
        if(r > max_dcross_over_dvio2) {
          max_dcross_over_dvio2 = r;
          max_dcross_over_dvio2_at = in.set + " " + in.model + " param " + std::to_string(in.param) + " n " + std::to_string(n);
        }
      }
    }
    if(!violation.empty()) {
      ++violations;
      std::printf("!!!!!!!! VIOLATION %s: %s %s param %g n %zu: D_local %zu D %zu D_missing %zu Lawson %s D_cross %zu\n",
                  violation.c_str(), in.set.c_str(), in.model.c_str(), in.param, n, m.D_local, m.D,
                  m.D_missing, m.D_flip_upper ? std::to_string(*m.D_flip_upper).c_str() : "-", m.D_cross);
      check(false, "(d) measure relation violated: " + violation);
    }
    const double x = in.rho > 0 ? std::log(double(n)) / in.rho : 0;
    if(in.rho > 0 && m.is_triangulation) {
      Fit& f = fit_of(in.set + " " + in.model);
      f.xy += x * double(m.d_cross);
      f.xx += x * x;
      ++f.count;
      f.max_ratio = std::max(f.max_ratio, double(m.d_cross) / x);
      if(m.d_cross > 0) {
        const double lx = std::log(x), ly = std::log(double(m.d_cross));
        f.lx += lx;
        f.ly += ly;
        f.lxx += lx * lx;
        f.lxy += lx * ly;
        ++f.logs;
      }
    }
    csv << in.set << ',' << in.model << ',' << in.param << ',';
    if(in.rho >= 0)
      csv << in.rho;
    csv << ',';
    if(in.k > 0)
      csv << in.k;
    csv << ',' << n << ',' << m.faces << ',' << int(m.is_triangulation) << ',' << csv_quote(m.not_a_triangulation)
        << ',' << m.D << ',' << m.D_missing << ',' << m.D_local << ',' << m.D_cross << ',' << m.d_cross
        << ',' << m.D_vio << ',' << m.d_vio << ',' << m.D_flip_lower << ',';
    if(m.D_flip_upper)
      csv << *m.D_flip_upper;
    csv << ',' << double(m.d_vio) * double(m.d_vio) << ',';
    if(in.rho > 0)
      csv << x;
    csv << ',' << timer.time() << ',' << csv_quote(violation) << '\n';
    csv.flush();
  };

  // rho model (both completions) and random-flip model, at every n of --nd.
  for(const std::string& set : set_names)
    for(const std::size_t n : o.nd) {
      CGAL::Real_timer t;
      t.start();
      Instance in;
      in.set = set;
      in.points = make_points(set, n, seed_for(o.seed, "d/points/" + set, n));
      for(const char* model : {"rho_adversarial", "rho_random", "random_flip"})
        for(const double rho : rhos)
          for(int rep = 0; rep < 2; ++rep) {
            const std::uint64_t seed = seed_for(o.seed, "d/" + set + "/" + model + std::to_string(rep),
                                                std::uint64_t(rho * 1000) + 7919 * n);
            in.model = model;
            in.param = in.rho = rho;
            in.faces = model_prediction(model, in.points, rho, seed);
            run(in);
          }
      t.stop();
      std::printf("    %-8s n=%6zu rho models: %.1f s\n", set.c_str(), in.points.size(), t.time());
      std::fflush(stdout);
    }
  // k flips and moved points at the middle n.
  for(const std::string& set : set_names) {
    CGAL::Real_timer t;
    t.start();
    Instance in;
    in.set = set;
    in.points = make_points(set, n_mid, seed_for(o.seed, "d/points/" + set, n_mid));
    const std::size_t n = in.points.size();
    in.model = "k_flips";
    for(const double f : {0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0, 3.0}) {
      in.param = f;
      in.k = std::size_t(std::llround(f * double(n)));
      in.faces = DFP::k_flip_prediction(in.points, in.k, seed_for(o.seed, "d/kflips/" + set, std::uint64_t(f * 1000)));
      run(in);
    }
    in.model = "capped_flips";
    for(const double cap : {0.75, 1.0, 1.5, 2.0, 3.0, 4.0})
      for(const double f : {0.1, 1.0}) {
        in.param = cap;
        std::size_t made = 0;
        in.faces = capped_flip_prediction(in.points, std::size_t(std::llround(f * double(n))), cap,
                                          seed_for(o.seed, "d/capped/" + set, std::uint64_t(cap * 100 + f * 7)), made);
        in.k = made;
        run(in);
      }
    in.k = 0;
    in.model = "moved_points";
    for(const double noise : {0.001, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0}) {
      in.param = noise;
      in.faces = DFP::moved_points_prediction(in.points, noise,
                                              seed_for(o.seed, "d/moved/" + set, std::uint64_t(noise * 1e4)));
      run(in);
    }
    t.stop();
    std::printf("    %-8s n=%6zu k flips, moved points: %.1f s\n", set.c_str(), n, t.time());
    std::fflush(stdout);
  }
  // The lower-bound configurations (D_cross ~ n^2: small).
  {
    CGAL::Real_timer t;
    t.start();
    auto run_lists = [&](const char* model, std::size_t param, auto&& configuration) {
      Instance in;
      in.set = "lists";
      in.model = model;
      in.param = double(param);
      in.points = std::move(configuration.points);
      in.faces = std::move(configuration.faces);
      run(in);
    };
    const std::size_t target = o.large ? 2000 : 1000;
    for(const std::size_t k : {2, 4, 8, 16, 32, 64}) {
      const std::size_t m = std::max<std::size_t>(1, target / k);
      run_lists("merging_lists", k, DFP::merging_lists_configuration<K>(k, m, seed_for(o.seed, "d/merge", k)));
    }
    for(const std::size_t n : {100, 300, 1000})
      run_lists("sorting", n, DFP::sorting_configuration<K>(n, seed_for(o.seed, "d/sort", n)));
    t.stop();
    std::printf("    merging lists, sorting: %.1f s\n", t.time());
  }
  total.stop();
  std::printf("    %zu instances (%zu triangulations) in %.1f s; relation violations: %zu%s\n", instances,
              triangulations, total.time(), violations,
              violations == 0 ? " (D_local <= D <= Lawson <= D_cross and D = D_missing held everywhere)" : "");
  std::printf("    largest d_cross / d_vio^2 over triangulations: %.3g (%s)\n", max_dcross_over_dvio2,
              max_dcross_over_dvio2_at.c_str());
  std::ofstream fits_csv = open_csv(o, "exp_d_dcross_fits.csv");
  fits_csv << "set,model,instances,slope_through_0,largest_ratio,power_a,power_b\n";
  for(const auto& [key, f] : fits) {
    const double b = (f.logs * f.lxy - f.lx * f.ly) / (f.logs * f.lxx - f.lx * f.lx);
    const double a = std::exp((f.ly - b * f.lx) / f.logs);
    std::printf("    d_cross vs x = (1/rho) ln n, %-24s slope through 0: %.3f, largest d_cross/x %.3f, "
                "power law %.2f x^%.2f (%d instances)\n",
                key.c_str(), f.xy / f.xx, f.max_ratio, a, b, f.count);
    const std::size_t space = key.find(' ');
    fits_csv << key.substr(0, space) << ',' << key.substr(space + 1) << ',' << f.count << ',' << f.xy / f.xx
             << ',' << f.max_ratio << ',' << a << ',' << b << '\n';
  }
}

} // namespace

int main(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  const bool keep = keep_freed_memory();

  std::string command;
  for(int i = 0; i < argc; ++i)
    command += (i ? " " : "") + std::string(argv[i]);
  std::ostringstream header;
  header << "Delaunay_from_prediction experiments, " << local_date_time() << "\n"
         << "command: " << command << "\n"
         << "machine: " << sysconf(_SC_NPROCESSORS_ONLN) << " CPUs online, " << read_first("/proc/cpuinfo", "model name") << "\n"
         << "build:   " << build_description() << "\n"
         << "setup:   Epick, CGAL::Delaunay_triangulation_2<Epick> for CGAL and for us, one thread, wall clock,\n"
         << "         median (and min) of the repetitions, interleaved; malloc "
         << (keep ? "keep (no trim, no mmap)" : "glibc default (mallopt failed)") << "; seed " << o.seed << "\n";
  std::printf("%s", header.str().c_str());
  {
    std::ofstream meta(o.out + "/experiments_info.txt");
    if(!meta) {
      std::fprintf(stderr, "cannot write %s/experiments_info.txt (does the directory exist?)\n", o.out.c_str());
      return 2;
    }
    meta << header.str();
  }

  CGAL::Real_timer total;
  total.start();
  if(o.wants("a"))
    experiment_a(o);
  if(o.wants("b"))
    experiment_b(o);
  if(o.wants("c"))
    experiment_c(o);
  if(o.wants("d"))
    experiment_d(o);
  total.stop();
  std::printf("\ntotal %.1f s. ", total.time());
  if(check_failures == 0) {
    std::printf("All checks passed.\n");
    return 0;
  }
  std::printf("!!!!!!!! %d CHECK(S) FAILED !!!!!!!!\n", check_failures);
  return 1;
}
