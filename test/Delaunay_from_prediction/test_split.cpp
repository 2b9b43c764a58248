// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// split_delaunay(): DT(S1) and DT(S2) from DT(S1 u S2). Each part is compared with CGAL's
// triangulation of its points built from scratch with the same kernel (validity, dimension,
// vertices, edges and faces by coordinates), and the vertex info is checked to be copied from
// the input, for both methods (the default, in the input's vertex order, and the paper's
// randomized algorithm): random, spatial and lopsided partitions, a part empty, n < 3, grids,
// co-circular, collinear and duplicate points, huge and tiny coordinates, inputs whose vertex
// order is spatial or random; triangulation types with and without info; bad input.

#include <CGAL/Delaunay_from_prediction/split.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <functional>

using namespace dfp_test;

template <class K>
struct Split_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  using Input = DT_with_info<K>;
  CGAL::Random rng{4242};

  // Checks that `tr` is CGAL's Delaunay triangulation of the points of `all` whose index is
  // in the part, and that each vertex info (if any) is the index of its point, in the part.
  template <class Tr>
  void check_part(const Tr& tr, const Points& all, const std::vector<bool>& in_part, bool exact)
  {
    // The reference: CGAL's build with K, or for an inexact K with Epick on the same doubles
    // (the package decides those by exact predicates).
    using Ref = std::conditional_t<DFP::internal::decides_by_exact_predicates<K>::value, CGAL::Epick, K>;
    auto to_ref = [](const typename K::Point_2& p) {
      if constexpr(std::is_same<Ref, K>::value)
        return p;
      else
        return typename Ref::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    };
    std::vector<typename Ref::Point_2> sub;
    for(std::size_t i = 0; i < all.size(); ++i)
      if(in_part[i])
        sub.push_back(to_ref(all[i]));
    const CGAL::Delaunay_triangulation_2<Ref> reference(sub.begin(), sub.end());
    DFP_CHECK(exact ? tr.is_valid() : tr.tds().is_valid());
    DFP_CHECK_MSG(tr.number_of_vertices() == reference.number_of_vertices(),
                  tr.number_of_vertices() << " vs " << reference.number_of_vertices());
    DFP_CHECK_MSG(tr.dimension() == reference.dimension(), tr.dimension() << " vs " << reference.dimension());
    const auto got = geometry_of(tr, to_ref), expected = geometry_of(reference);
    DFP_CHECK(got.vertices == expected.vertices);
    DFP_CHECK_MSG(got.edges == expected.edges, count_missing(got.edges, expected.edges)
                                                   << " edges not in CGAL's DT, "
                                                   << count_missing(expected.edges, got.edges) << " missing");
    DFP_CHECK_MSG(got.faces == expected.faces, count_missing(got.faces, expected.faces)
                                                   << " faces not in CGAL's DT, "
                                                   << count_missing(expected.faces, got.faces) << " missing");
    if constexpr(has_vertex_info<Tr>) {
      bool info_ok = true;
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
        const std::size_t i = std::size_t(v->info());
        info_ok = info_ok && i < all.size() && in_part[i] && all[i] == v->point();
      }
      DFP_CHECK_MSG(info_ok, "a vertex info is not the index of its point in its part");
    }
  }

  // The input: CGAL's triangulation of the points, info = index (one index for duplicates),
  // built by CGAL's range insertion (vertices in spatial-sort order) or point by point in the
  // given order.
  static Input input_of(const Points& points, bool range_insert = true)
  {
    Input dt;
    if(range_insert) {
      std::vector<std::pair<Point, std::size_t>> pairs;
      for(std::size_t i = 0; i < points.size(); ++i)
        pairs.emplace_back(points[i], i);
      dt.insert(pairs.begin(), pairs.end());
    } else {
      for(std::size_t i = 0; i < points.size(); ++i) {
        const std::size_t count = dt.number_of_vertices();
        const auto v = dt.insert(points[i]);
        if(dt.number_of_vertices() != count)
          v->info() = i;
      }
    }
    return dt;
  }

  // Splits `dt` by `first` (indexed by info) into triangulations holding other points first,
  // with each method, and checks both parts. The input must stay as it was.
  template <class Out1 = DT_with_info<K>, class Out2 = DT_with_info<K>>
  void split(const Input& dt, const Points& points, const std::vector<bool>& first, bool exact = true)
  {
    std::vector<bool> in_first(points.size(), false), in_second(points.size(), false);
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      (first[v->info()] ? in_first : in_second)[v->info()] = true;
    const auto before = geometry_of(dt);
    for(DFP::Split_method method :
        {DFP::Split_method::automatic, DFP::Split_method::ordered, DFP::Split_method::randomized}) {
      Scope s(method == DFP::Split_method::randomized ? "randomized"
              : method == DFP::Split_method::ordered  ? "ordered"
                                                      : "automatic");
      Out1 dt1;
      Out2 dt2;
      dt1.insert(make_point<K>(-50., 7.));
      dt2.insert(make_point<K>(-51., 7.));
      dt2.insert(make_point<K>(-52., 8.));
      std::size_t calls = 0;
      const DFP::Statistics st = DFP::split_delaunay(
          dt, [&](typename Input::Vertex_handle v) { ++calls; return bool(first[v->info()]); }, dt1, dt2,
          DFP::parameters::split_method(method));
      DFP_CHECK_MSG(calls == dt.number_of_vertices(), calls << " calls for " << dt.number_of_vertices());
      check_part(dt1, points, in_first, exact);
      check_part(dt2, points, in_second, exact);
      DFP_CHECK(st.points_reinserted == dt.number_of_vertices());
      if(DFP::internal::decides_by_exact_predicates<K>::value)
        DFP_CHECK(st.fell_back); // inexact predicates: each part built by exact ones
      else if(method == DFP::Split_method::randomized && dt.dimension() == 2 && dt.number_of_vertices() >= 1000)
        DFP_CHECK_MSG(st.points_located + 8 > dt.number_of_vertices() &&
                          st.faces_visited < 4 * st.points_located,
                      st.points_located << " located, " << st.faces_visited << " faces");
    }
    const auto after = geometry_of(dt);
    DFP_CHECK(before.vertices == after.vertices && before.faces == after.faces);
  }

  // The partitions of every point set.
  void partitions_of(const XYs& xy, bool exact = true)
  {
    const Points points = to_points<K>(xy);
    const std::size_t n = points.size();
    const Input dt = input_of(points);
    std::vector<bool> first(n);
    {
      Scope s("random halves");
      for(std::size_t i = 0; i < n; ++i)
        first[i] = rng.get_bool();
      split(dt, points, first, exact);
    }
    {
      Scope s("one tenth in the first part");
      for(std::size_t i = 0; i < n; ++i)
        first[i] = rng.get_int(0, 10) == 0;
      split(dt, points, first, exact);
    }
    {
      Scope s("left and right of the median x");
      std::vector<double> xs;
      for(const XY& p : xy)
        xs.push_back(p.x);
      std::nth_element(xs.begin(), xs.begin() + std::ptrdiff_t(n / 2), xs.end());
      const double median = n ? xs[n / 2] : 0.;
      for(std::size_t i = 0; i < n; ++i)
        first[i] = xy[i].x < median;
      split(dt, points, first, exact);
    }
    {
      Scope s("all in the first part");
      first.assign(n, true);
      split(dt, points, first, exact);
    }
    {
      Scope s("all in the second part");
      first.assign(n, false);
      split(dt, points, first, exact);
    }
  }

  void random_inputs()
  {
    for(std::size_t n : {0u, 1u, 2u, 3u, 4u, 10u, 100u, 2000u}) {
      Scope s("uniform, n = ", n);
      partitions_of(uniform_points(n, rng));
    }
    {
      Scope s("clustered");
      partitions_of(clustered_points(1500, rng));
    }
  }

  void degenerate_inputs()
  {
    {
      Scope s("grid 30 x 30 (co-circular quadruples)");
      partitions_of(grid_points(30, 30, rng));
    }
    {
      Scope s("lattice points on two circles and the centre");
      partitions_of(lattice_circle_points(65, rng, 25));
    }
    {
      Scope s("collinear");
      partitions_of(collinear_points(200, rng));
    }
    {
      Scope s("duplicates");
      partitions_of(with_duplicates(uniform_points(500, rng), 200, rng));
    }
    {
      Scope s("huge coordinates");
      partitions_of(transformed(uniform_points(500, rng), 1e150, 3e150));
    }
    {
      Scope s("tiny coordinates");
      partitions_of(transformed(uniform_points(500, rng), 1e-150, -2e-150));
    }
    {
      Scope s("all points equal");
      partitions_of(XYs(20, XY{0.5, 0.25}));
    }
  }

  // Inputs large enough for the order check: vertices in spatial order (range insertion) and
  // in random order (inserted one by one).
  void vertex_orders()
  {
    const Points points = to_points<K>(uniform_points(20000, rng));
    std::vector<bool> first(points.size());
    for(std::size_t i = 0; i < first.size(); ++i)
      first[i] = rng.get_int(0, 3) == 0;
    {
      Scope s("20000 points, range-inserted input");
      split(input_of(points, true), points, first);
    }
    {
      Scope s("20000 points, input inserted in random order");
      split(input_of(points, false), points, first);
    }
  }

  // Output types: without info, with a vertex base of the user's, with info not assignable.
  void output_types()
  {
    Scope s("output types");
    const Points points = to_points<K>(uniform_points(300, rng));
    const Input dt = input_of(points);
    std::vector<bool> first(points.size());
    for(std::size_t i = 0; i < first.size(); ++i)
      first[i] = rng.get_bool();
    split<DT_plain<K>, DT_colored<K>>(dt, points, first);
    split<DT_labeled<K>, DT_with_info<K, int>>(dt, points, first);
  }
};

// Bad input: an output that is the input, or both outputs the same object, throws with
// nothing changed; an exception from the predicate leaves the outputs as they were.
void bad_input()
{
  using K = CGAL::Epick;
  using Tr = DT_with_info<K>;
  CGAL::Random rng(17);
  const auto points = to_points<K>(uniform_points(100, rng));
  Tr dt = Split_test<K>::input_of(points);
  Tr other;
  for(int k = 0; k < 5; ++k)
    other.insert(make_point<K>(k, k * k))->info() = 100 + std::size_t(k);
  const Snapshot<Tr> dt_before(dt), other_before(other);
  auto in_first = [](Tr::Vertex_handle v) { return v->info() % 2 == 0; };
  auto throws_naming = [&](const auto& body, const std::string& words) {
    const std::string message = exception_message<DFP::Invalid_prediction>(body);
    return DFP_CHECK_MSG(message.find(words) != std::string::npos, message);
  };
  {
    Scope s("dt1 is dt");
    throws_naming([&] { DFP::split_delaunay(dt, in_first, dt, other); }, "two triangulations other than dt");
    check_unchanged(dt, dt_before);
    check_unchanged(other, other_before);
  }
  {
    Scope s("dt2 is dt");
    throws_naming([&] { DFP::split_delaunay(dt, in_first, other, dt); }, "two triangulations other than dt");
    check_unchanged(dt, dt_before);
    check_unchanged(other, other_before);
  }
  {
    Scope s("dt1 is dt2");
    throws_naming([&] { DFP::split_delaunay(dt, in_first, other, other); }, "two triangulations other than dt");
    check_unchanged(other, other_before);
  }
  {
    Scope s("the predicate throws");
    Tr second = other;
    const Snapshot<Tr> second_before(second);
    bool thrown = false;
    try {
      DFP::split_delaunay(
          dt,
          [](Tr::Vertex_handle v) {
            if(v->info() == 37)
              throw std::runtime_error("no part for 37");
            return true;
          },
          other, second);
    } catch(const std::runtime_error&) {
      thrown = true;
    }
    DFP_CHECK(thrown);
    check_unchanged(other, other_before);
    check_unchanged(second, second_before);
    check_unchanged(dt, dt_before);
  }
}

int main()
{
  {
    Scope s("Epick");
    Split_test<CGAL::Epick> t;
    DFP_RUN(t.random_inputs());
    DFP_RUN(t.degenerate_inputs());
    DFP_RUN(t.vertex_orders());
    DFP_RUN(t.output_types());
  }
  {
    Scope s("Epeck");
    Split_test<CGAL::Epeck> t;
    DFP_RUN(t.partitions_of(uniform_points(300, t.rng)));
    DFP_RUN(t.partitions_of(lattice_circle_points(25, t.rng, 5)));
    DFP_RUN(t.partitions_of(with_duplicates(grid_points(8, 8, t.rng), 20, t.rng)));
  }
  {
    // Inexact: each part is Epick's Delaunay triangulation of the same doubles.
    Scope s("Simple_cartesian<double>");
    Split_test<CGAL::Simple_cartesian<double>> t;
    DFP_RUN(t.partitions_of(uniform_points(1000, t.rng), false));
    DFP_RUN(t.partitions_of(jittered(grid_points(20, 20, t.rng), 1e-13, t.rng), false));
  }
  DFP_RUN(bad_input());
  return finish("test_split");
}
