// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Differential fuzzer: random point families x prediction families x kernels x entry points x
// named parameters x, for make_delaunay and the prediction entry points, the concurrency tag
// (Sequential_tag or Parallel_if_available_tag, with blocks of a few points for the region-parallel
// build from scratch), Kinetic_Delaunay_triangulation_2 on every make_delaunay case, each result compared with CGAL's Delaunay_triangulation_2 built from
// scratch with the same kernel (as index triples, vertex sets and info); the periodic entry
// points (periodic_2.h, each point family in a square domain around it) against CGAL's
// Periodic_2_Delaunay_triangulation_2 (faces as (index, offset) triples, covering); plus the consistency of
// the Statistics, is_valid(), and "malformed input throws Invalid_prediction and changes
// nothing". Seeded and budgeted; cases run in forked children so that a crash or a hang is
// reported with its seed and case number; every new failure is minimized (points and faces
// dropped while it persists) and printed as C++ initializers.
//
//   test_fuzz_differential [--seed S] [--cases N] [--seconds T] [--case K] [--family NAME]
//                          [--kernel epick|epeck|sc] [--check-hierarchy 0|1] [--verbose]
//
// Without arguments (as ctest runs it): seed 1, cases 0 to 3999 (a fixed set, so that a run
// passes or fails the same way on any machine), or as many as the environment variable
// DFP_FUZZ_CASES says (the sanitizer build runs fewer). Exit status 1 on any failure.
// Simple_cartesian<double> (the inexact kernel) is checked against CGAL's Epick build of the same
// doubles: the package decides its faces by exact predicates.

#include "fuzz_util.h"

#include <CGAL/Delaunay_from_predicted_edges_2.h>
#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_from_prediction/brio_dc.h>
#include <CGAL/Delaunay_from_prediction/imprecise_points.h>
#include <CGAL/Delaunay_from_prediction/periodic_2.h>
#include <CGAL/Delaunay_from_prediction/prediction_models.h>
#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/split.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <numeric>
#include <set>
#include <typeinfo>

#include <sys/resource.h>

using namespace dfp_fuzz;
namespace DFP = CGAL::Delaunay_from_prediction;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using SC = CGAL::Simple_cartesian<double>;

template <class K>
using Hier_tds = CGAL::Triangulation_data_structure_2<
    CGAL::Triangulation_hierarchy_vertex_base_2<CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>>,
    CGAL::Triangulation_face_base_2<K>>;
template <class K>
using DT_hier = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<K, Hier_tds<K>>>;

// Periodic cases: CGAL's periodic triangulation, vertices with the point index.
template <class K>
using Periodic_traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
template <class K>
using Periodic_DT = CGAL::Periodic_2_Delaunay_triangulation_2<
    Periodic_traits<K>,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Periodic_traits<K>,
                                                    CGAL::Periodic_2_triangulation_vertex_base_2<Periodic_traits<K>>>,
        CGAL::Periodic_2_triangulation_face_base_2<Periodic_traits<K>>>>;

// The square domain [xmin, xmin + width) x [ymin, ymin + width) of a periodic case, a function
// of its points: width twice the least power of two above their spread, the corners multiples
// of half of it, so that both sides are exactly `width` long in doubles. False when no such
// square of doubles holds the points (coordinates too far apart in magnitude): then the case
// is skipped.
struct Periodic_domain
{
  double xmin = 0, ymin = 0, width = 1;
};

inline bool periodic_domain_of(const XYs& xy, Periodic_domain& d)
{
  if(xy.empty())
    return true;
  double xlo = xy[0].x, xhi = xlo, ylo = xy[0].y, yhi = ylo;
  for(const XY& p : xy) {
    xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x);
    ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  }
  const double spread = std::max({xhi - xlo, yhi - ylo, std::abs(xlo) * 0x1p-40, std::abs(ylo) * 0x1p-40, 0x1p-1000});
  if(!std::isfinite(spread))
    return false;
  const double half = std::ldexp(1.0, std::ilogb(spread) + 1); // > spread, a power of two
  d.width = 2 * half;
  d.xmin = std::floor(xlo / half) * half;
  d.ymin = std::floor(ylo / half) * half;
  const double xmax = d.xmin + d.width, ymax = d.ymin + d.width;
  return std::isfinite(d.width) && std::isfinite(xmax) && std::isfinite(ymax) && xmax - d.xmin == d.width &&
         ymax - d.ymin == d.width && xhi < xmax && yhi < ymax && d.xmin <= xlo && d.ymin <= ylo;
}

// The points without repeats (the first of equal points kept), in order.
inline XYs dedupe(const XYs& xy)
{
  XYs out;
  std::set<std::pair<double, double>> seen;
  for(const XY& p : xy)
    if(seen.insert({p.x, p.y}).second)
      out.push_back(p);
  return out;
}

// Whether CGAL's periodic triangulation with Epick (double) can decide the covering for this
// period: the package refuses the others (periodic_2.h, check_domain_width()).
inline bool double_period_fits(const Periodic_domain& d)
{
  return d.width >= std::ldexp(1.0, -500) && d.width <= std::ldexp(1.0, 500);
}

// x wrapped into [low, low + width).
inline double wrap_into(double x, double low, double width)
{
  double y = x - width * std::floor((x - low) / width);
  if(!(y < low + width))
    y = low;
  return y < low ? low : y;
}

inline XYs wrapped_into(XYs xy, const Periodic_domain& d)
{
  for(XY& p : xy)
    p = {wrap_into(p.x, d.xmin, d.width), wrap_into(p.y, d.ymin, d.width)};
  return xy;
}

// The faces of a periodic triangulation as (point index, offset) corners (the smallest index of
// equal points; offsets of least value 0; rotated to the least corner), sorted.
using Periodic_corners = std::array<std::tuple<std::size_t, int, int>, 3>;
template <class P2DT2>
std::vector<Periodic_corners> periodic_faces_of(const P2DT2& t, const XYs& xy, bool& found_all)
{
  std::map<std::pair<double, double>, std::size_t> index;
  for(std::size_t i = xy.size(); i-- > 0;)
    index[{xy[i].x, xy[i].y}] = i;
  std::vector<Periodic_corners> faces;
  found_all = true;
  for(auto it = t.periodic_triangles_begin(P2DT2::UNIQUE); it != t.periodic_triangles_end(P2DT2::UNIQUE); ++it) {
    const int low_x = std::min({(*it)[0].second.x(), (*it)[1].second.x(), (*it)[2].second.x()});
    const int low_y = std::min({(*it)[0].second.y(), (*it)[1].second.y(), (*it)[2].second.y()});
    Periodic_corners f;
    for(int k = 0; k < 3; ++k) {
      const auto at = index.find({CGAL::to_double((*it)[k].first.x()), CGAL::to_double((*it)[k].first.y())});
      found_all = found_all && at != index.end();
      f[k] = {at == index.end() ? 0 : at->second, (*it)[k].second.x() - low_x, (*it)[k].second.y() - low_y};
    }
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

struct Options
{
  unsigned long long seed = 1;
  long long cases = 4000;
  double seconds = 1e18;
  long long single_case = -1;
  int family = -1, kernel = -1;
  bool verbose = false, check_hierarchy = true;
  unsigned case_timeout = 20;
  double minimize_seconds = 3;
  std::size_t max_n = std::size_t(-1);
};
inline Options opt; // inline: one object for both translation units (fuzz_differential_epeck.cpp)

#ifndef DFP_FUZZ_EPECK_PART

// ---------------------------------------------------------------------------------------------
// Generation (kernel independent: predictions are computed with Epick, exact predicates)
// ---------------------------------------------------------------------------------------------

static int pick(CGAL::Random& rng, std::initializer_list<int> weights)
{
  int total = 0;
  for(int w : weights)
    total += w;
  int r = rng.get_int(0, total), k = 0;
  for(int w : weights) {
    if(r < w)
      return k;
    r -= w;
    ++k;
  }
  return k - 1;
}

static double pow2(int e) { return std::ldexp(1.0, e); }

static XYs base_points(std::size_t n, CGAL::Random& rng, bool centred)
{
  switch(rng.get_int(0, 3)) {
  case 0: return dfp_test::uniform_points(n, rng, centred ? -1. : 0., 1.);
  case 1: {
    const int w = std::max(1, int(std::sqrt(double(n)) + 0.5));
    XYs g = dfp_test::grid_points(w, std::max(1, int(n) / w), rng);
    if(centred)
      g = dfp_test::transformed(g, 1., -double(w / 2));
    return g;
  }
  default: {
    XYs c = dfp_test::clustered_points(n, rng, 1 + rng.get_int(0, 5));
    if(centred)
      c = dfp_test::transformed(c, 2., -1.);
    return c;
  }
  }
}

static std::size_t draw_size(CGAL::Random& rng)
{
  const int r = rng.get_int(0, 100);
  std::size_t n;
  if(r < 10)
    n = std::size_t(rng.get_int(0, 5));
  else if(r < 85)
    n = std::size_t(rng.get_int(5, 41));
  else if(r < 98)
    n = std::size_t(rng.get_int(41, 120));
  else
    n = std::size_t(rng.get_int(120, 400));
  return std::min(n, opt.max_n);
}

static XYs gen_points(int family, std::size_t n, CGAL::Random& rng)
{
  switch(family) {
  case P_UNIFORM: return dfp_test::uniform_points(n, rng, rng.get_bool() ? -1. : 0., 1.);
  case P_CLUSTERED: return dfp_test::clustered_points(n, rng, 1 + rng.get_int(0, 8));
  case P_GRID: {
    const int w = 1 + rng.get_int(0, 8);
    return dfp_test::grid_points(w, std::max(1, int(n) / w), rng);
  }
  case P_CIRCLE: {
    if(rng.get_bool()) {
      const long radii[] = {5, 25, 65, 325};
      return dfp_test::lattice_circle_points(radii[rng.get_int(0, 4)], rng, rng.get_bool() ? 5 : 0);
    }
    XYs xy; // points of a circle rounded to doubles, plus maybe the centre
    for(std::size_t i = 0; i < n; ++i) {
      const double a = 6.283185307179586 * double(i) / double(std::max<std::size_t>(n, 1));
      xy.push_back({std::cos(a), std::sin(a)});
    }
    if(rng.get_bool())
      xy.push_back({0., 0.});
    dfp_test::shuffle(xy, rng);
    return xy;
  }
  case P_COLLINEAR_H:
  case P_COLLINEAR_V:
  case P_COLLINEAR_D: {
    XYs xy;
    const double c = double(rng.get_int(-3, 4));
    for(std::size_t i = 0; i < n; ++i) {
      const double t = double(rng.get_int(-50, 50));
      xy.push_back(family == P_COLLINEAR_H ? XY{t, c} : family == P_COLLINEAR_V ? XY{c, t} : XY{t, 2 * t + c});
    }
    if(n > 2 && rng.get_int(0, 4) == 0) // one point off the line
      xy.push_back({0.5, 0.25});
    dfp_test::shuffle(xy, rng);
    return xy;
  }
  case P_DUPLICATES: {
    const std::size_t distinct = std::max<std::size_t>(1, n / std::size_t(1 + rng.get_int(1, 5)));
    return dfp_test::with_duplicates(base_points(distinct, rng, false), n - std::min(n, distinct) + 1, rng);
  }
  case P_HUGE: {
    const double scales[] = {1e300, 1e160, 1e200, 5e307 / 2};
    return dfp_test::transformed(base_points(n, rng, true), scales[rng.get_int(0, 4)] / 64, 0.);
  }
  case P_TINY: {
    const double scales[] = {1e-300, 2.2250738585072014e-308 * 64, 2.2e-308 * 1024, 1e-160};
    return dfp_test::transformed(base_points(n, rng, true), scales[rng.get_int(0, 4)], 0.);
  }
  case P_DENORMAL: {
    const double scales[] = {pow2(-1022), pow2(-1020), pow2(-1000), pow2(-1040)};
    XYs xy = base_points(n, rng, true);
    const double s = scales[rng.get_int(0, 4)];
    if(rng.get_bool()) // grid-like: exact multiples
      for(XY& p : xy)
        p = {std::round(p.x * 64) * s, std::round(p.y * 64) * s};
    else
      xy = dfp_test::transformed(xy, s, 0.);
    return xy;
  }
  case P_OFFSET: {
    const double spread = std::pow(10., rng.get_double(-2., 1.));
    return dfp_test::transformed(base_points(n, rng, false), spread, rng.get_bool() ? 1e15 : -1e15);
  }
  default: { // few
    const std::size_t m = std::size_t(rng.get_int(0, 5));
    XYs xy = base_points(m, rng, false);
    if(xy.size() > 1 && rng.get_bool())
      xy.back() = xy[0];
    return xy;
  }
  }
}

static Tris as_tris(const dfp_test::Faces& f)
{
  Tris t;
  for(const auto& a : f)
    t.push_back({(long long)a[0], (long long)a[1], (long long)a[2]});
  return t;
}

static Tris gen_faces(int family, const XYs& xy, CGAL::Random& rng)
{
  using namespace dfp_test;
  const auto P = to_points<Epick>(xy);
  const std::size_t n = xy.size();
  const std::uint64_t seed = std::uint64_t(rng.get_int(0, 1 << 30));
  Faces dt = delaunay_faces<Epick>(P);
  Faces f;
  switch(family) {
  case F_EXACT:
    f = shuffled(dt, rng);
    for(Face& t : f)
      if(rng.get_bool())
        std::swap(t[1], t[2]);
    break;
  case F_FLIPS: f = shuffled(flipped_delaunay_faces<Epick>(P, std::size_t(rng.get_int(1, int(n) + 2)), rng), rng); break;
  case F_DELETED: f = with_faces_deleted(dt, std::size_t(rng.get_int(1, int(dt.size()) + 2)), rng); break;
  case F_DUPLICATED:
    f = dt;
    for(const Face& t : dt)
      if(rng.get_int(0, 3) == 0)
        f.push_back(rng.get_bool() ? t : Face{t[0], t[2], t[1]});
    f = shuffled(f, rng);
    break;
  case F_FOREIGN:
    f = dt;
    for(Face& t : f)
      if(rng.get_int(0, 4) == 0) {
        const std::size_t j = std::size_t(rng.get_int(0, int(n)));
        const int at = rng.get_int(0, 3);
        if(j != t[(at + 1) % 3] && j != t[(at + 2) % 3])
          t[at] = j;
      }
    break;
  case F_GARBAGE: f = random_triples(n, std::size_t(rng.get_int(1, 2 * int(n) + 2)), rng); break;
  case F_SUBSET: {
    std::vector<std::size_t> chosen;
    for(std::size_t i = 0; i < n; ++i)
      if(rng.get_bool())
        chosen.push_back(i);
    std::vector<Epick::Point_2> sub;
    for(std::size_t i : chosen)
      sub.push_back(P[i]);
    for(Face t : delaunay_faces<Epick>(sub))
      f.push_back({chosen[t[0]], chosen[t[1]], chosen[t[2]]});
    break;
  }
  case F_OVERLAP:
    f = dt;
    for(const Face& t : flipped_delaunay_faces<Epick>(P, std::size_t(rng.get_int(1, 6)), rng))
      if(rng.get_bool())
        f.push_back(t);
    f = shuffled(f, rng);
    break;
  case F_EMPTY: break;
  case F_MOVED:
    try { // prediction_models.h throws at huge scales (moved points overflow): then the exact faces
      if(n >= 3)
        for(const auto& t : DFP::moved_points_prediction(P, rng.get_double(0.05, 2.), seed))
          f.push_back(t);
    } catch(const std::exception&) {
      f = dt;
    }
    break;
  default: // crossing
    try {
      if(n >= 3)
        for(const auto& t : DFP::self_crossing_prediction(P, std::size_t(rng.get_int(1, 4)), seed))
          f.push_back(t);
    } catch(const std::exception&) {
      f = dt;
    }
    break;
  }
  return as_tris(f);
}

static void add_edge(Tris& e, std::size_t a, std::size_t b) { e.push_back({(long long)a, (long long)b, -1}); }

static Tris edges_of(const Tris& faces)
{
  Tris e;
  for(const Tri& t : faces)
    for(int j = 0; j < 3; ++j)
      e.push_back({t[j], t[(j + 1) % 3], -1});
  return e;
}

static Tris emst_edges(const XYs& xy) // Prim on doubles: "EMST-ish"
{
  const std::size_t n = xy.size();
  Tris e;
  if(n == 0)
    return e;
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> from(n, 0);
  std::vector<char> in(n, 0);
  best[0] = 0;
  for(std::size_t step = 0; step < n; ++step) {
    std::size_t u = n;
    for(std::size_t i = 0; i < n; ++i)
      if(!in[i] && (u == n || best[i] < best[u]))
        u = i;
    in[u] = 1;
    if(step > 0)
      add_edge(e, from[u], u);
    for(std::size_t i = 0; i < n; ++i) {
      const double dx = xy[i].x - xy[u].x, dy = xy[i].y - xy[u].y, d = dx * dx + dy * dy;
      if(!in[i] && d < best[i]) {
        best[i] = d;
        from[i] = u;
      }
    }
  }
  return e;
}

static Tris gen_graph(int family, const XYs& xy, CGAL::Random& rng)
{
  const std::size_t n = xy.size();
  Tris e;
  switch(family) {
  case F_G_DT: e = edges_of(as_tris(dfp_test::delaunay_faces<Epick>(dfp_test::to_points<Epick>(xy)))); break;
  case F_G_EMST: e = emst_edges(xy); break;
  case F_G_TREE:
    for(std::size_t i = 1; i < n; ++i)
      add_edge(e, std::size_t(rng.get_int(0, int(i))), i);
    break;
  case F_G_GRAPH:
    if(n >= 2)
      for(int k = rng.get_int(0, 3 * int(n)); k > 0; --k) {
        const std::size_t a = std::size_t(rng.get_int(0, int(n))), b = std::size_t(rng.get_int(0, int(n)));
        if(a != b)
          add_edge(e, a, b);
      }
    break;
  case F_G_CROSSING: {
    e = edges_of(as_tris(dfp_test::delaunay_faces<Epick>(dfp_test::to_points<Epick>(xy))));
    std::vector<std::size_t> chosen;
    for(std::size_t i = 0; i < n; ++i)
      if(rng.get_int(0, 4) == 0)
        chosen.push_back(i);
    const auto label = dfp_test::permuted_among(n, chosen, rng);
    for(Tri& t : e)
      t = {(long long)label[std::size_t(t[0])], (long long)label[std::size_t(t[1])], -1};
    if(e.empty())
      e = emst_edges(xy);
    break;
  }
  default: break; // empty
  }
  dfp_test::shuffle(e, rng);
  return e;
}

static Case gen_case(unsigned long long seed, long long k)
{
  CGAL::Random rng(unsigned(splitmix(splitmix(seed) ^ std::uint64_t(k)) & 0x7fffffff));
  Case c;
  c.entry = pick(rng, {30, 14, 6, 8, 3, 3, 3, 7, 6, 8, 6, 10});
  if(opt.family >= 0)
    c.entry = opt.family;
  c.kernel = pick(rng, {65, 20, 15});
  if(opt.kernel >= 0)
    c.kernel = opt.kernel;
  c.point_family = pick(rng, {20, 8, 10, 6, 3, 3, 3, 8, 5, 4, 4, 4, 6});
  if(c.entry == E_PERIODIC && c.kernel == K_SC)
    c.kernel = K_EPICK; // the periodic overloads need exact predicates
  std::size_t n = draw_size(rng);
  if(c.kernel == K_EPECK) // CGAL's periodic build with Epeck is slow, the more so for periods far from 1
    n = std::min<std::size_t>(n, c.entry != E_PERIODIC ? 150
                                 : c.point_family == P_HUGE || c.point_family == P_TINY || c.point_family == P_DENORMAL ? 10
                                                                                                                       : 40);
  if(c.entry == E_EMST || c.entry == E_RNG || c.entry == E_GABRIEL)
    n = std::min<std::size_t>(n, 40);
  c.pts = gen_points(c.point_family, n, rng);
  n = c.pts.size();
  c.output = pick(rng, {60, 20, 20});
  switch(c.entry) {
  case E_DFP:
  case E_EDGES: {
    c.pred_family = pick(rng, {14, 14, 8, 6, 6, 10, 6, 6, 4, 6, 6});
    c.faces = gen_faces(c.pred_family, c.pts, rng);
    c.parallel = rng.get_bool();
    if(c.entry == E_EDGES) {
      c.faces = edges_of(c.faces);
      for(int extra = rng.get_int(0, 4) == 0 ? rng.get_int(1, 6) : 0; extra > 0 && n >= 2; --extra) {
        const std::size_t a = std::size_t(rng.get_int(0, int(n))), b = std::size_t(rng.get_int(0, int(n)));
        if(a != b)
          add_edge(c.faces, a, b);
      }
    }
    if(rng.get_int(0, 3) == 0)
      c.strategy = rng.get_int(0, 10); // every Strategy
    if(rng.get_int(0, 8) == 0)
      c.max_flips = rng.get_bool() ? 0 : rng.get_int(1, 6);
    if(rng.get_int(0, 6) == 0)
      c.region_size = rng.get_int(1, 9);
    if(rng.get_int(0, 10) == 0)
      c.screen = false;
    break;
  }
  case E_MD: {
    c.pts = dedupe(c.pts);
    n = c.pts.size();
    c.t2 = rng.get_bool();
    c.parallel = rng.get_bool();
    c.output = rng.get_bool() ? O_INFO : O_PLAIN;
    c.pred_family = pick(rng, {5, 30, 30, 10, 15}) + F_MD_NONE;
    c.pts2 = c.pts;
    const double spread = [&] {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for(const XY& p : c.pts) {
        lo = std::min({lo, p.x, p.y});
        hi = std::max({hi, p.x, p.y});
      }
      return n > 0 && hi > lo ? hi - lo : 1.;
    }();
    switch(c.pred_family) {
    case F_MD_LITTLE:
      c.pts2 = dfp_test::jittered(c.pts, spread / std::sqrt(double(n + 1)) * rng.get_double(0.01, 0.6), rng);
      break;
    case F_MD_LOT:
      for(XY& p : c.pts2)
        if(rng.get_bool())
          p = {p.x + rng.get_double(-spread, spread), p.y + rng.get_double(-spread, spread)};
      break;
    case F_MD_ONTO:
      if(n >= 2) {
        const std::size_t i = std::size_t(rng.get_int(0, int(n))), j = (i + 1 + std::size_t(rng.get_int(0, int(n) - 1))) % n;
        c.pts2[i] = c.pts2[j];
      }
      break;
    case F_MD_DIMENSION:
      if(rng.get_bool()) // everything onto a line
        for(XY& p : c.pts2)
          p = {p.x, 3 * p.x + 1};
      else // off the line (or some)
        for(XY& p : c.pts2)
          if(rng.get_bool())
            p = {p.x + rng.get_double(-spread, spread), p.y + rng.get_double(-spread, spread)};
      break;
    default: break;
    }
    if(c.pred_family != F_MD_ONTO) { // moved points must stay distinct (else it is the onto case)
      std::set<std::pair<double, double>> seen;
      for(std::size_t i = 0; i < n; ++i)
        if(!seen.insert({c.pts2[i].x, c.pts2[i].y}).second)
          c.pts2[i] = c.pts[i], seen.insert({c.pts2[i].x, c.pts2[i].y});
      seen.clear();
      for(std::size_t i = 0; i < n; ++i)
        if(!seen.insert({c.pts2[i].x, c.pts2[i].y}).second)
          c.pred_family = F_MD_ONTO; // could not keep them apart: then it must throw
    }
    if(rng.get_int(0, 3) == 0)
      c.strategy = rng.get_int(0, 10); // every Strategy
    if(rng.get_int(0, 8) == 0)
      c.max_flips = rng.get_bool() ? 0 : rng.get_int(1, 6);
    break;
  }
  case E_SG:
  case E_EMST:
  case E_RNG:
  case E_GABRIEL:
    c.pred_family = pick(rng, {20, 20, 20, 15, 15, 5}) + F_G_DT;
    c.faces = gen_graph(c.pred_family, c.pts, rng);
    break;
  case E_IMPRECISE: {
    c.pred_family = pick(rng, {30, 20, 20, 30}) + F_I_INSIDE;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for(const XY& p : c.pts) {
      lo = std::min({lo, p.x, p.y});
      hi = std::max({hi, p.x, p.y});
    }
    const double spread = n > 0 && hi > lo ? hi - lo : 1.;
    const double spacing = spread / std::sqrt(double(n + 1));
    const int radius_kind = rng.get_int(0, 4);
    for(std::size_t i = 0; i < n; ++i)
      c.radii.push_back(radius_kind == 0 ? 0. : radius_kind == 1 ? spacing : rng.get_double(0., 2 * spacing));
    for(std::size_t i = 0; i < n; ++i) {
      const XY o = c.pts[i];
      const double r = c.radii[i];
      int kind = c.pred_family - F_I_INSIDE;
      if(c.pred_family == F_I_MIXED)
        kind = rng.get_int(0, 3);
      if(kind == 0) {
        const double a = rng.get_double(0., 6.283185307179586), u = rng.get_double(0., 0.7);
        c.pts2.push_back({o.x + r * u * std::cos(a), o.y + r * u * std::sin(a)});
      } else if(kind == 1) {
        const int side = rng.get_int(0, 4);
        c.pts2.push_back(side == 0 ? XY{o.x + r, o.y} : side == 1 ? XY{o.x - r, o.y} : side == 2 ? XY{o.x, o.y + r} : XY{o.x, o.y - r});
      } else
        c.pts2.push_back({o.x + rng.get_double(-spread, spread), o.y + rng.get_double(-spread, spread)});
    }
    if(c.pred_family == F_I_MIXED && n >= 2)
      for(int d = rng.get_int(0, 3); d > 0; --d)
        c.pts2[std::size_t(rng.get_int(0, int(n)))] = c.pts2[std::size_t(rng.get_int(0, int(n)))];
    break;
  }
  case E_SPLIT: {
    c.pred_family = pick(rng, {60, 15, 25}) + F_S_RANDOM;
    const bool side = rng.get_bool();
    double median = 0;
    if(n > 0) {
      std::vector<double> x;
      for(const XY& p : c.pts)
        x.push_back(p.x);
      std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(n / 2), x.end());
      median = x[n / 2];
    }
    for(std::size_t i = 0; i < n; ++i)
      c.part.push_back(c.pred_family == F_S_RANDOM ? int(rng.get_bool())
                       : c.pred_family == F_S_ALL  ? int(side)
                                                   : int(c.pts[i].x < median));
    c.split_method = rng.get_int(-1, 3);
    if(rng.get_bool())
      c.param_seed = unsigned(rng.get_int(1, 1 << 30));
    break;
  }
  case E_PERIODIC: {
    // The points in their square domain; moved points (make_delaunay, the kinetic class) and a
    // prediction (delaunay_from_prediction) made with CGAL's periodic triangulation (Epick).
    Periodic_domain d;
    if(!periodic_domain_of(c.pts, d))
      break; // skipped when run
    c.parallel = rng.get_bool();
    c.output = rng.get_int(0, 3); // the moves: little, a lot, one point onto another (describe())
    c.pts2 = c.pts;
    const double spacing = d.width / std::sqrt(double(n + 1));
    if(c.output == 0)
      c.pts2 = dfp_test::jittered(c.pts, spacing * rng.get_double(0.001, 0.5), rng);
    else if(c.output == 1) {
      for(XY& p : c.pts2)
        if(rng.get_bool())
          p = {p.x + rng.get_double(-d.width, d.width), p.y + rng.get_double(-d.width, d.width)};
    } else if(n >= 2)
      c.pts2[std::size_t(rng.get_int(0, int(n)))] = c.pts2[std::size_t(rng.get_int(0, int(n)))];
    c.pts2 = wrapped_into(c.pts2, d);
    c.pred_family = pick(rng, {25, 10, 10, 10, 0, 15, 0, 0, 10, 20});
    const XYs& of = c.pred_family == F_MOVED ? c.pts2 : c.pts;
    Periodic_DT<Epick> t(Periodic_DT<Epick>::Iso_rectangle(d.xmin, d.ymin, d.xmin + d.width, d.ymin + d.width));
    const auto P = dfp_test::to_points<Epick>(of);
    if(double_period_fits(d))
      t.insert(P.begin(), P.end());
    else if(c.pred_family != F_EMPTY)
      c.pred_family = F_GARBAGE; // CGAL's triangulation in double cannot be built: no faces from it
    bool found_all = true;
    c.faces.clear();
    if(c.pred_family != F_EMPTY && c.pred_family != F_GARBAGE)
      for(const Periodic_corners& f : periodic_faces_of(t, of, found_all)) {
        Tri face{(long long)std::get<0>(f[0]), (long long)std::get<0>(f[1]), (long long)std::get<0>(f[2])};
        if(face[0] == face[1] || face[1] == face[2] || face[2] == face[0])
          continue; // a 9-sheeted covering's face through two copies of a point
        if(rng.get_bool())
          std::swap(face[1], face[2]);
        if(c.pred_family == F_DELETED && rng.get_int(0, 6) == 0)
          continue;
        c.faces.push_back(face);
        if(c.pred_family == F_DUPLICATED && rng.get_int(0, 8) == 0)
          c.faces.push_back(face);
      }
    if(c.pred_family == F_GARBAGE && n >= 3)
      for(std::size_t k = 0; k < 2 * n; ++k) {
        const long long a = rng.get_int(0, int(n)), b = (a + 1 + rng.get_int(0, int(n) - 1)) % (long long)n;
        const long long e = (b + 1 + rng.get_int(0, int(n) - 1)) % (long long)n;
        if(e != a && e != b)
          c.faces.push_back({a, b, e});
      }
    for(std::size_t k = c.faces.size(); k > 1; --k) // shuffled
      std::swap(c.faces[k - 1], c.faces[std::size_t(rng.get_int(0, int(k)))]);
    if(rng.get_int(0, 4) == 0)
      c.strategy = rng.get_bool() ? int(DFP::Strategy::rebuild) : int(DFP::Strategy::flips);
    if(rng.get_int(0, 8) == 0)
      c.max_flips = rng.get_bool() ? 0 : rng.get_int(1, 6);
    break;
  }
  case E_BRIO:
    c.pred_family = F_NONE;
    if(rng.get_bool())
      c.param_seed = unsigned(rng.get_int(1, 1 << 30));
    if(rng.get_int(0, 3) == 0) {
      const double q[] = {1., 0.5, 0.01, 0.125};
      c.sample_probability = q[rng.get_int(0, 4)];
    }
    break;
  default: { // malformed
    c.pred_family = F_M_RANGE + rng.get_int(0, F_M_BRIO - F_M_RANGE + 1);
    if(c.kernel == K_EPECK && (c.pred_family == F_M_NAN || c.pred_family == F_M_INF || c.pred_family == F_M_IMPRECISE ||
                               c.pred_family == F_M_BRIO))
      c.kernel = K_EPICK; // an Epeck point cannot even be made from a NaN (Gmpq raises SIGFPE)
    if(n < 3) {
      c.pts = dfp_test::uniform_points(5, rng);
      n = 5;
    }
    c.faces = as_tris(dfp_test::delaunay_faces<Epick>(dfp_test::to_points<Epick>(c.pts)));
    const std::size_t at = std::size_t(rng.get_int(0, int(c.faces.size()) + 1));
    const long long a = rng.get_int(0, int(n)), b = (a + 1) % (long long)n;
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    switch(c.pred_family) {
    case F_M_RANGE: c.faces.insert(c.faces.begin() + std::ptrdiff_t(at), Tri{a, (long long)n + rng.get_int(0, 3), b}); break;
    case F_M_NEGATIVE: c.faces.insert(c.faces.begin() + std::ptrdiff_t(at), Tri{a, -1 - rng.get_int(0, 3), b}); break;
    case F_M_REPEAT: c.faces.insert(c.faces.begin() + std::ptrdiff_t(at), Tri{a, b, a}); break;
    case F_M_NAN: c.pts[std::size_t(a)].y = nan; break;
    case F_M_INF: c.pts[std::size_t(a)].x = rng.get_bool() ? inf : -inf; break;
    case F_M_EDGE_RANGE:
      c.faces = edges_of(c.faces);
      c.faces.insert(c.faces.begin() + std::ptrdiff_t(std::min(at, c.faces.size())), Tri{a, (long long)n + 2, -1});
      break;
    case F_M_EDGE_LOOP:
      c.faces = edges_of(c.faces);
      c.faces.insert(c.faces.begin() + std::ptrdiff_t(std::min(at, c.faces.size())), Tri{a, a, -1});
      break;
    case F_M_IMPRECISE:
      c.faces.clear();
      c.radii.assign(n, 0.1);
      c.pts2 = c.pts;
      c.pts2[std::size_t(a)].x = nan;
      break;
    default: // brio
      c.faces.clear();
      c.pts[std::size_t(a)].y = inf;
      break;
    }
    // Which entry point reads the malformed input: any that takes it.
    c.output = rng.get_int(0, 2); // the face range / edge range variant (see run_malformed)
    break;
  }
  }
  // Builds from scratch by regions (block_parallel_build.h) at the fuzzer's sizes: blocks of
  // a few points, so that most points are near a seam.
  if(c.parallel && rng.get_int(0, 2) == 0)
    c.region_block_points = rng.get_int(3, 64);
  return c;
}
#endif // DFP_FUZZ_EPECK_PART

// The tuning of a case's calls: Tuning::min_points_per_block as the case says; parallel calls
// build in blocks from 2 threads, so that the blocks are drawn on a 2-core machine too.
inline DFP::Tuning tuning_of(const Case& c)
{
  DFP::Tuning t;
  t.min_threads_for_blocks = 2;
  if(c.region_block_points >= 0)
    t.min_points_per_block = std::size_t(c.region_block_points);
  return t;
}

// ---------------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------------

struct Checker
{
  std::string failure; // "tag :: detail", first failure only
  void fail(const std::string& tag, const std::string& detail)
  {
    if(failure.empty())
      failure = tag + " :: " + detail;
  }
};

// Runs f with std::cerr captured; the text of the DFP_CHECKs that failed, or "".
template <class F>
std::string captured(const F& f)
{
  std::ostringstream buf;
  std::streambuf* old = std::cerr.rdbuf(buf.rdbuf());
  const int before = dfp_test::failures();
  try {
    f();
  } catch(...) {
    std::cerr.rdbuf(old);
    throw;
  }
  std::cerr.rdbuf(old);
  if(dfp_test::failures() == before)
    return "";
  dfp_test::failures() = before;
  return buf.str();
}

inline std::string first_expression(const std::string& text)
{
  const std::string marker = "CHECK FAILED: ";
  const std::size_t at = text.find(marker);
  if(at == std::string::npos)
    return "?";
  std::size_t end = text.find_first_of("(\n", at + marker.size());
  std::string e = text.substr(at + marker.size(), end == std::string::npos ? std::string::npos : end - at - marker.size());
  while(!e.empty() && e.back() == ' ')
    e.pop_back();
  return e;
}

template <class Tr, class = void>
struct is_hierarchy : std::false_type {};
template <class Tr>
struct is_hierarchy<Tr, std::void_t<typename Tr::Tr_Base>>
    : std::is_base_of<CGAL::Triangulation_hierarchy_2<typename Tr::Tr_Base>, Tr> {};

template <class Tr>
const auto& base_of(const Tr& tr)
{
  if constexpr(is_hierarchy<Tr>::value)
    return static_cast<const typename Tr::Tr_Base&>(tr);
  else
    return tr;
}

// The result against CGAL's build: with the same kernel, or for the inexact kernel with Epick
// (the exact decision on the same doubles, which the package promises there); the upper
// levels of a hierarchy behind --check-hierarchy (for the inexact kernel: left empty).
template <class Tr, class Point>
void check_result(Checker& ck, const Tr& tr, const std::vector<Point>& points, bool exact)
{
  const auto& t0 = base_of(tr);
  const std::string out = captured([&] {
    if(exact)
      dfp_test::check_is_cgal_delaunay(t0, points);
    else
      dfp_test::check_is_cgal_delaunay<Epick>(t0, points);
  });
  if(!out.empty())
    ck.fail("oracle:" + first_expression(out), out);
  if(!exact && out.empty()) {
    ++shared_memory()->inexact_checked;
    bool valid = false;
    try {
      valid = t0.is_valid();
    } catch(const CGAL::Failure_exception&) { // with CGAL's assertions on, is_valid() asserts
    }
    shared_memory()->inexact_not_valid += !valid;
  }
  if constexpr(is_hierarchy<Tr>::value) {
    if(opt.check_hierarchy && ck.failure.empty()) {
      bool up_ok = true;
      std::size_t with_up = 0;
      for(auto v = t0.finite_vertices_begin(); v != t0.finite_vertices_end(); ++v) {
        int levels = 0;
        for(auto u = v->up(); u != typename Tr::Vertex_handle() && levels < 64; u = u->up(), ++levels)
          up_ok = up_ok && u->point() == v->point();
        with_up += v->up() != typename Tr::Vertex_handle();
      }
      if(!up_ok)
        ck.fail("hierarchy:up_point", "a vertex's up() copy is not at its point");
      else if(!exact && with_up != 0)
        ck.fail("hierarchy:inexact_upper_levels", std::to_string(with_up) + " vertices with up(), none expected");
      else if(exact && t0.number_of_vertices() >= 300 && with_up == 0) // P = (29/30)^300 < 4e-5 for CGAL's own
        ck.fail("hierarchy:no_upper_levels", std::to_string(t0.number_of_vertices()) + " vertices, none with up()");
      else if(exact && !tr.is_valid())
        ck.fail("hierarchy:is_valid", "Triangulation_hierarchy_2::is_valid() (all levels) is false");
    }
  }
}

inline void check_stats(Checker& ck, const DFP::Statistics& s, long long faces_in, long long n, long long vertices)
{
  std::ostringstream d;
  if(faces_in >= 0 && (long long)s.faces_in != faces_in)
    d << "faces_in " << s.faces_in << " vs " << faces_in, ck.fail("stats:faces_in", d.str());
  else if(s.faces_certified > s.faces_in)
    d << s.faces_certified << " certified > " << s.faces_in << " in", ck.fail("stats:faces_certified>faces_in", d.str());
  else if(n >= 0 && (long long)s.duplicate_points != n - vertices)
    d << "duplicate_points " << s.duplicate_points << ", expected " << n - vertices << " (" << n << " points, "
      << vertices << " vertices)",
        ck.fail("stats:duplicate_points", d.str());
  else if(s.fell_back && s.outcome == DFP::Outcome::ok)
    ck.fail("stats:fell_back_without_reason", "");
}

template <class F>
void expect_no_throw(Checker& ck, const F& f)
{
  try {
    f();
  } catch(const DFP::Invalid_prediction& e) {
    ck.fail("threw:Invalid_prediction", e.what());
  } catch(const CGAL::Failure_exception& e) {
    ck.fail("threw:CGAL_failure", e.what());
  } catch(const std::exception& e) {
    ck.fail(std::string("threw:") + typeid(e).name(), e.what());
  }
}

// ---------------------------------------------------------------------------------------------
// Entry points
// ---------------------------------------------------------------------------------------------

template <class K>
std::vector<typename K::Point_2> points_of(const XYs& xy)
{
  return dfp_test::to_points<K>(xy);
}

template <class Tr, class K>
void run_dfp(Checker& ck, const Case& c, bool exact)
{
  const auto P = points_of<K>(c.pts);
  Tr tr;
  DFP::Statistics s;
  const bool any = c.strategy >= 0 || c.max_flips >= 0 || c.region_size >= 0 || !c.screen;
  const std::size_t n = P.size();
  auto call_with = [&](auto tag) {
    using Tag = decltype(tag);
    if(c.entry == E_EDGES) {
      std::vector<std::pair<long long, long long>> e;
      for(const Tri& t : c.faces)
        e.emplace_back(t[0], t[1]);
      s = DFP::delaunay_from_predicted_edges<Tag>(P, e, tr, DFP::parameters::tuning(tuning_of(c)));
    } else if(!any && c.region_block_points < 0)
      s = DFP::delaunay_from_prediction<Tag>(P, c.faces, tr);
    else if(!any)
      s = DFP::delaunay_from_prediction<Tag>(P, c.faces, tr, DFP::parameters::tuning(tuning_of(c)));
    else
      s = DFP::delaunay_from_prediction<Tag>(
          P, c.faces, tr,
          DFP::parameters::strategy(
              c.strategy >= 0 ? DFP::Strategy(c.strategy) : DFP::Strategy::automatic,
              DFP::parameters::max_flips(
                  c.max_flips >= 0 ? std::size_t(c.max_flips) : 3 * n / 4 + 64,
                  DFP::parameters::region_size(
                      c.region_size >= 0 ? std::size_t(c.region_size) : DFP::internal::default_region_size(n),
                      DFP::parameters::screen_prediction(c.screen)))).tuning(tuning_of(c)));
  };
  expect_no_throw(ck, [&] {
    if(c.parallel)
      call_with(CGAL::Parallel_if_available_tag());
    else
      call_with(CGAL::Sequential_tag());
  });
  if(!ck.failure.empty())
    return;
  check_result(ck, tr, P, exact);
  long long faces_in = (long long)c.faces.size();
  if(c.entry == E_EDGES) {
    std::vector<std::pair<std::size_t, std::size_t>> e;
    for(const Tri& t : c.faces)
      e.emplace_back(std::size_t(t[0]), std::size_t(t[1]));
    faces_in = (long long)DFP::internal::graph_triangles(n, e).size();
  }
  check_stats(ck, s, faces_in, (long long)n, (long long)tr.number_of_vertices());
  // CGAL's own faces as the prediction: certified as they are, whatever the scale (no fallback).
  if(exact && ck.failure.empty() && c.entry == E_DFP && c.pred_family == F_EXACT && !c.faces.empty() && c.max_flips < 0 &&
     (c.strategy < 0 || c.strategy == int(DFP::Strategy::automatic) || c.strategy == int(DFP::Strategy::flips) ||
      c.strategy == int(DFP::Strategy::carve)) &&
     (s.fell_back || s.faces_certified != s.faces_in || s.flips != 0))
    ck.fail("certify:exact_prediction_not_certified",
            std::to_string(s.faces_certified) + " of " + std::to_string(s.faces_in) + " certified, " +
                std::to_string(s.flips) + " flips, fell_back " + std::to_string(s.fell_back) + " (" +
                to_string(s.outcome) + ")");
  if(exact && ck.failure.empty() && c.entry == E_DFP && c.output == O_INFO) {
    dfp_test::Faces f;
    for(const Tri& t : c.faces)
      f.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    const std::string out = captured([&] { dfp_test::check_statistics(s, f, P, tr); });
    if(!out.empty())
      ck.fail("stats_deep:" + first_expression(out), out);
  }
}

template <class Tr, class K>
void run_md(Checker& ck, const Case& c, bool exact)
{
  const auto P0 = points_of<K>(c.pts), P1 = points_of<K>(c.pts2);
  Tr tr;
  dfp_test::Handles<Tr> handles;
  dfp_test::insert_all(tr, P0, handles); // the inexact kernel's faces by exact predicates
  const std::size_t faces_before = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  for(std::size_t i = 0; i < handles.size(); ++i)
    handles[i]->set_point(P1[i]);
  const dfp_test::Snapshot<Tr> before(tr);
  DFP::Statistics s;
  auto call_with = [&](auto tag) {
    using Tag = decltype(tag);
    if(c.strategy < 0 && c.max_flips < 0 && c.region_block_points < 0)
      s = DFP::make_delaunay<Tag>(tr);
    else if(c.strategy < 0 && c.max_flips < 0)
      s = DFP::make_delaunay<Tag>(tr, DFP::parameters::tuning(tuning_of(c)));
    else
      s = DFP::make_delaunay<Tag>(tr, DFP::parameters::strategy(
                                          c.strategy >= 0 ? DFP::Strategy(c.strategy) : DFP::Strategy::automatic,
                                          DFP::parameters::max_flips(c.max_flips >= 0 ? std::size_t(c.max_flips)
                                                                                      : 3 * P0.size() / 4 + 64))
                                          .tuning(tuning_of(c)));
  };
  auto call = [&] {
    if(c.parallel)
      call_with(CGAL::Parallel_if_available_tag());
    else
      call_with(CGAL::Sequential_tag());
  };
  std::set<std::pair<double, double>> seen;
  bool distinct = true;
  for(const XY& p : c.pts2)
    distinct = seen.insert({p.x, p.y}).second && distinct;
  if(!distinct) {
    try {
      call();
      ck.fail("md_onto:no_throw", "two vertices at one point, no Invalid_prediction");
    } catch(const DFP::Invalid_prediction& e) {
      // names both vertices by their rank in finite-vertex order
      std::map<const void*, std::size_t> rank;
      std::size_t r = 0;
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
        rank[&*v] = r++;
      std::map<std::pair<double, double>, std::vector<std::size_t>> at;
      for(std::size_t i = 0; i < handles.size(); ++i)
        at[{c.pts2[i].x, c.pts2[i].y}].push_back(i);
      bool named = false;
      for(const auto& [p, ids] : at)
        if(ids.size() > 1)
          for(std::size_t a = 0; a < ids.size(); ++a)
            for(std::size_t b = a + 1; b < ids.size(); ++b)
              named = named || (dfp_test::mentions_number(e.what(), rank[&*handles[ids[a]]]) &&
                                dfp_test::mentions_number(e.what(), rank[&*handles[ids[b]]]));
      if(!named)
        ck.fail("md_onto:message", std::string("does not name both vertices: ") + e.what());
      const std::string out = captured([&] { dfp_test::check_unchanged(tr, before); });
      if(!out.empty())
        ck.fail("md_onto:changed:" + first_expression(out), out);
    } catch(const std::exception& e) {
      ck.fail(std::string("md_onto:threw:") + typeid(e).name(), e.what());
    }
    return;
  }
  expect_no_throw(ck, call);
  if(!ck.failure.empty())
    return;
  check_result(ck, tr, P1, exact);
  if(ck.failure.empty()) {
    const std::string out = captured([&] { dfp_test::check_handles(tr, handles, P1); });
    if(!out.empty())
      ck.fail("md:handles:" + first_expression(out), out);
  }
  check_stats(ck, s, (long long)faces_before, -1, 0);
}

// Kinetic_Delaunay_triangulation_2 on the same move: built on the points before, moved to the
// points after (which may bring points together: a merge) and back (a split). Each result is
// CGAL's DT with every point at its index's vertex, rebuilt exactly when points merged or split.
template <class K>
void run_kinetic(Checker& ck, const Case& c)
{
  using DT = dfp_test::DT_with_info<K>;
  const auto P0 = points_of<K>(c.pts), P1 = points_of<K>(c.pts2);
  std::set<std::pair<double, double>> seen;
  bool merged = false;
  for(const XY& p : c.pts2)
    merged = !seen.insert({p.x, p.y}).second || merged;
  DFP::Kinetic_Delaunay_triangulation_2<DT> kdt;
  expect_no_throw(ck, [&] { kdt.build(P0); });
  for(const auto* P : {&P1, &P0}) {
    if(!ck.failure.empty())
      return;
    expect_no_throw(ck, [&] {
      if(c.parallel)
        kdt.template move<CGAL::Parallel_if_available_tag>(*P);
      else
        kdt.move(*P);
    });
    if(!ck.failure.empty())
      return;
    check_result(ck, kdt.triangulation(), *P, true);
    for(std::size_t i = 0; i < P->size() && ck.failure.empty(); ++i)
      if(!(kdt.point(i) == (*P)[i]))
        ck.fail("kinetic:point_not_at_its_vertex", "point " + std::to_string(i));
    if(ck.failure.empty() && kdt.last_move_rebuilt() != merged)
      ck.fail("kinetic:rule", std::string(merged ? "points merged or split, not rebuilt" : "rebuilt, no merge or split"));
  }
}

// Periodic cases: delaunay_from_prediction() of the points with the case's faces, make_delaunay()
// after moving CGAL's triangulation of the distinct points to the moved ones (refused when two
// meet), and Kinetic_Delaunay_triangulation_2 there and back; each result equal to CGAL's
// periodic range insertion (faces as (index, offset) corners, covering), is_valid(), every
// vertex's info() its point's smallest index.
template <class K>
void run_periodic(Checker& ck, const Case& c)
{
  using P2DT2 = Periodic_DT<K>;
  Periodic_domain d;
  if(!periodic_domain_of(c.pts, d))
    return;
  const typename P2DT2::Iso_rectangle domain(d.xmin, d.ymin, d.xmin + d.width, d.ymin + d.width);
  const XYs pts2 = wrapped_into(c.pts2.size() == c.pts.size() ? c.pts2 : c.pts, d);
  if(std::is_same<K, Epick>::value && !double_period_fits(d)) { // refused by every entry point
    auto refuses = [&](const char* what, const auto& call) {
      try {
        call();
        ck.fail(std::string("periodic:") + what + ":period_not_refused", "no Invalid_prediction");
      } catch(const DFP::Invalid_prediction&) {
      } catch(const std::exception& e) {
        ck.fail(std::string("periodic:") + what + ":wrong_exception", e.what());
      }
    };
    P2DT2 t(domain);
    refuses("delaunay_from_prediction", [&] { DFP::delaunay_from_prediction(points_of<K>(c.pts), c.faces, t); });
    DFP::Kinetic_Delaunay_triangulation_2<P2DT2> kinetic{P2DT2(domain)};
    if(!c.pts.empty())
      refuses("kinetic", [&] { kinetic.build(points_of<K>(c.pts)); });
    return;
  }
  auto reference = [&](const XYs& xy) {
    P2DT2 r(domain);
    const auto P = points_of<K>(xy);
    r.insert(P.begin(), P.end());
    bool found = true;
    return std::make_pair(periodic_faces_of(r, xy, found), r.is_1_cover());
  };
  auto check = [&](const P2DT2& t, const XYs& xy, const char* what, bool check_info) {
    if(!ck.failure.empty())
      return;
    if(!t.is_valid()) {
      ck.fail(std::string("periodic:") + what + ":is_valid", "is_valid() is false");
      return;
    }
    bool found = true;
    const auto got = std::make_pair(periodic_faces_of(t, xy, found), t.is_1_cover());
    if(!found)
      ck.fail(std::string("periodic:") + what + ":vertex_not_a_point", "a vertex is at none of the points");
    else if(got != reference(xy))
      ck.fail(std::string("periodic:") + what + ":faces", got.second ? "faces differ from CGAL's" : "faces or covering differ");
    std::map<std::pair<double, double>, std::size_t> index;
    for(std::size_t i = xy.size(); i-- > 0;)
      index[{xy[i].x, xy[i].y}] = i;
    if(check_info && ck.failure.empty())
      for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
        if(index[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}] != v->info()) {
          ck.fail(std::string("periodic:") + what + ":info", "a vertex's info() is not its point's smallest index");
          break;
        }
    // Cleared on every vertex, as CGAL leaves it after its own operations: indeterminate, it
    // would be read by copying the triangulation (UBSan halts on that load here).
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end() && ck.failure.empty(); ++v)
      if(v->get_offset_flag())
        ck.fail(std::string("periodic:") + what + ":offset_flag", "a vertex's offset flag is set");
  };
  // f(the case's named parameters, those it gives only), f(tag, np) for both tags.
  auto with_parameters = [&](auto f) {
    auto call = [&](const auto& np) {
      return c.parallel ? f(CGAL::Parallel_if_available_tag(), np) : f(CGAL::Sequential_tag(), np);
    };
    const std::size_t flips = std::size_t(c.max_flips);
    const DFP::Strategy strategy = DFP::Strategy(c.strategy);
    if(c.max_flips >= 0 && c.strategy >= 0)
      return call(DFP::parameters::max_flips(flips).strategy(strategy));
    if(c.max_flips >= 0)
      return call(DFP::parameters::max_flips(flips));
    if(c.strategy >= 0)
      return call(DFP::parameters::strategy(strategy));
    return call(DFP::parameters::default_values());
  };
  // delaunay_from_prediction()
  const auto P = points_of<K>(c.pts);
  std::vector<std::array<long long, 3>> faces;
  for(const Tri& f : c.faces)
    faces.push_back({f[0], f[1], f[2]});
  P2DT2 t(domain);
  expect_no_throw(ck, [&] {
    with_parameters([&](auto tag, const auto& np) {
      return DFP::delaunay_from_prediction<decltype(tag)>(P, faces, t, np);
    });
  });
  check(t, c.pts, "delaunay_from_prediction", true);
  // make_delaunay() on CGAL's triangulation of the distinct points, moved.
  const XYs distinct = dedupe(c.pts);
  std::map<std::pair<double, double>, std::size_t> first_at;
  for(std::size_t i = 0; i < c.pts.size(); ++i)
    first_at.emplace(std::make_pair(c.pts[i].x, c.pts[i].y), i);
  XYs before, after;
  for(const XY& p : distinct) {
    before.push_back(p);
    after.push_back(pts2[first_at[{p.x, p.y}]]);
  }
  const bool meet = dedupe(after).size() != after.size();
  {
    P2DT2 m(domain);
    const auto B = points_of<K>(before);
    m.insert(B.begin(), B.end());
    std::map<std::pair<double, double>, std::size_t> rank; // in `before`, distinct points
    for(std::size_t k = 0; k < before.size(); ++k)
      rank[{before[k].x, before[k].y}] = k;
    const auto A = points_of<K>(after);
    for(auto v = m.tds().vertices().begin(); v != m.tds().vertices().end(); ++v) { // every copy
      const std::size_t k = rank[{CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}];
      v->set_point(A[k]);
      v->info() = k;
    }
    bool threw = false;
    try {
      with_parameters([&](auto tag, const auto& np) { return DFP::make_delaunay<decltype(tag)>(m, np); });
    } catch(const DFP::Invalid_prediction&) {
      threw = true;
    } catch(const std::exception& e) {
      ck.fail(std::string("periodic:make_delaunay:threw:") + typeid(e).name(), e.what());
    }
    if(ck.failure.empty() && threw != meet)
      ck.fail("periodic:make_delaunay:refusal", meet ? "two vertices at one point were accepted" : "threw on distinct points");
    if(!meet)
      check(m, after, "make_delaunay", true);
  }
  // Kinetic_Delaunay_triangulation_2: to the moved points and back.
  DFP::Kinetic_Delaunay_triangulation_2<P2DT2> kinetic{P2DT2(domain)};
  expect_no_throw(ck, [&] { kinetic.build(P); });
  for(const XYs* xy : {&pts2, &c.pts}) {
    if(!ck.failure.empty())
      return;
    expect_no_throw(ck, [&] {
      if(c.parallel)
        kinetic.template move<CGAL::Parallel_if_available_tag>(points_of<K>(*xy));
      else
        kinetic.move(points_of<K>(*xy));
    });
    check(kinetic.triangulation(), *xy, "kinetic", true);
    for(std::size_t i = 0; i < xy->size() && ck.failure.empty(); ++i)
      if(CGAL::to_double(kinetic.point(i).x()) != (*xy)[i].x || CGAL::to_double(kinetic.point(i).y()) != (*xy)[i].y)
        ck.fail("periodic:kinetic:point_not_at_its_vertex", "point " + std::to_string(i));
  }
}

// Brute-force proximity graphs (exact predicates), on representatives (smallest index).
template <class K>
void run_proximity(Checker& ck, const Case& c)
{
  const auto P = points_of<K>(c.pts);
  const std::size_t n = P.size();
  std::vector<std::pair<long long, long long>> e;
  for(const Tri& t : c.faces)
    e.emplace_back(t[0], t[1]);
  std::vector<std::pair<std::size_t, std::size_t>> got, expected;
  expect_no_throw(ck, [&] {
    if(c.entry == E_EMST)
      DFP::euclidean_minimum_spanning_tree_from_prediction(P, e, std::back_inserter(got));
    else if(c.entry == E_RNG)
      DFP::relative_neighborhood_graph_from_prediction(P, e, std::back_inserter(got));
    else
      DFP::gabriel_graph_from_prediction(P, e, std::back_inserter(got));
  });
  if(!ck.failure.empty())
    return;
  const K k;
  auto cmp = k.compare_distance_2_object();
  std::vector<std::size_t> rep(n);
  for(std::size_t i = 0; i < n; ++i) {
    rep[i] = i;
    for(std::size_t j = 0; j < i; ++j)
      if(P[j] == P[i]) {
        rep[i] = j;
        break;
      }
  }
  if(c.entry == E_EMST) {
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j)
        pairs.emplace_back(i, j);
    std::stable_sort(pairs.begin(), pairs.end(), [&](const auto& a, const auto& b) {
      const auto r = cmp(P[a.first], P[a.second], P[b.first], P[b.second]);
      return r == CGAL::SMALLER || (r == CGAL::EQUAL && a < b);
    });
    std::vector<std::size_t> root(n);
    std::iota(root.begin(), root.end(), std::size_t(0));
    std::function<std::size_t(std::size_t)> find = [&](std::size_t x) { return root[x] == x ? x : root[x] = find(root[x]); };
    for(const auto& p : pairs) {
      const std::size_t a = find(p.first), b = find(p.second);
      if(a != b) {
        root[a] = b;
        expected.push_back(p);
      }
    }
  } else {
    auto sbc = k.side_of_bounded_circle_2_object();
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 1; j < n; ++j) {
        if(rep[i] != i || rep[j] != j)
          continue;
        bool edge = true;
        for(std::size_t r = 0; r < n && edge; ++r) {
          if(rep[r] != r || r == i || r == j)
            continue;
          if(c.entry == E_RNG)
            edge = !(cmp(P[i], P[r], P[i], P[j]) == CGAL::SMALLER && cmp(P[j], P[r], P[j], P[i]) == CGAL::SMALLER);
          else
            edge = sbc(P[i], P[j], P[r]) == CGAL::ON_UNBOUNDED_SIDE;
        }
        if(edge)
          expected.emplace_back(i, j);
      }
  }
  std::sort(expected.begin(), expected.end());
  if(got != expected) {
    std::ostringstream d;
    d << got.size() << " edges vs " << expected.size() << " by brute force; first differences:";
    std::vector<std::pair<std::size_t, std::size_t>> a, b;
    std::set_difference(got.begin(), got.end(), expected.begin(), expected.end(), std::back_inserter(a));
    std::set_difference(expected.begin(), expected.end(), got.begin(), got.end(), std::back_inserter(b));
    for(std::size_t i = 0; i < std::min<std::size_t>(3, a.size()); ++i)
      d << " extra(" << a[i].first << "," << a[i].second << ")";
    for(std::size_t i = 0; i < std::min<std::size_t>(3, b.size()); ++i)
      d << " missing(" << b[i].first << "," << b[i].second << ")";
    ck.fail(std::string(entry_names[c.entry]) + ":edges", d.str());
  }
}

template <class Tr, class K>
void run_sg(Checker& ck, const Case& c, bool exact)
{
  const auto P = points_of<K>(c.pts);
  std::vector<std::array<long long, 2>> e;
  for(const Tri& t : c.faces)
    e.push_back({t[0], t[1]});
  Tr tr;
  DFP::Statistics s;
  expect_no_throw(ck, [&] { s = DFP::delaunay_from_spanning_graph(P, e, tr); });
  if(!ck.failure.empty())
    return;
  check_result(ck, tr, P, exact);
  check_stats(ck, s, 0, (long long)P.size(), (long long)tr.number_of_vertices());
  if(s.edges_in != e.size())
    ck.fail("stats:edges_in", std::to_string(s.edges_in) + " vs " + std::to_string(e.size()));
  // Section 3 as written, on the same graph.
  Tr t3;
  expect_no_throw(ck, [&] {
    s = DFP::delaunay_from_spanning_graph(P, e, t3, DFP::parameters::strategy(DFP::Strategy::section_3));
  });
  if(!ck.failure.empty())
    return;
  check_result(ck, t3, P, exact);
  check_stats(ck, s, 0, (long long)P.size(), (long long)t3.number_of_vertices());
}

template <class Tr, class K>
void run_imprecise(Checker& ck, const Case& c, bool exact)
{
  const auto C = points_of<K>(c.pts), I = points_of<K>(c.pts2);
  Tr tr;
  DFP::Statistics s;
  expect_no_throw(ck, [&] {
    const DFP::Imprecise_points_2<K> disks(C, c.radii);
    s = disks.triangulate(I, tr);
  });
  if(!ck.failure.empty())
    return;
  check_result(ck, tr, I, exact);
  check_stats(ck, s, 0, (long long)I.size(), (long long)tr.number_of_vertices());
}

template <class Tr, class K>
void run_brio(Checker& ck, const Case& c, bool exact)
{
  const auto P = points_of<K>(c.pts);
  Tr tr;
  DFP::Statistics s;
  expect_no_throw(ck, [&] {
    if(c.param_seed && c.sample_probability > 0)
      s = DFP::brio_dc_delaunay(P, tr, DFP::parameters::sample_probability(c.sample_probability, CGAL::parameters::random_seed(c.param_seed)));
    else if(c.param_seed)
      s = DFP::brio_dc_delaunay(P, tr, CGAL::parameters::random_seed(c.param_seed));
    else if(c.sample_probability > 0)
      s = DFP::brio_dc_delaunay(P, tr, DFP::parameters::sample_probability(c.sample_probability));
    else
      s = DFP::brio_dc_delaunay(P, tr);
  });
  if(!ck.failure.empty())
    return;
  check_result(ck, tr, P, exact);
  check_stats(ck, s, 0, (long long)P.size(), (long long)tr.number_of_vertices());
}

template <class K>
void run_split(Checker& ck, const Case& c, bool exact)
{
  using DT = dfp_test::DT_with_info<K>;
  const auto P = points_of<K>(c.pts);
  DT dt;
  dfp_test::Handles<DT> handles;
  dfp_test::insert_all(dt, P, handles); // the inexact kernel's faces by exact predicates
  const dfp_test::Snapshot<DT> before(dt);
  DT dt1, dt2;
  auto first = [&](typename DT::Vertex_handle v) { return c.part[v->info()] == 0; };
  expect_no_throw(ck, [&] {
    if(c.split_method < 0 && !c.param_seed)
      DFP::split_delaunay(dt, first, dt1, dt2);
    else
      DFP::split_delaunay(dt, first, dt1, dt2,
                          DFP::parameters::split_method(c.split_method >= 0 ? DFP::Split_method(c.split_method)
                                                                             : DFP::Split_method::automatic,
                                                        CGAL::parameters::random_seed(c.param_seed ? c.param_seed : 1u)));
  });
  if(!ck.failure.empty())
    return;
  std::vector<typename K::Point_2> part[2];
  std::map<typename K::Point_2, std::size_t> info;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    part[c.part[v->info()] == 0 ? 0 : 1].push_back(v->point());
    info[v->point()] = v->info();
  }
  const DT* out[2] = {&dt1, &dt2};
  for(int k = 0; k < 2; ++k) {
    const DT& t = *out[k];
    // The inexact kernel against Epick's build of the same doubles (the exact decision).
    using Ref = std::conditional_t<std::is_same<K, SC>::value, Epick, K>;
    auto to_ref = [](const typename K::Point_2& p) {
      return typename Ref::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    };
    std::vector<typename Ref::Point_2> ref_part;
    for(const auto& p : part[k])
      ref_part.push_back(to_ref(p));
    const CGAL::Delaunay_triangulation_2<Ref> ref(ref_part.begin(), ref_part.end());
    const auto r = dfp_test::geometry_of(ref);
    const auto g = [&] {
      if constexpr(std::is_same<K, Ref>::value)
        return dfp_test::geometry_of(t);
      else
        return dfp_test::geometry_of(t, to_ref);
    }();
    if(exact ? !t.is_valid() : !t.tds().is_valid())
      ck.fail("split:is_valid", "dt" + std::to_string(k + 1) + ".is_valid() is false (" + std::to_string(t.number_of_vertices()) + " vertices, dimension " + std::to_string(t.dimension()) + ")");
    else if(g.vertices != r.vertices)
      ck.fail("split:vertices", "dt" + std::to_string(k + 1));
    else if(g.faces != r.faces || g.edges != r.edges)
      ck.fail("split:faces", "dt" + std::to_string(k + 1) + " differs from CGAL's DT of its part");
    bool info_ok = true;
    for(auto v = t.finite_vertices_begin(); v != t.finite_vertices_end(); ++v)
      info_ok = info_ok && info.count(v->point()) && info[v->point()] == v->info();
    if(!info_ok)
      ck.fail("split:info", "dt" + std::to_string(k + 1) + ": info not copied");
  }
  const std::string out2 = captured([&] { dfp_test::check_unchanged(dt, before); });
  if(!out2.empty())
    ck.fail("split:input_changed:" + first_expression(out2), out2);
}

// Malformed input: must throw Invalid_prediction, and leave the caller's dt unchanged.
template <class K>
void run_malformed(Checker& ck, const Case& c)
{
  using DT = dfp_test::DT_with_info<K>;
  const auto P = points_of<K>(c.pts);
  DT dt;
  const XY fixed[] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.3, 0.6}};
  for(std::size_t i = 0; i < 5; ++i)
    dt.insert(dfp_test::make_point<K>(fixed[i].x, fixed[i].y))->info() = 100 + i;
  const dfp_test::Snapshot<DT> before(dt);
  std::string what;
  auto call = [&] {
    std::vector<std::array<long long, 2>> e;
    for(const Tri& t : c.faces)
      e.push_back({t[0], t[1]});
    switch(c.pred_family) {
    case F_M_EDGE_RANGE:
    case F_M_EDGE_LOOP:
      if(c.output == 0)
        DFP::delaunay_from_predicted_edges(P, e, dt);
      else
        DFP::delaunay_from_spanning_graph(P, e, dt);
      break;
    case F_M_IMPRECISE: {
      const DFP::Imprecise_points_2<K> disks(P, c.radii);
      disks.triangulate(points_of<K>(c.pts2), dt);
      break;
    }
    case F_M_BRIO: DFP::brio_dc_delaunay(P, dt); break;
    default:
      if(c.output == 0)
        DFP::delaunay_from_prediction(P, c.faces, dt);
      else { // as std::vector<int> faces
        std::vector<std::vector<int>> f;
        for(const Tri& t : c.faces)
          f.push_back({int(t[0]), int(t[1]), int(t[2])});
        DFP::delaunay_from_prediction(P, f, dt);
      }
    }
  };
  try {
    call();
    ck.fail("malformed:no_throw", "no Invalid_prediction");
  } catch(const DFP::Invalid_prediction& e) {
    what = e.what();
  } catch(const std::exception& e) {
    ck.fail(std::string("malformed:wrong_exception:") + typeid(e).name(), e.what());
  }
  const std::string out = captured([&] { dfp_test::check_unchanged(dt, before); });
  if(!out.empty())
    ck.fail("malformed:dt_changed:" + first_expression(out), out);
  if(ck.failure.empty() && (c.pred_family == F_M_RANGE || c.pred_family == F_M_NEGATIVE || c.pred_family == F_M_REPEAT)) {
    std::size_t bad = 0;
    for(; bad < c.faces.size(); ++bad) {
      const Tri& t = c.faces[bad];
      bool b = false;
      for(int j = 0; j < 3; ++j)
        b = b || t[j] < 0 || t[j] >= (long long)P.size() || t[j] == t[(j + 1) % 3];
      if(b)
        break;
    }
    if(!dfp_test::mentions_number(what, bad))
      ck.fail("malformed:message", "what() does not name face " + std::to_string(bad) + ": " + what);
  }
}

template <class K>
std::string run_kernel(const Case& c)
{
  Checker ck;
  const bool exact = !std::is_same<K, SC>::value;
  try {
    switch(c.entry) {
    case E_DFP:
    case E_EDGES:
      if(c.output == O_INFO)
        run_dfp<dfp_test::DT_with_info<K>, K>(ck, c, exact);
      else if(c.output == O_PLAIN)
        run_dfp<dfp_test::DT_plain<K>, K>(ck, c, exact);
      else
        run_dfp<DT_hier<K>, K>(ck, c, exact);
      break;
    case E_MD:
      if(c.t2)
        c.output == O_INFO ? run_md<dfp_test::T2_with_info<K>, K>(ck, c, exact)
                           : run_md<dfp_test::T2_plain<K>, K>(ck, c, exact);
      else
        c.output == O_INFO ? run_md<dfp_test::DT_with_info<K>, K>(ck, c, exact)
                           : run_md<dfp_test::DT_plain<K>, K>(ck, c, exact);
      if(exact && ck.failure.empty())
        run_kinetic<K>(ck, c);
      break;
    case E_SG:
      if(c.output == O_HIER)
        run_sg<DT_hier<K>, K>(ck, c, exact);
      else
        run_sg<dfp_test::DT_with_info<K>, K>(ck, c, exact);
      break;
    case E_EMST:
    case E_RNG:
    case E_GABRIEL:
      if(exact)
        run_proximity<K>(ck, c);
      else
        run_proximity<Epick>(ck, c); // brute force needs exact predicates
      break;
    case E_IMPRECISE:
      if(c.output == O_HIER)
        run_imprecise<DT_hier<K>, K>(ck, c, exact);
      else
        run_imprecise<dfp_test::DT_with_info<K>, K>(ck, c, exact);
      break;
    case E_SPLIT: run_split<K>(ck, c, exact); break;
    case E_BRIO:
      if(c.output == O_HIER)
        run_brio<DT_hier<K>, K>(ck, c, exact);
      else if(c.output == O_PLAIN)
        run_brio<dfp_test::DT_plain<K>, K>(ck, c, exact);
      else
        run_brio<dfp_test::DT_with_info<K>, K>(ck, c, exact);
      break;
    case E_PERIODIC:
      if constexpr(std::is_same<K, SC>::value)
        run_periodic<Epick>(ck, c); // needs exact predicates (gen_case draws Epick)
      else
        run_periodic<K>(ck, c);
      break;
    default: run_malformed<K>(ck, c); break;
    }
  } catch(const std::exception& e) {
    ck.fail(std::string("threw_in_check:") + typeid(e).name(), e.what());
  }
  return ck.failure;
}

// The checks with Epeck are instantiated in fuzz_differential_epeck.cpp, a translation unit of
// their own that the build compiles in parallel with this one (the longest of the tests to
// compile, most of all under the sanitizers).
#ifdef DFP_FUZZ_EPECK_PART
template std::string run_kernel<Epeck>(const Case& c);
#else
extern template std::string run_kernel<Epeck>(const Case& c);

static std::string run_case(const Case& c)
{
  switch(c.kernel) {
  case K_EPECK: return run_kernel<Epeck>(c);
  case K_SC: return run_kernel<SC>(c);
  default: return run_kernel<Epick>(c);
  }
}

static std::string tag_of(const std::string& failure)
{
  const std::size_t at = failure.find(" :: ");
  return at == std::string::npos ? failure : failure.substr(0, at);
}

// ---------------------------------------------------------------------------------------------
// Driver
// ---------------------------------------------------------------------------------------------

static std::string repro_command(long long k)
{
  std::ostringstream s;
  s << "test_fuzz_differential --seed " << opt.seed << " --case " << k;
  if(opt.family >= 0)
    s << " --family " << entry_names[opt.family];
  if(opt.kernel >= 0)
    s << " --kernel " << kernel_names[opt.kernel];
  if(opt.max_n != std::size_t(-1))
    s << " --max-n " << opt.max_n;
  return s.str();
}

// A failure of case k: counted; the first of its signature minimized and printed.
static void report(const Case& c, long long k, const std::string& failure)
{
  Shared* sh = shared_memory();
  ++sh->failures;
  ++sh->by_entry[c.entry][1];
  ++sh->by_points[c.point_family][1];
  ++sh->by_pred[c.pred_family][1];
  ++sh->by_kernel[c.kernel][1];
  const std::string tag = tag_of(failure);
  const std::string key = std::string(entry_names[c.entry]) + " | " + kernel_names[c.kernel] + " | " +
                          point_family_names[c.point_family] + " | " + tag;
  const bool fresh = record_signature(key, k);
  std::cout << "FAIL seed=" << opt.seed << " case=" << k << ": " << tag << "\n  " << describe(c)
            << "\n  reproduce: " << repro_command(k) << std::endl;
  if(!fresh)
    return;
  std::string detail = failure.substr(std::min(failure.size(), tag.size()));
  if(detail.size() > 600)
    detail = detail.substr(0, 600) + "...";
  std::cout << "  detail" << detail << std::endl;
  const auto start = std::chrono::steady_clock::now();
  const Case small = minimize(c, [&](const Case& d) {
    return seconds_since(start) < opt.minimize_seconds && tag_of(in_child([&] { return run_case(d); }, 10)) == tag;
  });
  std::cout << "  minimized (" << small.pts.size() << " points, " << small.faces.size() << " faces/edges):\n"
            << as_cpp(small) << std::endl;
}

static void count_case(const Case& c)
{
  Shared* sh = shared_memory();
  ++sh->cases;
  ++sh->by_entry[c.entry][0];
  ++sh->by_points[c.point_family][0];
  ++sh->by_pred[c.pred_family][0];
  ++sh->by_kernel[c.kernel][0];
}

static int usage()
{
  std::cerr << "usage: test_fuzz_differential [--seed S] [--cases N] [--seconds T] [--case K] [--family NAME]\n"
               "       [--kernel epick|epeck|sc] [--check-hierarchy 0|1] [--case-timeout S] [--minimize-seconds S] [--max-n N] [--verbose]\n"
               "families:";
  for(const char* f : entry_names)
    std::cerr << " " << f;
  std::cerr << std::endl;
  return 2;
}

int main(int argc, char** argv)
{
  if(const char* cases = std::getenv("DFP_FUZZ_CASES"))
    opt.cases = std::stoll(cases);
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::exit(usage());
      }
      return argv[++i];
    };
    if(a == "--seed")
      opt.seed = std::stoull(next());
    else if(a == "--cases")
      opt.cases = std::stoll(next()), opt.seconds = 1e18;
    else if(a == "--seconds")
      opt.seconds = std::stod(next());
    else if(a == "--case")
      opt.single_case = std::stoll(next());
    else if(a == "--verbose")
      opt.verbose = true;
    else if(a == "--inexact-kernel")
      ; // accepted for old reproduce lines: Simple_cartesian<double> is drawn by default
    else if(a == "--check-hierarchy")
      opt.check_hierarchy = next() != "0";
    else if(a == "--max-n")
      opt.max_n = std::size_t(std::stoull(next()));
    else if(a == "--minimize-seconds")
      opt.minimize_seconds = std::stod(next());
    else if(a == "--case-timeout")
      opt.case_timeout = unsigned(std::stoul(next()));
    else if(a == "--family") {
      const std::string f = next();
      for(int k = 0; k < E_COUNT; ++k)
        if(f == entry_names[k])
          opt.family = k;
      if(opt.family < 0)
        return usage();
    } else if(a == "--kernel") {
      const std::string f = next();
      for(int k = 0; k < K_COUNT; ++k)
        if(f == kernel_names[k])
          opt.kernel = k;
      if(opt.kernel < 0)
        return usage();
    } else
      return usage();
  }
  const struct rlimit no_core = {0, 0};
  setrlimit(RLIMIT_CORE, &no_core); // crashes are expected and reported: no core files
  Shared* sh = shared_memory();
  const auto t0 = std::chrono::steady_clock::now();
  long long first = 0, last = opt.cases >= 0 ? opt.cases : std::numeric_limits<long long>::max();
  if(opt.single_case >= 0) {
    first = opt.single_case;
    last = first + 1;
    opt.seconds = 1e18;
  }
  // Children run consecutive cases; a child that dies leaves the case it was running in shared
  // memory: reported as a crash, and the next child goes on after it.
  for(long long next = first; next < last && seconds_since(t0) < opt.seconds;) {
    sh->current_case = -1;
    std::cout.flush();
    const pid_t child = fork();
    if(child == 0) {
      for(long long k = next; k < last && seconds_since(t0) < opt.seconds; ++k) {
        sh->current_case = k;
        const Case c = gen_case(opt.seed, k);
        if(opt.verbose)
          std::cout << "case " << k << ": " << describe(c) << std::endl;
        alarm(opt.case_timeout);
        const std::string failure = run_case(c);
        alarm(0);
        count_case(c);
        if(!failure.empty())
          report(c, k, failure);
      }
      sh->current_case = -1;
      std::cout.flush();
      std::_Exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if(WIFSIGNALED(status) && sh->current_case >= 0) {
      const long long k = sh->current_case;
      const Case c = gen_case(opt.seed, k);
      count_case(c);
      const std::string sig = WTERMSIG(status) == SIGALRM ? std::string("timeout") : strsignal(WTERMSIG(status));
      report(c, k, "crash:" + sig + " :: the case died (" + sig + ")");
      next = k + 1;
    } else if(WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0)) {
      std::cout << "fuzz: the runner died outside a case" << std::endl;
      ++sh->failures;
      break;
    } else
      break;
  }
  const double elapsed = seconds_since(t0);
  std::cout << "\nper entry point (cases / failures):";
  for(int k = 0; k < E_COUNT; ++k)
    if(sh->by_entry[k][0])
      std::cout << " " << entry_names[k] << " " << sh->by_entry[k][0] << "/" << sh->by_entry[k][1];
  std::cout << "\nper kernel:";
  for(int k = 0; k < K_COUNT; ++k)
    if(sh->by_kernel[k][0])
      std::cout << " " << kernel_names[k] << " " << sh->by_kernel[k][0] << "/" << sh->by_kernel[k][1];
  std::cout << "\nper point family:";
  for(int k = 0; k < P_COUNT; ++k)
    if(sh->by_points[k][0])
      std::cout << " " << point_family_names[k] << " " << sh->by_points[k][0] << "/" << sh->by_points[k][1];
  std::cout << "\nper prediction family:";
  for(int k = 0; k < F_COUNT; ++k)
    if(sh->by_pred[k][0])
      std::cout << " " << pred_family_names[k] << " " << sh->by_pred[k][0] << "/" << sh->by_pred[k][1];
  if(sh->inexact_checked > 0)
    std::cout << "\nSimple_cartesian<double> results equal to Epick's build: " << sh->inexact_checked
              << ", of which the kernel's own is_valid() rejects " << sh->inexact_not_valid << " (not a failure)";
  std::cout << "\ndistinct failure signatures: " << sh->signatures << "\n";
  for(int k = 0; k < sh->signatures; ++k)
    std::cout << "  " << sh->signature[k].count << " x " << sh->signature[k].key << " (first: case "
              << sh->signature[k].first_case << ")\n";
  std::cout << "fuzz: " << sh->cases << " cases, " << sh->failures << " failures (seed " << opt.seed << ") in "
            << elapsed << " s, " << double(sh->cases) / std::max(elapsed, 1e-9) << " cases/s" << std::endl;
  return sh->failures == 0 ? 0 : 1;
}
#endif // DFP_FUZZ_EPECK_PART
