// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Degenerate point sets, with Epick and Epeck (one templated body): integer grids and exactly
// co-circular lattice points (ties that only CGAL's symbolic perturbation decides), collinear
// sets, exact duplicates, all points equal, fewer than 3 points, huge offsets (1e15) and tiny
// scales (1e-300). Each is given several predictions (its DT, reversed, flipped, a plain
// Triangulation_2, a subset, jittered, random triples, none); the result must be exactly CGAL's
// DT, by coordinates and, with info, by smallest point indices. make_delaunay too.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>

using namespace dfp_test;

template <class K>
struct Degenerate_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;

  CGAL::Random rng{31337};

  template <class DT, class NP = DFP::parameters::Default_named_parameters>
  DFP::Statistics run(const Points& points, const Faces& faces,
                      const NP& np = DFP::parameters::default_values())
  {
    DT dt;
    dt.insert(make_point<K>(-7., 3.)); // must be cleared
    const DFP::Statistics s =
        with_concurrency([&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt, np); });
    check_is_cgal_delaunay(dt, points);
    check_statistics(s, faces, points, dt);
    return s;
  }

  template <class DT>
  void predictions(const Points& points, const XYs& xy)
  {
    const std::size_t n = points.size();
    const auto reference = indexed_delaunay<K>(points);
    const Faces dt_faces = faces_by_info(reference);
    const bool flat = reference.dimension() < 2;
    {
      Scope s("the DT itself");
      const DFP::Statistics st = run<DT>(points, shuffled(dt_faces, rng));
      DFP_CHECK(st.fell_back == flat);
      if(!flat) {
        DFP_CHECK(st.faces_certified == st.faces_in);
        DFP_CHECK(st.flips == 0);
        DFP_CHECK(st.edges_not_locally_delaunay == 0);
        DFP_CHECK(st.points_unused == n - reference.number_of_vertices());
      }
    }
    {
      Scope s("the DT reversed");
      const DFP::Statistics st = run<DT>(points, reversed(dt_faces));
      DFP_CHECK(st.fell_back == flat);
      DFP_CHECK(flat || st.flips == 0);
    }
    if(!flat) {
      Scope s("the DT after random flips");
      auto flipped = indexed_delaunay<K>(points);
      const std::size_t done = flip_randomly(flipped, std::max<std::size_t>(1, dt_faces.size() / 16), rng);
      const DFP::Statistics st = run<DT>(points, faces_by_info(flipped));
      DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
      if(done > 0)
        DFP_CHECK(st.flips > 0);
    }
    {
      Scope s("a plain Triangulation_2, large flip budget");
      const Faces t2 = faces_by_info(indexed_triangulation<K>(points));
      DT dt;
      const DFP::Statistics st =
          DFP::delaunay_from_prediction(points, t2, dt, DFP::parameters::max_flips(100 * n + 100));
      check_is_cgal_delaunay(dt, points);
      check_statistics(st, t2, points, dt);
      DFP_CHECK(st.fell_back == flat);
    }
    {
      Scope s("a plain Triangulation_2, default parameters");
      run<DT>(points, faces_by_info(indexed_triangulation<K>(points)));
    }
    {
      Scope s("the DT of the first half of the points");
      run<DT>(points, delaunay_faces<K>(Points(points.begin(), points.begin() + std::ptrdiff_t(n / 2))));
    }
    {
      Scope s("the DT of the points jittered");
      double lo = 0., hi = 0.;
      for(const XY& p : xy) {
        lo = std::min(lo, p.x - xy[0].x);
        hi = std::max(hi, p.x - xy[0].x);
      }
      run<DT>(points, delaunay_faces<K>(to_points<K>(jittered(xy, 1e-3 * (hi - lo), rng))));
    }
    {
      Scope s("random triples");
      run<DT>(points, random_triples(n, n, rng));
    }
    {
      Scope s("no faces, strategy(flips)");
      const DFP::Statistics st = run<DT>(points, Faces(), DFP::parameters::strategy(DFP::Strategy::flips));
      DFP_CHECK(st.fell_back);
    }
    {
      Scope s("no faces, default strategy");
      const DFP::Statistics st = run<DT>(points, Faces());
      DFP_CHECK(st.faces_certified == 0);
    }
  }

  // With each concurrency (test_util.h): the parallel certification cuts these triangulations
  // into blocks of 32 faces or more, so the degenerate ones cross block boundaries too.
  void make_delaunay_checks(const Points& points)
  {
    for_each_concurrency([&] { make_delaunay_checks_once(points); });
  }

  void make_delaunay_checks_once(const Points& points)
  {
    {
      Scope s("make_delaunay on a Triangulation_2 of the points");
      T2_plain<K> tr;
      tr.insert(points.begin(), points.end());
      const std::size_t nv = tr.number_of_vertices();
      with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr); });
      DFP_CHECK(tr.number_of_vertices() == nv);
      check_is_cgal_delaunay(tr, points);
    }
    {
      Scope s("make_delaunay on the Triangulation_2 with random flips, large budget");
      T2_plain<K> tr;
      tr.insert(points.begin(), points.end());
      flip_randomly(tr, points.size(), rng);
      const DFP::Statistics st = with_concurrency([&](auto tag) {
        return DFP::make_delaunay<decltype(tag)>(tr, DFP::parameters::max_flips(100 * points.size() + 100));
      });
      check_is_cgal_delaunay(tr, points);
      if(tr.dimension() == 2)
        DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
    }
    {
      Scope s("make_delaunay on the DT after random flips");
      DT_plain<K> tr(points.begin(), points.end());
      flip_randomly(tr, points.size() / 4 + 1, rng);
      const DFP::Statistics st = with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr); });
      check_is_cgal_delaunay(tr, points);
      if(tr.dimension() == 2)
        DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
    }
  }

  void input(const char* name, const XYs& xy)
  {
    Scope scope(name, " (", xy.size(), " points)");
    const Points points = to_points<K>(xy);
    // With each concurrency: the parallel import cuts the faces into chunks of 32 or more, so
    // the degenerate inputs cross chunk boundaries too.
    for_each_concurrency([&] {
      {
        Scope s("DT with info");
        DFP_RUN(predictions<DT_with_info<K>>(points, xy));
      }
      {
        Scope s("DT without info");
        DFP_RUN(predictions<DT_plain<K>>(points, xy));
      }
    });
    DFP_RUN(make_delaunay_checks(points));
  }

  // Four co-circular points: both diagonals are Delaunay without perturbation; exactly one is
  // CGAL's. One prediction is certified as it is, the other needs exactly one flip.
  void cocircular_quadrilaterals()
  {
    const XYs shapes[] = {
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}},         // square
        {{0, 0}, {4, 0}, {4, 2}, {0, 2}},         // rectangle
        {{5, 0}, {0, 5}, {-5, 0}, {-3, -4}},      // on x^2 + y^2 = 25
        {{3, 4}, {-4, 3}, {-3, -4}, {4, -3}},     // another on the same circle
        {{-1, 0}, {0, -1}, {1, 0}, {0, 1}},       // diamond: lexicographic ties in x
    };
    for(const XYs& xy : shapes) {
      Scope scope("co-circular quadrilateral (", xy[0].x, ", ", xy[0].y, ") ...");
      const Points points = to_points<K>(xy);
      std::size_t flips[2], certified = 0;
      const Faces diagonals[2] = {{{0, 1, 2}, {0, 2, 3}}, {{0, 1, 3}, {1, 2, 3}}};
      for(int d = 0; d < 2; ++d) {
        const DFP::Statistics st = run<DT_with_info<K>>(points, diagonals[d]);
        DFP_CHECK(!st.fell_back);
        flips[d] = st.flips;
        certified += st.faces_certified;
      }
      DFP_CHECK_MSG((flips[0] == 0 && flips[1] == 1) || (flips[0] == 1 && flips[1] == 0),
                    flips[0] << ", " << flips[1]);
      DFP_CHECK(certified == 2);
      // make_delaunay on CGAL's DT and on the other diagonal.
      for(int d = 0; d < 2; ++d) {
        DT_plain<K> tr(points.begin(), points.end());
        if(d == 1)
          DFP_CHECK(flip_randomly(tr, 1, rng) == 1);
        const DFP::Statistics st = DFP::make_delaunay(tr);
        check_is_cgal_delaunay(tr, points);
        DFP_CHECK(!st.fell_back);
        DFP_CHECK(st.flips == std::size_t(d));
      }
    }
  }

  // Small random subsets of exactly co-circular lattice points: no central symmetry, so a
  // perturbation that is CGAL's mirrored (another consistent tie-breaking) gives other faces.
  void cocircular_subsets()
  {
    const XYs circle = lattice_circle_points(1105, rng);
    for(int trial = 0; trial < 150; ++trial) {
      XYs xy = circle;
      shuffle(xy, rng);
      xy.resize(std::size_t(rng.get_int(4, 9)));
      Scope scope("co-circular subset, trial ", trial);
      const Points points = to_points<K>(xy);
      run<DT_with_info<K>>(points, delaunay_faces<K>(points));
      auto flipped = indexed_delaunay<K>(points);
      flip_randomly(flipped, 3, rng);
      run<DT_with_info<K>>(points, faces_by_info(flipped));
      T2_plain<K> tr(points.begin(), points.end());
      DFP::make_delaunay(tr);
      check_is_cgal_delaunay(tr, points);
    }
  }

  void small_inputs()
  {
    const XYs cases[] = {
        {},
        {{0.5, 0.5}},
        {{0.5, 0.5}, {0.5, 0.5}},
        {{0.5, 0.5}, {1.5, -0.5}},
        {{0.5, 0.5}, {1.5, -0.5}, {0.5, 0.5}},
        {{0, 0}, {1, 1}, {2, 2}},
        {{0, 0}, {1, 0}, {0, 1}},
        {{0, 0}, {1, 0}, {0, 1}, {1, 0}},
    };
    for(const XYs& xy : cases) {
      Scope scope("small input of ", xy.size(), " points");
      const Points points = to_points<K>(xy);
      const std::size_t n = points.size();
      run<DT_with_info<K>>(points, Faces());
      run<DT_plain<K>>(points, Faces());
      run<DT_with_info<K>>(points, delaunay_faces<K>(points));
      if(n >= 3) {
        run<DT_with_info<K>>(points, Faces{{0, 1, 2}});
        run<DT_with_info<K>>(points, Faces{{2, 1, 0}, {0, 1, 2}});
      }
      make_delaunay_checks(points);
    }
  }

  void all(int grid_size, std::size_t n)
  {
    DFP_RUN(cocircular_quadrilaterals());
    DFP_RUN(small_inputs());
    DFP_RUN(cocircular_subsets());
    input("integer grid", grid_points(grid_size, grid_size, rng));
    input("integer grid, non-square", grid_points(grid_size + 7, 3, rng));
    input("integer grid with duplicates", with_duplicates(grid_points(grid_size, grid_size / 2, rng), n / 4, rng));
    input("lattice points of x^2+y^2=1105^2 (all co-circular)", lattice_circle_points(1105, rng));
    {
      XYs xy = lattice_circle_points(1105, rng, 65);
      input("lattice points of two concentric circles and the centre", xy);
      xy.resize(xy.size() / 2);
      input("a random half of those", xy);
    }
    input("collinear (y = 2x + 1)", collinear_points(n / 4, rng));
    input("collinear, horizontal", transformed(grid_points(int(n / 4), 1, rng), 1., 0.));
    input("collinear, vertical", grid_points(1, int(n / 4), rng));
    input("collinear with duplicates", with_duplicates(collinear_points(n / 8, rng), n / 8, rng));
    input("uniform with duplicates", with_duplicates(uniform_points(n, rng), n / 3, rng));
    input("all points equal", XYs(40, XY{0.3, 0.7}));
    input("two distinct points, many copies", with_duplicates(XYs{{0.3, 0.7}, {0.9, -2.}}, 30, rng));
    input("uniform in [0, 1000]^2 + 1e15 (rounded to multiples of 1/8)",
          transformed(uniform_points(n, rng, 0., 1000.), 1., 1e15));
    input("integer grid + 1e15", transformed(grid_points(grid_size, grid_size, rng), 1., 1e15));
    input("uniform * 1e-300", transformed(uniform_points(n, rng), 1e-300, 0.));
    input("integer grid * 2^-1000", transformed(grid_points(grid_size, grid_size, rng), std::ldexp(1., -1000), 0.));
    input("uniform * 1e300 (squares overflow double)", transformed(uniform_points(n, rng), 1e300, 0.));
    input("uniform * 1e-13 + 1 (coordinates a few hundred ulps apart)",
          transformed(uniform_points(n, rng), 1e-13, 1.));
    for(double tiny_scale : {1e-300, 1e-160, 1e-310 /* subnormal */}) {
      XYs xy = uniform_points(n / 2, rng, -1., 1.);
      const XYs tiny = transformed(uniform_points(n / 2, rng, -1., 1.), tiny_scale, 0.);
      xy.insert(xy.end(), tiny.begin(), tiny.end());
      shuffle(xy, rng);
      std::ostringstream name;
      name << "half uniform in [-1, 1]^2, half that * " << tiny_scale;
      input(name.str().c_str(), xy);
    }
    input("clustered, blobs down to 1e-12 wide", [&] {
      XYs xy = clustered_points(n, rng);
      XYs tight = transformed(uniform_points(n / 4, rng), 1e-12, 0.5);
      xy.insert(xy.end(), tight.begin(), tight.end());
      shuffle(xy, rng);
      return xy;
    }());
  }
};

template struct Degenerate_test<CGAL::Exact_predicates_inexact_constructions_kernel>;
template struct Degenerate_test<CGAL::Exact_predicates_exact_constructions_kernel>;

int main()
{
  {
    Scope scope("Epick");
    Degenerate_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all(20, 400);
  }
  {
    Scope scope("Epeck");
    Degenerate_test<CGAL::Exact_predicates_exact_constructions_kernel>().all(9, 120);
  }
  return finish("test_degenerate");
}
