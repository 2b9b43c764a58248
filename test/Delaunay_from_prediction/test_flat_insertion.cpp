// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The from-scratch build on flat arrays (internal/build/flat_insertion.h), with Epick and
// Epeck, in the two places it serves: build_from_scratch() into an empty triangulation (the
// fallbacks of delaunay_from_prediction) and rebuild_keeping_vertices() (make_delaunay's
// rebuild), on point sets whose ties only CGAL's symbolic perturbation decides (lattice points
// on common circles, integer grids), duplicates, collinear sets with one point off the line
// (the hull's collinear vertices), all-collinear sets (dimension 1: the insertion takes over),
// huge and tiny coordinates, in several input orders. The result must be exactly CGAL's DT,
// with info the smallest index of each point; the rebuild keeps every vertex object, resets
// the reused faces' info(), and on two vertices at one point throws before touching anything.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

using namespace dfp_test;
namespace internal = CGAL::Delaunay_from_prediction::internal;

template <class K>
struct Flat_insertion_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Fb = CGAL::Triangulation_face_base_with_info_2<int, K>;
  using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb, Fb>>;

  CGAL::Random rng{4242};

  std::vector<std::pair<std::string, Points>> point_sets(std::size_t n)
  {
    std::vector<std::pair<std::string, Points>> sets;
    Points uniform, grid, circles, hull_collinear, collinear, huge, tiny;
    for(std::size_t i = 0; i < n; ++i) {
      uniform.emplace_back(rng.get_double(), rng.get_double());
      grid.emplace_back(rng.get_int(0, 9), rng.get_int(0, 9)); // duplicates too
      const int c[12][2] = {{5, 0}, {-5, 0}, {0, 5}, {0, -5}, {3, 4}, {-3, 4}, {3, -4}, {-3, -4}, {4, 3}, {-4, 3}, {4, -3}, {-4, -3}};
      const int k = rng.get_int(0, 12), cx = 10 * rng.get_int(0, 4), cy = 10 * rng.get_int(0, 4);
      circles.emplace_back(cx + c[k][0], cy + c[k][1]); // 12 points on each of 16 circles
      hull_collinear.emplace_back(double(i), i == n / 2 ? 1.0 : 0.0);
      collinear.emplace_back(double(i), 2.0 * double(i));
      huge.emplace_back(1e300 * rng.get_int(-5, 5), 1e300 * rng.get_int(-5, 5));
      tiny.emplace_back(1e-300 * rng.get_double(), 1e-300 * rng.get_double());
    }
    sets.emplace_back("uniform", uniform);
    sets.emplace_back("grid with duplicates", grid);
    sets.emplace_back("lattice points on circles", circles);
    sets.emplace_back("collinear but one", hull_collinear);
    sets.emplace_back("collinear", collinear);
    sets.emplace_back("huge", huge);
    sets.emplace_back("tiny", tiny);
    return sets;
  }

  void build_from_scratch(const Points& points)
  {
    for(const bool given_grid_order : {false, true}) {
      Scope scope(given_grid_order ? "grid order given" : "any order");
      std::vector<std::uint32_t> order;
      if(given_grid_order) {
        for(std::uint32_t i = 0; i < points.size(); ++i)
          order.push_back(i);
        internal::sort_along_grid(order, [&](std::uint32_t i) -> const Point& { return points[i]; }, false);
      }
      DT dt;
      CGAL::Delaunay_from_prediction::Statistics stats;
      internal::build_from_scratch(dt, points.begin(), points.size(), stats, order);
      check_is_cgal_delaunay(dt, points);
      DFP_CHECK(stats.points_reinserted == points.size());
      DFP_CHECK(stats.duplicate_points == points.size() - dt.number_of_vertices());
    }
  }

  // A triangulation of other points (the same number, distinct), then moved onto `points`.
  void rebuild_keeping_vertices(const Points& points)
  {
    const std::map<Point, std::size_t> first = smallest_indices(points);
    if(first.size() != points.size())
      return; // duplicates: see below
    DT tr;
    for(std::size_t i = 0; i < points.size(); ++i)
      tr.insert(Point(rng.get_double(), rng.get_double()))->info() = i;
    if(tr.number_of_vertices() != points.size())
      return;
    std::vector<typename DT::Vertex_handle> vertex(points.size());
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      vertex[v->info()] = v;
    for(std::size_t i = 0; i < points.size(); ++i)
      vertex[i]->set_point(points[i]);
    for(auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
      f->info() = 7;
    CGAL::Delaunay_from_prediction::Statistics stats;
    internal::rebuild_keeping_vertices(tr, stats);
    check_is_cgal_delaunay(tr, points);
    bool same_objects = true;
    for(std::size_t i = 0; i < points.size(); ++i)
      same_objects = same_objects && vertex[i]->info() == i && vertex[i]->point() == points[i];
    DFP_CHECK(same_objects);
    bool info_reset = true;
    for(auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
      info_reset = info_reset && f->info() == 0;
    DFP_CHECK(tr.dimension() < 2 || info_reset);
  }

  // Two vertices moved onto one point: Invalid_prediction, the triangulation as it was.
  void rebuild_refuses_duplicates()
  {
    DT tr;
    for(std::size_t i = 0; i < 200; ++i)
      tr.insert(Point(rng.get_double(), rng.get_double()))->info() = i;
    auto v = tr.finite_vertices_begin();
    const Point target = v->point();
    ++v;
    v->set_point(target);
    const Geometry<Point> before = geometry_of(tr);
    CGAL::Delaunay_from_prediction::Statistics stats;
    DFP_CHECK(throws_exception<CGAL::Delaunay_from_prediction::Invalid_prediction>(
        [&] { internal::rebuild_keeping_vertices(tr, stats); }));
    const Geometry<Point> after = geometry_of(tr);
    DFP_CHECK(after.faces == before.faces);
  }

  void all(std::size_t runs, std::size_t n)
  {
    for(std::size_t run = 0; run < runs; ++run)
      for(std::size_t size : {std::size_t(3), std::size_t(4), std::size_t(10), n}) {
        for(const auto& named : point_sets(size)) {
          Scope scope(named.first, ", n = ", size, ", run ", run);
          build_from_scratch(named.second);
          rebuild_keeping_vertices(named.second);
        }
      }
    rebuild_refuses_duplicates();
  }
};

int main()
{
  {
    Scope scope("Epick");
    Flat_insertion_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all(12, 2000);
  }
  {
    Scope scope("Epeck");
    Flat_insertion_test<CGAL::Exact_predicates_exact_constructions_kernel>().all(3, 500);
  }
  return finish("test_flat_insertion");
}
