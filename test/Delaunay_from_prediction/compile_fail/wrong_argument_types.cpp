// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Must NOT compile: each entry point called with a wrong argument type, one mistake per build
// (DFP_MISTAKE = faces, points or edges). The ctest tests wrong_*_type_is_refused compile it
// (syntax only) and expect the package's static_assert message for that mistake.

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <utility>
#include <vector>

namespace DFP = CGAL::Delaunay_from_prediction;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_2<K>;

int main()
{
  DT dt;
  std::vector<K::Point_2> points = {{0, 0}, {1, 0}, {0, 1}};
#if defined(DFP_MISTAKE_faces)
  const std::vector<std::array<double, 3>> faces = {{0, 1, 2}}; // indices must be integers
  DFP::delaunay_from_prediction(points, faces, dt);
#elif defined(DFP_MISTAKE_points)
  const std::vector<std::pair<K::Point_2, int>> indexed = {{{0, 0}, 0}, {{1, 0}, 1}, {{0, 1}, 2}};
  const std::vector<std::array<int, 3>> faces = {{0, 1, 2}};
  DFP::delaunay_from_prediction(indexed, faces, dt); // points with info: not DT::Point
#elif defined(DFP_MISTAKE_edges)
  const std::vector<int> edges = {0, 1, 1, 2}; // a flat list, not pairs
  DFP::delaunay_from_spanning_graph(points, edges, dt);
#endif
}
