// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The README's first program, shown there from its first #include on (scripts/check_docs.py
// compares them): a Delaunay triangulation from a predicted one, then kept Delaunay as the
// points move; each result is checked against CGAL's Delaunay_triangulation_2 built from
// scratch, and the program returns 1 if one differs.

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <algorithm>
#include <array>
#include <iostream>
#include <set>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>; // v->info(): a point index
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
namespace DFP = CGAL::Delaunay_from_prediction;

// Has dt the faces (as index triples) of CGAL's Delaunay triangulation of points, built from scratch?
bool same_as_cgal(const DT& dt, const std::vector<K::Point_2>& points)
{
  std::vector<std::pair<K::Point_2, std::size_t>> indexed;
  for(std::size_t i = 0; i < points.size(); ++i)
    indexed.emplace_back(points[i], i);
  const DT cgal(indexed.begin(), indexed.end());
  auto faces = [](const DT& t) {
    std::set<std::array<std::size_t, 3>> triples;
    for(auto f : t.finite_face_handles()) {
      std::array<std::size_t, 3> a = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      std::sort(a.begin(), a.end());
      triples.insert(a);
    }
    return triples;
  };
  return faces(dt) == faces(cgal);
}

int main()
{
  std::vector<K::Point_2> points; // a 10 x 10 grid, odd rows shifted
  for(int y = 0; y < 10; ++y)
    for(int x = 0; x < 10; ++x)
      points.emplace_back(x + 0.3 * (y % 2), y);
  std::vector<std::array<int, 3>> faces; // the prediction: each cell cut by the same diagonal
  for(int a = 0; a < 89; ++a)
    if(a % 10 != 9) {
      faces.push_back({a, a + 1, a + 11});
      faces.push_back({a, a + 11, a + 10});
    }

  DT dt;
  DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt);
  std::cout << s << "\n"; // what the call did: faces kept, flips, whether it built from scratch
  bool ok = same_as_cgal(dt, points);

  for(auto v : dt.finite_vertex_handles()) { // the points move: dt is a prediction again
    const std::size_t i = v->info();
    points[i] = K::Point_2(points[i].x() + 0.2 * (i % 3), points[i].y() + 0.1 * (i % 5));
    v->set_point(points[i]);
  }
  s = DFP::make_delaunay(dt); // Delaunay again: the same vertex objects, the same info()
  std::cout << s << "\n";
  ok = ok && same_as_cgal(dt, points);
  return ok ? 0 : 1; // 1 if a result differs from CGAL's
}
