// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Periodic domains (periodic_2.h): every result equals CGAL's Periodic_2_Delaunay_triangulation_2
// built by range insertion from the same points, compared as sets of faces of (point index,
// offset) triples and by covering (1- or 9-sheeted), with Epick and Epeck and every
// concurrency: uniform points, lattices (every point co-circular), points at the domain's sides
// and corners, moves that cross the sides, few and clustered points (9-sheeted), duplicates,
// wrong predictions, other domains, Kinetic_Delaunay_triangulation_2 on the torus,
// indexed_periodic_triangles(), and each stage reported to a visitor at most once.
// make_delaunay() keeps the vertex handles and their info() when the result is 1-sheeted; bad
// input throws and leaves the triangulation as it was.

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/periodic_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

using namespace dfp_test;

namespace {

template <class K>
using Periodic_traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
template <class K>
using Periodic_with_info = CGAL::Periodic_2_Delaunay_triangulation_2<
    Periodic_traits<K>,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Periodic_traits<K>,
                                                    CGAL::Periodic_2_triangulation_vertex_base_2<Periodic_traits<K>>>,
        CGAL::Periodic_2_triangulation_face_base_2<Periodic_traits<K>>>>;

// A face as three (point index, x offset, y offset), offsets translated to least value 0 in
// each coordinate, rotated to start at its least corner.
using Corner = std::tuple<std::size_t, int, int>;
using Periodic_face = std::array<Corner, 3>;

struct Periodic_result
{
  std::vector<Periodic_face> faces;
  bool one_cover = true;
  bool operator==(const Periodic_result& o) const { return faces == o.faces && one_cover == o.one_cover; }
};

// The faces of `t` (one per periodic triangle), each point numbered by its index in `xy`
// (the first of equal points).
template <class P2DT2>
Periodic_result result_of(const P2DT2& t, const XYs& xy)
{
  std::map<std::pair<double, double>, std::size_t> index;
  for(std::size_t i = xy.size(); i-- > 0;)
    index[{xy[i].x, xy[i].y}] = i;
  Periodic_result r;
  r.one_cover = t.is_1_cover();
  for(auto it = t.periodic_triangles_begin(P2DT2::UNIQUE); it != t.periodic_triangles_end(P2DT2::UNIQUE); ++it) {
    Periodic_face f;
    int low_x = std::numeric_limits<int>::max(), low_y = low_x;
    for(int i = 0; i < 3; ++i) {
      low_x = (std::min)(low_x, (*it)[i].second.x());
      low_y = (std::min)(low_y, (*it)[i].second.y());
    }
    for(int i = 0; i < 3; ++i) {
      const auto& p = (*it)[i].first;
      const auto found = index.find({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
      DFP_CHECK(found != index.end());
      f[i] = Corner{found == index.end() ? 0 : found->second, (*it)[i].second.x() - low_x, (*it)[i].second.y() - low_y};
    }
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    r.faces.push_back(f);
  }
  std::sort(r.faces.begin(), r.faces.end());
  return r;
}

template <class K>
CGAL::Iso_rectangle_2<K> rectangle(double xmin, double ymin, double xmax, double ymax)
{
  return CGAL::Iso_rectangle_2<K>(make_point<K>(xmin, ymin), make_point<K>(xmax, ymax));
}

// CGAL's build, by range insertion.
template <class K>
Periodic_with_info<K> cgal_build(const XYs& xy, const CGAL::Iso_rectangle_2<K>& domain)
{
  Periodic_with_info<K> t(domain);
  const std::vector<typename K::Point_2> points = to_points<K>(xy);
  t.insert(points.begin(), points.end());
  return t;
}

// The faces of CGAL's build as index triples (the prediction D = 0), but for those that repeat
// a point (a 9-sheeted covering of few points has some; index triples cannot).
template <class K>
Faces faces_of_build(const XYs& xy, const CGAL::Iso_rectangle_2<K>& domain)
{
  Faces faces;
  for(const Periodic_face& f : result_of(cgal_build<K>(xy, domain), xy).faces) {
    const Face face{std::get<0>(f[0]), std::get<0>(f[1]), std::get<0>(f[2])};
    if(face[0] != face[1] && face[1] != face[2] && face[2] != face[0])
      faces.push_back(face);
  }
  return faces;
}

// Checks delaunay_from_prediction(points, faces, t) against CGAL's build, with every concurrency;
// returns the statistics of the sequential call.
template <class K>
DFP::Statistics check_prediction(const XYs& xy, const Faces& faces, const CGAL::Iso_rectangle_2<K>& domain)
{
  const Periodic_result expected = result_of(cgal_build<K>(xy, domain), xy);
  const std::vector<typename K::Point_2> points = to_points<K>(xy);
  DFP::Statistics first;
  bool have_first = false;
  for_each_concurrency([&] {
    Periodic_with_info<K> t(domain);
    const DFP::Statistics s = with_concurrency([&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, t); });
    DFP_CHECK(t.is_valid());
    DFP_CHECK_MSG(result_of(t, xy) == expected, s);
    // info() is the point's index (the first of equal points) on every vertex, copies included;
    // the offset flag is cleared, as CGAL leaves it after its own operations.
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v) {
      DFP_CHECK(v->info() < xy.size() && xy[v->info()].x == CGAL::to_double(v->point().x()) &&
                xy[v->info()].y == CGAL::to_double(v->point().y()));
      DFP_CHECK(!v->get_offset_flag());
    }
    if(!have_first) {
      first = s;
      have_first = true;
    }
  });
  return first;
}

// Builds CGAL's triangulation of `before`, moves its vertices to `after` with set_point(),
// calls make_delaunay() and checks it against CGAL's build of `after`; the vertex handles and
// info() survive when both are 1-sheeted.
template <class K>
DFP::Statistics check_moves(const XYs& before, const XYs& after, const CGAL::Iso_rectangle_2<K>& domain)
{
  const Periodic_result expected = result_of(cgal_build<K>(after, domain), after);
  DFP::Statistics first;
  bool have_first = false;
  for_each_concurrency([&] {
    Periodic_with_info<K> t = cgal_build<K>(before, domain);
    std::map<std::pair<double, double>, std::size_t> index;
    for(std::size_t i = 0; i < before.size(); ++i)
      index[{before[i].x, before[i].y}] = i;
    std::vector<typename Periodic_with_info<K>::Vertex_handle> handles(before.size());
    for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v)
      handles[index[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}]] = v;
    const bool was_one_cover = t.is_1_cover();
    // Every vertex moves, with the copies of a 9-sheeted covering.
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v) {
      v->info() = index[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}];
      v->set_point(make_point<K>(after[v->info()].x, after[v->info()].y));
    }
    const DFP::Statistics s = with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(t); });
    DFP_CHECK(t.is_valid());
    DFP_CHECK_MSG(result_of(t, after) == expected, s);
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
      DFP_CHECK(!v->get_offset_flag()); // cleared, as after CGAL's own operations
    if(was_one_cover && t.is_1_cover()) {
      std::size_t seen = 0;
      for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v, ++seen)
        DFP_CHECK(&*handles[v->info()] == &*v && after[v->info()].x == CGAL::to_double(v->point().x()));
      DFP_CHECK(seen == after.size());
    }
    if(!have_first) {
      first = s;
      have_first = true;
    }
  });
  return first;
}

double wrap(double x, double lo, double hi)
{
  const double w = hi - lo;
  double y = x - w * std::floor((x - lo) / w);
  if(!(y < hi)) // rounding up to the upper side
    y = lo;
  return y < lo ? lo : y;
}

XYs moved(const XYs& xy, double sigma, CGAL::Random& rng, double lo = 0, double hi = 1)
{
  XYs out = xy;
  for(XY& p : out)
    p = {wrap(p.x + sigma * gaussian(rng), lo, hi), wrap(p.y + sigma * gaussian(rng), lo, hi)};
  return out;
}

// k x k points of a lattice of spacing 1/k (every empty circle has four points on it), shifted.
XYs lattice(int k, double shift_x, double shift_y)
{
  XYs xy;
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      xy.push_back({(i + shift_x) / k, (j + shift_y) / k});
  return xy;
}

// The lattice's cells split by random diagonals: a triangulation of the torus at the points.
Faces lattice_triangulation(int k, CGAL::Random& rng)
{
  Faces faces;
  auto at = [k](int i, int j) { return std::size_t(((i + k) % k) * k + (j + k) % k); };
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j) {
      if(rng.get_bool()) {
        faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      } else {
        faces.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        faces.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  return faces;
}

template <class K>
void uniform_points_and_moves()
{
  CGAL::Random rng(4601);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  for(std::size_t n : {300, 3000}) {
    Scope scope("n = ", n);
    const XYs xy = uniform_points(n, rng);
    {
      Scope s("exact prediction");
      // Below about a thousand uniform points the widest empty circle may make CGAL's covering
      // doubtful: then CGAL builds.
      const DFP::Statistics st = check_prediction<K>(xy, faces_of_build<K>(xy, unit), unit);
      DFP_CHECK_MSG(n < 1000 || (!st.fell_back && st.flips == 0 && st.edges_not_locally_delaunay == 0), st);
    }
    const double spacing = 1 / std::sqrt(double(n));
    for(double sigma : {0.01, 0.05, 0.1, 0.5, 3.0}) {
      Scope s("moves of ", sigma, " spacing");
      const XYs after = moved(xy, sigma * spacing, rng);
      const DFP::Statistics st = check_prediction<K>(after, faces_of_build<K>(xy, unit), unit);
      const DFP::Statistics sm = check_moves<K>(xy, after, unit);
      if(n >= 1000 && sigma <= 0.01) {
        DFP_CHECK_MSG(!st.fell_back, st);
        DFP_CHECK_MSG(!sm.fell_back, sm);
      }
      if(n >= 1000 && sigma == 0.05) // faces no flip untangles: vertices taken out and put back
        DFP_CHECK_MSG(!sm.fell_back && sm.points_reinserted > 0, sm);
    }
    {
      Scope s("faces in reverse orientation, shuffled");
      Faces faces = faces_of_build<K>(xy, unit);
      for(Face& f : faces)
        std::swap(f[1], f[2]);
      shuffle(faces, rng);
      const DFP::Statistics st = check_prediction<K>(xy, faces, unit);
      DFP_CHECK_MSG(n < 1000 || !st.fell_back, st);
    }
  }
}

// Points on the domain's sides and at its corners, and moves that cross the sides.
template <class K>
void sides_and_corners()
{
  CGAL::Random rng(4602);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  XYs xy = uniform_points(1000, rng);
  for(int i = 0; i < 40; ++i) {
    xy.push_back({0, rng.get_double(0, 1)});
    xy.push_back({rng.get_double(0, 1), 0});
    xy.push_back({1 - 1e-9 * rng.get_double(0, 1), rng.get_double(0, 1)});
  }
  xy.push_back({0, 0});
  xy.push_back({0.5, 0});
  xy.push_back({0, 0.5});
  const DFP::Statistics st = check_prediction<K>(xy, faces_of_build<K>(xy, unit), unit);
  DFP_CHECK_MSG(!st.fell_back, st);
  // Every point moved by a third of the spacing: hundreds cross a side.
  const XYs after = moved(xy, 0.3 / std::sqrt(double(xy.size())), rng);
  check_moves<K>(xy, after, unit);
  check_prediction<K>(after, faces_of_build<K>(xy, unit), unit);
  // A whole translation by half the domain: every face keeps its shape.
  XYs shifted = xy;
  for(XY& p : shifted)
    p = {wrap(p.x + 0.5, 0, 1), wrap(p.y + 0.25, 0, 1)};
  const DFP::Statistics sm = check_moves<K>(xy, shifted, unit);
  DFP_CHECK_MSG(!sm.fell_back, sm);
}

// Lattices: every point co-circular with its neighbours, so every face is decided by CGAL's
// symbolic perturbation.
template <class K>
void lattices()
{
  CGAL::Random rng(4603);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  for(int k : {8, 12, 20}) {
    for(double shift : {0.0, 0.5}) {
      Scope scope(k, " x ", k, " lattice shifted by ", shift);
      const XYs xy = lattice(k, shift, shift);
      check_prediction<K>(xy, faces_of_build<K>(xy, unit), unit);
      const DFP::Statistics st = check_prediction<K>(xy, lattice_triangulation(k, rng), unit);
      DFP_CHECK_MSG(!st.fell_back || k == 8, st);
      check_moves<K>(lattice(k, 0.25, 0.25), xy, unit);
    }
  }
}

// Few or clustered points: CGAL keeps a 9-sheeted covering, and so does the result.
template <class K>
void few_and_clustered_points()
{
  CGAL::Random rng(4604);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  for(std::size_t n : {1, 2, 3, 5, 10, 20, 40}) {
    Scope scope(n, " points");
    const XYs xy = uniform_points(n, rng);
    const DFP::Statistics st = check_prediction<K>(xy, faces_of_build<K>(xy, unit), unit);
    if(!cgal_build<K>(xy, unit).is_1_cover())
      DFP_CHECK_MSG(st.fell_back, st);
    check_moves<K>(xy, moved(xy, 0.05, rng), unit);
  }
  {
    Scope scope("a cluster in a corner of the domain");
    const XYs xy = uniform_points(500, rng, 0.0, 0.2);
    check_prediction<K>(xy, faces_of_build<K>(xy, unit), unit);
    check_moves<K>(xy, moved(xy, 0.001, rng), unit);
  }
  {
    Scope scope("uniform points, then all gathered in a band");
    const XYs xy = uniform_points(500, rng);
    XYs band = xy;
    for(XY& p : band)
      p.y = 0.3 + 0.1 * p.y;
    check_moves<K>(xy, band, unit);
  }
}

// Duplicate points (equal after the caller's wrap): CGAL keeps one vertex per point, info() the
// smallest index; make_delaunay() refuses two vertices at one point.
template <class K>
void duplicates()
{
  CGAL::Random rng(4605);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  XYs xy = uniform_points(800, rng);
  const Faces faces = faces_of_build<K>(xy, unit);
  for(int i = 0; i < 30; ++i)
    xy.push_back(xy[std::size_t(rng.get_int(0, 800))]);
  xy.push_back({wrap(1.0, 0, 1), 0.5}); // 1 wraps to 0
  xy.push_back({0.0, 0.5});
  const DFP::Statistics st = check_prediction<K>(xy, faces, unit);
  DFP_CHECK_MSG(st.fell_back && st.duplicate_points >= 31, st);

  Periodic_with_info<K> t = cgal_build<K>(uniform_points(500, rng), unit);
  auto v = t.unique_vertices_begin();
  auto w = std::next(v, 7);
  v->set_point(w->point());
  DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::make_delaunay(t); }));
}

// Bad input throws and leaves the triangulation as it was; wrong predictions only fall back.
template <class K>
void bad_input_and_wrong_predictions()
{
  CGAL::Random rng(4606);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  const XYs xy = uniform_points(600, rng);
  const Faces faces = faces_of_build<K>(xy, unit);
  Periodic_with_info<K> t = cgal_build<K>(xy, unit);
  const Periodic_result kept = result_of(t, xy);
  auto refuses = [&](XYs points, Faces f, const std::string& what) {
    Scope scope(what);
    const std::vector<typename K::Point_2> p = to_points<K>(points);
    const std::string message =
        exception_message<DFP::Invalid_prediction>([&] { DFP::delaunay_from_prediction(p, f, t); });
    DFP_CHECK_MSG(message.find(what) != std::string::npos, message);
    DFP_CHECK(result_of(t, xy) == kept);
  };
  XYs outside = xy;
  outside[17] = {1.0, 0.5};
  refuses(outside, faces, "point 17");
  outside = xy;
  outside[3] = {0.5, -1e-300};
  refuses(outside, faces, "point 3");
  if(!std::is_same<K, CGAL::Epeck>::value) { // Epeck's numbers cannot hold a NaN
    outside = xy;
    outside[5] = {std::numeric_limits<double>::quiet_NaN(), 0.5};
    refuses(outside, faces, "non-finite");
  }
  Faces bad = faces;
  bad[9][1] = xy.size();
  refuses(xy, bad, "face 9");
  bad = faces;
  bad[4][2] = bad[4][0];
  refuses(xy, bad, "face 4");
  {
    Scope scope("make_delaunay, a vertex moved outside the domain");
    auto v = std::next(t.unique_vertices_begin(), 11);
    const auto p = v->point();
    v->set_point(make_point<K>(1.5, 0.5));
    const std::string message = exception_message<DFP::Invalid_prediction>([&] { DFP::make_delaunay(t); });
    DFP_CHECK_MSG(message.find("vertex 11") != std::string::npos, message);
    v->set_point(p);
    DFP_CHECK(result_of(t, xy) == kept);
  }
  // Wrong predictions: the result is still CGAL's.
  {
    Scope scope("faces missing");
    Faces f = faces;
    f.resize(f.size() - 5);
    DFP_CHECK(check_prediction<K>(xy, f, unit).fell_back);
  }
  {
    Scope scope("a face repeated");
    Faces f = faces;
    f.push_back(f[3]);
    DFP_CHECK(check_prediction<K>(xy, f, unit).fell_back);
  }
  {
    Scope scope("points relabelled");
    check_prediction<K>(xy, with_points_relabelled(faces, xy.size(), 20, rng), unit);
  }
  {
    Scope scope("random triples");
    Faces f;
    for(std::size_t k = 0; k < 2 * xy.size(); ++k) {
      const std::size_t a = std::size_t(rng.get_int(0, int(xy.size())));
      const std::size_t b = (a + 1 + std::size_t(rng.get_int(0, int(xy.size()) - 1))) % xy.size();
      std::size_t c = (b + 1) % xy.size();
      if(c == a)
        c = (c + 1) % xy.size();
      f.push_back({a, b, c});
    }
    check_prediction<K>(xy, f, unit);
  }
  {
    Scope scope("no faces");
    DFP_CHECK(check_prediction<K>(xy, Faces(), unit).outcome == DFP::Outcome::no_faces);
  }
  {
    Scope scope("a triangulation of the torus far from Delaunay: faces stretched in x");
    // The Delaunay triangulation of 300 points, drawn twice as wide side by side (x / 2 and
    // x / 2 + 1/2): every face squeezed to half its width, every point and its copy.
    const XYs half = uniform_points(300, rng);
    XYs twice;
    for(const XY& p : half)
      twice.push_back({p.x / 2, p.y});
    for(const XY& p : half)
      twice.push_back({p.x / 2 + 0.5, p.y});
    Faces f;
    for(const Periodic_face& face : result_of(cgal_build<K>(half, unit), half).faces)
      for(std::size_t copy : {0, 1}) { // a corner one period further in x is the other copy
        Face g;
        for(int i = 0; i < 3; ++i)
          g[i] = std::get<0>(face[i]) + 300 * ((copy + std::size_t(std::get<1>(face[i]))) % 2);
        f.push_back(g);
      }
    check_prediction<K>(twice, f, unit);
  }
  {
    Scope scope("max_flips(0) and Strategy::rebuild");
    const XYs after = moved(xy, 0.1 / std::sqrt(600.), rng);
    const std::vector<typename K::Point_2> p = to_points<K>(after);
    Periodic_with_info<K> u(unit);
    const DFP::Statistics s0 = DFP::delaunay_from_prediction(p, faces, u, DFP::parameters::max_flips(std::size_t(0)));
    DFP_CHECK(result_of(u, after) == result_of(cgal_build<K>(after, unit), after));
    DFP_CHECK_MSG(s0.fell_back, s0);
    const DFP::Statistics s1 =
        DFP::delaunay_from_prediction(p, faces, u, DFP::parameters::strategy(DFP::Strategy::rebuild));
    DFP_CHECK(s1.fell_back && s1.outcome == DFP::Outcome::rebuild_requested);
    DFP_CHECK(result_of(u, after) == result_of(cgal_build<K>(after, unit), after));
  }
}

// Other domains: offset and scaled, far from the origin.
template <class K>
void other_domains()
{
  CGAL::Random rng(4607);
  constexpr bool exact = std::is_same<K, CGAL::Epeck>::value;
  for(const std::array<double, 3>& d : {std::array<double, 3>{-3, -5, 8}, std::array<double, 3>{1e6, 1e6, 1},
                                        std::array<double, 3>{0x1p-400, -0x1p-400, 0x1p-398},
                                        std::array<double, 3>{1e-200, -1e-200, 3e-200}}) {
    Scope scope("domain [", d[0], ", ", d[0] + d[2], ") x [", d[1], ", ", d[1] + d[2], ")");
    const auto domain = rectangle<K>(d[0], d[1], d[0] + d[2], d[1] + d[2]);
    XYs xy = uniform_points(exact ? 1000 : 1500, rng);
    for(XY& p : xy)
      p = {wrap(d[0] + d[2] * p.x, d[0], d[0] + d[2]), wrap(d[1] + d[2] * p.y, d[1], d[1] + d[2])};
    if(!exact && d[2] < 0x1p-500) {
      // Below 2^-500 CGAL's covering test squares the period in double (underflow): refused,
      // by every entry point, before anything changes.
      Periodic_with_info<K> t(domain);
      const auto points = to_points<K>(xy);
      DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::delaunay_from_prediction(points, Faces(), t); }));
      DFP_CHECK(t.number_of_vertices() == 0);
      DFP::Kinetic_Delaunay_triangulation_2<Periodic_with_info<K>> kinetic{Periodic_with_info<K>(domain)};
      DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { kinetic.build(points); }));
      for(std::size_t i = 0; i < 20; ++i)
        t.tds().create_vertex()->set_point(points[i]);
      DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::make_delaunay(t); }));
      continue;
    }
    const DFP::Statistics st = check_prediction<K>(xy, faces_of_build<K>(xy, domain), domain);
    DFP_CHECK_MSG(!st.fell_back, st);
    XYs after = xy;
    for(XY& p : after)
      p = {wrap(p.x + 0.003 * d[2] * gaussian(rng), d[0], d[0] + d[2]),
           wrap(p.y + 0.003 * d[2] * gaussian(rng), d[1], d[1] + d[2])};
    check_moves<K>(xy, after, domain);
  }
}

// A triangulation repaired by make_delaunay() stays usable: CGAL inserts into it and removes
// from it.
void usable_after_repair()
{
  using K = CGAL::Epick;
  CGAL::Random rng(4608);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  const XYs xy = uniform_points(2000, rng);
  Periodic_with_info<K> t = cgal_build<K>(xy, unit);
  XYs after = moved(xy, 0.002, rng);
  std::size_t i = 0;
  std::map<std::pair<double, double>, std::size_t> index;
  for(std::size_t k = 0; k < xy.size(); ++k)
    index[{xy[k].x, xy[k].y}] = k;
  for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v, ++i) {
    const std::size_t k = index[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}];
    v->set_point(make_point<K>(after[k].x, after[k].y));
  }
  DFP::make_delaunay(t);
  DFP_CHECK(t.is_valid());
  const auto v = t.insert(make_point<K>(0.123456, 0.654321));
  DFP_CHECK(t.is_valid() && t.number_of_vertices() == xy.size() + 1);
  t.remove(v);
  DFP_CHECK(t.is_valid() && t.number_of_vertices() == xy.size());
  DFP_CHECK(result_of(t, after) == result_of(cgal_build<K>(after, unit), after));
}

// Random cases: sizes, distributions (uniform, clustered, a jittered lattice, points on a few
// lines) and moves drawn at random, both entry points against CGAL's build.
void random_cases()
{
  using K = CGAL::Epick;
  CGAL::Random rng(4609);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  for(int round = 0; round < 24; ++round) {
    const std::size_t n = std::size_t(rng.get_int(20, 2500));
    const int kind = rng.get_int(0, 4);
    Scope scope("random case ", round, ": ", n, " points of kind ", kind);
    XYs xy;
    if(kind == 0) {
      xy = uniform_points(n, rng);
    } else if(kind == 1) {
      xy = clustered_points(n, rng);
      for(XY& p : xy)
        p = {wrap(p.x, 0, 1), wrap(p.y, 0, 1)};
    } else if(kind == 2) {
      const int k = int(std::sqrt(double(n))) + 1;
      for(const XY& p : lattice(k, 0, 0))
        xy.push_back({wrap(p.x + (rng.get_int(0, 4) == 0 ? 1e-9 * rng.get_double(-1, 1) : 0), 0, 1), p.y});
    } else {
      for(std::size_t i = 0; i < n; ++i)
        xy.push_back({rng.get_double(0, 1), double(rng.get_int(0, 7)) / 7});
    }
    const double spacing = 1 / std::sqrt(double(xy.size()));
    const XYs after = moved(xy, spacing * std::pow(10.0, rng.get_double(-3, 0.3)), rng);
    check_moves<K>(xy, after, unit);
    check_prediction<K>(after, faces_of_build<K>(xy, unit), unit);
  }
}

// The faces of indexed_periodic_triangles(t), in result_of()'s canonical form.
template <class P2DT2>
Periodic_result indexed_result_of(const P2DT2& t)
{
  Periodic_result r;
  r.one_cover = t.is_1_cover();
  for(const DFP::Indexed_periodic_triangle& it : DFP::indexed_periodic_triangles(t)) {
    Periodic_face f;
    for(int k = 0; k < 3; ++k) {
      DFP_CHECK(it.offsets[k][0] >= 0 && it.offsets[k][1] >= 0);
      f[k] = Corner{it.vertices[k], it.offsets[k][0], it.offsets[k][1]};
    }
    DFP_CHECK((std::min)({it.offsets[0][0], it.offsets[1][0], it.offsets[2][0]}) == 0 &&
              (std::min)({it.offsets[0][1], it.offsets[1][1], it.offsets[2][1]}) == 0);
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    r.faces.push_back(f);
  }
  std::sort(r.faces.begin(), r.faces.end());
  return r;
}

// Kinetic_Delaunay_triangulation_2 on the torus: frames of moves (crossing the sides), points
// that merge and split, few points (9-sheeted), a point outside the domain (refused, nothing
// changed); every frame CGAL's build, indexed_periodic_triangles() its triangles.
template <class K>
void kinetic_frames()
{
  CGAL::Random rng(4607);
  const auto domain = rectangle<K>(-3, -3, 5, 5);
  using P2DT2 = Periodic_with_info<K>;
  DFP::Kinetic_Delaunay_triangulation_2<P2DT2> kinetic{P2DT2(domain)};
  auto check_frame = [&](const XYs& xy) {
    const P2DT2& t = kinetic.triangulation();
    DFP_CHECK(t.is_valid() && t.domain() == domain);
    DFP_CHECK(indexed_result_of(t) == result_of(cgal_build<K>(xy, domain), xy));
    DFP_CHECK(kinetic.number_of_points() == xy.size());
    for(std::size_t i = 0; i < xy.size(); ++i)
      DFP_CHECK(CGAL::to_double(kinetic.point(i).x()) == xy[i].x && CGAL::to_double(kinetic.point(i).y()) == xy[i].y);
  };
  XYs xy = uniform_points(2000, rng, -3, 5);
  kinetic.build(to_points<K>(xy), Faces());
  check_frame(xy);
  const double spacing = 8 / std::sqrt(2000.0);
  for(int frame = 0; frame < 3; ++frame) {
    Scope scope("frame ", frame);
    const auto before = &*kinetic.vertex(17);
    xy = moved(xy, 0.02 * spacing, rng, -3, 5);
    const DFP::Statistics s = with_concurrency([&](auto tag) { return kinetic.template move<decltype(tag)>(to_points<K>(xy)); });
    DFP_CHECK_MSG(!kinetic.last_move_rebuilt() && !s.fell_back && &*kinetic.vertex(17) == before, s);
    check_frame(xy);
  }
  {
    Scope scope("points 5 and 9 merge, then split");
    xy[5] = xy[9];
    kinetic.move(to_points<K>(xy));
    DFP_CHECK(kinetic.last_move_rebuilt() && kinetic.has_shared_vertices() && kinetic.vertex(5) == kinetic.vertex(9));
    check_frame(xy);
    xy = moved(xy, 0.01 * spacing, rng, -3, 5);
    kinetic.move(to_points<K>(xy));
    DFP_CHECK(kinetic.last_move_rebuilt() && !kinetic.has_shared_vertices());
    check_frame(xy);
  }
  {
    Scope scope("a point outside the domain");
    XYs outside = xy;
    outside[3].x = 5;
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { kinetic.move(to_points<K>(outside)); }));
    check_frame(xy);
  }
  {
    Scope scope("few points: 9-sheeted");
    XYs few = uniform_points(12, rng, -3, 5);
    DFP::Kinetic_Delaunay_triangulation_2<P2DT2> small{P2DT2(domain)};
    small.build(to_points<K>(few), Faces());
    DFP_CHECK(!small.triangulation().is_1_cover());
    for(int frame = 0; frame < 3; ++frame) {
      few = moved(few, 0.3, rng, -3, 5);
      small.move(to_points<K>(few));
      DFP_CHECK(small.triangulation().is_valid());
      DFP_CHECK(indexed_result_of(small.triangulation()) == result_of(cgal_build<K>(few, domain), few));
      for(std::size_t i = 0; i < few.size(); ++i)
        DFP_CHECK(CGAL::to_double(small.point(i).x()) == few[i].x);
    }
  }
}

// Each stage is reported to the visitor at most once, begun and ended in turn, never nested:
// for index triples and for make_delaunay(), on a triangulation that is certified, one that
// needs untangling and Lawson's flips, and one that CGAL rebuilds.
struct Stage_log
{
  std::vector<DFP::Stage> begun, ended;
  bool nested = false;
  void stage_begin(DFP::Stage s)
  {
    nested = nested || begun.size() != ended.size();
    begun.push_back(s);
  }
  void stage_end(DFP::Stage s) { ended.push_back(s); }
  void check(const DFP::Statistics& st) const
  {
    DFP_CHECK_MSG(!nested && begun == ended && !begun.empty(), st);
    std::vector<DFP::Stage> sorted = begun;
    std::sort(sorted.begin(), sorted.end());
    DFP_CHECK_MSG(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(), st);
    DFP_CHECK_MSG(std::count(begun.begin(), begun.end(), DFP::Stage::rebuild) == (st.fell_back ? 1 : 0), st);
  }
};

template <class K>
void stages_reported_once()
{
  CGAL::Random rng(4611);
  const auto unit = rectangle<K>(0, 0, 1, 1);
  const XYs xy = uniform_points(3000, rng);
  const double spacing = 1 / std::sqrt(3000.);
  for(double sigma : {0.0, 0.01, 0.05, 0.5}) {
    Scope s("moves of ", sigma, " spacing");
    const XYs after = sigma == 0 ? xy : moved(xy, sigma * spacing, rng);
    {
      Stage_log log;
      Periodic_with_info<K> t(unit);
      const std::vector<typename K::Point_2> points = to_points<K>(after);
      const DFP::Statistics st =
          DFP::delaunay_from_prediction(points, faces_of_build<K>(xy, unit), t, DFP::parameters::visitor(std::ref(log)));
      log.check(st);
      DFP_CHECK(result_of(t, after) == result_of(cgal_build<K>(after, unit), after));
    }
    {
      Stage_log log;
      Periodic_with_info<K> t = cgal_build<K>(xy, unit);
      std::map<std::pair<double, double>, std::size_t> index;
      for(std::size_t i = 0; i < xy.size(); ++i)
        index[{xy[i].x, xy[i].y}] = i;
      for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v) {
        const std::size_t i = index[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}];
        v->set_point(make_point<K>(after[i].x, after[i].y));
      }
      const DFP::Statistics st = DFP::make_delaunay(t, DFP::parameters::visitor(std::ref(log)));
      log.check(st);
      DFP_CHECK(result_of(t, after) == result_of(cgal_build<K>(after, unit), after));
    }
  }
}

} // namespace

int main()
{
  DFP_RUN(uniform_points_and_moves<CGAL::Epick>());
  DFP_RUN(sides_and_corners<CGAL::Epick>());
  DFP_RUN(lattices<CGAL::Epick>());
  DFP_RUN(few_and_clustered_points<CGAL::Epick>());
  DFP_RUN(duplicates<CGAL::Epick>());
  DFP_RUN(bad_input_and_wrong_predictions<CGAL::Epick>());
  DFP_RUN(other_domains<CGAL::Epick>());
  DFP_RUN(other_domains<CGAL::Epeck>());
  DFP_RUN(usable_after_repair());
  DFP_RUN(random_cases());
  DFP_RUN(kinetic_frames<CGAL::Epick>());
  DFP_RUN(stages_reported_once<CGAL::Epick>());
  DFP_RUN(uniform_points_and_moves<CGAL::Epeck>());
  DFP_RUN(lattices<CGAL::Epeck>());
  DFP_RUN(few_and_clustered_points<CGAL::Epeck>());
  DFP_RUN(bad_input_and_wrong_predictions<CGAL::Epeck>());
  DFP_RUN(kinetic_frames<CGAL::Epeck>());
  return finish("test_periodic");
}
