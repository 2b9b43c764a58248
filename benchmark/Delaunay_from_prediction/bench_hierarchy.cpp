// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// CGAL::Triangulation_hierarchy_2 filled by the package against CGAL's own hierarchy build
// (Triangulation_hierarchy_2::insert(begin, end)), uniform points, per repetition (the calls
// alternating):
//   - "cgal":       CGAL's hierarchy build;
//   - "dfp":        delaunay_from_prediction() into a hierarchy, perfect prediction;
//   - "dfp DT":     the same into a plain Delaunay_triangulation_2 (no upper levels);
//   - "levels":     the upper levels alone, sampled anew from level 0 (rebuild_upper_levels());
//   - "make":       make_delaunay() on CGAL's hierarchy after moves of 0.1 spacing;
//   - "make DT":    the same on a plain Delaunay_triangulation_2;
//   - "locate":     the same random queries located in CGAL's hierarchy and in ours.
// Printed: medians of the per-repetition ratios to "cgal" (locate: ours over CGAL's), and the
// level-1 sizes. Every result is checked against CGAL's (face-set signatures).
//
// Usage: bench_hierarchy [--n 1e5,1e6] [--reps 5] [--seed S]

#include "benchmark_util.h"

#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>

using namespace dfp_bench;

using H = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<CGAL::Triangulation_vertex_base_2<K>>>>>;

std::size_t level_one_size(const H& h)
{
  std::size_t count = 0;
  for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v)
    count += v->up() != H::Vertex_handle() ? 1 : 0;
  return count;
}

template <class Tr>
double time_locate(const Tr& tr, const std::vector<Point>& queries, std::uint64_t& checksum)
{
  CGAL::Real_timer timer;
  timer.start();
  for(const Point& q : queries) {
    const auto f = tr.locate(q);
    checksum += reinterpret_cast<std::uintptr_t>(&*f->vertex(0)) >> 4;
  }
  timer.stop();
  return timer.time();
}

void usage(const char* program) { std::printf("usage: %s [--n 1e5,1e6] [--reps 5] [--seed S]\n", program); }

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {100000, 1000000};
  int reps = 5;
  std::uint64_t seed = 20261201;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = sizes_of(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else
      help_or_unknown(a, argv[0], usage);
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_hierarchy, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::printf("n,cgal_s,dfp/cgal,dfp_DT/cgal,levels/cgal,make/cgal,make_DT/cgal,locate_ours/cgal,locate_us_per_query,"
              "level1_ours,level1_cgal\n");
  bool all_same = true;
  for(const std::size_t n : sizes) {
    const std::vector<Point> points = uniform_points(n, salted_seed(0x41e7, seed, "points", n));
    const std::vector<Face> faces = export_faces(build_indexed(points));
    Rng rng{salted_seed(0x41e8, seed, "moves", n)};
    const double spacing = 1. / std::sqrt(double(n));
    std::vector<Point> queries(n);
    for(Point& q : queries)
      q = Point(rng.uniform(), rng.uniform());
    std::vector<double> t_cgal, r_dfp, r_dfp_dt, r_levels, r_make, r_make_dt, r_locate, us_locate;
    std::size_t level1_ours = 0, level1_cgal = 0;
    std::uint64_t checksum = 0;
    for(int rep = 0; rep < reps; ++rep) {
      Signature sig_cgal, sig, sig_moved_cgal;
      H cgal;
      const double cgal_s = time_call(cgal, [&] { cgal.insert(points.begin(), points.end()); }, sig_cgal);
      level1_cgal = level_one_size(cgal);
      H ours;
      const double dfp_s = time_call(ours, [&] { DFP::delaunay_from_prediction(points, faces, ours); }, sig);
      all_same = all_same && sig == sig_cgal && ours.is_valid();
      level1_ours = level_one_size(ours);
      double dfp_dt_s;
      {
        DT dt;
        dfp_dt_s = time_call(dt, [&] { DFP::delaunay_from_prediction(points, faces, dt); }, sig);
        all_same = all_same && sig == sig_cgal;
      }
      CGAL::Real_timer timer;
      timer.start();
      DFP::internal::rebuild_upper_levels(ours);
      timer.stop();
      const double levels_s = timer.time();
      // locate, interleaved: CGAL's, ours, CGAL's, ours (halves of the queries).
      double locate_cgal = 0, locate_ours = 0;
      {
        const std::size_t half = queries.size() / 2;
        const std::vector<Point> a(queries.begin(), queries.begin() + std::ptrdiff_t(half));
        const std::vector<Point> b(queries.begin() + std::ptrdiff_t(half), queries.end());
        std::uint64_t sum_cgal = 0, sum_ours = 0;
        locate_cgal += time_locate(cgal, a, sum_cgal);
        locate_ours += time_locate(ours, a, sum_ours);
        locate_ours += time_locate(ours, b, sum_ours);
        locate_cgal += time_locate(cgal, b, sum_cgal);
        checksum += sum_cgal + sum_ours;
      }
      // make_delaunay after moves, on a hierarchy built by CGAL (the copies are not timed).
      double make_s, make_dt_s;
      {
        H moving(cgal);
        for(auto v = moving.finite_vertices_begin(); v != moving.finite_vertices_end(); ++v)
          v->set_point(Point(v->point().x() + 0.1 * spacing * (2 * rng.uniform() - 1),
                             v->point().y() + 0.1 * spacing * (2 * rng.uniform() - 1)));
        DT plain;
        plain.insert(points.begin(), points.end());
        {
          // The same moves for the plain triangulation: by point.
          std::vector<std::pair<Point, Point>> to;
          auto v = cgal.finite_vertices_begin();
          for(auto w = moving.finite_vertices_begin(); w != moving.finite_vertices_end(); ++w, ++v)
            to.emplace_back(v->point(), w->point());
          std::sort(to.begin(), to.end());
          for(auto u = plain.finite_vertices_begin(); u != plain.finite_vertices_end(); ++u)
            u->set_point(std::lower_bound(to.begin(), to.end(), std::make_pair(u->point(), Point(-1e300, -1e300)))->second);
        }
        make_s = time_call(moving, [&] { DFP::make_delaunay(moving); }, sig);
        Signature sig_dt;
        make_dt_s = time_call(plain, [&] { DFP::make_delaunay(plain); }, sig_dt);
        std::vector<Point> moved_points;
        for(auto w = moving.finite_vertices_begin(); w != moving.finite_vertices_end(); ++w)
          moved_points.push_back(w->point());
        time_cgal(moved_points, sig_moved_cgal);
        all_same = all_same && sig == sig_moved_cgal && sig_dt == sig_moved_cgal && moving.is_valid();
      }
      t_cgal.push_back(cgal_s);
      r_dfp.push_back(dfp_s / cgal_s);
      r_dfp_dt.push_back(dfp_dt_s / cgal_s);
      r_levels.push_back(levels_s / cgal_s);
      r_make.push_back(make_s / cgal_s);
      r_make_dt.push_back(make_dt_s / cgal_s);
      r_locate.push_back(locate_ours / locate_cgal);
      us_locate.push_back(1e6 * locate_cgal / double(queries.size()));
    }
    std::printf("%zu,%.4f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%zu,%zu\n", n, median(t_cgal), median(r_dfp),
                median(r_dfp_dt), median(r_levels), median(r_make), median(r_make_dt), median(r_locate),
                median(us_locate), level1_ours, level1_cgal);
    std::fflush(stdout);
    if(checksum == 42)
      std::printf("#\n");
  }
  std::printf("# results identical to CGAL's: %s\n", all_same ? "yes" : "NO");
  return all_same ? 0 : 1;
}
