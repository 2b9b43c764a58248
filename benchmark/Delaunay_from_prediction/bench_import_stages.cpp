// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// delaunay_from_prediction() on index triples stage by stage, on one thread and with
// CGAL::Parallel_tag in a TBB arena of --threads threads: what limits its parallel speed-up
// (an ablation of the call into the stages it runs one after the other). The stages are
// called as delaunay_from_prediction() calls them on its default path:
//   read     the faces validated into 32-bit triples (read_index_triples());
//   screens  the sampling screen and the count of missing faces;
//   order    the spatial reordering of points and faces, with the copy of the points;
//   import   the import with its certificate (orientation, pairing, in-circle tests);
//   flips    Lawson's flips of the edges that failed;
// and a last column times the whole call on a fresh triangulation; what it spends beyond the
// stages is the construction and swap of the result and the count of certified faces. Cases
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

#include <CGAL/Delaunay_from_prediction/internal/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/import_prediction.h>
#include <CGAL/Delaunay_from_prediction/internal/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/prediction_screens.h>
#include <CGAL/hilbert_sort.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace dfp_bench;

namespace {

constexpr int stage_count = 6;
const char* const stage_names[stage_count] = {"read", "screens", "order", "import", "flips", "call"};

// The stages of delaunay_from_prediction()'s default path, timed into `seconds[0..4]`; the
// result in `dt`. False if the prediction does not take that path (a screen or the import
// failed, holes to repair).
bool run_stages(const std::vector<Point>& points, const std::vector<Face>& faces, DT& dt, bool parallel,
                double* seconds)
{
  namespace internal = DFP::internal;
  const std::size_t n = points.size();
  CGAL::Real_timer clock;
  clock.start();
  double last = 0;
  auto lap = [&](int stage) {
    const double now = clock.time();
    seconds[stage] = now - last;
    last = now;
  };
  std::vector<std::uint32_t> triples;
  if(!internal::read_index_triples(faces, n, faces.size(), triples, parallel))
    return false;
  lap(0);
  const auto& gt = dt.geom_traits();
  if(internal::fails_sampling_screen(gt, points.begin(), n, triples) ||
     internal::missing_faces_exceed(gt, points.begin(), n, triples, n / 8 + 16))
    return false;
  lap(1);
  internal::Imported_prediction<DT> imported;
  double import_seconds[2] = {0, 0};
  internal::Prediction_importer<DT>::run(dt, points.begin(), n, triples, imported, true, parallel,
                                         import_seconds);
  clock.stop();
  seconds[2] = import_seconds[0];
  seconds[3] = import_seconds[1];
  clock.start();
  last = clock.time();
  if(imported.failure != internal::Outcome::ok || imported.needs_repair || !imported.unused_points.empty())
    return false;
  std::vector<DT::Face_handle> touched;
  std::size_t flips = 0;
  const bool flipped =
      internal::lawson_flip(dt, imported.not_locally_delaunay, std::size_t(-1), flips, touched, parallel);
  lap(4);
  return flipped;
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
  for(const char* name : stage_names)
    std::printf(" %9s", name);
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
          ok = ok && (!ran || got == expected);
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
  std::printf("(seconds, medians; read + screens + order + import + flips are the stages called one by one,\n"
              " call the whole delaunay_from_prediction() on a fresh triangulation)\n");
  return all_ok ? 0 : 1;
#endif
}
