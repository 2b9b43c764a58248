// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// A prediction given as a tree: the minimum spanning tree of the previous positions of
// moving points. The points move a little; the old tree is then a good guess of the new
// one, and of which points are neighbours. From it, delaunay_from_spanning_graph() builds the
// new Delaunay triangulation (Section 3 of the paper), and
// euclidean_minimum_spanning_tree_from_prediction() the new minimum spanning tree
// (Corollary 3.6). Both are compared with what CGAL computes from scratch; the program
// returns 0 only if both agree.

#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>

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
#include <iterator>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
using Edge = std::pair<std::size_t, std::size_t>;
namespace DFP = CGAL::Delaunay_from_prediction;

int main()
{
  CGAL::Random rng(2026);
  const std::size_t n = 50000;
  std::vector<Point> before, after;
  for(std::size_t i = 0; i < n; ++i) {
    before.emplace_back(rng.get_double(), rng.get_double());
    // each point moves by up to a tenth of the mean spacing
    const double step = 0.1 / std::sqrt(double(n));
    after.emplace_back(before.back().x() + rng.get_double(-step, step),
                       before.back().y() + rng.get_double(-step, step));
  }

  // The prediction: the minimum spanning tree of the old positions (computed here with the
  // package too, from a path through the points in index order: a poor guess, still exact).
  std::vector<Edge> path, old_tree;
  for(std::size_t i = 1; i < n; ++i)
    path.emplace_back(i - 1, i);
  DFP::euclidean_minimum_spanning_tree_from_prediction(before, path, std::back_inserter(old_tree));

  // The new Delaunay triangulation from the old tree.
  DT dt;
  const DFP::Statistics s = DFP::delaunay_from_spanning_graph(after, old_tree, dt);
  std::cout << "Delaunay triangulation from the old tree: " << dt.number_of_faces() << " faces, "
            << s.points_located << " points located by walks of "
            << double(s.faces_visited) / double((std::max)(s.points_located, std::size_t(1)))
            << " faces on average, " << s.walk_fallbacks << " walks past their cap, "
            << (s.fell_back ? "fell back" : "no fallback") << "\n";

  // The same triangulation as CGAL's, face by face (as point index triples).
  auto faces_of = [](const DT& t) {
    std::vector<std::array<std::size_t, 3>> faces;
    for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
      std::array<std::size_t, 3> a = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
      faces.push_back(a);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
  };
  std::vector<std::pair<Point, std::size_t>> indexed;
  for(std::size_t i = 0; i < n; ++i)
    indexed.emplace_back(after[i], i);
  const DT reference(indexed.begin(), indexed.end());
  const bool same_dt = faces_of(dt) == faces_of(reference);
  std::cout << "same as CGAL's triangulation: " << (same_dt ? "yes" : "NO") << "\n";

  // The new minimum spanning tree from the old one, checked against Kruskal on CGAL's edges.
  std::vector<Edge> new_tree;
  DFP::euclidean_minimum_spanning_tree_from_prediction(after, old_tree, std::back_inserter(new_tree));
  std::vector<std::pair<double, Edge>> by_length;
  for(auto e = reference.finite_edges_begin(); e != reference.finite_edges_end(); ++e) {
    std::size_t a = e->first->vertex(DT::ccw(e->second))->info(), b = e->first->vertex(DT::cw(e->second))->info();
    if(b < a)
      std::swap(a, b);
    by_length.push_back({CGAL::squared_distance(after[a], after[b]), Edge(a, b)});
  }
  std::sort(by_length.begin(), by_length.end());
  std::vector<std::size_t> parent(n);
  for(std::size_t i = 0; i < n; ++i)
    parent[i] = i;
  auto find = [&](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<Edge> expected;
  for(const auto& le : by_length) {
    const std::size_t a = find(le.second.first), b = find(le.second.second);
    if(a != b) {
      parent[a] = b;
      expected.push_back(le.second);
    }
  }
  std::sort(expected.begin(), expected.end());
  std::size_t kept = 0;
  for(const Edge& e : new_tree)
    kept += std::binary_search(old_tree.begin(), old_tree.end(), e) ? 1 : 0;
  const bool same_tree = new_tree == expected;
  std::cout << "new minimum spanning tree: " << new_tree.size() << " edges, " << kept
            << " of them in the old tree; same as Kruskal on CGAL's triangulation: " << (same_tree ? "yes" : "NO")
            << "\n";
  return same_dt && same_tree ? 0 : 1;
}
