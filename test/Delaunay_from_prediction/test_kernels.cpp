// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// One templated test body, instantiated (as CGAL does) over Epick, Epeck,
// Simple_cartesian<double> (inexact) and Simple_cartesian<Gmpq> (exact, slow: small n).
// For each kernel: delaunay_from_prediction() with the main predictions and make_delaunay()
// after small and large moves, compared with CGAL's DT built with the same kernel. Exact
// kernels also get co-circular inputs; the inexact kernel gets a near-degenerate input on which
// it must still terminate with a valid triangulation (built by CGAL's insertion: a fallback).

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>

using namespace dfp_test;

template <class K>
struct Kernel_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;

  CGAL::Random rng{2718};
  // Inexact predicates (Simple_cartesian<double>): every entry point builds with CGAL's own
  // insertion (a fallback), so the checks of how the prediction was used do not apply.
  static constexpr bool exact_predicates = !DFP::internal::decides_by_exact_predicates<K>::value;

  // delaunay_from_prediction into a pre-filled dt; compares with CGAL if `compare`.
  template <class DT, class NP = DFP::parameters::Default_named_parameters>
  DFP::Statistics run(const Points& points, const Faces& faces, bool compare = true,
                      const NP& np = DFP::parameters::default_values())
  {
    DT dt;
    dt.insert(make_point<K>(10., 10.));
    dt.insert(make_point<K>(11., 10.));
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt, np);
    if(compare) {
      check_is_cgal_delaunay(dt, points);
      check_statistics(s, faces, points, dt);
    } else {
      DFP_CHECK(dt.is_valid());
      DFP_CHECK(dt.number_of_vertices() == points.size());
    }
    return s;
  }

  template <class DT>
  void predictions(const Points& points, const XYs& xy)
  {
    const std::size_t n = points.size();
    const Faces dt_faces = delaunay_faces<K>(points);
    {
      Scope s("the DT itself");
      const DFP::Statistics st = run<DT>(points, shuffled(dt_faces, rng));
      DFP_CHECK(st.fell_back == !exact_predicates);
      if(exact_predicates) {
        DFP_CHECK(st.faces_certified == st.faces_in);
        DFP_CHECK(st.flips == 0);
        DFP_CHECK(st.edges_tested == 2 * dt_faces.size() + 1 - n);
      }
    }
    {
      Scope s("the DT reversed");
      const DFP::Statistics st = run<DT>(points, reversed(dt_faces));
      DFP_CHECK(!exact_predicates || (!st.fell_back && st.flips == 0));
    }
    {
      Scope s("the DT after random flips");
      std::size_t done = 0;
      const Faces faces = flipped_delaunay_faces<K>(points, n / 10 + 1, rng, &done);
      const std::size_t wrong = edges_not_in_delaunay<K>(faces, points);
      const DFP::Statistics st = run<DT>(points, faces);
      DFP_CHECK(done > 0 && wrong > 0);
      if(exact_predicates) {
        DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
        DFP_CHECK_MSG(st.flips >= wrong, st.flips << " vs " << wrong);
        DFP_CHECK(st.edges_not_locally_delaunay >= 1 && st.edges_not_locally_delaunay <= wrong);
      }
    }
    {
      Scope s("a plain Triangulation_2, max_flips(100 n)");
      const DFP::Statistics st = run<DT>(points, faces_by_info(indexed_triangulation<K>(points)),
                                         true, DFP::parameters::max_flips(100 * n));
      if(exact_predicates) {
        DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
        DFP_CHECK(st.flips > 0);
      }
    }
    {
      Scope s("a plain Triangulation_2, default parameters");
      run<DT>(points, faces_by_info(indexed_triangulation<K>(points)));
    }
    {
      Scope s("the DT of jittered points");
      run<DT>(points, delaunay_faces<K>(to_points<K>(jittered(xy, 0.2 / std::sqrt(double(n)), rng))));
    }
    {
      Scope s("faces deleted");
      run<DT>(points, with_faces_deleted(dt_faces, 3, rng));
    }
    {
      Scope s("random triples");
      run<DT>(points, random_triples(n, n, rng));
    }
    {
      Scope s("no faces, strategy(flips)");
      DFP_CHECK(run<DT>(points, Faces(), true, DFP::parameters::strategy(DFP::Strategy::flips)).fell_back);
    }
    {
      Scope s("no faces, default strategy");
      DFP_CHECK(run<DT>(points, Faces()).faces_certified == 0);
    }
    {
      Scope s("the DT of half the points");
      const DFP::Statistics st =
          run<DT>(points, delaunay_faces<K>(Points(points.begin(), points.begin() + std::ptrdiff_t(n / 2))));
      if(exact_predicates) {
        DFP_CHECK(!st.fell_back);
        DFP_CHECK(st.points_unused == n - n / 2);
      }
    }
  }

  template <class Tr>
  void moving(const Points& points)
  {
    Tr tr;
    Handles<Tr> handles;
    build(tr, points, handles);
    const std::size_t n = points.size();
    const double spacing = 1. / std::sqrt(double(n));
    auto step = [&](const char* what, DFP::Strategy strategy = DFP::Strategy::automatic) {
      Scope s(what);
      const Points now = current_points(handles);
      const DFP::Statistics st = DFP::make_delaunay(tr, DFP::parameters::strategy(strategy));
      check_handles(tr, handles, now);
      check_is_cgal_delaunay(tr, now);
      return st;
    };
    auto mirror = [&] {
      for(const auto& v : handles)
        v->set_point(make_point<K>(-CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())));
    };
    step("initial");
    move_keeping_faces_ccw(tr, handles, 0.03 * spacing, rng);
    DFP_CHECK(step("small moves keeping faces ccw").fell_back == !exact_predicates);
    for(const auto& v : handles)
      v->set_point(make_point<K>(CGAL::to_double(v->point().x()) + rng.get_double(-2., 2.) * spacing,
                                 CGAL::to_double(v->point().y()) + rng.get_double(-2., 2.) * spacing));
    DFP_CHECK(inverted_faces(tr) > 0);
    step("large moves");
    // The mirror image of a DT has every face inverted: mirrored, then mirrored back.
    mirror();
    DFP_CHECK(inverted_faces(tr) == tr.number_of_faces());
    DFP_CHECK(step("mirrored, strategy(flips)", DFP::Strategy::flips).fell_back);
    mirror();
    DFP_CHECK(inverted_faces(tr) == tr.number_of_faces());
    const DFP::Statistics st = step("mirrored back, default strategy");
    DFP_CHECK(st.fell_back || st.faces_carved > 0);
  }

  void cocircular()
  {
    {
      Scope s("integer grid");
      const XYs xy = grid_points(9, 8, rng);
      const Points points = to_points<K>(xy);
      predictions<DT_with_info<K>>(points, xy);
    }
    {
      Scope s("lattice points of x^2 + y^2 = 1105^2");
      const Points points = to_points<K>(lattice_circle_points(1105, rng));
      run<DT_with_info<K>>(points, delaunay_faces<K>(points));
      run<DT_with_info<K>>(points, flipped_delaunay_faces<K>(points, 20, rng));
      run<DT_with_info<K>>(points, faces_by_info(indexed_triangulation<K>(points)));
      T2_plain<K> tr(points.begin(), points.end());
      DFP::make_delaunay(tr);
      check_is_cgal_delaunay(tr, points);
    }
  }

  // Inexact kernel on points that are nearly co-circular: the in-circle test is unreliable,
  // Lawson's flips may cycle; the call must still end with a valid triangulation of the points.
  void near_degenerate()
  {
    XYs xy;
    for(int i = 0; i < 300; ++i) {
      const double t = 6.283185307179586 * i / 300.;
      xy.push_back({std::cos(t), std::sin(t)});
    }
    const XYs inside = uniform_points(50, rng, -0.5, 0.5);
    xy.insert(xy.end(), inside.begin(), inside.end());
    shuffle(xy, rng);
    const Points points = to_points<K>(xy);
    const Faces t2 = faces_by_info(indexed_triangulation<K>(points));
    {
      Scope s("nearly co-circular, plain Triangulation_2, default budget");
      run<DT_with_info<K>>(points, t2, false);
    }
    {
      Scope s("nearly co-circular, plain Triangulation_2, max_flips(1e5)");
      run<DT_with_info<K>>(points, t2, false, DFP::parameters::max_flips(100000));
    }
    {
      Scope s("nearly co-circular, make_delaunay");
      T2_plain<K> tr(points.begin(), points.end());
      DFP::make_delaunay(tr);
      DFP_CHECK(tr.is_valid());
      DFP_CHECK(tr.number_of_vertices() == points.size());
    }
  }

  void all(const char* name, std::size_t n, bool exact)
  {
    Scope scope(name);
    const XYs xy = uniform_points(n, rng);
    const Points points = to_points<K>(xy);
    {
      Scope s("uniform, n = ", n, ", DT with info");
      DFP_RUN(predictions<DT_with_info<K>>(points, xy));
    }
    {
      Scope s("uniform, n = ", n, ", DT without info");
      DFP_RUN(predictions<DT_plain<K>>(points, xy));
    }
    {
      const XYs blobs = clustered_points(n, rng, 4);
      Scope s("clustered, n = ", n, ", DT with info");
      DFP_RUN(predictions<DT_with_info<K>>(to_points<K>(blobs), blobs));
    }
    {
      Scope s("make_delaunay, Delaunay_triangulation_2 with info");
      DFP_RUN(moving<DT_with_info<K>>(points));
    }
    {
      Scope s("make_delaunay, Triangulation_2");
      DFP_RUN(moving<T2_plain<K>>(points));
    }
    if(exact)
      DFP_RUN(cocircular());
    else
      DFP_RUN(near_degenerate());
  }
};

template struct Kernel_test<CGAL::Exact_predicates_inexact_constructions_kernel>;
template struct Kernel_test<CGAL::Exact_predicates_exact_constructions_kernel>;
template struct Kernel_test<CGAL::Simple_cartesian<double>>;
template struct Kernel_test<CGAL::Simple_cartesian<CGAL::Gmpq>>;

int main()
{
  Kernel_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all("Epick", 2000, true);
  Kernel_test<CGAL::Exact_predicates_exact_constructions_kernel>().all("Epeck", 400, true);
  Kernel_test<CGAL::Simple_cartesian<double>>().all("Simple_cartesian<double>", 1000, false);
  Kernel_test<CGAL::Simple_cartesian<CGAL::Gmpq>>().all("Simple_cartesian<Gmpq>", 150, true);
  return finish("test_kernels");
}
