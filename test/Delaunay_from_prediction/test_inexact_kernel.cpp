// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The project rule for inexact kernels: with Simple_cartesian<double> (no filtered or exact
// predicates) every entry point terminates, without a crash, with the Delaunay triangulation
// decided by exact predicates on the same doubles: CGAL's Epick build, as coordinates and,
// where the vertices carry a point index, as index triples.
// The minimized fuzzer findings (fuzz.md F6, F7, F8 "related", F9, F12), then seeded random
// small cases per entry point: uniform, almost collinear (y = 3x + 1 rounded), almost
// co-circular (the unit circle rounded), and make_delaunay moves onto a line or a circle.
// Each case runs in a child process with a time limit (isolated, test_util.h).

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/brio_dc.h>
#include <CGAL/Delaunay_from_prediction/imprecise_points.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/split.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Projection_traits_xz_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace dfp_test;
using SC = CGAL::Simple_cartesian<double>;
using Point = SC::Point_2;
using Pts = std::vector<std::array<double, 2>>;
using Random = DFP::internal::Splitmix64;
using Hierarchy = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<
    SC, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<
            CGAL::Triangulation_vertex_base_with_info_2<std::size_t, SC>>>>>;

namespace {

constexpr unsigned time_limit = 20; // seconds per case: all of them take milliseconds

std::vector<Point> to_points(const Pts& p)
{
  std::vector<Point> out;
  for(const auto& xy : p)
    out.emplace_back(xy[0], xy[1]);
  return out;
}

std::vector<CGAL::Epick::Point_2> to_points_epick(const Pts& p)
{
  std::vector<CGAL::Epick::Point_2> out;
  for(const auto& xy : p)
    out.emplace_back(xy[0], xy[1]);
  return out;
}

bool distinct(const std::vector<Point>& p)
{
  std::set<std::pair<double, double>> seen;
  for(const Point& q : p)
    if(!seen.insert({q.x(), q.y()}).second)
      return false;
  return true;
}

// make_delaunay after moving the vertices of a triangulation of p0 to p1: terminates, keeps the
// vertex objects, their points and info, and gives the Delaunay triangulation decided by exact
// predicates (CGAL's Epick build of the same doubles), or throws naming two equal points.
template <class Tr>
void check_make_delaunay(const Pts& p0, const Pts& p1)
{
  const std::vector<Point> P0 = to_points(p0), P1 = to_points(p1);
  Tr tr;
  Handles<Tr> handles;
  build(tr, P0, handles); // by exact predicates (test_util.h): CGAL's SC insertion can crash
  for(std::size_t i = 0; i < handles.size(); ++i)
    handles[i]->set_point(P1[i]);
  if(!distinct(P1)) {
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::make_delaunay(tr); }));
    return;
  }
  const DFP::Statistics s = DFP::make_delaunay(tr);
  DFP_CHECK(s.fell_back); // inexact predicates: always rebuilt
  check_handles(tr, handles, P1);
  check_is_cgal_delaunay<CGAL::Epick>(tr, P1);
}

void check_make_delaunay_all(const Pts& p0, const Pts& p1)
{
  check_make_delaunay<T2_plain<SC>>(p0, p1);
  check_make_delaunay<T2_with_info<SC>>(p0, p1);
  check_make_delaunay<DT_plain<SC>>(p0, p1);
  check_make_delaunay<DT_with_info<SC>>(p0, p1);
}

// `dt` is the Delaunay triangulation of P decided by exact predicates: CGAL's Epick build of
// the same doubles, compared by coordinates (the info is checked where it is a point index).
template <class DT>
void check_result(const DT& dt, const std::vector<Point>& P)
{
  auto to_epick = [](const Point& p) { return CGAL::Epick::Point_2(p.x(), p.y()); };
  std::vector<CGAL::Epick::Point_2> E;
  for(const Point& p : P)
    E.push_back(to_epick(p));
  const CGAL::Delaunay_triangulation_2<CGAL::Epick> reference(E.begin(), E.end());
  DFP_CHECK(dt.tds().is_valid());
  DFP_CHECK_MSG(dt.number_of_vertices() == reference.number_of_vertices(),
                dt.number_of_vertices() << " vs " << reference.number_of_vertices());
  const auto got = geometry_of(dt, to_epick), expected = geometry_of(reference);
  DFP_CHECK(got.vertices == expected.vertices);
  DFP_CHECK(got.edges == expected.edges);
  DFP_CHECK(got.faces == expected.faces);
}

void check_imprecise(const Pts& centres, const std::vector<double>& radii, const Pts& instance)
{
  const std::vector<Point> C = to_points(centres), I = to_points(instance);
  DFP::Imprecise_points_2<SC> disks(C, radii);
  DT_with_info<SC> dt;
  disks.triangulate(I, dt);
  check_result(dt, I);
}

void check_split(const Pts& p, const std::vector<bool>& in_first)
{
  const std::vector<Point> P = to_points(p);
  DT_with_info<SC> dt, dt1, dt2;
  // The input built by the package (CGAL's own SC insertion may lose almost collinear points).
  DFP::delaunay_from_prediction(P, Faces(), dt);
  DFP_CHECK(dt.number_of_vertices() == P.size());
  for(auto method : {DFP::Split_method::automatic, DFP::Split_method::ordered, DFP::Split_method::randomized}) {
    DFP::split_delaunay(dt, [&](auto v) { return bool(in_first[v->info()]); }, dt1, dt2,
                        DFP::parameters::split_method(method));
    std::vector<Point> P1, P2;
    for(std::size_t i = 0; i < P.size(); ++i)
      (in_first[i] ? P1 : P2).push_back(P[i]);
    check_result(dt1, P1);
    check_result(dt2, P2);
  }
}

void check_builds(const Pts& p)
{
  const std::vector<Point> P = to_points(p);
  // CGAL's faces by exact predicates (its SC build may lose almost collinear points).
  const Faces exact = delaunay_faces<CGAL::Epick>(to_points_epick(p));
  { // delaunay_from_prediction: CGAL's faces, and those faces reversed and partly deleted
    DT_with_info<SC> dt;
    DFP::delaunay_from_prediction(P, exact, dt);
    check_is_cgal_delaunay<CGAL::Epick>(dt, P);
    Faces noisy = reversed(exact);
    if(noisy.size() > 2)
      noisy.resize(noisy.size() - 1);
    DT_plain<SC> dt2;
    DFP::delaunay_from_prediction(P, noisy, dt2);
    check_result(dt2, P);
  }
  { // a Triangulation_hierarchy_2: level 0 decided exactly, the upper levels left empty
    Hierarchy h;
    DFP::delaunay_from_prediction(P, exact, h);
    check_is_cgal_delaunay<CGAL::Epick>(static_cast<const Hierarchy::Tr_Base&>(h), P);
    bool linked = false;
    for(auto v = h.Tr_Base::finite_vertices_begin(); v != h.Tr_Base::finite_vertices_end(); ++v)
      linked = linked || v->up() != Hierarchy::Vertex_handle();
    DFP_CHECK(!linked);
  }
  { // brio_dc_delaunay
    DT_with_info<SC> dt;
    DFP::brio_dc_delaunay(P, dt);
    check_is_cgal_delaunay<CGAL::Epick>(dt, P);
  }
  { // delaunay_from_spanning_graph: a path through the points
    std::vector<std::array<std::size_t, 2>> path;
    for(std::size_t i = 1; i < P.size(); ++i)
      path.push_back({i - 1, i});
    DT_with_info<SC> dt;
    DFP::delaunay_from_spanning_graph(P, path, dt);
    check_result(dt, P);
  }
}

// ---------------------------------------------------------------------------------------------
// Random small cases
// ---------------------------------------------------------------------------------------------

enum Family { uniform, collinear, cocircular, families };
const char* family_name[] = {"uniform", "almost collinear", "almost co-circular"};

Pts random_points(Random& rng, Family family, std::size_t n)
{
  Pts p;
  for(std::size_t i = 0; i < n; ++i) {
    const double u = rng.uniform(), v = rng.uniform();
    switch(family) {
    case uniform: p.push_back({u, v}); break;
    case collinear: p.push_back({u, 3 * u + 1}); break; // rounded: almost collinear
    default: p.push_back({std::cos(6.283185307179586 * u), std::sin(6.283185307179586 * u)});
    }
  }
  return p;
}

// The moves: onto a line (y = 3x + 1, x kept), onto the unit circle, or a small jitter.
Pts moved(Random& rng, const Pts& p, int kind)
{
  Pts q = p;
  for(auto& xy : q) {
    if(kind == 0)
      xy[1] = 3 * xy[0] + 1;
    else if(kind == 1) {
      const double a = std::atan2(xy[1] - 0.5, xy[0] - 0.5);
      xy = {std::cos(a), std::sin(a)};
    } else {
      xy[0] += 1e-3 * (rng.uniform() - 0.5);
      xy[1] += 1e-3 * (rng.uniform() - 0.5);
    }
  }
  return q;
}

void random_cases(std::uint64_t seed, std::size_t count)
{
  Random rng{seed};
  for(std::size_t k = 0; k < count; ++k) {
    const Family family = Family(k % families);
    const std::size_t n = 3 + rng.below(10);
    const Pts p = random_points(rng, family, n);
    const std::string name = std::string(family_name[family]) + " case " + std::to_string(k) + " (seed " +
                             std::to_string(seed) + ", n " + std::to_string(n) + ")";
    // make_delaunay: from a uniform triangulation, moved onto a line, a circle, or jittered.
    const Pts start = random_points(rng, uniform, n);
    const Pts to = family == uniform ? moved(rng, start, int(rng.below(3))) : p;
    isolated("make_delaunay, " + name, [&] { check_make_delaunay_all(start, to); }, time_limit);
    // Imprecise points: disks around the points, the instance on their boundaries or inside.
    std::vector<double> radii(n);
    Pts instance = p;
    for(std::size_t i = 0; i < n; ++i) {
      radii[i] = 0.01 + 0.1 * rng.uniform();
      const double a = 6.283185307179586 * rng.uniform(), t = k % 2 == 0 ? 1.0 : rng.uniform();
      instance[i] = {p[i][0] + t * radii[i] * std::cos(a), p[i][1] + t * radii[i] * std::sin(a)};
    }
    isolated("Imprecise_points_2::triangulate, " + name, [&] { check_imprecise(p, radii, instance); }, time_limit);
    isolated("Imprecise_points_2::triangulate (the centres), " + name, [&] {
      check_imprecise(p, std::vector<double>(n, 0.0), p);
    }, time_limit);
    std::vector<bool> in_first(n);
    for(std::size_t i = 0; i < n; ++i)
      in_first[i] = rng.below(3) == 0;
    isolated("split_delaunay, " + name, [&] { check_split(p, in_first); }, time_limit);
    isolated("builds, " + name, [&] { check_builds(p); }, time_limit);
  }
}

} // namespace

int main(int argc, char** argv)
{
  const std::size_t count = argc > 1 ? std::size_t(std::stoul(argv[1])) : 300;

  // The trait that routes the kernels (internal/toolbox/predicates.h).
  DFP_CHECK(DFP::internal::decides_by_exact_predicates<SC>::value);
  DFP_CHECK(DFP::internal::has_exact_predicates<CGAL::Epick>::value);
  DFP_CHECK(DFP::internal::has_exact_predicates<CGAL::Epeck>::value);
  DFP_CHECK(DFP::internal::has_exact_predicates<CGAL::Simple_cartesian<CGAL::Gmpq>>::value);
  DFP_CHECK(!DFP::internal::decides_by_exact_predicates<CGAL::Epick>::value);
  // 3D points under projection traits: no 2D coordinates to round, the traits are used as they are.
  DFP_CHECK(!DFP::internal::decides_by_exact_predicates<CGAL::Projection_traits_xz_3<SC>>::value);

  // F6: a spurious "vertices i and j are both at ..." for distinct moved points.
  isolated("F6 make_delaunay, moved onto y = 3x + 1", [] {
    check_make_delaunay_all({{0.015416343380252008, 0.86351689866644255}, {0.77970816341336391, 0.86043883128178544},
                             {0.78794403202919172, 0.87324114971377775}, {0.45038097460467014, 0.066759100681163572}},
                            {{0.015416343380252008, 1.0462490301407561}, {0.77970816341336391, 3.3391244902400916},
                             {0.78794403202919172, 3.3638320960875752}, {0.45038097460467014, 2.3511429238140105}});
  }, time_limit);
  // F8 related: an invalid result (Triangulation_2 with info).
  isolated("F8 make_delaunay, invalid result", [] {
    check_make_delaunay_all({{0.13744251752145381, 0.38171530656936642}, {0.5626483070011441, 0.076951115403180351},
                             {0.96951763654170076, 0.80859063813108778}, {0.97060495327590601, 0.80972782257446829},
                             {0.57266114547810454, 0.54201957610762552}},
                            {{0.13744251752145381, 1.4123275525643615}, {0.5626483070011441, 2.6879449210034325},
                             {0.96951763654170076, 3.9085529096251022}, {0.97060495327590601, 3.911814859827718},
                             {0.57266114547810454, 2.7179834364343138}});
  }, time_limit);
  // F9: a SIGSEGV (DT plain) and a hang (Triangulation_2 plain).
  isolated("F9 make_delaunay, SIGSEGV", [] {
    check_make_delaunay_all({{1, 0}, {-0.49999999999999978, 0.86602540378443871}, {0.76604444311897779, -0.64278760968653958},
                             {-0.058144828910476239, -0.99830815827126818}, {0.59715859170278585, -0.80212319275504396},
                             {-0.93969262078590854, -0.34202014332566821}},
                            {{1, 4}, {-0.49999999999999978, -0.49999999999999933}, {0.76604444311897779, 3.2981333293569333},
                             {-0.058144828910476239, 0.8255655132685713}, {0.59715859170278585, 2.7914757751083576},
                             {-0.93969262078590854, -1.8190778623577257}});
  }, time_limit);
  isolated("F9 make_delaunay, hang", [] {
    check_make_delaunay_all({{0.0054189204943768995, 0.50280325800081693}, {0.0056115185088072258, 0.50220715963951712},
                             {0.0056559288184890614, 0.50315808941577411}, {1.0033096687805387, 0.17856069813908571},
                             {0.18489422941489816, 0.64943492489965604}, {0.0047683577834736653, 0.5027112578628794}},
                            {{0.0054189204943768995, 1.0162567614831306}, {0.0056115185088072258, 1.0168345555264218},
                             {0.0056559288184890614, 1.0169677864554671}, {1.0033096687805387, 4.0099290063416166},
                             {0.18489422941489816, 1.5546826882446945}, {0.0047683577834736653, 1.0143050733504211}});
  }, time_limit);
  // Equal moved points still throw, naming them (by coordinates, not by an inexact test).
  isolated("make_delaunay, two vertices moved onto one point", [] {
    check_make_delaunay_all({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {{0, 0}, {1, 0}, {0.5, 0.5}, {0.5, 0.5}});
  }, time_limit);
  // F7: Imprecise_points_2::triangulate, instance on the disks' boundaries.
  isolated("F7 Imprecise_points_2::triangulate", [] {
    check_imprecise({{2, 0}, {0, 1}, {4, 3}, {0, 0}, {3, 3}, {2, 1}, {4, 2}, {3, 1}, {4, 1}},
                    std::vector<double>(9, 0.87287156094396956),
                    {{2, -0.87287156094396956}, {0.87287156094396956, 1}, {3.1271284390560306, 3},
                     {0, -0.87287156094396956}, {3, 2.1271284390560306}, {1.1271284390560306, 1},
                     {4.8728715609439694, 2}, {3, 0.12712843905603044}, {4, 0.12712843905603044}});
  }, time_limit);
  // F12: split_delaunay, 4 almost co-circular points all in the second part.
  isolated("F12 split_delaunay", [] {
    check_split({{-0.50000000000000044, -0.86602540378443837}, {-0.93969262078590832, 0.34202014332566888},
                 {0.17364817766692997, -0.98480775301220813}, {0.17364817766693041, 0.98480775301220802}},
                std::vector<bool>(4, false));
  }, time_limit);

  // Extreme scales: CGAL's own SC predicates overflow or underflow there; the decision is exact.
  for(const double scale : {std::ldexp(1.0, -1060), 1e-300, 1e300, 1.5e307}) {
    Random rng{7};
    for(const Family family : {uniform, collinear, cocircular}) {
      Pts p = random_points(rng, family, 40);
      for(auto& xy : p)
        xy = {xy[0] * scale, xy[1] * scale};
      std::ostringstream at;
      at << " at scale " << scale << ", " << family_name[family];
      isolated("builds" + at.str(),
               [&] { check_builds(p); }, time_limit);
      Pts q = random_points(rng, uniform, 40);
      for(auto& xy : q)
        xy = {xy[0] * scale, xy[1] * scale};
      if(distinct(to_points(q)))
        isolated("make_delaunay" + at.str(),
               [&] { check_make_delaunay_all(q, p); }, time_limit);
    }
  }

  random_cases(1, count);
  return finish("test_inexact_kernel");
}
