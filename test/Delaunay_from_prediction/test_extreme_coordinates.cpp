// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Coordinates at the ends of the double range: squared distances of coordinates near 1e+-300
// overflow to inf or underflow to 0, widths of boxes overflow (points at -1e308 and +1e308)
// or are subnormal. Every entry point that computes in double (BrioDC's nearest-neighbour
// graphs, the grids of the imprecise points, of the split and of the spanning-graph insertion,
// the hint searches, the noise of moved_points_prediction) is run at scales 2^-1074
// (subnormal), 2^-1022, 1e-300, 1, 1e150, 1e300 and 1.7e308, and on mixed sets (points at
// -1e308 and +1e308, a huge offset with a small spread), on uniform points, a co-circular
// grid, collinear points, duplicates and 0..4 points. Each result is compared with CGAL's
// Delaunay_triangulation_2 (Epick) built from scratch, as index triples; the proximity graphs
// with brute force.

#include <CGAL/Delaunay_from_prediction/brio_dc.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/imprecise_points.h>
#include <CGAL/Delaunay_from_prediction/measures.h>
#include <CGAL/Delaunay_from_prediction/prediction_models.h>
#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Delaunay_from_prediction/split.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>

using namespace dfp_test;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Points = std::vector<Point>;
using Edge = std::pair<std::size_t, std::size_t>;
using Edges = std::vector<Edge>;

namespace {

CGAL::Random rng{20261201};

// The points of `xy` with each coordinate scaled by `scale` then moved by `offset` (rounded
// to double: duplicates may appear at subnormal scales, and are expected to be handled).
Points scaled(const XYs& xy, double scale, double offset = 0)
{
  Points points;
  for(const XY& p : xy)
    points.emplace_back(p.x * scale + offset, p.y * scale + offset);
  return points;
}

// Integer points, shuffled: exact at every scale a power of two away (subnormals included).
XYs integer_points(std::size_t n, int range)
{
  XYs xy;
  for(std::size_t i = 0; i < n; ++i)
    xy.push_back({double(rng.get_int(0, range)), double(rng.get_int(0, range))});
  return xy;
}

// The finite faces of `tr` as sorted canonical triples of vertex info.
template <class Tr>
Faces info_faces(const Tr& tr)
{
  Faces faces;
  if(tr.dimension() == 2)
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
      faces.push_back(canonical(Face{std::size_t(f->vertex(0)->info()), std::size_t(f->vertex(1)->info()),
                                     std::size_t(f->vertex(2)->info())}));
  std::sort(faces.begin(), faces.end());
  return faces;
}

// ----- BrioDC ---------------------------------------------------------------------------------

void brio_dc(const Points& points)
{
  Scope s("brio_dc_delaunay");
  DT_with_info<K> dt;
  const DFP::Statistics st = DFP::brio_dc_delaunay(points, dt);
  check_is_cgal_delaunay(dt, points);
  DFP_CHECK_MSG(st.duplicate_points == points.size() - dt.number_of_vertices(),
                st.duplicate_points << " duplicates, " << dt.number_of_vertices() << " vertices, " << points.size()
                                    << " points");
  DFP_CHECK(st.points_reinserted == points.size());
}

// The nearest-neighbour graph on the coordinates as doubles: a neighbour for every point,
// never itself; with `exact`, against brute force with the kernel's exact comparison of
// distances (ties: any nearest point will do). Points closer than 2^-511 of their box tie in
// double: on such sets the graph is approximate (only the insertion order depends on it).
void nearest_neighbours(const Points& points, bool exact)
{
  Scope s("nearest_neighbour_graph");
  const std::size_t m = points.size();
  std::vector<double> xy;
  for(const Point& p : points) {
    xy.push_back(p.x());
    xy.push_back(p.y());
  }
  std::vector<std::uint32_t> order, nn;
  DFP::internal::nearest_neighbour_graph(xy.data(), m, order, nn);
  DFP_CHECK(order.size() == m && nn.size() == m);
  std::vector<std::uint32_t> sorted(order);
  std::sort(sorted.begin(), sorted.end());
  bool permutation = true;
  for(std::size_t k = 0; k < sorted.size(); ++k)
    permutation = permutation && sorted[k] == k;
  DFP_CHECK(permutation);
  if(m == 1)
    DFP_CHECK(nn[0] == DFP::internal::no_rank);
  if(!permutation || m < 2)
    return;
  auto compare_distance = K().compare_distance_2_object();
  std::size_t wrong = 0, out_of_range = 0;
  for(std::size_t k = 0; k < m; ++k) {
    if(nn[k] >= m || nn[k] == k) {
      ++out_of_range;
      continue;
    }
    if(!exact)
      continue;
    const Point& p = points[order[k]];
    const Point& q = points[order[nn[k]]];
    for(std::size_t j = 0; j < m; ++j)
      if(j != k && compare_distance(p, points[order[j]], p, q) == CGAL::SMALLER) {
        ++wrong;
        break;
      }
  }
  DFP_CHECK_MSG(out_of_range == 0, out_of_range << " points without a neighbour or their own neighbour");
  DFP_CHECK_MSG(wrong == 0, wrong << " of " << m << " neighbours not nearest");
}

// ----- Imprecise points -------------------------------------------------------------------

void imprecise(const Points& points, double radius)
{
  Scope s("Imprecise_points_2, radius ", radius);
  for(const DFP::Disk_order order : {DFP::Disk_order::spatial, DFP::Disk_order::random}) {
    Scope so(order == DFP::Disk_order::spatial ? "spatial order" : "random order");
    const DFP::Imprecise_points_2<K> disks(points, K::FT(radius), DFP::parameters::disk_order(order));
    // The instance: the centres themselves, and the centres in reverse (points far from their disks).
    for(bool reversed : {false, true}) {
      Scope si(reversed ? "reversed instance" : "centres as instance");
      const Points instance = reversed ? Points(points.rbegin(), points.rend()) : points;
      DT_with_info<K> dt;
      const DFP::Statistics st = disks.triangulate(instance, dt);
      check_is_cgal_delaunay(dt, instance);
      DFP_CHECK(st.duplicate_points == instance.size() - dt.number_of_vertices());
    }
  }
}

// Imprecise_points_2::contains() where squares of distances overflow or underflow in double.
void disk_containment()
{
  for(const double unit : {1e200, 1e-200, std::ldexp(1.0, -1070), 1e307}) {
    Scope s("contains() at ", unit);
    const Points centres = {Point(0, 0), Point(4 * unit, 0)};
    const DFP::Imprecise_points_2<K> disks(centres, K::FT(unit));
    DFP_CHECK(disks.contains(0, Point(unit, 0)));      // on the circle
    DFP_CHECK(disks.contains(0, Point(0, -unit)));     // on the circle
    DFP_CHECK(!disks.contains(0, Point(2 * unit, 0))); // outside
    DFP_CHECK(!disks.contains(0, Point(unit, unit)));  // outside
    DFP_CHECK(disks.contains(1, Point(4 * unit, unit / 2)));
    DFP_CHECK(!disks.contains(1, Point(-4 * unit, 0)));
  }
}

// ----- Split ------------------------------------------------------------------------------

void split(const Points& points)
{
  Scope s("split_delaunay");
  const DT_with_info<K> dt = indexed_delaunay<K>(points);
  for(const DFP::Split_method method : {DFP::Split_method::ordered, DFP::Split_method::randomized}) {
    Scope sm(method == DFP::Split_method::ordered ? "ordered" : "randomized");
    DT_with_info<K> dt1, dt2;
    auto in_first = [](DT_with_info<K>::Vertex_handle v) { return (v->info() * 7 % 3) != 0; };
    DFP::split_delaunay(dt, in_first, dt1, dt2, DFP::parameters::split_method(method));
    for(int part = 0; part < 2; ++part) {
      Scope sp("part ", part + 1);
      std::vector<std::pair<Point, std::size_t>> sub;
      for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        if(in_first(v) == (part == 0))
          sub.emplace_back(v->point(), v->info());
      DT_with_info<K> reference;
      reference.insert(sub.begin(), sub.end());
      const DT_with_info<K>& got = part == 0 ? dt1 : dt2;
      DFP_CHECK(got.is_valid());
      DFP_CHECK_MSG(got.number_of_vertices() == sub.size(), got.number_of_vertices() << " vs " << sub.size());
      DFP_CHECK(got.dimension() == reference.dimension());
      DFP_CHECK(info_faces(got) == info_faces(reference));
    }
  }
}

// ----- Spanning graph and proximity graphs --------------------------------------------------

std::vector<std::size_t> representatives(const Points& points)
{
  const auto first = smallest_indices(points);
  std::vector<std::size_t> rep(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    rep[i] = first.at(points[i]);
  return rep;
}

void spanning_graph(const Points& points)
{
  Scope s("delaunay_from_spanning_graph");
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  shuffle(order, rng);
  Edges path, chain;
  for(std::size_t k = 1; k < n; ++k) {
    path.emplace_back(order[k - 1], order[k]);
    chain.emplace_back(k - 1, k);
  }
  for(const Edges* edges : {&path, &chain}) {
    Scope se(edges == &path ? "random path" : "chain in input order");
    DT_with_info<K> dt;
    const DFP::Statistics st = DFP::delaunay_from_spanning_graph(points, *edges, dt);
    check_is_cgal_delaunay(dt, points);
    DFP_CHECK(st.duplicate_points == n - dt.number_of_vertices());
  }
}

// EMST, RNG and Gabriel graph against brute force over all pairs of representatives (exact
// comparisons of the kernel), from a path in random order as the prediction.
void proximity_graphs(const Points& points)
{
  Scope s("proximity graphs");
  const std::size_t n = points.size();
  const auto rep = representatives(points);
  Edges pairs;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(rep[i] == i && rep[j] == j)
        pairs.emplace_back(i, j);
  K kernel;
  auto cmp = kernel.compare_distance_2_object();
  auto angle = kernel.angle_2_object();
  auto equal = kernel.equal_2_object();
  // EMST: Kruskal under the documented order (exact length, then the pair).
  Edges sorted = pairs, expected_emst;
  std::sort(sorted.begin(), sorted.end(), [&](const Edge& a, const Edge& b) {
    const auto c = cmp(points[a.first], points[a.second], points[b.first], points[b.second]);
    return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
  });
  DFP::internal::Union_find sets(n);
  for(std::size_t i = 0; i < n; ++i)
    if(rep[i] != i && sets.join(i, rep[i]))
      expected_emst.emplace_back(rep[i], i);
  for(const Edge& e : sorted)
    if(sets.join(e.first, e.second))
      expected_emst.push_back(e);
  std::sort(expected_emst.begin(), expected_emst.end());
  Edges expected_rng, expected_gabriel;
  for(const Edge& e : pairs) {
    const Point& p = points[e.first];
    const Point& q = points[e.second];
    bool rng_empty = true, gabriel_empty = true;
    for(std::size_t r = 0; r < n; ++r) {
      const Point& x = points[r];
      rng_empty = rng_empty && !(cmp(p, x, p, q) == CGAL::SMALLER && cmp(q, x, q, p) == CGAL::SMALLER);
      gabriel_empty = gabriel_empty && (equal(x, p) || equal(x, q) || angle(p, x, q) == CGAL::ACUTE);
    }
    if(rng_empty)
      expected_rng.push_back(e);
    if(gabriel_empty)
      expected_gabriel.push_back(e);
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  shuffle(order, rng);
  Edges path;
  for(std::size_t k = 1; k < n; ++k)
    path.emplace_back(order[k - 1], order[k]);
  Edges emst, rng_graph, gabriel;
  DFP::euclidean_minimum_spanning_tree_from_prediction(points, path, std::back_inserter(emst));
  DFP::relative_neighborhood_graph_from_prediction(points, path, std::back_inserter(rng_graph));
  DFP::gabriel_graph_from_prediction(points, path, std::back_inserter(gabriel));
  DFP_CHECK_MSG(emst == expected_emst, emst.size() << " edges vs " << expected_emst.size());
  DFP_CHECK_MSG(rng_graph == expected_rng, rng_graph.size() << " edges vs " << expected_rng.size());
  DFP_CHECK_MSG(gabriel == expected_gabriel, gabriel.size() << " edges vs " << expected_gabriel.size());
}

// ----- Prediction models and measures -----------------------------------------------------

void models_and_measures(const Points& points)
{
  Scope s("prediction models and measures");
  const Faces expected = delaunay_faces<K>(points);
  Faces exact;
  for(const auto& f : DFP::delaunay_triangles(points))
    exact.push_back({std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])});
  {
    // No noise: the points where they are, whatever the spacing computed in double.
    Scope sm("moved_points_prediction, noise 0");
    Faces moved;
    DFP_CHECK(survives([&] { DFP::moved_points_prediction(points, 0.0, 7); }));
    for(const auto& f : DFP::moved_points_prediction(points, 0.0, 7))
      moved.push_back(canonical(Face{std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])}));
    Faces reference;
    for(const Face& f : exact)
      reference.push_back(canonical(f));
    std::sort(moved.begin(), moved.end());
    std::sort(reference.begin(), reference.end());
    DFP_CHECK(moved == reference);
  }
  {
    // With noise: a prediction of the right points (finite, in range), whatever the scale.
    Scope sm("moved_points_prediction, noise 0.3");
    DFP_CHECK(survives([&] {
      for(const auto& f : DFP::moved_points_prediction(points, 0.3, 7))
        for(int j = 0; j < 3; ++j)
          if(std::size_t(f[j]) >= points.size())
            throw std::logic_error("index out of range");
    }));
  }
  if(!exact.empty()) { // (below dimension 2 DT(P)'s edges are not in a list of faces)
    Scope sm("prediction_measures of DT(P)");
    const DFP::Prediction_measures m = DFP::prediction_measures(points, exact);
    DFP_CHECK(m.D == 0 && m.D_missing == 0 && m.D_local == 0 && m.D_cross == 0 && m.D_vio == 0);
  }
  (void)expected;
}

// ----- The point sets at every scale --------------------------------------------------------

// A named point set generator: points in about [0, 1)^2 (or integers, scaled to that box).
struct Shape
{
  const char* name;
  XYs xy;
  double unit; // the coordinates of xy are multiples of unit times small integers
};

std::vector<Shape> shapes()
{
  std::vector<Shape> s;
  s.push_back({"uniform integers (0..999)^2, 500 points", integer_points(500, 1000), 1.0 / 1024});
  s.push_back({"grid 20 x 20 (co-circular)", grid_points(20, 20, rng), 1.0 / 32});
  s.push_back({"collinear, 100 points", collinear_points(100, rng), 1.0 / 256});
  s.push_back({"duplicates", with_duplicates(integer_points(200, 64), 60, rng), 1.0 / 64});
  s.push_back({"all equal, 80 points", XYs(80, XY{3., 5.}), 1.0 / 8});
  for(std::size_t n = 0; n <= 4; ++n)
    s.push_back({"few points", integer_points(n, 16), 1.0 / 16});
  s.push_back({"three collinear", XYs{{0., 0.}, {1., 1.}, {3., 3.}}, 1.0 / 4});
  s.push_back({"four co-circular", XYs{{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}}, 1.0 / 2});
  return s;
}

// Runs `body` in a child process, where a crash (the reported failure was a SIGSEGV) cannot
// take the other cases down; its failed checks print there and count as one failure here.
template <class F>
void isolated(const char* what, const F& body)
{
#if defined(__unix__) || defined(__APPLE__)
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if(child == 0) {
    const int before = failures();
    DFP_RUN(body());
    std::cerr.flush();
    std::_Exit(failures() == before ? 0 : 3);
  }
  if(child > 0) {
    int status = 0;
    waitpid(child, &status, 0);
    DFP_CHECK_MSG(WIFEXITED(status) && WEXITSTATUS(status) == 0,
                  what << (WIFSIGNALED(status) ? ": crashed (signal " : ": failed (status ")
                       << (WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status)) << ")");
    return;
  }
#endif
  DFP_RUN(body());
}

// With an argument, only the cases whose name contains it run.
std::string only;

// Runs every entry point on `points`; proximity graphs only on small sets (brute force).
void all_entry_points(const Points& points, bool exact_neighbours = true)
{
  if(where().find(only) == std::string::npos)
    return;
  isolated("brio_dc_delaunay", [&] { brio_dc(points); });
  isolated("nearest_neighbour_graph", [&] { nearest_neighbours(points, exact_neighbours); });
  isolated("Imprecise_points_2", [&] {
    imprecise(points, 0.0);
    imprecise(points, 1e308); // the box of the disks overflows
  });
  isolated("split_delaunay", [&] { split(points); });
  isolated("delaunay_from_spanning_graph", [&] { spanning_graph(points); });
  isolated("prediction models and measures", [&] { models_and_measures(points); });
  if(points.size() <= 120)
    isolated("proximity graphs", [&] { proximity_graphs(points); });
}

void scales()
{
  struct Scale
  {
    const char* name;
    double factor; // the box side
  };
  const Scale list[] = {{"2^-1074 (subnormal)", std::ldexp(1.0, -1074)},
                        {"2^-1022", std::ldexp(1.0, -1022)},
                        {"1e-300", 1e-300},
                        {"1", 1.0},
                        {"1e150", 1e150},
                        {"1e300", 1e300},
                        {"1.7e308", 1.7e308}};
  for(const Shape& shape : shapes()) {
    for(const Scale& scale : list) {
      // Integer coordinates times a power of two stay exact (at subnormal scales each integer
      // is a multiple of 2^-1074); otherwise the box side is `factor`.
      const double factor = scale.factor == std::ldexp(1.0, -1074) ? scale.factor : scale.factor * shape.unit;
      Scope s(shape.name, " (", shape.xy.size(), " points) at scale ", scale.name);
      all_entry_points(scaled(shape.xy, factor));
    }
    {
      Scope s(shape.name, " (", shape.xy.size(), " points) spread over about [-0.85e308, 0.85e308]");
      // The coordinates times unit are in about [0, 1): the box's width overflows a double.
      all_entry_points(scaled(shape.xy, 1.7e308 * shape.unit, -0.85e308));
    }
    {
      Scope s(shape.name, " (", shape.xy.size(), " points) offset by 1e15 with spread 1");
      all_entry_points(scaled(shape.xy, shape.unit, 1e15));
    }
  }
}

// ----- The reported failures ----------------------------------------------------------------

// 65 points (i * 1e160, (i*i % 7) * 1e160): every squared distance overflows to inf.
void overflowing_distances()
{
  Scope s("65 points (i * 1e160, (i*i % 7) * 1e160)");
  Points points;
  for(int i = 0; i < 65; ++i)
    points.emplace_back(i * 1e160, (i * i % 7) * 1e160);
  all_entry_points(points);
}

// An integer grid scaled by 2^-1020: every squared distance underflows to 0.
void underflowing_distances()
{
  Scope s("grid 30 x 30 scaled by 2^-1020");
  Points points;
  for(int i = 0; i < 30; ++i)
    for(int j = 0; j < 30; ++j)
      points.emplace_back(std::ldexp(double((i * 17) % 30), -1020), std::ldexp(double(j), -1020));
  all_entry_points(points);
}

// Points near both ends of the range and subnormal ones near 0: the box's width overflows,
// and the subnormal points are closer than 2^-511 of it (their nearest neighbours in double
// are approximate).
void mixed_magnitudes()
{
  Scope s("mixed magnitudes");
  const double big = std::numeric_limits<double>::max();
  XYs xy = uniform_points(300, rng, -1., 1.);
  Points points;
  for(const XY& p : xy)
    points.emplace_back(p.x * big, p.y * big);
  for(int i = 0; i < 40; ++i) // a cluster of tiny and subnormal points near the origin
    points.emplace_back(std::ldexp(double(i % 7), -1074 + i), std::ldexp(double(i / 7), -1060));
  points.emplace_back(big, big);
  points.emplace_back(-big, -big);
  points.emplace_back(-big, big);
  points.emplace_back(big, -big);
  all_entry_points(points, false);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc > 1)
    only = argv[1];
  DFP_RUN(overflowing_distances());
  DFP_RUN(underflowing_distances());
  DFP_RUN(mixed_magnitudes());
  DFP_RUN(disk_containment());
  DFP_RUN(scales());
  return finish("test_extreme_coordinates");
}
