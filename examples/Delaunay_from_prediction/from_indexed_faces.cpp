// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Delaunay triangulation from a prediction given as index triples, as read from a mesh file.
//
// The scene is a small structured mesh: a grid of points in which some points keep their
// exact integer coordinates (so many groups of four points are co-circular and CGAL breaks the
// ties by symbolic perturbation) and the others are slightly jittered. Two predictions are
// tried: CGAL's own Delaunay triangulation with shuffled faces, and the same with a few edges
// flipped. Each result is compared, face by face, with the triangulation CGAL builds from
// scratch. The program returns 0 only if both comparisons succeed.

#include <CGAL/Delaunay_from_prediction_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iostream>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
// Each vertex carries the index of its point.
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using Face = std::array<int, 3>;

namespace DFP = CGAL::Delaunay_from_prediction;

// The finite faces of `dt` as index triples, each rotated to start at its smallest index
// (which keeps the orientation), sorted: two triangulations are equal iff these are equal.
std::vector<std::array<std::size_t, 3>> face_set(const DT& dt)
{
  std::vector<std::array<std::size_t, 3>> faces;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(),
                                    f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The faces of `dt` as a prediction: index triples in random order, each starting at a
// random corner, half of them clockwise.
std::vector<Face> faces_as_prediction(const DT& dt, CGAL::Random& random)
{
  std::vector<Face> faces;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    Face t = {int(f->vertex(0)->info()), int(f->vertex(1)->info()), int(f->vertex(2)->info())};
    std::rotate(t.begin(), t.begin() + random.get_int(0, 3), t.end());
    if(random.get_bool())
      std::swap(t[1], t[2]);
    faces.push_back(t);
  }
  for(std::size_t k = faces.size(); k > 1; --k) // Fisher-Yates shuffle
    std::swap(faces[k - 1], faces[std::size_t(random.get_int(0, int(k)))]);
  return faces;
}

// Flips up to `count` random interior edges of `dt` whose quadrilateral is strictly convex.
// `dt` is then a triangulation of the same points, but no longer Delaunay.
std::size_t flip_random_edges(DT& dt, std::size_t count, CGAL::Random& random)
{
  std::vector<DT::Face_handle> faces;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    faces.push_back(f);
  std::size_t flipped = 0;
  for(std::size_t attempt = 0; attempt < 100 * count && flipped < count; ++attempt) {
    const DT::Face_handle f = faces[std::size_t(random.get_int(0, int(faces.size())))];
    const int i = random.get_int(0, 3);
    const DT::Face_handle g = f->neighbor(i);
    if(dt.is_infinite(g))
      continue;
    const Point& a = f->vertex(i)->point();
    const Point& b = f->vertex(DT::ccw(i))->point();
    const Point& c = f->vertex(DT::cw(i))->point();
    const Point& d = g->vertex(dt.mirror_index(f, i))->point();
    if(CGAL::orientation(a, b, d) != CGAL::LEFT_TURN || CGAL::orientation(a, d, c) != CGAL::LEFT_TURN)
      continue;
    dt.flip(f, i); // both faces stay finite faces, so `faces` stays valid
    ++flipped;
  }
  return flipped;
}

void print(const DFP::Statistics& s)
{
  std::cout << "  faces_in                   " << s.faces_in << "\n"
            << "  faces_certified            " << s.faces_certified << "\n"
            << "  edges_tested               " << s.edges_tested << "\n"
            << "  edges_not_locally_delaunay " << s.edges_not_locally_delaunay << "\n"
            << "  flips                      " << s.flips << "\n"
            << "  points_unused              " << s.points_unused << "\n"
            << "  points_reinserted          " << s.points_reinserted << "\n"
            << "  duplicate_points           " << s.duplicate_points << "\n"
            << "  fell_back                  " << (s.fell_back ? "yes" : "no");
  if(s.fell_back)
    std::cout << " (" << to_string(s.outcome) << ")";
  std::cout << "\n";
}

int main()
{
  CGAL::Random random(20260114);

  // The mesh: a 40 x 30 grid; about half of the points are jittered by up to 0.2.
  std::vector<Point> points;
  for(int y = 0; y < 30; ++y)
    for(int x = 0; x < 40; ++x) {
      if(random.get_bool())
        points.emplace_back(x, y);
      else
        points.emplace_back(x + random.get_double(-0.2, 0.2), y + random.get_double(-0.2, 0.2));
    }

  // The reference: CGAL's Delaunay triangulation built from scratch, info() = point index.
  std::vector<std::pair<Point, std::size_t>> indexed;
  for(std::size_t i = 0; i < points.size(); ++i)
    indexed.emplace_back(points[i], i);
  DT reference;
  reference.insert(indexed.begin(), indexed.end());
  const auto expected = face_set(reference);

  // Prediction 1: the exact answer, shuffled. Prediction 2: a few edges flipped away from it.
  DT perturbed = reference;
  const std::size_t flipped = flip_random_edges(perturbed, 25, random);
  const std::vector<Face> predictions[2] = {faces_as_prediction(reference, random),
                                            faces_as_prediction(perturbed, random)};
  const char* names[2] = {"CGAL's Delaunay triangulation, shuffled",
                          "the same with edges flipped"};

  std::cout << points.size() << " points, " << expected.size() << " Delaunay faces\n";
  bool ok = true;
  for(int k = 0; k < 2; ++k) {
    std::cout << "\nPrediction " << k + 1 << ": " << names[k];
    if(k == 1)
      std::cout << " (" << flipped << " random flips)";
    std::cout << "\n";

    DT dt;
    const DFP::Statistics stats = DFP::delaunay_from_prediction(points, predictions[k], dt);
    print(stats);

    // Release builds erase assert(): check explicitly.
    bool same = dt.number_of_vertices() == points.size() && face_set(dt) == expected;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      same = same && v->info() < points.size() && v->point() == points[v->info()];
    std::cout << "  result equals CGAL's from-scratch triangulation: " << (same ? "yes" : "NO")
              << "\n";
    ok = ok && same;
  }
  std::cout << "\n" << (ok ? "OK" : "FAILED") << "\n";
  return ok ? 0 : 1;
}
