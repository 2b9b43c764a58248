// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Kinetic_Delaunay_triangulation_2, with Epick and Epeck and every concurrency: after every
// move the triangulation is exactly CGAL's DT of the new points (info the smallest index of
// each point), and the class follows its rule: in place (same vertex handles) for moves small
// and large, a dimension change and equal points that stay equal; rebuilt when points merge or
// split, the indices of equal points then sharing one vertex. Bad input (a wrong point count, a
// non-finite coordinate, a triangulation that is not of the points) throws and changes nothing.

#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h> // first: self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <limits>

using namespace dfp_test;

template <class K>
struct Kinetic_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
  using Kinetic = DFP::Kinetic_Delaunay_triangulation_2<DT>;

  CGAL::Random rng{777};

  DFP::Statistics move(Kinetic& k, const Points& points)
  {
    return with_concurrency([&](auto tag) { return k.template move<decltype(tag)>(points); });
  }

  std::vector<typename DT::Vertex_handle> handles(const Kinetic& k)
  {
    std::vector<typename DT::Vertex_handle> h;
    for(std::size_t i = 0; i < k.number_of_points(); ++i)
      h.push_back(k.vertex(i));
    return h;
  }

  // The class's own invariants: vertex(i) holds point i, and its info is the smallest index
  // of an equal point; the triangulation is CGAL's DT of the points.
  void check(const Kinetic& k, const Points& points)
  {
    DFP_CHECK(k.number_of_points() == points.size());
    check_is_cgal_delaunay(k.triangulation(), points);
    const auto first = smallest_indices(points);
    bool ok = true;
    for(std::size_t i = 0; i < points.size(); ++i)
      ok = ok && k.point(i) == points[i] && k.vertex(i)->info() == first.at(points[i]);
    DFP_CHECK_MSG(ok, "a vertex(i) does not hold point i with the smallest index as info");
    DFP_CHECK(k.has_shared_vertices() == (first.size() < points.size()));
  }

  Points jitter(Points points, double amplitude)
  {
    for(Point& p : points)
      p = Point(p.x() + amplitude * (rng.get_double() - 0.5), p.y() + amplitude * (rng.get_double() - 0.5));
    return points;
  }

  void moves_in_place(std::size_t n)
  {
    Points points = to_points<K>(uniform_points(n, rng));
    Kinetic k;
    k.build(points);
    check(k, points);
    const auto before = handles(k);
    for(const double amplitude : {1e-4, 1e-2, 0.3, 2.0}) {
      Scope scope("jitter " + std::to_string(amplitude));
      points = jitter(points, amplitude);
      move(k, points);
      DFP_CHECK(!k.last_move_rebuilt());
      DFP_CHECK(handles(k) == before);
      check(k, points);
    }
    // Every point onto another's place (a permutation): inverted faces everywhere, in place.
    Points permuted = points;
    shuffle(permuted, rng);
    move(k, permuted);
    DFP_CHECK(!k.last_move_rebuilt());
    DFP_CHECK(handles(k) == before);
    check(k, permuted);
  }

  void dimension_changes()
  {
    Points line;
    for(int i = 0; i < 20; ++i)
      line.emplace_back(i, 2 * i);
    Kinetic k;
    k.build(line);
    check(k, line);
    DFP_CHECK(k.triangulation().dimension() == 1);
    Points off = line;
    off[7] = Point(7, 20);
    move(k, off);
    DFP_CHECK(!k.last_move_rebuilt());
    DFP_CHECK(k.triangulation().dimension() == 2);
    check(k, off);
    move(k, line);
    DFP_CHECK(k.triangulation().dimension() == 1);
    check(k, line);
  }

  void merge_and_split(std::size_t n)
  {
    Points points = to_points<K>(uniform_points(n, rng));
    Kinetic k;
    k.build(points);
    // Point 5 moves onto point 2, point 9 onto point 3: merged, rebuilt.
    Points merged = points;
    merged[5] = merged[2];
    merged[9] = merged[3];
    move(k, merged);
    DFP_CHECK(k.last_move_rebuilt());
    DFP_CHECK(k.vertex(5) == k.vertex(2) && k.vertex(9) == k.vertex(3));
    check(k, merged);
    // Everything translated: the equal points stay equal, in place.
    const auto before = handles(k);
    Points translated;
    for(const Point& p : merged)
      translated.emplace_back(p.x() + 0.25, p.y() - 0.5);
    move(k, translated);
    DFP_CHECK(!k.last_move_rebuilt());
    DFP_CHECK(handles(k) == before);
    check(k, translated);
    // Point 9 leaves point 3: a vertex splits, rebuilt.
    Points split = translated;
    split[9] = Point(split[9].x() + 1e-3, split[9].y());
    move(k, split);
    DFP_CHECK(k.last_move_rebuilt());
    DFP_CHECK(k.vertex(9) != k.vertex(3) && k.vertex(5) == k.vertex(2));
    check(k, split);
  }

  void duplicates_from_the_start()
  {
    Points grid = to_points<K>(with_duplicates(grid_points(12, 12, rng), 40, rng));
    Kinetic k;
    k.build(grid);
    check(k, grid);
    DFP_CHECK(k.has_shared_vertices());
    move(k, grid); // nothing moved: in place
    DFP_CHECK(!k.last_move_rebuilt());
    const Points moved = jitter(grid, 0.1);
    move(k, moved);
    DFP_CHECK(k.last_move_rebuilt());
    check(k, moved);
  }

  // A throw leaves the points, the handles and the triangulation as they were.
  void bad_input(std::size_t n)
  {
    const Points points = to_points<K>(uniform_points(n, rng));
    Kinetic k;
    k.build(points);
    const auto before = handles(k);
    const auto geometry = geometry_of(k.triangulation());
    auto same_geometry = [&] {
      const auto now = geometry_of(k.triangulation());
      return now.vertices == geometry.vertices && now.edges == geometry.edges && now.faces == geometry.faces;
    };
    Points fewer(points.begin(), points.end() - 1);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { move(k, fewer); }));
    // Epeck cannot even hold a NaN (Interval_nt asserts on it).
    if constexpr(std::is_same<K, CGAL::Exact_predicates_inexact_constructions_kernel>::value) {
      Points nan = jitter(points, 0.01);
      nan[n / 2] = Point(std::numeric_limits<double>::quiet_NaN(), 0.5);
      const std::string what = exception_message<DFP::Invalid_prediction>([&] { move(k, nan); });
      DFP_CHECK_MSG(what.find("point " + std::to_string(n / 2)) != std::string::npos, what);
    }
    DFP_CHECK(handles(k) == before);
    DFP_CHECK(same_geometry());
    check(k, points);
  }

  void assign()
  {
    Points points = to_points<K>(with_duplicates(uniform_points(300, rng), 30, rng));
    DT dt;
    DFP::delaunay_from_prediction(points, std::vector<std::array<int, 3>>(), dt);
    Kinetic k;
    k.assign(dt, points);
    DFP_CHECK(dt.number_of_vertices() == 0);
    check(k, points);
    // A triangulation of other points is refused, and k keeps its own.
    DT other;
    Points shifted = jitter(points, 0.5);
    DFP::delaunay_from_prediction(shifted, std::vector<std::array<int, 3>>(), other);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { k.assign(other, points); }));
    DFP_CHECK(other.number_of_vertices() > 0);
    check(k, points);
    points = jitter(points, 0.01);
    move(k, points);
    check(k, points);
  }

  void all(std::size_t n)
  {
    for_each_concurrency([&] {
      { Scope s("moves in place"); moves_in_place(n); }
      { Scope s("dimension changes"); dimension_changes(); }
      { Scope s("merge and split"); merge_and_split(n); }
      { Scope s("duplicates from the start"); duplicates_from_the_start(); }
      { Scope s("bad input"); bad_input(n); }
      { Scope s("assign"); assign(); }
    });
  }
};

int main()
{
  {
    Scope scope("Epick");
    Kinetic_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all(3000);
  }
  {
    Scope scope("Epeck");
    Kinetic_test<CGAL::Exact_predicates_exact_constructions_kernel>().all(500);
  }
  return finish("test_kinetic_triangulation");
}
