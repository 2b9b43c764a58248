// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// CGAL::Triangulation_hierarchy_2 passed to every entry point that fills or repairs a
// triangulation: level 0 is exactly CGAL's Delaunay triangulation, and the upper levels are
// kept as CGAL keeps them: sampled at about the same rate as CGAL's own build of the same
// points (level 1 about n/30), every copy at its vertex's current point and linked both ways,
// each level a valid Delaunay triangulation (is_valid()), locate() answering as on CGAL's
// build. make_delaunay keeps vertex handles and info(); malformed input leaves the hierarchy
// as it was, upper levels included.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_predicted_edges_2.h>
#include <CGAL/Delaunay_from_prediction/brio_dc.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/imprecise_points.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/split.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>

using namespace dfp_test;

template <class K, class Vb>
using Hierarchy_of = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<Vb>>>>;
template <class K>
using Hierarchy_with_info = Hierarchy_of<K, CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>>;
template <class K>
using Hierarchy_plain = Hierarchy_of<K, CGAL::Triangulation_vertex_base_2<K>>;
// A user's class derived from CGAL's hierarchy.
template <class K>
struct Derived_hierarchy : Hierarchy_plain<K>
{
  using Hierarchy_plain<K>::Hierarchy_plain;
  int tag = 7;
};
// A hierarchy over a plain Triangulation_2 (make_delaunay's input may be one).
template <class K>
using T2_hierarchy = CGAL::Triangulation_hierarchy_2<CGAL::Triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<
           CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>>>>>;

static_assert(DFP::internal::is_triangulation_hierarchy<Hierarchy_plain<CGAL::Epick>>::value, "");
static_assert(DFP::internal::is_triangulation_hierarchy<Derived_hierarchy<CGAL::Epick>>::value, "");
static_assert(!DFP::internal::is_triangulation_hierarchy<DT_plain<CGAL::Epick>>::value, "");
static_assert(!DFP::internal::is_triangulation_hierarchy<
                  typename Hierarchy_plain<CGAL::Epick>::Tr_Base>::value, "");

using Edges = std::vector<std::pair<std::size_t, std::size_t>>;

template <class Tr>
Edges edges_by_info(const Tr& tr)
{
  Edges edges;
  if(tr.dimension() >= 1)
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e)
      edges.emplace_back(e->first->vertex(tr.ccw(e->second))->info(), e->first->vertex(tr.cw(e->second))->info());
  return edges;
}

// Number of level-0 vertices with a copy at level >= k, for k = 1..4 (index k).
using Level_sizes = std::array<std::size_t, 5>;

// Checks the up/down links of `h` (every copy at its vertex's point, linked both ways) and
// returns the number of copies per level.
template <class H>
Level_sizes check_upper_levels(const H& h)
{
  Level_sizes sizes{};
  bool points_ok = true, links_ok = true;
  for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v) {
    sizes[0]++;
    typename H::Vertex_handle below = v, up = v->up();
    int level = 1;
    while(up != typename H::Vertex_handle()) {
      links_ok = links_ok && level < 5 && up->down() == below;
      points_ok = points_ok && up->point() == v->point();
      if(level < 5)
        sizes[level]++;
      below = up;
      up = up->up();
      ++level;
    }
  }
  DFP_CHECK_MSG(points_ok, "an upper copy is not at its vertex's current point");
  DFP_CHECK_MSG(links_ok, "an upper copy is not linked to its vertex (up()->down())");
  return sizes;
}

// CGAL's own hierarchy of the same points (range insertion).
template <class K, class Point>
Level_sizes cgal_level_sizes(const std::vector<Point>& points)
{
  Hierarchy_plain<K> reference;
  reference.insert(points.begin(), points.end());
  return check_upper_levels(reference);
}

template <class Point>
std::array<Point, 3> sorted_triple(const std::array<Point, 3>& t)
{
  std::array<Point, 3> s = t;
  std::sort(s.begin(), s.end());
  return s;
}

// Checks that `h` is CGAL's Delaunay triangulation of `points` at level 0, that its upper
// levels are consistent and sampled as CGAL samples them, and that locate() answers as on
// CGAL's own hierarchy of the points.
template <class K, class H>
void check_hierarchy(const H& h, const std::vector<typename K::Point_2>& points, CGAL::Random& rng)
{
  using Point = typename K::Point_2;
  check_is_cgal_delaunay(h, points); // is_valid() of the hierarchy: every level, every link
  const Level_sizes got = check_upper_levels(h);
  const Level_sizes expected = cgal_level_sizes<K>(points);
  DFP_CHECK(got[0] == expected[0]);
  // A vertex has a copy at level 1 with probability 1/30: level 1 of 20,000 vertices has
  // 667 +- 25 copies; the ratio of two such counts is within [0.5, 1.5] unless both are tiny.
  if(expected[1] >= 40)
    DFP_CHECK_MSG(got[1] >= expected[1] / 2 && got[1] <= expected[1] + expected[1] / 2,
                  got[1] << " copies at level 1 against CGAL's " << expected[1]);
  if(got[0] >= 3000) {
    DFP_CHECK_MSG(got[1] > 0, "no upper level for " << got[0] << " vertices");
    DFP_CHECK_MSG(got[1] <= got[0] / 10, got[1] << " copies at level 1 of " << got[0] << " vertices");
  }
  if(expected[2] >= 40)
    DFP_CHECK_MSG(got[2] >= expected[2] / 2 && got[2] <= expected[2] + expected[2] / 2,
                  got[2] << " copies at level 2 against CGAL's " << expected[2]);
  // locate(): the same face as on CGAL's build (level 0 is the same triangulation).
  if(points.size() >= 3 && h.dimension() == 2) {
    Hierarchy_plain<K> reference;
    reference.insert(points.begin(), points.end());
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for(const Point& p : points) {
      xmin = (std::min)(xmin, CGAL::to_double(p.x()));
      xmax = (std::max)(xmax, CGAL::to_double(p.x()));
      ymin = (std::min)(ymin, CGAL::to_double(p.y()));
      ymax = (std::max)(ymax, CGAL::to_double(p.y()));
    }
    std::size_t same = 0, queries = 0;
    for(int k = 0; k < 200; ++k) {
      const Point q = make_point<K>(rng.get_double(xmin, xmax), rng.get_double(ymin, ymax));
      const auto f = h.locate(q);
      const auto g = reference.locate(q);
      if(reference.is_infinite(g)) {
        DFP_CHECK(h.is_infinite(f));
        continue;
      }
      ++queries;
      if(!h.is_infinite(f) &&
         sorted_triple(std::array<Point, 3>{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()}) ==
             sorted_triple(std::array<Point, 3>{g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point()}))
        ++same;
    }
    DFP_CHECK_MSG(same == queries, same << " of " << queries << " queries located in CGAL's face");
  }
}

// Everything a call could change: level 0 (vertex objects, points, info, faces) and the upper
// levels (the copies of each vertex, by address and point).
template <class H>
std::vector<std::string> snapshot(const H& h)
{
  std::vector<std::string> s;
  for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v) {
    std::ostringstream line;
    line.precision(17);
    line << "v " << static_cast<const void*>(&*v) << ' ' << v->point();
    if constexpr(has_vertex_info<H>)
      line << " info " << v->info();
    for(auto u = v->up(); u != typename H::Vertex_handle(); u = u->up())
      line << " up " << static_cast<const void*>(&*u) << ' ' << u->point();
    s.push_back(line.str());
  }
  if(h.dimension() == 2)
    for(auto f = h.finite_faces_begin(); f != h.finite_faces_end(); ++f) {
      std::ostringstream line;
      std::array<const void*, 3> t = {&*f->vertex(0), &*f->vertex(1), &*f->vertex(2)};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      line << "f " << t[0] << ' ' << t[1] << ' ' << t[2];
      s.push_back(line.str());
    }
  std::sort(s.begin(), s.end());
  return s;
}

template <class K>
struct Hierarchy_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  using H = Hierarchy_with_info<K>;
  CGAL::Random rng{4242};
  std::size_t n;

  explicit Hierarchy_test(std::size_t n_) : n(n_) {}

  // A hierarchy holding other points first, with upper levels of its own.
  template <class Tr>
  void prefill(Tr& h)
  {
    Points other = to_points<K>(uniform_points(3000, rng, -3., -2.));
    h.insert(other.begin(), other.end());
  }

  void from_prediction()
  {
    Scope scope("delaunay_from_prediction");
    for(const XYs& xy : {uniform_points(n, rng), clustered_points(n, rng), grid_points(100, n / 100, rng)}) {
      const Points points = to_points<K>(xy);
      const Faces faces = delaunay_faces<K>(points);
      {
        H h;
        DFP::delaunay_from_prediction(points, faces, h);
        check_hierarchy<K>(h, points, rng);
      }
      {
        H h; // reused: its old upper levels must go
        prefill(h);
        DFP::delaunay_from_prediction(points, flipped_delaunay_faces<K>(points, n / 20, rng), h);
        check_hierarchy<K>(h, points, rng);
        // A damaged prediction (local repair), then one that falls back to a rebuild.
        DFP::delaunay_from_prediction(points, with_faces_deleted(faces, n / 50, rng), h);
        check_hierarchy<K>(h, points, rng);
        DFP::delaunay_from_prediction(points, random_triples(points.size(), points.size(), rng), h);
        check_hierarchy<K>(h, points, rng);
      }
      {
        Derived_hierarchy<K> h;
        DFP::delaunay_from_prediction(points, faces, h);
        check_hierarchy<K>(h, points, rng);
        DFP_CHECK(h.tag == 7);
      }
    }
  }

  void predicted_edges()
  {
    Scope scope("delaunay_from_predicted_edges");
    const Points points = to_points<K>(uniform_points(n, rng));
    Edges edges = edges_by_info(indexed_delaunay<K>(points));
    edges.resize(edges.size() - edges.size() / 10); // some edges missing
    H h;
    prefill(h);
    DFP::delaunay_from_predicted_edges(points, edges, h);
    check_hierarchy<K>(h, points, rng);
  }

  void spanning_graph()
  {
    Scope scope("delaunay_from_spanning_graph");
    const Points points = to_points<K>(uniform_points(n, rng));
    const Edges edges = edges_by_info(indexed_delaunay<K>(points));
    H h;
    prefill(h);
    DFP::delaunay_from_spanning_graph(points, edges, h);
    check_hierarchy<K>(h, points, rng);
  }

  void brio_dc()
  {
    Scope scope("brio_dc_delaunay");
    const Points points = to_points<K>(clustered_points(n, rng));
    H h;
    prefill(h);
    DFP::brio_dc_delaunay(points, h);
    check_hierarchy<K>(h, points, rng);
  }

  void imprecise()
  {
    Scope scope("Imprecise_points_2::triangulate");
    const Points centres = to_points<K>(uniform_points(n, rng, 0., 100.));
    const DFP::Imprecise_points_2<K> disks(centres, typename K::FT(0.3));
    Points instance;
    for(const Point& c : centres)
      instance.push_back(make_point<K>(CGAL::to_double(c.x()) + rng.get_double(-0.2, 0.2),
                                       CGAL::to_double(c.y()) + rng.get_double(-0.2, 0.2)));
    H h;
    prefill(h);
    disks.triangulate(instance, h);
    check_hierarchy<K>(h, instance, rng);
  }

  void split()
  {
    Scope scope("split_delaunay");
    const Points points = to_points<K>(uniform_points(n, rng));
    Hierarchy_plain<K> input;
    input.insert(points.begin(), points.end());
    auto in_first = [](typename Hierarchy_plain<K>::Vertex_handle v) { return v->point().x() < 0.3; };
    Points first, second;
    for(const Point& p : points)
      (p.x() < 0.3 ? first : second).push_back(p);
    for(auto method : {DFP::Split_method::ordered, DFP::Split_method::randomized}) {
      Hierarchy_plain<K> h1;
      Derived_hierarchy<K> h2;
      prefill(h1);
      DFP::split_delaunay(input, in_first, h1, h2, DFP::parameters::split_method(method));
      check_hierarchy<K>(h1, first, rng);
      check_hierarchy<K>(h2, second, rng);
      DFP_CHECK(input.is_valid());
      // One output a hierarchy, the other not.
      DT_plain<K> plain;
      DFP::split_delaunay(input, in_first, plain, h1, DFP::parameters::split_method(method));
      check_is_cgal_delaunay(plain, first);
      check_hierarchy<K>(h1, second, rng);
    }
    // A user's exception from is_in_first, or aliased outputs: nothing changed.
    const auto before = snapshot(input);
    Hierarchy_plain<K> h1, h2;
    prefill(h1);
    const auto before1 = snapshot(h1);
    DFP_CHECK(throws_exception<std::runtime_error>([&] {
      DFP::split_delaunay(input, [](auto) -> bool { throw std::runtime_error("user"); }, h1, h2);
    }));
    DFP_CHECK(snapshot(h1) == before1);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::split_delaunay(input, in_first, h1, h1); }));
    DFP_CHECK(snapshot(h1) == before1);
    DFP_CHECK(h1.is_valid());
    DFP_CHECK(snapshot(input) == before);
  }

  // make_delaunay after moves: the same vertex objects and info(), upper copies moved along.
  template <class Tr>
  void moved(double amplitude, const XYs& xy)
  {
    Tr h;
    const Points points = to_points<K>(xy);
    for(std::size_t i = 0; i < points.size(); ++i)
      h.insert(points[i])->info() = i; // CGAL's own hierarchy insertion
    std::vector<typename Tr::Vertex_handle> vertex_of(points.size());
    for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v)
      vertex_of[v->info()] = v;
    Points moved_points(points.size());
    for(std::size_t i = 0; i < points.size(); ++i) {
      moved_points[i] = make_point<K>(CGAL::to_double(points[i].x()) + rng.get_double(-amplitude, amplitude),
                                      CGAL::to_double(points[i].y()) + rng.get_double(-amplitude, amplitude));
      vertex_of[i]->set_point(moved_points[i]);
    }
    DFP::make_delaunay(h);
    bool same_objects = h.number_of_vertices() == points.size();
    for(std::size_t i = 0; i < points.size(); ++i)
      same_objects = same_objects && vertex_of[i]->info() == i && vertex_of[i]->point() == moved_points[i];
    std::size_t count = 0;
    for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v)
      count += vertex_of[v->info()] == typename Tr::Vertex_handle(v) ? 1 : 0;
    DFP_CHECK_MSG(same_objects && count == points.size(), "make_delaunay changed the vertex objects or info()");
    check_hierarchy<K>(h, moved_points, rng);
  }

  void make_delaunay()
  {
    Scope scope("make_delaunay");
    const double spacing = 1. / std::sqrt(double(n));
    for(double move : {0.1, 0.5, 3.}) {
      Scope s2("move " + std::to_string(move));
      moved<H>(move * spacing, uniform_points(n, rng));
    }
    moved<T2_hierarchy<K>>(0.2 * spacing, uniform_points(n, rng));
  }

  void bad_input()
  {
    Scope scope("bad input leaves the hierarchy unchanged");
    const Points points = to_points<K>(uniform_points(500, rng));
    Faces faces = delaunay_faces<K>(points);
    H h;
    prefill(h);
    const auto before = snapshot(h);
    Faces bad = faces;
    bad[7][1] = points.size();
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::delaunay_from_prediction(points, bad, h); }));
    DFP_CHECK(snapshot(h) == before);
    Points nan_points = points;
    nan_points[3] = make_point<K>(std::nan(""), 0.);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::delaunay_from_prediction(nan_points, faces, h); }));
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::brio_dc_delaunay(nan_points, h); }));
    DFP_CHECK(throws_exception<std::invalid_argument>(
        [&] { DFP::brio_dc_delaunay(points, h, DFP::parameters::sample_probability(2.)); }));
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>(
        [&] { DFP::delaunay_from_spanning_graph(points, Edges{{0, points.size()}}, h); }));
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>(
        [&] { DFP::delaunay_from_predicted_edges(points, Edges{{0, 0}}, h); }));
    const DFP::Imprecise_points_2<K> disks(points, typename K::FT(0.1));
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { disks.triangulate(nan_points, h); }));
    DFP_CHECK(snapshot(h) == before);
    DFP_CHECK(h.is_valid());

    // make_delaunay with two vertices moved to the same point.
    H g;
    for(std::size_t i = 0; i < points.size(); ++i)
      g.insert(points[i])->info() = i;
    auto v = g.finite_vertices_begin();
    auto w = std::next(v, 10);
    w->set_point(v->point());
    const auto moved = snapshot(g);
    DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::make_delaunay(g); }));
    DFP_CHECK(snapshot(g) == moved);
  }

  void degenerate()
  {
    Scope scope("degenerate inputs");
    for(std::size_t m : {0, 1, 2, 3, 4}) {
      Scope s2("n = " + std::to_string(m));
      const Points points = to_points<K>(uniform_points(m, rng));
      H h;
      prefill(h);
      DFP::delaunay_from_prediction(points, delaunay_faces<K>(points), h);
      check_hierarchy<K>(h, points, rng);
      H g;
      DFP::delaunay_from_prediction(points, Faces(), g);
      check_hierarchy<K>(g, points, rng);
      DFP::brio_dc_delaunay(points, g);
      check_hierarchy<K>(g, points, rng);
      DFP::make_delaunay(g);
      check_hierarchy<K>(g, points, rng);
    }
    {
      Scope s2("collinear");
      const Points points = to_points<K>(collinear_points(5000, rng));
      H h;
      prefill(h);
      DFP::delaunay_from_prediction(points, Faces(), h);
      check_hierarchy<K>(h, points, rng);
      DFP_CHECK(h.dimension() == 1);
      // Moved off their line: dimension 2.
      Points moved = points;
      for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v) {
        moved[v->info()] = make_point<K>(CGAL::to_double(v->point().x()) + rng.get_double(-1e-3, 1e-3),
                                         CGAL::to_double(v->point().y()) + rng.get_double(-1e-3, 1e-3));
        v->set_point(moved[v->info()]);
      }
      DFP::make_delaunay(h);
      DFP_CHECK(h.dimension() == 2);
      check_hierarchy<K>(h, moved, rng);
    }
    {
      Scope s2("duplicates");
      const Points points = to_points<K>(with_duplicates(uniform_points(n, rng), n / 10, rng));
      H h;
      DFP::delaunay_from_prediction(points, delaunay_faces<K>(points), h);
      check_hierarchy<K>(h, points, rng);
      DFP::brio_dc_delaunay(points, h);
      check_hierarchy<K>(h, points, rng);
    }
  }

  void run_all()
  {
    DFP_RUN(from_prediction());
    DFP_RUN(predicted_edges());
    DFP_RUN(spanning_graph());
    DFP_RUN(brio_dc());
    DFP_RUN(imprecise());
    DFP_RUN(split());
    DFP_RUN(make_delaunay());
    DFP_RUN(bad_input());
    DFP_RUN(degenerate());
  }
};

int main()
{
  {
    Scope scope("Epick");
    Hierarchy_test<CGAL::Epick>(20000).run_all();
  }
  {
    Scope scope("Epeck");
    Hierarchy_test<CGAL::Epeck> t(3000);
    DFP_RUN(t.from_prediction());
    DFP_RUN(t.make_delaunay());
    DFP_RUN(t.degenerate());
  }
  return finish("test_hierarchy");
}
