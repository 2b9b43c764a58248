// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Imprecise_points_2 against CGAL, and the table of Section 5 of Devillers' paper reproduced:
// time per point and triangles visited per point for
//   - "hint, random order": an instance triangulated with Disk_order::random;
//   - "spatial sort + insert": CGAL's range insert (spatial_sort, then each point located
//     from the previous one); its sort timed alone on a copy of the points;
//   - "Delaunay hierarchy": CGAL's Triangulation_hierarchy_2, points inserted one by one in
//     the order of the point set (a random order);
//   - "hint, spatial order": an instance triangulated with Disk_order::spatial (the default);
// plus the preprocessing time per disk of both orders and the ratio CGAL range insert / ours.
//
// The point set is the paper's: disk centres drawn uniformly in a 2 sqrt(n) x 2 sqrt(n)
// square, each kept if farther than 1 from those kept before (disjoint disks of radius 1/2);
// one instance point uniform in each disk (case "inside"). Case "2 radii": the instance points
// uniform in the disks of radius 1 around the centres, outside their disks 3/4 of the time.
// "Triangles per point" for the walks from hints is faces entered per located point
// (Statistics::faces_visited / points_located); for the spatial sort it is the same count for
// a visibility walk from the previous point's vertex in CGAL's spatial_sort order, measured in
// a separate, untimed pass. Every result is checked against CGAL's (face set signature).
// Times are medians over --reps repetitions (calls alternating) and over the point sets.
//
// Usage: bench_imprecise_points [--n 1e3,1e4,1e5,1e6] [--sets S] [--reps 3] [--cases inside,2radii]
//                               [--seed S] [--csv file]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/imprecise_points.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>
#include <CGAL/spatial_sort.h>

#include <cmath>

using namespace dfp_bench;

namespace {

using Hierarchy_tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<
    CGAL::Triangulation_vertex_base_2<K>>>;
using Hierarchy = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<K, Hierarchy_tds>>;
using Imprecise = DFP::Imprecise_points_2<K>;

// The paper's disk centres (dart throwing on a grid of unit cells: a new centre is compared
// with the centres of the 3 x 3 cells around it).
std::vector<Point> paper_centres(std::size_t n, Rng& rng)
{
  const double side = 2 * std::sqrt(double(n));
  const std::size_t cells = std::size_t(side) + 1;
  std::vector<std::vector<std::uint32_t>> cell(cells * cells);
  std::vector<Point> centres;
  centres.reserve(n);
  while(centres.size() < n) {
    const double x = side * rng.uniform(), y = side * rng.uniform();
    const std::size_t cx = std::size_t(x), cy = std::size_t(y);
    bool far = true;
    for(std::size_t a = cx > 0 ? cx - 1 : 0; a <= cx + 1 && a < cells && far; ++a)
      for(std::size_t b = cy > 0 ? cy - 1 : 0; b <= cy + 1 && b < cells && far; ++b)
        for(std::uint32_t i : cell[b * cells + a]) {
          const double dx = centres[i].x() - x, dy = centres[i].y() - y;
          if(dx * dx + dy * dy <= 1) {
            far = false;
            break;
          }
        }
    if(far) {
      cell[cy * cells + cx].push_back(std::uint32_t(centres.size()));
      centres.emplace_back(x, y);
    }
  }
  return centres;
}

// One point uniform in the disk of radius r around each centre.
std::vector<Point> instance_of(const std::vector<Point>& centres, double r, Rng& rng)
{
  std::vector<Point> points;
  points.reserve(centres.size());
  for(const Point& c : centres) {
    double u, v;
    do {
      u = 2 * rng.uniform() - 1;
      v = 2 * rng.uniform() - 1;
    } while(u * u + v * v > 1);
    points.emplace_back(c.x() + r * u, c.y() + r * v);
  }
  return points;
}

// Faces entered per point by a visibility walk from the previous point's vertex, in CGAL's
// spatial_sort order (what CGAL's range insert does, counted with the package's walk).
double spatial_sort_walk_length(std::vector<Point> points)
{
  CGAL::spatial_sort(points.begin(), points.end(), K());
  DT dt;
  std::vector<std::pair<DT::Face_handle, int>> stack;
  std::size_t steps = 0, located = 0;
  DT::Face_handle hint;
  for(const Point& p : points) {
    if(dt.dimension() == 2) {
      DT::Face_handle f = hint;
      int collinear = 0;
      DFP::internal::walk_towards(dt, f, p, std::size_t(-1), steps, collinear);
      ++located;
    }
    hint = DFP::internal::insert_near(dt, p, hint, stack)->face();
  }
  return located ? double(steps) / double(located) : 0;
}

struct Row
{
  std::vector<double> pre_random, pre_spatial;        // s per set
  std::vector<double> random, spatial, cgal, sort, hierarchy; // s per set (medians of reps)
  std::vector<double> walk_random, walk_spatial, walk_sorted; // faces per located point
};

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes = {1000, 10000, 100000, 1000000};
  std::vector<std::string> cases = {"inside", "2radii"};
  int reps = 3, sets = 0;
  std::uint64_t seed = 20261127;
  std::string csv_file;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = sizes_of(option_value(argc, argv, i));
    else if(a == "--cases")
      cases = split(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--sets")
      sets = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else if(a == "--csv")
      csv_file = option_value(argc, argv, i);
    else {
      std::printf("usage: %s [--n 1e3,1e4,1e5,1e6] [--sets S] [--reps 3] [--cases inside,2radii] [--seed S] "
                  "[--csv file]\n",
                  argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_imprecise_points, %s, %s, malloc policy %s, reps %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::printf("# times in us per point (medians); faces = faces entered per located point; ratio = CGAL range "
              "insert / ours, spatial order\n");
  std::printf("%-7s %8s %4s | %8s %8s | %8s %6s | %8s %8s %6s | %8s | %8s %6s | %6s\n", "case", "n", "sets",
              "pre rnd", "pre spa", "hint rnd", "faces", "sort", "insert", "faces", "hierar.", "hint spa",
              "faces", "ratio");
  std::ofstream csv;
  if(!csv_file.empty()) {
    csv.open(csv_file);
    csv << "case,n,sets,preprocess_random_us,preprocess_spatial_us,hint_random_us,hint_random_faces,"
           "spatial_sort_us,spatial_insert_us,spatial_sort_faces,hierarchy_us,hint_spatial_us,hint_spatial_faces,"
           "cgal_us,ratio\n";
  }
  bool all_same = true;
  for(const std::string& what : cases) {
    const double instance_radius = what == "2radii" ? 1.0 : 0.5;
    for(const std::size_t n : sizes) {
      const int point_sets = sets > 0 ? sets : int(std::max<std::size_t>(1, std::min<std::size_t>(10, 1000000 / n)));
      Row row;
      for(int set = 0; set < point_sets; ++set) {
        Rng rng{salted_seed(0xd15c, seed, what, n * 100 + std::size_t(set))};
        const std::vector<Point> centres = paper_centres(n, rng);
        const std::vector<Point> points = instance_of(centres, instance_radius, rng);
        CGAL::Real_timer timer;
        timer.start();
        const Imprecise random_order(centres, K::FT(0.5), DFP::parameters::disk_order(DFP::Disk_order::random));
        timer.stop();
        row.pre_random.push_back(timer.time());
        timer.reset();
        timer.start();
        const Imprecise spatial_order(centres, K::FT(0.5));
        timer.stop();
        row.pre_spatial.push_back(timer.time());
        std::vector<double> t_random, t_spatial, t_cgal, t_sort, t_hierarchy;
        DFP::Statistics s_random, s_spatial;
        for(int r = 0; r < reps; ++r) {
          Signature reference, sig;
          t_cgal.push_back(time_cgal(points, reference));
          {
            DT dt;
            t_spatial.push_back(time_call(dt, [&] { s_spatial = spatial_order.triangulate(points, dt); }, sig));
            all_same = all_same && sig == reference;
          }
          {
            DT dt;
            t_random.push_back(time_call(dt, [&] { s_random = random_order.triangulate(points, dt); }, sig));
            all_same = all_same && sig == reference;
          }
          {
            std::vector<Point> copy = points;
            timer.reset();
            timer.start();
            CGAL::spatial_sort(copy.begin(), copy.end(), K());
            timer.stop();
            t_sort.push_back(timer.time());
          }
          {
            Hierarchy h;
            timer.reset();
            timer.start();
            for(const Point& p : points)
              h.insert(p);
            timer.stop();
            t_hierarchy.push_back(timer.time());
            all_same = all_same && signature(h) == reference;
          }
        }
        row.cgal.push_back(median(t_cgal));
        row.spatial.push_back(median(t_spatial));
        row.random.push_back(median(t_random));
        row.sort.push_back(median(t_sort));
        row.hierarchy.push_back(median(t_hierarchy));
        row.walk_random.push_back(double(s_random.faces_visited) / double(std::max<std::size_t>(1, s_random.points_located)));
        row.walk_spatial.push_back(double(s_spatial.faces_visited) /
                                   double(std::max<std::size_t>(1, s_spatial.points_located)));
        row.walk_sorted.push_back(spatial_sort_walk_length(points));
      }
      const double us = 1e6 / double(n);
      const double cgal = median(row.cgal), sort = median(row.sort), spatial = median(row.spatial);
      std::printf("%-7s %8zu %4d | %8.3f %8.3f | %8.3f %6.2f | %8.3f %8.3f %6.2f | %8.3f | %8.3f %6.2f | %6.2f\n",
                  what.c_str(), n, point_sets, median(row.pre_random) * us, median(row.pre_spatial) * us,
                  median(row.random) * us, median(row.walk_random), sort * us, (cgal - sort) * us,
                  median(row.walk_sorted), median(row.hierarchy) * us, spatial * us, median(row.walk_spatial),
                  cgal / spatial);
      std::fflush(stdout);
      if(csv.is_open())
        csv << what << ',' << n << ',' << point_sets << ',' << median(row.pre_random) * us << ','
            << median(row.pre_spatial) * us << ',' << median(row.random) * us << ',' << median(row.walk_random) << ','
            << sort * us << ',' << (cgal - sort) * us << ',' << median(row.walk_sorted) << ','
            << median(row.hierarchy) * us << ',' << spatial * us << ',' << median(row.walk_spatial) << ','
            << cgal * us << ',' << cgal / spatial << '\n';
    }
  }
  std::printf("# every result equal to CGAL's: %s\n", all_same ? "yes" : "NO");
  return all_same ? 0 : 1;
}
