// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// How to fill the holes of the local repair: the candidates timed against each other. The holes `carve` makes are links of carved vertices: star-shaped polygons of
// about six vertices (measured at 1e6 points moved by 0.1 spacing: 48,861 carved faces in 7,757
// holes). This program takes the link of every k-th interior vertex of the Delaunay
// triangulation of n uniform points (the hole its carving leaves) and fills every one of them
// with each candidate, timing the whole batch (median of --reps):
//   ear clipping   the package's filler (internal/import/hole_tracing.h), scratch space reused;
//   DT per hole    an auxiliary CGAL Delaunay_triangulation_2 of the hole's points, built anew
//                  for each hole (what "a small Delaunay triangulation of the hole points"
//                  costs, before any gluing);
//   DT reused      the same, one triangulation cleared and refilled for each hole;
//   direct checks  the emptiness test of the paper's certification done directly: for each
//                  ear, an in-circle test against every other vertex of the hole (what it
//                  costs to certify an ear clipping fill without flips).
// It prints the time per hole and the ratio to ear clipping; the fills are checked (ear
// clipping gives m - 2 ears, the DT as many faces when the hole is convex).
//
// Usage: bench_hole_filling [--n 1000000] [--every 8] [--reps 5]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/internal/import/hole_tracing.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace dfp_bench;

namespace {

struct Holes
{
  std::vector<Point> points;       // the polygons' vertices, one after the other, ccw
  std::vector<std::size_t> start;  // polygon h is points[start[h], start[h + 1])
  std::size_t size(std::size_t h) const { return start[h + 1] - start[h]; }
};

Holes links_of_every(const DT& dt, std::size_t every)
{
  Holes holes;
  holes.start.push_back(0);
  std::size_t k = 0;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    if(k++ % every != 0)
      continue;
    bool interior = true;
    std::vector<Point> link;
    auto w = dt.incident_vertices(v), end = w;
    do {
      if(dt.is_infinite(w))
        interior = false;
      else
        link.push_back(w->point());
    } while(++w != end);
    if(!interior)
      continue;
    holes.points.insert(holes.points.end(), link.begin(), link.end());
    holes.start.push_back(holes.points.size());
  }
  return holes;
}

template <class F>
double median_time(int reps, const F& f)
{
  std::vector<double> t;
  for(int r = 0; r < reps; ++r) {
    CGAL::Real_timer timer;
    timer.start();
    f();
    timer.stop();
    t.push_back(timer.time());
  }
  return median(t);
}

} // namespace

int main(int argc, char** argv)
{
  std::size_t n = 1000000, every = 8;
  int reps = 5;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      n = std::size_t(std::atof(option_value(argc, argv, i).c_str()));
    else if(a == "--every")
      every = std::size_t(std::max(1, std::atoi(option_value(argc, argv, i).c_str())));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else {
      std::printf("usage: %s [--n 1000000] [--every 8] [--reps 5]\n", argv[0]);
      return a == "--help" ? 0 : 2;
    }
  }
  const std::vector<Point> points = uniform_points(n, 20260101);
  DT dt(points.begin(), points.end());
  const Holes holes = links_of_every(dt, every);
  const std::size_t count = holes.start.size() - 1;
  const K gt;

  std::size_t ears_made = 0, dt_faces = 0, checks_failed = 0;
  std::vector<std::array<std::size_t, 3>> ears;
  std::vector<std::size_t> prev, next;
  const double ear_time = median_time(reps, [&] {
    ears_made = 0;
    for(std::size_t h = 0; h < count; ++h) {
      const Point* p = holes.points.data() + holes.start[h];
      DFP::internal::clip_ears(gt, holes.size(h), [&](std::size_t i) -> const Point& { return p[i]; }, ears, prev,
                               next);
      ears_made += ears.size();
    }
  });
  const double dt_new_time = median_time(reps, [&] {
    dt_faces = 0;
    for(std::size_t h = 0; h < count; ++h) {
      DT aux(holes.points.begin() + std::ptrdiff_t(holes.start[h]),
             holes.points.begin() + std::ptrdiff_t(holes.start[h + 1]));
      dt_faces += aux.number_of_faces();
    }
  });
  const double dt_reused_time = median_time(reps, [&] {
    DT aux;
    for(std::size_t h = 0; h < count; ++h) {
      aux.clear();
      aux.insert(holes.points.begin() + std::ptrdiff_t(holes.start[h]),
                 holes.points.begin() + std::ptrdiff_t(holes.start[h + 1]));
    }
  });
  // Direct checks: every ear of the (stored) ear clipping fill against every hole vertex.
  std::vector<std::vector<std::array<std::size_t, 3>>> fills(count);
  for(std::size_t h = 0; h < count; ++h) {
    const Point* p = holes.points.data() + holes.start[h];
    DFP::internal::clip_ears(gt, holes.size(h), [&](std::size_t i) -> const Point& { return p[i]; }, fills[h], prev,
                             next);
  }
  std::size_t not_empty = 0;
  const double check_time = median_time(reps, [&] {
    not_empty = 0;
    for(std::size_t h = 0; h < count; ++h) {
      const Point* p = holes.points.data() + holes.start[h];
      for(const auto& e : fills[h])
        for(std::size_t q = 0; q < holes.size(h); ++q)
          if(q != e[0] && q != e[1] && q != e[2] &&
             DFP::internal::side_of_oriented_circle_perturbed(gt, p[e[0]], p[e[1]], p[e[2]], p[q]) ==
                 CGAL::ON_POSITIVE_SIDE) {
            ++not_empty;
            break;
          }
    }
  });
  // Checks: m - 2 ears per hole; the DT of a hole's points has at least as many faces.
  std::size_t expected_ears = 0;
  for(std::size_t h = 0; h < count; ++h)
    expected_ears += holes.size(h) - 2;
  checks_failed += ears_made != expected_ears ? 1 : 0;
  checks_failed += dt_faces < expected_ears ? 1 : 0;

  std::printf("bench_hole_filling: n = %zu, the links of every %zu-th interior vertex: %zu holes, %.2f vertices each,"
              " median of %d\n",
              n, every, count, double(holes.points.size()) / double(count), reps);
  std::printf("%-16s %12s %14s %10s\n", "filler", "total [s]", "per hole [us]", "vs ears");
  auto row = [&](const char* name, double t) {
    std::printf("%-16s %12.4f %14.3f %10.2f\n", name, t, 1e6 * t / double(count), t / ear_time);
  };
  row("ear clipping", ear_time);
  row("DT per hole", dt_new_time);
  row("DT reused", dt_reused_time);
  row("direct checks", check_time);
  std::printf("ears not Delaunay within their hole (the flips fix them): %zu of %zu\n", not_empty, expected_ears);
  if(checks_failed != 0) {
    std::printf("CHECK FAILED\n");
    return 1;
  }
  return 0;
}
