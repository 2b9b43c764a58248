// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// make_delaunay() on Delaunay_triangulation_2 and Triangulation_2, with and without vertex
// info (Epick), through a sequence of "time steps" that move the vertices with set_point():
// no move, small moves that keep every face ccw, a shear, a few vertices moved far (a few
// inverted faces: local repair, or a fallback with strategy(flips)), large moves that invert
// many faces, a mirror image, collapse onto a line and back. After every call the triangulation must be
// CGAL's DT of the moved points, every original vertex handle still in it with its point and
// info. Then lower dimensions (0 to 3 vertices), and two vertices at the same point: throws
// Invalid_prediction naming both, and leaves the triangulation as it was.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <functional>
#include <set>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Points = std::vector<Point>;

// Calls make_delaunay and checks everything that must hold afterwards.
//
// Faces that are not ccw (inverted or flat) are untangled by flips or carved by the local
// repair (their vertices reinserted) unless the strategy is `flips`, or the damage is over the
// repair's budget: then the call falls back. A triangulation whose faces are all ccw is never
// carved.
template <class Tr, class NP = DFP::parameters::Default_named_parameters>
DFP::Statistics make_and_check(Tr& tr, const Handles<Tr>& handles,
                               const NP& np = DFP::parameters::default_values())
{
  const Points points = current_points(handles);
  const std::size_t faces_before = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  const std::size_t inverted = inverted_faces(tr);
  const bool hull_was_convex = tr.dimension() == 2 && DFP::internal::hull_is_convex_and_wound_once(tr);
  const DFP::Statistics s = with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr, np); });
  check_handles(tr, handles, points);
  check_is_cgal_delaunay(tr, points); // info i is point i: also checks the info
  DFP_CHECK_MSG(s.faces_in == faces_before, s.faces_in << " vs " << faces_before);
  DFP_CHECK(s.faces_certified <= s.faces_in);
  DFP_CHECK_MSG((s.outcome == DFP::Outcome::ok) == !s.fell_back, to_string(s.outcome));
  DFP_CHECK_MSG(inverted > 0 || (s.faces_carved == 0 && s.holes_refilled == 0 && s.carve_rounds == 0),
                s.faces_carved << " faces carved, " << s.holes_refilled << " holes refilled, "
                               << s.carve_rounds << " rounds, with every face ccw");
  if(s.fell_back) {
    DFP_CHECK(s.points_reinserted == points.size());
  } else {
    DFP_CHECK(s.edges_not_locally_delaunay <= s.edges_tested);
    DFP_CHECK_MSG(s.faces_certified + s.faces_carved <= s.faces_in,
                  s.faces_certified << " certified, " << s.faces_carved << " carved, " << s.faces_in << " in");
    // Inverted faces were untangled by flips or carved.
    DFP_CHECK(inverted == 0 || s.flips > 0 || s.faces_carved > 0);
    if(s.faces_carved == 0) {
      DFP_CHECK_MSG(s.points_reinserted == 0, s.points_reinserted << " reinserted, nothing carved");
    } else {
      // The carved vertices, each reinserted once.
      DFP_CHECK_MSG(s.points_reinserted > 0 && s.points_reinserted <= points.size() &&
                        s.points_reinserted <= 3 * s.faces_carved,
                    s.points_reinserted << " reinserted, " << s.faces_carved << " faces carved");
    }
    if(inverted == 0) {
      // Failing edges need flips; with a convex hull, flips need failing edges (a hull that is
      // not convex is flipped convex first, which may leave no edge failing).
      DFP_CHECK_MSG(s.edges_not_locally_delaunay == 0 || s.flips > 0,
                    s.flips << " flips, " << s.edges_not_locally_delaunay << " failing");
      DFP_CHECK_MSG(!hull_was_convex || s.flips == 0 || s.edges_not_locally_delaunay > 0,
                    s.flips << " flips, " << s.edges_not_locally_delaunay << " failing");
      DFP_CHECK(s.faces_certified + 2 * s.flips >= s.faces_in);
    }
  }
  return s;
}

// Moves one hull vertex just inside the segment joining its two hull neighbours, where every
// face around it stays ccw: all faces are ccw, but the hull is no longer convex (the vertex
// will leave the hull). Returns false if no hull vertex allows it.
template <class Tr>
bool dent_the_hull(Tr& tr)
{
  std::vector<typename Tr::Vertex_handle> hull;
  auto c = tr.incident_vertices(tr.infinite_vertex()), done = c;
  do
    hull.push_back(c);
  while(++c != done);
  const std::size_t m = hull.size();
  for(std::size_t k = 0; k < m; ++k) {
    const auto v = hull[k];
    const Point& a = hull[(k + m - 1) % m]->point();
    const Point& b = hull[(k + 1) % m]->point();
    const Point mid = CGAL::midpoint(a, b);
    const Point p = mid + 0.05 * (v->point() - mid) * -1.; // a little beyond the chord, inwards
    if(CGAL::orientation(a, p, b) == CGAL::orientation(a, v->point(), b))
      continue; // not reflex
    bool ccw = true;
    auto f = tr.incident_faces(v), fdone = f;
    do
      if(!tr.is_infinite(f)) {
        const int i = f->index(v);
        ccw = ccw && CGAL::orientation(p, f->vertex(tr.ccw(i))->point(), f->vertex(tr.cw(i))->point()) ==
                         CGAL::LEFT_TURN;
      }
    while(++f != fdone);
    if(ccw) {
      v->set_point(p);
      return true;
    }
  }
  return false;
}

template <class Tr>
void move_all(const Handles<Tr>& handles, const std::function<Point(const Point&)>& f)
{
  for(const auto& v : handles)
    v->set_point(f(v->point()));
}

template <class Tr>
void test_time_steps(const char* name, CGAL::Random& rng)
{
  Scope scope(name, ", time steps");
  const std::size_t n = 1000;
  const double spacing = 1. / std::sqrt(double(n));
  Tr tr;
  Handles<Tr> handles;
  build(tr, to_points<K>(uniform_points(n, rng)), handles);
  {
    Scope step("initial triangulation");
    make_and_check(tr, handles);
  }
  {
    Scope step("no move (already Delaunay)");
    const DFP::Statistics s = make_and_check(tr, handles);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.flips == 0);
    DFP_CHECK(s.edges_not_locally_delaunay == 0);
    DFP_CHECK(s.faces_certified == s.faces_in);
    DFP_CHECK(s.faces_in == tr.number_of_faces());
    DFP_CHECK(s.edges_tested == 2 * s.faces_in + 1 - n);
  }
  for(double relative : {0.05, 0.3}) {
    Scope step("small moves (", relative, " of the spacing) keeping every face ccw");
    const std::size_t moved = move_keeping_faces_ccw(tr, handles, relative * spacing, rng);
    DFP_CHECK(moved > n / 2);
    DFP_CHECK(inverted_faces(tr) == 0);
    const DFP::Statistics s = make_and_check(tr, handles);
    // A valid triangulation that needs few flips (about n/8 here) is repaired, not rebuilt;
    // the larger moves need about n/2 flips, near the default budget: either is allowed.
    if(relative < 0.1)
      DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome) << ", " << s.flips << " flips");
    else
      DFP_CHECK(s.fell_back || s.flips > 0);
  }
  {
    Scope step("a hull vertex pushed inside its hull edge (faces ccw, hull not convex)");
    DFP_CHECK(dent_the_hull(tr));
    DFP_CHECK(inverted_faces(tr) == 0);
    const DFP::Statistics s = make_and_check(tr, handles);
    // Repaired in place: a flip of the infinite edge at the dented vertex, then Lawson.
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.flips > 0);
  }
  {
    Scope step("shear x += 0.1 y (orientation preserving)");
    move_all<Tr>(handles, [](const Point& p) { return Point(p.x() + 0.1 * p.y(), p.y()); });
    const DFP::Statistics s = make_and_check(tr, handles);
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.flips > 0);
  }
  for(const bool flips : {true, false}) {
    // A few faces inverted: the local repair carves around them, or untangles them by flips
    // (strategy(flips): any inverted face makes the call fall back).
    Scope step("a few vertices moved by 3 spacings, ", flips ? "strategy(flips)" : "default strategy");
    CGAL::Random local(flips ? 91 : 92); // leaves rng, and so the other steps, as they were
    for(int moved = 0; moved < 100 && (moved < 3 || inverted_faces(tr) == 0); ++moved) {
      const auto v = handles[std::size_t(local.get_int(0, int(n)))];
      v->set_point(Point(v->point().x() + local.get_double(-3., 3.) * spacing,
                         v->point().y() + local.get_double(-3., 3.) * spacing));
    }
    DFP_CHECK(inverted_faces(tr) > 0);
    if(flips) {
      const DFP::Statistics s = make_and_check(tr, handles, DFP::parameters::strategy(DFP::Strategy::flips));
      DFP_CHECK(s.fell_back);
    } else {
      make_and_check(tr, handles);
    }
  }
  {
    Scope step("large moves (2 spacings) inverting faces");
    move_all<Tr>(handles, [&](const Point& p) {
      return Point(p.x() + rng.get_double(-2., 2.) * spacing, p.y() + rng.get_double(-2., 2.) * spacing);
    });
    DFP_CHECK(inverted_faces(tr) > 0);
    make_and_check(tr, handles);
  }
  {
    // Mirrored twice: the mirror image of a DT has every face inverted.
    Scope step("mirror image x -> -x (every face inverted)");
    move_all<Tr>(handles, [](const Point& p) { return Point(-p.x(), p.y()); });
    DFP_CHECK(inverted_faces(tr) == tr.number_of_faces());
    {
      Scope flips("strategy(flips): falls back");
      const DFP::Statistics s = make_and_check(tr, handles, DFP::parameters::strategy(DFP::Strategy::flips));
      DFP_CHECK(s.fell_back);
    }
    move_all<Tr>(handles, [](const Point& p) { return Point(-p.x(), p.y()); });
    DFP_CHECK(inverted_faces(tr) == tr.number_of_faces());
    {
      Scope automatic("mirrored back, default strategy");
      const DFP::Statistics s = make_and_check(tr, handles);
      DFP_CHECK(s.fell_back || s.faces_carved > 0);
    }
  }
  {
    Scope step("all points moved onto a line (dimension 2 -> 1)");
    std::size_t k = 0;
    move_all<Tr>(handles, [&](const Point&) {
      const double x = double(k++);
      return Point(x, 3. * x - 2.);
    });
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 1);
  }
  {
    Scope step("moved along the line, shuffled (dimension 1 -> 1)");
    std::vector<double> xs;
    for(std::size_t k = 0; k < n; ++k)
      xs.push_back(double(k) * 0.5);
    shuffle(xs, rng);
    std::size_t k = 0;
    move_all<Tr>(handles, [&](const Point&) {
      const double x = xs[k++];
      return Point(x, 3. * x - 2.);
    });
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 1);
  }
  {
    Scope step("one point moved off the line (dimension 1 -> 2)");
    handles[n / 2]->set_point(Point(10., 0.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 2);
  }
  {
    Scope step("spread out again at random (dimension 2, random points)");
    move_all<Tr>(handles, [&](const Point&) { return Point(rng.get_double(), rng.get_double()); });
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 2);
  }
  {
    Scope step("onto an integer grid (co-circular ties)");
    std::vector<std::size_t> order(n);
    for(std::size_t k = 0; k < n; ++k)
      order[k] = k;
    shuffle(order, rng);
    std::size_t k = 0;
    move_all<Tr>(handles, [&](const Point&) {
      const std::size_t c = order[k++];
      return Point(double(c % 40), double(c / 40));
    });
    make_and_check(tr, handles);
  }
  {
    Scope step("grid, then small moves keeping faces ccw");
    move_keeping_faces_ccw(tr, handles, 0.3, rng);
    make_and_check(tr, handles);
  }
}

// A non-Delaunay Triangulation_2 repaired with a large flip budget: Lawson's path, not a rebuild.
template <class Tr>
void test_large_budget(const char* name, CGAL::Random& rng)
{
  Scope scope(name, ", Lawson repair with max_flips(100 n)");
  const std::size_t n = 1000;
  Tr tr;
  Handles<Tr> handles;
  build(tr, to_points<K>(clustered_points(n, rng)), handles);
  flip_randomly(tr, 50, rng);
  const DFP::Statistics s = make_and_check(tr, handles, DFP::parameters::max_flips(100 * n));
  DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
  DFP_CHECK(s.flips > 0);
}

template <class Tr>
void test_small_dimensions(const char* name, CGAL::Random& rng)
{
  Scope scope(name, ", small dimensions");
  {
    Scope c("no vertex");
    Tr tr;
    const DFP::Statistics s = DFP::make_delaunay(tr);
    DFP_CHECK(tr.number_of_vertices() == 0);
    DFP_CHECK(tr.dimension() == -1);
    DFP_CHECK(tr.is_valid());
    DFP_CHECK(s.faces_in == 0 && s.flips == 0);
  }
  {
    Scope c("one vertex, moved");
    Tr tr;
    Handles<Tr> handles;
    build(tr, Points{Point(1., 2.)}, handles);
    handles[0]->set_point(Point(-5., 7.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 0);
  }
  {
    Scope c("two vertices, moved");
    Tr tr;
    Handles<Tr> handles;
    build(tr, Points{Point(1., 2.), Point(3., 4.)}, handles);
    handles[0]->set_point(Point(10., 10.));
    handles[1]->set_point(Point(-10., 10.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 1);
  }
  {
    Scope c("three vertices, moved to a line, then swapped along it, then off it");
    Tr tr;
    Handles<Tr> handles;
    build(tr, Points{Point(0., 0.), Point(1., 0.), Point(0., 1.)}, handles);
    handles[2]->set_point(Point(2., 0.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 1);
    handles[0]->set_point(Point(5., 0.)); // now 1 (1,0) - 2 (2,0) - 0 (5,0)
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 1);
    handles[1]->set_point(Point(3., -1.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 2);
    handles[1]->set_point(Point(3., 1.)); // the one face is now inverted
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 2);
  }
  {
    // A centre and a convex pentagon (its DT is the fan around the centre); the five hull
    // vertices are moved so that, in their combinatorial ccw order, they visit the pentagon
    // in pentagram order: every face is still ccw and every hull turn is a left turn, but the
    // hull winds twice around the centre.
    Scope c("fan of a pentagon, hull moved to wind twice");
    const Points pentagon = {Point(1000, 0), Point(309, 951), Point(-809, 588), Point(-809, -588),
                             Point(309, -951)};
    for(const bool flips : {true, false}) {
      Scope strategy(flips ? "strategy(flips)" : "default strategy");
      Tr tr;
      Handles<Tr> handles;
      Points points = pentagon;
      points.push_back(Point(0, 0));
      build(tr, points, handles);
      make_and_check(tr, handles);
      const auto centre = handles[5];
      DFP_CHECK(tr.degree(centre) == 5);
      auto w = tr.incident_vertices(centre), done = w;
      std::size_t k = 0;
      do
        w->set_point(pentagon[(2 * k++) % 5]);
      while(++w != done);
      DFP_CHECK(inverted_faces(tr) == 0);
      if(flips) {
        const DFP::Statistics s = make_and_check(tr, handles, DFP::parameters::strategy(DFP::Strategy::flips));
        DFP_CHECK(s.fell_back);
      } else {
        make_and_check(tr, handles);
      }
    }
  }
  {
    Scope c("collinear points, a few moved off their line");
    Tr tr;
    Handles<Tr> handles;
    build(tr, to_points<K>(collinear_points(30, rng)), handles);
    DFP_CHECK(tr.dimension() == 1);
    make_and_check(tr, handles);
    handles[3]->set_point(Point(0.5, 40.));
    handles[7]->set_point(Point(-3., -40.));
    make_and_check(tr, handles);
    DFP_CHECK(tr.dimension() == 2);
  }
}

template <class Tr>
std::size_t finite_rank(const Tr& tr, typename Tr::Vertex_handle v)
{
  std::size_t rank = 0;
  for(auto w = tr.finite_vertices_begin(); w != tr.finite_vertices_end(); ++w, ++rank)
    if(&*w == &*v)
      return rank;
  return std::size_t(-1);
}

// Moves handles a and b to p and q (p == q, or one of them the other's current point) and
// expects make_delaunay to throw, naming both vertices, and to leave tr as it was.
template <class Tr>
void expect_collision(Tr& tr, const Handles<Tr>& handles, std::size_t a, std::size_t b,
                      const Point& p, const Point& q)
{
  const Point old_a = handles[a]->point(), old_b = handles[b]->point();
  const Geometry<Point> geometry = geometry_of(tr);
  handles[a]->set_point(p);
  handles[b]->set_point(q);
  const Snapshot<Tr> before(tr);
  const std::size_t rank_a = finite_rank(tr, handles[a]), rank_b = finite_rank(tr, handles[b]);
  bool thrown = false;
  try {
    with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr); });
  } catch(const DFP::Invalid_prediction& e) {
    thrown = true;
    const std::string what = e.what();
    DFP_CHECK_MSG(mentions_number(what, rank_a) && mentions_number(what, rank_b),
                  "ranks " << rank_a << ", " << rank_b << ": " << what);
  }
  DFP_CHECK(thrown);
  check_unchanged(tr, before);
  // Put the points back: the triangulation is the valid one it was before the moves.
  handles[a]->set_point(old_a);
  handles[b]->set_point(old_b);
  DFP_CHECK(tr.is_valid());
  check_handles(tr, handles, current_points(handles));
  const Geometry<Point> after = geometry_of(tr);
  DFP_CHECK(after.vertices == geometry.vertices && after.edges == geometry.edges &&
            after.faces == geometry.faces);
}

template <class Tr>
void test_collisions(const char* name, CGAL::Random& rng)
{
  Scope scope(name, ", two vertices at the same point");
  {
    Scope c("2D, one vertex moved onto another (far apart)");
    Tr tr;
    Handles<Tr> handles;
    build(tr, to_points<K>(uniform_points(300, rng)), handles);
    DFP::make_delaunay(tr);
    expect_collision(tr, handles, 17, 211, handles[211]->point(), handles[211]->point());
    Scope d("then both moved to a new common point");
    expect_collision(tr, handles, 5, 250, Point(0.5, 0.5), Point(0.5, 0.5));
    Scope e("then the two last ranks in finite-vertex order");
    std::vector<typename Tr::Vertex_handle> order;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      order.push_back(v);
    const std::size_t a = std::size_t(std::find(handles.begin(), handles.end(), order[298]) - handles.begin());
    const std::size_t b = std::size_t(std::find(handles.begin(), handles.end(), order[299]) - handles.begin());
    expect_collision(tr, handles, a, b, Point(2., 2.), Point(2., 2.));
    Scope f("then a valid call still works");
    make_and_check(tr, handles);
  }
  {
    Scope c("2D, neighbours moved together, the rest moved too");
    Tr tr;
    Handles<Tr> handles;
    build(tr, to_points<K>(uniform_points(50, rng)), handles);
    const auto v = handles[10];
    const auto w = tr.incident_vertices(v);
    std::size_t b = 0;
    auto c2 = w;
    while(tr.is_infinite(c2))
      ++c2;
    b = std::size_t(std::find(handles.begin(), handles.end(), typename Tr::Vertex_handle(c2)) - handles.begin());
    expect_collision(tr, handles, 10, b, handles[b]->point(), handles[b]->point());
  }
  {
    Scope c("dimension 1");
    Tr tr;
    Handles<Tr> handles;
    build(tr, to_points<K>(collinear_points(10, rng)), handles);
    expect_collision(tr, handles, 2, 8, handles[8]->point(), handles[8]->point());
  }
  {
    Scope c("two vertices (dimension 1 -> would be 0)");
    Tr tr;
    Handles<Tr> handles;
    build(tr, Points{Point(0., 0.), Point(1., 1.)}, handles);
    expect_collision(tr, handles, 0, 1, Point(3., 3.), Point(3., 3.));
  }
  {
    Scope c("three vertices, dimension 2");
    Tr tr;
    Handles<Tr> handles;
    build(tr, Points{Point(0., 0.), Point(1., 0.), Point(0., 1.)}, handles);
    expect_collision(tr, handles, 0, 1, Point(1., 0.), Point(1., 0.)); // 0 onto 1's point
  }
}

// A user's vertex base derived from CGAL's: the vertex objects, and so their members, survive.
template <class Tr>
void test_colored(const char* name, CGAL::Random& rng)
{
  Scope scope(name);
  Tr tr;
  Handles<Tr> handles;
  build(tr, to_points<K>(uniform_points(500, rng)), handles);
  for(std::size_t i = 0; i < handles.size(); ++i)
    handles[i]->color = int(i);
  auto check_colors = [&] {
    bool colors = true;
    for(std::size_t i = 0; i < handles.size(); ++i)
      colors = colors && handles[i]->color == int(i);
    DFP_CHECK(colors);
  };
  make_and_check(tr, handles);
  check_colors();
  move_all<Tr>(handles, [&](const Point& p) {
    return Point(p.x() + rng.get_double(-0.1, 0.1), p.y() + rng.get_double(-0.1, 0.1));
  });
  make_and_check(tr, handles);
  check_colors();
  move_keeping_faces_ccw(tr, handles, 0.01, rng);
  make_and_check(tr, handles);
  check_colors();
}

// The flips make_delaunay makes before its carve (during certification, and untangling) are
// logged, so that a call that ends by reporting two vertices at the same point can undo them.
// When the carve is rolled back, the faces it removed come back as new objects: the log must
// follow them. The carve is committed and rolled back by hand here (the public calls roll back
// only when the filled holes fail the final check, which moved points do not reach), then the
// log is undone: the triangulation must be exactly as it was, face for face.
void test_flip_log_survives_rollback(CGAL::Random& rng)
{
  using Tr = DT_with_info<K>;
  namespace I = DFP::internal;
  std::size_t logged_on_carved_faces = 0;
  for(int round = 0; round < 12; ++round) {
    Scope scope("round " + std::to_string(round));
    Tr tr;
    const Points points = to_points<K>(uniform_points(500 + 200 * round, rng));
    tr.insert(points.begin(), points.end());
    const double spacing = 1. / std::sqrt(double(points.size()));
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      v->set_point(Point(v->point().x() + 0.1 * spacing * rng.get_double(-1, 1),
                         v->point().y() + 0.1 * spacing * rng.get_double(-1, 1)));
    const Snapshot<Tr> before(tr);
    std::vector<std::pair<Tr::Face_handle, int>> stack;
    std::vector<Tr::Face_handle> bad, touched;
    I::Flip_log<Tr> log;
    std::size_t flips = 0, tested = 0;
    bool hull_is_convex = false;
    I::Inline_flips<Tr> inline_flips{tr.number_of_vertices(), flips, touched, log};
    DFP_CHECK(I::certify_faces(tr, stack, tested, hull_is_convex, &bad, tr.number_of_faces(),
                                       &inline_flips) == DFP::Outcome::ok);
    DFP_CHECK(flips > 0 && log.size() == flips);
    I::untangle_by_flips(tr, bad, stack, log, touched);
    DFP_CHECK(!bad.empty());
    I::Carve_repair<Tr> carve(tr, true);
    for(const Tr::Face_handle f : bad)
      carve.carve_star(f->vertex(round % 3));
    const DFP::Outcome why = carve.plan(I::default_carve_limits(tr.number_of_vertices()));
    DFP_CHECK_MSG(why == DFP::Outcome::ok, to_string(why));
    if(why != DFP::Outcome::ok)
      continue;
    carve.commit(stack);
    for(const auto& flip : log)
      logged_on_carved_faces += carve.is_removed(&*flip.first) ? 1 : 0;
    carve.rollback(log);
    I::undo_flips(tr, log);
    DFP_CHECK(tr.tds().is_valid()); // the moved points are not Delaunay: the TDS only
    check_unchanged(tr, before);
  }
  DFP_CHECK(logged_on_carved_faces > 0); // the case the remapping is for did occur
}

// make_delaunay's early decision to rebuild (tds_certify.h, inverted_faces_exceed_early()): a
// triangulation whose sampled faces are mostly inverted is rebuilt before any in-circle test or
// flip; moderate moves are still repaired in place; damage outside the sample, or only inside
// it, steers the call one way or the other, and the result is CGAL's DT either way. Run with
// each concurrency (the rule comes before both certifications).
void test_early_rebuild(CGAL::Random& rng)
{
  using Tr = DT_with_info<K>;
  namespace I = DFP::internal;
  const std::size_t n = 20000; // 40,000 faces: the sample is about 5% of them
  const double spacing = 1. / std::sqrt(double(n));
  const Points points = to_points<K>(uniform_points(n, rng));
  const std::size_t max_bad = I::default_carve_limits(n).max_bad_faces;
  // Builds DT(points), then moves the chosen vertices by Gaussian noise of sigma x spacing.
  auto moved_by = [&](Tr& tr, Handles<Tr>& handles, double sigma, auto chosen) {
    build(tr, points, handles);
    const std::set<const void*> moved = chosen(tr);
    for(std::size_t i = 0; i < n; ++i)
      if(moved.count(&*handles[i]) > 0)
        handles[i]->set_point(Point(points[i].x() + sigma * spacing * gaussian(rng),
                                    points[i].y() + sigma * spacing * gaussian(rng)));
  };
  auto all = [](const Tr& tr) {
    std::set<const void*> every;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      every.insert(&*v);
    return every;
  };
  {
    Scope c("Gaussian moves of 0.5 spacing: rebuilt at once");
    Tr tr;
    Handles<Tr> handles;
    moved_by(tr, handles, 0.5, all);
    DFP_CHECK_MSG(inverted_faces(tr) > 3 * max_bad, inverted_faces(tr) << " inverted, limit " << max_bad);
    DFP_CHECK(I::inverted_faces_exceed_early(tr, max_bad));
    const DFP::Statistics s = make_and_check(tr, handles); // CGAL's DT, same handles and info
    DFP_CHECK(s.fell_back);
    DFP_CHECK_MSG(s.outcome == DFP::Outcome::too_many_inverted_faces, to_string(s.outcome));
    DFP_CHECK_MSG(s.flips == 0 && s.edges_tested == 0, s.flips << " flips, " << s.edges_tested << " edges tested");
    DFP_CHECK(s.faces_carved == 0 && s.points_reinserted == n);
  }
  {
    Scope c("Gaussian moves of 0.5 spacing and two vertices at one point: throws, unchanged");
    Tr tr;
    Handles<Tr> handles;
    moved_by(tr, handles, 0.5, all);
    handles[123]->set_point(handles[4567]->point());
    DFP_CHECK(I::inverted_faces_exceed_early(tr, max_bad));
    const Snapshot<Tr> before(tr);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>(
        [&] { with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr); }); }));
    check_unchanged(tr, before);
  }
  {
    Scope c("Gaussian moves of 0.05 spacing: repaired in place");
    Tr tr;
    Handles<Tr> handles;
    moved_by(tr, handles, 0.05, all);
    DFP_CHECK(inverted_faces(tr) > 0);
    DFP_CHECK(!I::inverted_faces_exceed_early(tr, max_bad));
    const DFP::Statistics s = make_and_check(tr, handles);
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.flips > 0 && s.edges_tested > 0);
  }
  // The sample is the container's first faces: the vertices of those faces.
  auto sampled_vertices = [](const Tr& tr) {
    std::set<const void*> in_sample;
    std::size_t k = 0;
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end() && k < I::inverted_faces_sample; ++f, ++k)
      for(int j = 0; j < 3; ++j)
        in_sample.insert(&*f->vertex(j));
    return in_sample;
  };
  {
    Scope c("only the vertices of the sampled faces moved far: steered to a rebuild, same result");
    Tr tr;
    Handles<Tr> handles;
    std::size_t sampled = 0;
    moved_by(tr, handles, 0.5, [&](const Tr& t) {
      const std::set<const void*> in_sample = sampled_vertices(t);
      sampled = in_sample.size();
      return in_sample;
    });
    DFP_CHECK_MSG(sampled < n / 2, sampled << " vertices in the sampled faces");
    DFP_CHECK(inverted_faces(tr) > 0);
    DFP_CHECK(I::inverted_faces_exceed_early(tr, max_bad));
    const DFP::Statistics s = make_and_check(tr, handles);
    DFP_CHECK(s.fell_back && s.outcome == DFP::Outcome::too_many_inverted_faces && s.flips == 0);
  }
  {
    Scope c("every vertex but those of the sampled faces moved far: caught by the pass, same result");
    Tr tr;
    Handles<Tr> handles;
    moved_by(tr, handles, 0.5, [&](const Tr& t) {
      std::set<const void*> rest = all(t);
      for(const void* v : sampled_vertices(t))
        rest.erase(v);
      return rest;
    });
    DFP_CHECK(inverted_faces(tr) > 3 * max_bad);
    DFP_CHECK(!I::inverted_faces_exceed_early(tr, max_bad));
    const DFP::Statistics s = make_and_check(tr, handles);
    DFP_CHECK(s.fell_back && s.outcome == DFP::Outcome::too_many_inverted_faces);
    DFP_CHECK(s.edges_tested > 0 || current_concurrency() != Concurrency::sequential);
  }
}

template <class Tr>
void test_type(const char* name, CGAL::Random& rng)
{
  DFP_RUN(test_time_steps<Tr>(name, rng));
  DFP_RUN(test_large_budget<Tr>(name, rng));
  DFP_RUN(test_small_dimensions<Tr>(name, rng));
  DFP_RUN(test_collisions<Tr>(name, rng));
}

int main()
{
  CGAL::Random rng(4242);
  // Every call of make_and_check() and expect_collision() with each concurrency: the parallel
  // certification cuts even these small triangulations into blocks of 32 faces or more.
  for_each_concurrency([&] {
    test_type<DT_plain<K>>("Delaunay_triangulation_2 without info", rng);
    test_type<DT_with_info<K>>("Delaunay_triangulation_2 with size_t info", rng);
    test_type<T2_plain<K>>("Triangulation_2 without info", rng);
    test_type<T2_with_info<K, int>>("Triangulation_2 with int info", rng);
  });
  DFP_RUN(test_flip_log_survives_rollback(rng));
  for_each_concurrency([&] { DFP_RUN(test_early_rebuild(rng)); });
  DFP_RUN(test_colored<DT_colored<K>>("Delaunay_triangulation_2 with a user's vertex base", rng));
  DFP_RUN(test_colored<T2_colored<K>>("Triangulation_2 with a user's vertex base", rng));
  {
    Scope scope("Delaunay_triangulation_2 with non-index info");
    DT_labeled<K> tr;
    const Points points = to_points<K>(uniform_points(300, rng));
    tr.insert(points.begin(), points.end());
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      v->set_point(Point(v->point().x() * 2. + rng.get_double(-0.05, 0.05), v->point().y()));
    DFP::make_delaunay(tr);
    check_is_cgal_delaunay(tr, current_points(Handles<DT_labeled<K>>(tr.finite_vertex_handles().begin(), tr.finite_vertex_handles().end())));
    bool labels = true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      labels = labels && v->info().value == -3;
    DFP_CHECK(labels);
  }
  return finish("test_make_delaunay");
}
