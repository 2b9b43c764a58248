// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Particles in a periodic shear flow: keep the periodic Delaunay triangulation of particles
// carried by a flow on the flat torus (the unit square with opposite sides identified).
//
// N particles, uniform in the unit square, move with the velocity (sin(2 pi y), 0): the layers
// slide past each other in opposite directions, and the particles leave through the sides and
// come back through the opposite ones (each new position is wrapped into the square). Each
// frame moves every vertex of a CGAL Periodic_2_Delaunay_triangulation_2 with set_point(),
// calls make_delaunay() (the faces' offsets are repaired along with the connectivity), and
// checks the result against CGAL's periodic triangulation of the moved points built by range
// insertion: the same faces as (particle id, offset) triples, the same vertex objects.
//
// Usage: periodic_shear_flow [N [frames [step]]]
//   N       number of particles (default 50000)
//   frames  number of frames (default 5)
//   step    largest displacement of a particle per frame, as a fraction of the mean spacing
//           1 / sqrt(N) (default 0.01)
// Returns 0 only if every frame's check passes.

#include <CGAL/Delaunay_from_prediction/periodic_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>
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
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace DFP = CGAL::Delaunay_from_prediction;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Gt = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Gt, CGAL::Periodic_2_triangulation_vertex_base_2<Gt>>;
using Fb = CGAL::Periodic_2_triangulation_face_base_2<Gt>;
using Periodic_DT = CGAL::Periodic_2_Delaunay_triangulation_2<Gt, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
using Point = K::Point_2;

// A face as (particle id, x offset, y offset) corners, offsets translated to least value 0,
// least corner first.
using Corner = std::tuple<std::size_t, int, int>;
using Face = std::array<Corner, 3>;

// The faces of a 1-sheeted triangulation by the ids in the vertices' info().
std::vector<Face> faces_by_id(const Periodic_DT& t)
{
  std::vector<Face> faces;
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f) {
    Face face;
    int low_x = 1, low_y = 1;
    for(int i = 0; i < 3; ++i) {
      low_x = (std::min)(low_x, (f->offset(i) >> 1) & 1); // CGAL stores a face offset as 2x + y
      low_y = (std::min)(low_y, f->offset(i) & 1);
    }
    for(int i = 0; i < 3; ++i)
      face[i] = Corner{f->vertex(i)->info(), ((f->offset(i) >> 1) & 1) - low_x, (f->offset(i) & 1) - low_y};
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
    faces.push_back(face);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

double wrap(double x)
{
  const double y = x - std::floor(x);
  return y < 1 ? y : 0; // x just below an integer may round up to 1
}

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::size_t(std::atol(argv[1])) : 50000;
  const int frames = argc > 2 ? std::atoi(argv[2]) : 5;
  const double step = argc > 3 ? std::atof(argv[3]) : 0.01;
  const double max_move = step / std::sqrt(double(n));

  CGAL::Random rng(2026);
  std::vector<std::pair<Point, std::size_t>> particles;
  for(std::size_t i = 0; i < n; ++i)
    particles.emplace_back(Point(rng.get_double(0, 1), rng.get_double(0, 1)), i);
  Periodic_DT t; // the domain is the unit square
  t.insert(particles.begin(), particles.end());
  std::vector<Periodic_DT::Vertex_handle> vertex(n);
  for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v)
    vertex[v->info()] = v;
  std::printf("%zu particles in a periodic shear flow, %s covering, moves of up to %g of the spacing\n", n,
              t.is_1_cover() ? "1-sheeted" : "9-sheeted", step);

  int failures = 0;
  double repair_seconds = 0, cgal_seconds = 0;
  for(int frame = 1; frame <= frames; ++frame) {
    std::vector<Point> moved(n);
    for(std::size_t i = 0; i < n; ++i) {
      const Point& p = vertex[i]->point();
      moved[i] = Point(wrap(p.x() + max_move * std::sin(6.283185307179586 * p.y())), p.y());
      vertex[i]->set_point(moved[i]);
    }
    CGAL::Real_timer timer;
    timer.start();
    const DFP::Statistics stats = DFP::make_delaunay(t);
    timer.stop();
    repair_seconds += timer.time();

    // CGAL's periodic triangulation of the moved particles, built from scratch.
    std::vector<std::pair<Point, std::size_t>> input;
    for(std::size_t i = 0; i < n; ++i)
      input.emplace_back(moved[i], i);
    timer.reset();
    timer.start();
    Periodic_DT expected;
    expected.insert(input.begin(), input.end());
    timer.stop();
    cgal_seconds += timer.time();

    bool same = t.is_1_cover() == expected.is_1_cover() && t.is_valid();
    if(same && t.is_1_cover()) {
      same = faces_by_id(t) == faces_by_id(expected);
      for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v)
        same = same && &*vertex[v->info()] == &*v; // the same vertex objects
    } else if(same) { // few particles: both are CGAL's 9-sheeted build
      same = t.number_of_faces() == expected.number_of_faces();
    }
    std::printf("frame %d: %zu flips, %zu edges not locally Delaunay, %s%s\n", frame, stats.flips,
                stats.edges_not_locally_delaunay, stats.fell_back ? "rebuilt: " : "repaired",
                stats.fell_back ? DFP::to_string(stats.outcome) : "");
    if(!same) {
      std::printf("frame %d: the result differs from CGAL's periodic triangulation\n", frame);
      ++failures;
    }
  }
  std::printf("make_delaunay: %.3f s for %d frames; CGAL's periodic build: %.3f s (%.1fx)\n", repair_seconds, frames,
              cgal_seconds, cgal_seconds / repair_seconds);
  std::printf(failures == 0 ? "every frame equals CGAL's periodic triangulation\n" : "%d frame(s) differ\n", failures);
  return failures == 0 ? 0 : 1;
}
