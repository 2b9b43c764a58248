// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Moving points: keep the Delaunay triangulation of particles carried by a flow.
//
// N particles, uniform in the unit disk, are carried by a vortex that turns the fluid at
// radius r with angular velocity (1 - r^2)^2: fast near the centre, at rest on the rim, so
// neighbouring particles shear past each other and some Delaunay edges change every frame.
// Each frame moves every vertex of a CGAL Delaunay_triangulation_2 with set_point() (the
// triangulation is then the previous frame's, a prediction of the new one), calls
// make_delaunay(), and checks the result against CGAL's triangulation of the moved points
// built from scratch: same faces (as particle-id triples), same vertex objects, same ids.
//
// Usage: moving_points [N [frames [step]]]
//   N       number of particles (default 200000)
//   frames  number of frames (default 10)
//   step    largest displacement of a particle per frame, as a fraction of the mean spacing
//           sqrt(pi / N) (default 0.004)
// Returns 0 only if every frame's check passes.

#include <CGAL/Delaunay_from_prediction_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
// Each vertex carries the id of its particle.
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using Vertex_handle = DT::Vertex_handle;

namespace DFP = CGAL::Delaunay_from_prediction;

// The vortex: angular velocity at radius r.
double angular_velocity(double r2) // r2 = r * r
{
  const double s = r2 < 1 ? 1 - r2 : 0;
  return s * s;
}
// The largest speed r * (1 - r^2)^2, reached at r = 1 / sqrt(5).
const double max_speed = 16 / (25 * std::sqrt(5.0));

// Moves `p` along the flow for a time `dt`: a rotation about the origin, by the angle the
// vortex turns at the radius of `p` (the radius is kept, so the particle stays in the disk).
Point advect(const Point& p, double dt)
{
  const double x = p.x(), y = p.y();
  const double angle = angular_velocity(x * x + y * y) * dt;
  const double c = std::cos(angle), s = std::sin(angle);
  return Point(c * x - s * y, s * x + c * y);
}

// The finite faces of `dt` as particle-id triples, each rotated to start at its smallest id
// (which keeps the orientation), sorted: two triangulations are equal iff these are equal.
std::vector<std::array<std::size_t, 3>> face_set(const DT& dt)
{
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(dt.number_of_faces());
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(),
                                    f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// Every vertex object of `dt` is the one recorded for its particle id, holds that
// particle's position, and no particle is missing.
bool same_vertices(const DT& dt, const std::vector<Vertex_handle>& vertex_of,
                   const std::vector<Point>& position)
{
  if(dt.number_of_vertices() != vertex_of.size())
    return false;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const std::size_t id = v->info();
    if(id >= vertex_of.size() || vertex_of[id] != Vertex_handle(v) || v->point() != position[id])
      return false;
  }
  return true;
}

int main(int argc, char* argv[])
{
  const std::size_t n = argc > 1 ? std::size_t(std::strtoull(argv[1], nullptr, 10)) : 200000;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 10;
  const double step = argc > 3 ? std::atof(argv[3]) : 0.004;
  if(n < 3 || frames < 1 || !(step > 0)) {
    std::cerr << "usage: " << argv[0] << " [N >= 3 [frames >= 1 [step > 0]]]\n";
    return 2;
  }
  const double spacing = std::sqrt(CGAL_PI / double(n));
  const double dt_flow = step * spacing / max_speed; // time step of the flow

  // Frame 0: particles uniform in the unit disk, triangulated by CGAL.
  CGAL::Random random(20260114);
  std::vector<Point> position(n);
  for(Point& p : position) {
    double x, y;
    do {
      x = random.get_double(-1, 1);
      y = random.get_double(-1, 1);
    } while(x * x + y * y >= 1);
    p = Point(x, y);
  }
  std::vector<std::pair<Point, std::size_t>> indexed(n);
  for(std::size_t id = 0; id < n; ++id)
    indexed[id] = {position[id], id};
  DT tr;
  tr.insert(indexed.begin(), indexed.end());
  std::vector<Vertex_handle> vertex_of(n);
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    vertex_of[v->info()] = v;

  std::printf("%zu particles in a vortex, %d frames; per frame a particle moves at most %.2f%%"
              " of the mean spacing (%.3g)\n\n", n, frames, 100 * step, spacing);
  std::printf("non-LD edges: edges of the moved triangulation that fail the in-circle test;\n"
              "speed-up: CGAL rebuild time / make_delaunay time.\n\n");
  std::printf("%5s %12s %8s %10s %6s %17s %16s %9s\n", "frame", "non-LD edges", "flips",
              "fell_back", "check", "make_delaunay [s]", "CGAL rebuild [s]", "speed-up");

  int passed = 0, fell_back = 0;
  std::size_t total_flips = 0;
  double total_ours = 0, total_cgal = 0;
  for(int frame = 1; frame <= frames; ++frame) {
    // Move every particle; the triangulation keeps last frame's faces.
    for(std::size_t id = 0; id < n; ++id) {
      position[id] = advect(position[id], dt_flow);
      vertex_of[id]->set_point(position[id]);
    }

    CGAL::Real_timer ours;
    ours.start();
    const DFP::Statistics stats = DFP::make_delaunay(tr);
    ours.stop();

    for(std::size_t id = 0; id < n; ++id)
      indexed[id] = {position[id], id};
    CGAL::Real_timer cgal;
    cgal.start();
    DT reference;
    reference.insert(indexed.begin(), indexed.end());
    cgal.stop();

    // Release builds erase assert(): check explicitly.
    const bool ok = tr.tds().is_valid() && same_vertices(tr, vertex_of, position) &&
                    face_set(tr) == face_set(reference);
    passed += ok;
    fell_back += stats.fell_back;
    total_flips += stats.flips;
    total_ours += ours.time();
    total_cgal += cgal.time();
    std::printf("%5d %12zu %8zu %10s %6s %17.4f %16.4f %8.1fx\n", frame,
                stats.edges_not_locally_delaunay, stats.flips, stats.fell_back ? "yes" : "no",
                ok ? "OK" : "FAIL", ours.time(), cgal.time(), cgal.time() / ours.time());
    if(stats.fell_back)
      std::printf("      fell back: %s\n", to_string(stats.outcome));
  }

  std::printf("\nSummary: %d/%d frames checked OK; %d/%d frames repaired in place (fast path),"
              " %d fell back to a rebuild; %zu flips in all.\n",
              passed, frames, frames - fell_back, frames, fell_back, total_flips);
  std::printf("make_delaunay %.3f s in all, CGAL rebuild %.3f s in all: speed-up %.1fx.\n",
              total_ours, total_cgal, total_cgal / total_ours);
  return passed == frames ? 0 : 1;
}
