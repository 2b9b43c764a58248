// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// brio_dc_delaunay(): BrioDC, the Delaunay triangulation by samples that meet every
// nearest-neighbour graph component and walks along the graph's edges. Every result is
// compared with CGAL's triangulation built from scratch with the same kernel (by coordinates
// and by point indices): random, clustered and graded points, grids, co-circular, collinear
// and duplicate points, huge and tiny coordinates, n < 3, several seeds; triangulation types
// with and without info; sampling probabilities; the grid's nearest-neighbour graph against
// brute force; the walks being short; bad input.

#include <CGAL/Delaunay_from_prediction/brio_dc.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

using namespace dfp_test;

// Points whose density varies by orders of magnitude (x = u^4, y = v^4): crowded grid cells.
inline XYs graded_points(std::size_t n, CGAL::Random& rng)
{
  XYs xy;
  for(std::size_t i = 0; i < n; ++i) {
    const double u = rng.get_double(), v = rng.get_double();
    xy.push_back({u * u * u * u, v * v * v * v});
  }
  return xy;
}

template <class K>
struct Brio_dc_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  CGAL::Random rng{6174};

  // Triangulates into a triangulation holding other points first, then compares with CGAL.
  // A seed of 0 and a probability of 0 stand for the defaults.
  template <class DT = DT_with_info<K>>
  DFP::Statistics run(const XYs& xy, bool exact = true, unsigned seed = 0, double probability = 0)
  {
    const Points points = to_points<K>(xy);
    DT dt;
    dt.insert(make_point<K>(-50., 7.));
    dt.insert(make_point<K>(-51., 7.));
    const DFP::Statistics s =
        probability != 0 ? DFP::brio_dc_delaunay(points, dt, DFP::parameters::sample_probability(probability))
        : seed == 0      ? DFP::brio_dc_delaunay(points, dt)
                         : DFP::brio_dc_delaunay(points, dt, CGAL::parameters::random_seed(seed));
    if(exact) {
      check_is_cgal_delaunay(dt, points);
    } else {
      DFP_CHECK(dt.tds().is_valid());
      DFP_CHECK(dt.number_of_vertices() == smallest_indices(points).size());
    }
    DFP_CHECK(s.points_reinserted == points.size());
    DFP_CHECK_MSG(s.duplicate_points == points.size() - smallest_indices(points).size(), s.duplicate_points);
    DFP_CHECK(s.points_located <= points.size());
    // Inexact predicates: built by CGAL's insertion instead, a fallback (predicates.h).
    DFP_CHECK(s.fell_back == DFP::internal::decides_by_exact_predicates<K>::value);
    return s;
  }

  void random_inputs()
  {
    for(std::size_t n : {0u, 1u, 2u, 3u, 4u, 10u, 64u, 65u, 100u, 2000u}) {
      Scope s("uniform, n = ", n);
      run(uniform_points(n, rng));
    }
    {
      Scope s("clustered");
      run(clustered_points(3000, rng));
    }
    {
      Scope s("graded (x = u^4, y = v^4)");
      run(graded_points(3000, rng));
    }
    {
      Scope s("other seeds");
      const XYs xy = uniform_points(1500, rng);
      run(xy, true, 1);
      run(xy, true, 99);
    }
  }

  void degenerate_inputs()
  {
    {
      Scope s("grid 40 x 40 (co-circular quadruples, tied neighbours)");
      run(grid_points(40, 40, rng));
    }
    {
      Scope s("lattice points on two circles and the centre");
      run(lattice_circle_points(65, rng, 25));
    }
    {
      Scope s("collinear");
      run(collinear_points(500, rng));
    }
    {
      Scope s("vertical line");
      XYs xy;
      for(int i = 0; i < 300; ++i)
        xy.push_back({2.5, double((i * 37) % 300)});
      run(xy);
    }
    {
      Scope s("duplicates");
      run(with_duplicates(uniform_points(500, rng), 300, rng));
    }
    {
      Scope s("grid with duplicates");
      run(with_duplicates(grid_points(12, 12, rng), 60, rng));
    }
    {
      Scope s("huge coordinates");
      run(transformed(uniform_points(800, rng), 1e150, 3e150));
    }
    {
      Scope s("tiny coordinates");
      run(transformed(uniform_points(800, rng), 1e-150, -2e-150));
    }
    {
      Scope s("all points equal");
      run(XYs(200, XY{0.5, 0.25}));
    }
    {
      // More than a search reads in one cell: approximate neighbours, exact result.
      Scope s("a crowded cell: 2000 points in a box 1e-9 wide among 200 spread ones");
      XYs xy = uniform_points(200, rng);
      for(const XY& p : uniform_points(2000, rng))
        xy.push_back({0.5 + 1e-9 * p.x, 0.5 + 1e-9 * p.y});
      shuffle(xy, rng);
      run(xy);
    }
  }

  // Every sampling probability gives CGAL's triangulation; a larger one keeps more points a
  // level, hence no fewer levels (and more from the smallest to the largest).
  void sample_probabilities()
  {
    const XYs uniform = uniform_points(3000, rng), clustered = clustered_points(3000, rng);
    const XYs grid = grid_points(30, 30, rng), duplicates = with_duplicates(uniform_points(400, rng), 200, rng);
    std::size_t rounds_before = 0, fewest = 0;
    for(const double probability : {1e-9, 0.125, 0.5, 1.0}) {
      Scope s("sample_probability ", probability);
      const std::size_t rounds = run(uniform, true, 0, probability).insertion_rounds;
      DFP_CHECK_MSG(rounds >= rounds_before, rounds << " levels, " << rounds_before << " with a smaller probability");
      if(rounds_before == 0)
        fewest = rounds;
      else if(probability == 1.0)
        DFP_CHECK_MSG(rounds > fewest, rounds << " levels with probability 1, " << fewest << " with 1e-9");
      rounds_before = rounds;
      run(clustered, true, 0, probability);
      run(grid, true, 0, probability);
      run(duplicates, true, 0, probability);
    }
  }

  void triangulation_types()
  {
    Scope s("triangulation types");
    const XYs xy = uniform_points(500, rng);
    run<DT_plain<K>>(xy);
    run<DT_colored<K>>(xy);
    run<DT_labeled<K>>(xy);
  }
};

// The walks along the graph locate nearly every point in a few faces.
void walks_are_short()
{
  CGAL::Random rng(12);
  Brio_dc_test<CGAL::Epick> t;
  for(const bool clustered : {false, true}) {
    Scope s(clustered ? "30000 clustered points" : "30000 uniform points");
    const XYs xy = clustered ? clustered_points(30000, rng) : uniform_points(30000, rng);
    const DFP::Statistics st = t.run(xy);
    DFP_CHECK_MSG(st.points_located + 64 >= xy.size(), st.points_located);
    DFP_CHECK_MSG(st.faces_visited < 3 * st.points_located, st.faces_visited << " faces for " << st.points_located);
    DFP_CHECK_MSG(st.walk_fallbacks < xy.size() / 100, st.walk_fallbacks);
    DFP_CHECK_MSG(st.insertion_rounds >= 5, st.insertion_rounds);
  }
}

// The grid's nearest-neighbour graph against a brute-force search: the same distance for
// every point (the neighbour itself may differ among tied ones), `order` a permutation.
void nearest_neighbour_graph_is_exact()
{
  CGAL::Random rng(21);
  auto check = [](const XYs& points) {
    const std::size_t m = points.size();
    std::vector<double> xy;
    for(const XY& p : points) {
      xy.push_back(p.x);
      xy.push_back(p.y);
    }
    std::vector<std::uint32_t> order, nn;
    DFP::internal::nearest_neighbour_graph(xy.data(), m, order, nn);
    DFP_CHECK(order.size() == m && nn.size() == m);
    std::vector<unsigned char> seen(m, 0);
    for(std::uint32_t o : order) {
      DFP_CHECK(o < m && !seen[o]);
      seen[o] = 1;
    }
    auto squared = [&](std::size_t a, std::size_t b) {
      const double dx = points[a].x - points[b].x, dy = points[a].y - points[b].y;
      return dx * dx + dy * dy;
    };
    std::size_t wrong = 0;
    for(std::size_t k = 0; k < m; ++k) {
      double nearest = std::numeric_limits<double>::infinity();
      for(std::size_t j = 0; j < m; ++j)
        if(j != order[k])
          nearest = (std::min)(nearest, squared(order[k], j));
      if(m < 2) {
        DFP_CHECK(nn[k] == DFP::internal::no_rank);
      } else if(nn[k] >= m || nn[k] == k || squared(order[k], order[nn[k]]) != nearest) {
        ++wrong;
      }
    }
    DFP_CHECK_MSG(wrong == 0, wrong << " of " << m << " points without their nearest neighbour");
  };
  for(std::size_t m : {0u, 1u, 2u, 3u, 50u, 3000u}) {
    Scope s("uniform, m = ", m);
    check(uniform_points(m, rng));
  }
  {
    Scope s("clustered");
    check(clustered_points(4000, rng, 3));
  }
  {
    Scope s("graded");
    check(graded_points(4000, rng));
  }
  {
    Scope s("grid");
    check(grid_points(50, 50, rng));
  }
  {
    Scope s("collinear and vertical");
    check(collinear_points(800, rng));
    XYs xy;
    for(int i = 0; i < 500; ++i)
      xy.push_back({-1.0, double((i * 37) % 500)});
    check(xy);
  }
  {
    Scope s("duplicates");
    check(with_duplicates(uniform_points(700, rng), 400, rng));
  }
  {
    Scope s("dense clusters in refined cells, each among sparse points");
    XYs xy = uniform_points(500, rng);
    for(int c = 0; c < 4; ++c)
      for(const XY& p : uniform_points(600, rng))
        xy.push_back({0.2 + 0.2 * c + 1e-3 * p.x, 0.3 + 0.1 * c + 1e-3 * p.y});
    shuffle(xy, rng);
    check(xy);
  }
  {
    // Refined cells within refined cells: a search from outside must descend, not read a
    // crowded subcell whole (that would exhaust the search's budget).
    Scope s("a cluster within a cluster, among sparse points");
    XYs xy = uniform_points(400, rng);
    for(const XY& p : uniform_points(600, rng))
      xy.push_back({0.4 + 1e-3 * p.x, 0.6 + 1e-3 * p.y});
    for(const XY& p : uniform_points(2000, rng))
      xy.push_back({0.4005 + 1e-7 * p.x, 0.6005 + 1e-7 * p.y});
    shuffle(xy, rng);
    check(xy);
  }
}

// A non-finite point throws Invalid_prediction naming it; the triangulation is unchanged.
void bad_input()
{
  using K = CGAL::Epick;
  CGAL::Random rng(3);
  auto points = to_points<K>(uniform_points(300, rng));
  points[123] = make_point<K>(1., std::nan(""));
  DT_with_info<K> dt;
  for(int k = 0; k < 5; ++k)
    dt.insert(make_point<K>(k, k * k))->info() = 100 + std::size_t(k);
  const Snapshot<DT_with_info<K>> before(dt);
  const std::string message = exception_message<DFP::Invalid_prediction>([&] { DFP::brio_dc_delaunay(points, dt); });
  DFP_CHECK_MSG(message.find("point 123") != std::string::npos, message);
  check_unchanged(dt, before);
  // A sampling probability outside (0, 1]: std::invalid_argument naming it, nothing changed.
  points[123] = make_point<K>(1., 2.);
  for(const double probability : {0.0, -0.5, 1.5, std::nan("")}) {
    Scope s("sample_probability ", probability);
    const std::string bad = exception_message<std::invalid_argument>(
        [&] { DFP::brio_dc_delaunay(points, dt, DFP::parameters::sample_probability(probability)); });
    DFP_CHECK_MSG(bad.find("sample_probability") != std::string::npos, bad);
    check_unchanged(dt, before);
  }
}

int main()
{
  {
    Scope s("Epick");
    Brio_dc_test<CGAL::Epick> t;
    DFP_RUN(t.random_inputs());
    DFP_RUN(t.degenerate_inputs());
    DFP_RUN(t.sample_probabilities());
    DFP_RUN(t.triangulation_types());
  }
  {
    Scope s("Epeck");
    Brio_dc_test<CGAL::Epeck> t;
    DFP_RUN(t.run(uniform_points(400, t.rng)));
    DFP_RUN(t.run(lattice_circle_points(25, t.rng, 5)));
    DFP_RUN(t.run(with_duplicates(grid_points(10, 10, t.rng), 30, t.rng)));
  }
  {
    // Inexact: must terminate with a valid triangulation (exactness is not promised).
    Scope s("Simple_cartesian<double>");
    Brio_dc_test<CGAL::Simple_cartesian<double>> t;
    DFP_RUN(t.run(uniform_points(2000, t.rng), false));
    DFP_RUN(t.run(jittered(grid_points(30, 30, t.rng), 1e-13, t.rng), false));
  }
  DFP_RUN(nearest_neighbour_graph_is_exact());
  DFP_RUN(walks_are_short());
  DFP_RUN(bad_input());
  return finish("test_brio_dc");
}
