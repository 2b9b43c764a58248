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

#include <array>
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


// Subnormal points (fuzzer cases, minimized) whose nearest-neighbour grids, computed on the
// unscaled coordinates, had cells of width 0 and millions of them: each search went round
// ring after empty ring (> 20 s at 76 points).
void subnormal_neighbour_grids()
{
  Scope s("subnormal neighbour grids");
  const std::vector<std::pair<unsigned, std::vector<std::array<double, 2>>>> cases = {
      {157431748u, {{1.5038442955910648e-308, 1.5653886974005242e-308}, {7.7890412934893166e-309, -1.237125840173489e-308}, {7.7760238377627412e-309, -1.2279710749896235e-308}, {1.5035605586868461e-308, 1.6248722644167508e-308}, {-1.7116676437437303e-309, 9.1375117466326603e-309}, {1.4909709025822015e-308, 1.5669693756457542e-308}, {7.7783934139081105e-309, -1.2322796240605715e-308}, {-2.6117988651724765e-309, 9.1574960246720141e-309}, {7.7716067209065787e-309, -1.2325657740855323e-308}, {-2.2726392642119741e-309, 9.0096506477984101e-309}, {-1.8986486629375371e-309, 9.517950715033131e-309}, {1.5291783064190425e-308, 1.580402751504509e-308}, {-2.5772690458998984e-309, 9.4117402620528798e-309}, {-2.6100457047185598e-309, 9.1548793031678574e-309}, {1.4835176184837403e-308, 1.5412030274459981e-308}, {7.7590157876093556e-309, -1.2342330137513997e-308}, {-2.7359445410145469e-309, 9.2795893234927709e-309}, {1.5811201449725201e-308, 1.5900892821549643e-308}, {7.8037750746794012e-309, -1.2321813442131461e-308}, {7.8410122150964875e-309, -1.2320720974830481e-308}, {-2.1212431602510346e-309, 9.383133328071311e-309}, {7.7636209814518608e-309, -1.2308131212516229e-308}, {7.7690789058429431e-309, -1.230285190634081e-308}, {7.7653694098301886e-309, -1.2311466243433583e-308}, {1.4934771341422505e-308, 1.6192728971000034e-308}, {-2.0082131396067354e-309, 9.1697971636473827e-309}, {-2.1883414313830264e-309, 9.5908907600349411e-309}, {-2.6339587831130689e-309, 8.4539334982297528e-309}, {1.5292231606946479e-308, 1.5509031236133829e-308}, {-2.5233727656168519e-309, 9.0152124563756041e-309}, {7.7527848662929503e-309, -1.2292627167144365e-308}, {1.4995606456116237e-308, 1.6157367080862126e-308}, {1.5770588676397291e-308, 1.5655479608123186e-308}, {1.4301254393013208e-308, 1.4618695891461532e-308}, {7.796825250606913e-309, -1.2299956395785178e-308}, {7.8034786734904831e-309, -1.235975121446586e-308}, {-1.4543970388669159e-309, 9.0448408007674617e-309}, {1.5278890775657624e-308, 1.5592395504915508e-308}, {1.4337600860834558e-308, 1.6807006295926328e-308}, {1.499061715392888e-308, 1.6133257523817804e-308}, {1.47420648405813e-308, 1.5717105240286859e-308}, {-2.0789857734680384e-309, 9.3157499040135296e-309}, {7.8110236769253872e-309, -1.2299792934977839e-308}, {7.7799696263246078e-309, -1.2297673681962534e-308}, {7.7685155441103399e-309, -1.2308624164778636e-308}, {1.4889425197079983e-308, 1.5038810258665016e-308}, {7.7695674379035466e-309, -1.2284984902664125e-308}, {-1.9293185889370703e-309, 8.6615118318497791e-309}, {7.7643091482214595e-309, -1.2290639446840826e-308}, {-2.4949504400670838e-309, 9.2893248417363311e-309}, {-2.0150050193990457e-309, 9.4355827807157721e-309}, {7.8106737325242423e-309, -1.2328867337297506e-308}, {7.7753131428378404e-309, -1.2330742863662193e-308}, {-2.6242937986722048e-309, 8.8928125851529245e-309}, {1.5125606660755058e-308, 1.4841475214168318e-308}, {7.7956332011114379e-309, -1.2352366682756128e-308}, {1.5337882218356245e-308, 1.6231201597878673e-308}, {-2.097958922188277e-309, 9.0966427064251459e-309}, {-2.1063390173277501e-309, 9.5614952207486148e-309}, {-1.8560162732970591e-309, 8.6892909044688581e-309}, {1.520488092528001e-308, 1.4730666667412273e-308}, {1.4727474634178147e-308, 1.5285084233250908e-308}, {7.7952653133934739e-309, -1.2332970183732709e-308}, {-2.3372817122351524e-309, 9.2037178946761268e-309}, {1.519676832369271e-308, 1.619815553303665e-308}, {1.4154996839688055e-308, 1.5189296253768203e-308}, {-1.7538817273373608e-309, 9.7179655141900916e-309}, {-2.275160527371106e-309, 9.2003538522967902e-309}, {-2.6148457388719143e-309, 8.4919630998896616e-309}, {-1.8052555094869957e-309, 9.1563137193598412e-309}, {7.7919099611009682e-309, -1.2316788330794688e-308}, {1.5327709708997325e-308, 1.6169582670899506e-308}, {1.4682064677783896e-308, 1.5722784892462893e-308}, {7.8142682973145382e-309, -1.2287918679013579e-308}, {7.8129396902186097e-309, -1.2300229809572044e-308}, {1.4832931840554851e-308, 1.5046690065369042e-308}}},
      {0u, {{1.5118040648800202e-306, -5.3243180441501179e-307}, {2.9523243891861714e-307, -1.3382014126029243e-306}, {-8.4364341514879084e-307, 1.1717518433583517e-306}, {-8.2434864841617451e-307, 1.174096518370603e-306}, {9.0130007650136102e-307, -2.4003946363046627e-307}, {1.0459031936881988e-306, -4.5855851514307072e-307}, {1.5865553931816437e-306, -1.034061221443193e-306}, {1.351687712357111e-306, -5.3908323577664451e-307}, {-8.6863588447152328e-307, 1.1234800668489393e-306}, {1.0885119228998139e-306, -5.6737541330957603e-307}, {1.1466739478846749e-306, -2.6533911154346896e-307}, {1.1210189597947445e-306, -3.6919872897527542e-307}, {9.1712506449021332e-307, -3.8177790127453625e-307}, {1.0975204480559288e-306, -2.0463200236641752e-307}, {-8.2455716082167934e-307, 1.1297724028944864e-306}, {1.1985998055690893e-306, -9.2686234547054778e-307}, {4.5407915772417453e-307, -1.3020153499585007e-306}, {2.2029785050487273e-307, -1.2616470050897381e-306}, {2.768741118089437e-307, -1.2962586845799574e-306}, {9.9742119852202247e-307, -2.4911262489249602e-307}, {2.3558030355725208e-307, -1.3914350841815731e-306}, {1.6567606477608389e-306, -4.6962202403200453e-307}, {1.1460390512303018e-306, -9.5790231328592549e-307}, {3.0606204308245938e-307, -1.0486121234655328e-306}, {1.2338589001936404e-306, -4.47398630129883e-307}, {-8.2665861264942211e-307, 1.127669001005802e-306}, {2.6833758214901414e-307, -1.2731790007248436e-306}, {-8.6126485216605824e-307, 1.130849556710827e-306}, {-8.6091046348985256e-307, 1.1755418905240874e-306}, {1.7832712971941311e-306, -8.7718197811573929e-307}, {1.395080750203192e-306, -6.9652803902257512e-307}, {1.6050017268266121e-306, -4.5107754012034849e-307}, {-8.6289446623875109e-307, 1.1419866523090997e-306}, {2.4319604635143571e-307, -1.2834366293162036e-306}, {1.6424710124566627e-306, -6.9855197881854459e-307}, {1.44853475869049e-306, -8.3023740054126168e-307}, {3.2475456895489534e-307, -1.449070048310416e-306}, {1.1929368214794924e-306, -4.9763300116379633e-307}, {4.3875999884061801e-307, -1.2759348029280268e-306}, {3.5060269735149371e-307, -1.3601378105576132e-306}, {4.2487527541932216e-307, -1.3725922658998864e-306}, {1.6232775013429852e-306, -6.6527124293322887e-307}, {-8.7546945809021695e-307, 1.1649799184452659e-306}, {3.055708769507592e-307, -1.2984855124518722e-306}, {1.0871765037496449e-306, -1.2000206981415583e-306}, {-8.5323201876650875e-307, 1.1235374533757445e-306}, {-8.1521211627581393e-307, 1.1605596619584132e-306}, {3.7634479877152798e-307, -1.2668294248013449e-306}, {2.5707217063129123e-307, -1.2539036813525994e-306}, {3.4831022055181282e-307, -1.2901983167928684e-306}, {9.4956319068770633e-307, -5.2091047118306578e-307}, {1.377879209039339e-306, -9.0603143795155098e-307}, {3.6683659454571192e-307, -1.2693317518766773e-306}, {3.5646438070816529e-307, -1.2972025974193504e-306}, {-8.2972028686827427e-307, 1.1290078439782727e-306}, {3.1629941506226727e-307, -1.2598770683398002e-306}, {1.5964584053102757e-306, -9.3287540913997447e-307}, {8.7620550470473718e-307, -4.1882895250034866e-307}, {9.0107562606281417e-307, -6.7071332768298788e-307}, {3.7048172536858403e-307, -1.2417529217753421e-306}, {3.307697587184035e-307, -1.1846611481912142e-306}, {3.4643931818397519e-307, -1.4482507265155821e-306}, {3.1953517029630705e-307, -1.2131266914959409e-306}, {3.7621796384983838e-307, -1.3192094575173968e-306}, {1.4981742558002003e-306, -1.0619288033636362e-306}, {-8.5129419908637715e-307, 1.1348486593065544e-306}, {1.5983557670412629e-306, -9.0624515528664069e-307}, {1.2752439730034981e-306, -7.270963057004308e-307}, {9.7184421919027488e-307, -4.326402543882015e-307}, {1.2547488060056394e-306, -2.6365425006686419e-307}, {4.154365980604633e-307, -1.1826471290142065e-306}, {1.7600359077910834e-306, -1.0662221188419605e-306}, {9.0167567724961569e-307, -4.431247186345634e-307}, {1.2586687028692765e-306, -8.6640766550073869e-307}, {-8.3947102203804947e-307, 1.1291321032162986e-306}, {-8.5045862614723528e-307, 1.1777482971917315e-306}, {-8.5634247440798976e-307, 1.1239788357938748e-306}, {1.1394556452812925e-306, -2.4437116883929169e-307}, {-8.2907505289278811e-307, 1.1527032437741801e-306}, {1.2537253212002241e-306, -1.0265996570673858e-306}}},
  };
  for(const auto& c : cases) {
    Points points;
    for(const auto& p : c.second)
      points.emplace_back(p[0], p[1]);
    DT_with_info<K> dt;
    if(c.first != 0) // the fuzzer's parameters: a seed, or sample_probability 1
      DFP::brio_dc_delaunay(points, dt, CGAL::parameters::random_seed(c.first));
    else
      DFP::brio_dc_delaunay(points, dt, DFP::parameters::sample_probability(1.0));
    check_is_cgal_delaunay(dt, points);
  }
}

// sample_probability 1 keeps every point but one of each component of the nearest-neighbour
// graph: on equal points, points closer than the double resolution of their box (all tie at
// distance 0) or a geometric progression, the graph has a component or a few, and a sample
// per point would make the build quadratic (seconds at 2000 points). The number of samples
// stays logarithmic, and the result is CGAL's.
void slow_shrinking_samples()
{
  Scope s("samples that barely shrink");
  std::vector<Points> sets(3);
  for(int i = 0; i < 8000; ++i) {
    sets[0].emplace_back(double(i % 3), 0.5);                                              // three positions
    sets[1].emplace_back(std::ldexp(double(i % 7), -1074), std::ldexp(double(i % 5), -1074)); // subnormals
  }
  for(int i = 0; i < 2000; ++i) // x = 2^-500 .. 2^500, collinear: each point's neighbour is the previous one
    sets[2].emplace_back(std::ldexp(1.0 + double(i / 1000), i % 1000 - 500), 0.0);
  for(const Points& points : sets)
    for(double q : {1.0, 0.999}) {
      DT_with_info<K> dt;
      const DFP::Statistics st = DFP::brio_dc_delaunay(points, dt, DFP::parameters::sample_probability(q));
      check_is_cgal_delaunay(dt, points);
      DFP_CHECK_MSG(st.insertion_rounds <= 64, st.insertion_rounds << " samples of " << points.size() << " points");
    }
}

} // namespace

int main(int argc, char** argv)
{
  if(argc > 1)
    only = argv[1];
  DFP_RUN(overflowing_distances());
  DFP_RUN(underflowing_distances());
  DFP_RUN(mixed_magnitudes());
  DFP_RUN(slow_shrinking_samples());
  DFP_RUN(subnormal_neighbour_grids());
  DFP_RUN(disk_containment());
  DFP_RUN(scales());
  return finish("test_extreme_coordinates");
}
