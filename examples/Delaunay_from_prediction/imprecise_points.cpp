// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Imprecise points: sensors whose positions are known to within a radius (disks). The disks
// are preprocessed once; every new reading (one position per sensor, inside its disk) is
// then triangulated in expected linear time by Imprecise_points_2::triangulate(). Each result
// is compared with CGAL's triangulation of the same reading built from scratch, face by face
// as triples of sensor indices; the program returns 0 only if all agree.

#include <CGAL/Delaunay_from_prediction/imprecise_points.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
namespace DFP = CGAL::Delaunay_from_prediction;

// The faces of a triangulation whose vertex info is a sensor index, as sorted index triples.
std::vector<std::array<std::size_t, 3>> faces_of(const DT& t)
{
  std::vector<std::array<std::size_t, 3>> faces;
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> a = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    faces.push_back(a);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

int main()
{
  CGAL::Random rng(1309);
  // 20000 sensors on a jittered grid of unit spacing, each known to within 0.4.
  std::vector<Point> centres;
  std::vector<double> radii;
  for(int i = 0; i < 200; ++i)
    for(int j = 0; j < 100; ++j) {
      centres.emplace_back(i + rng.get_double(-0.1, 0.1), j + rng.get_double(-0.1, 0.1));
      radii.push_back(0.4);
    }
  const DFP::Imprecise_points_2<K> sensors(centres, radii); // preprocessing, once

  bool all_equal = true;
  for(int reading = 0; reading < 3; ++reading) {
    std::vector<Point> positions;
    for(std::size_t i = 0; i < centres.size(); ++i) {
      const double angle = rng.get_double(0, 6.283185307179586), r = radii[i] * std::sqrt(rng.get_double());
      positions.emplace_back(centres[i].x() + r * std::cos(angle), centres[i].y() + r * std::sin(angle));
    }
    DT dt;
    const DFP::Statistics s = sensors.triangulate(positions, dt); // info() = sensor index
    std::vector<std::pair<Point, std::size_t>> indexed;
    for(std::size_t i = 0; i < positions.size(); ++i)
      indexed.emplace_back(positions[i], i);
    const DT reference(indexed.begin(), indexed.end());
    const bool equal = faces_of(dt) == faces_of(reference);
    all_equal = all_equal && equal;
    std::cout << "reading " << reading << ": " << dt.number_of_faces() << " faces, "
              << double(s.faces_visited) / double((std::max)(s.points_located, std::size_t(1)))
              << " faces crossed per point from its hint, " << (equal ? "equal to" : "DIFFERENT FROM")
              << " CGAL's triangulation\n";
  }
  return all_equal ? 0 : 1;
}
