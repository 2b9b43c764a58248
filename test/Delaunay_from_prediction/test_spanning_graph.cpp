// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// delaunay_from_spanning_graph(): the Delaunay triangulation from a predicted graph, by the
// spanning-tree insertion of Section 3. Every result is compared with CGAL's triangulation
// built from scratch with the same kernel (by coordinates and by point indices): the true
// EMST, a tree with wrong edges, a random tree, a star, a path in random order, all edges of
// the Delaunay triangulation, a graph with cycles and crossings, a self-crossing
// combinatorial triangulation, disconnected graphs, on
// random and degenerate points; bad input throws with nothing changed; the statistics show
// the walks were used (and a random tree detected). Also the preorder forest the engine
// scans, on random graphs, and the faces entry point on self-crossing triangulations, by
// default and with Strategy::spanning_tree. Every graph also with Strategy::section_3 (Section
// 3 as written), whose samples and conflict lists are checked against brute force.

#include <CGAL/Delaunay_from_prediction/spanning_graph.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_predicted_edges_2.h> // both edge entry points in one unit
#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/union_find.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <numeric>
#include <tuple>

using namespace dfp_test;

using Edge = std::pair<std::size_t, std::size_t>;
using Edges = std::vector<Edge>;

// The edges of CGAL's Delaunay triangulation of the points, by point index.
template <class K>
Edges delaunay_edges(const std::vector<typename K::Point_2>& points)
{
  const auto dt = indexed_delaunay<K>(points);
  Edges edges;
  if(dt.dimension() >= 1)
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
      edges.emplace_back(e->first->vertex(dt.ccw(e->second))->info(), e->first->vertex(dt.cw(e->second))->info());
  return edges;
}

using DFP::internal::Union_find;

// A minimum spanning tree of the points (Kruskal on CGAL's Delaunay edges, lengths in
// double: the tests only need a tree of Delaunay edges); duplicates joined to one copy.
template <class K>
Edges emst_of(const std::vector<typename K::Point_2>& points)
{
  Edges edges = delaunay_edges<K>(points);
  auto length = [&](const Edge& e) { return CGAL::to_double(CGAL::squared_distance(points[e.first], points[e.second])); };
  std::sort(edges.begin(), edges.end(), [&](const Edge& a, const Edge& b) { return length(a) < length(b); });
  Union_find uf(points.size());
  Edges tree;
  const auto first = smallest_indices(points);
  for(std::size_t i = 0; i < points.size(); ++i)
    if(first.at(points[i]) != i && uf.join(first.at(points[i]), i))
      tree.emplace_back(first.at(points[i]), i);
  for(const Edge& e : edges)
    if(uf.join(e.first, e.second))
      tree.push_back(e);
  return tree;
}

// `tree` with `wrong` of its edges replaced by random edges that keep it a spanning tree.
inline Edges with_wrong_edges(Edges tree, std::size_t wrong, std::size_t n, CGAL::Random& rng)
{
  shuffle(tree, rng);
  tree.erase(tree.begin(), tree.begin() + std::ptrdiff_t((std::min)(wrong, tree.size())));
  Union_find uf(n);
  for(const Edge& e : tree)
    uf.join(e.first, e.second);
  while(tree.size() + 1 < n) {
    const std::size_t a = std::size_t(rng.get_int(0, int(n))), b = std::size_t(rng.get_int(0, int(n)));
    if(uf.join(a, b))
      tree.emplace_back(a, b);
  }
  shuffle(tree, rng);
  return tree;
}

inline Edges random_tree(std::size_t n, CGAL::Random& rng)
{
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  shuffle(order, rng);
  Edges tree;
  for(std::size_t k = 1; k < n; ++k)
    tree.emplace_back(order[k], order[std::size_t(rng.get_int(0, int(k)))]);
  return tree;
}

inline Edges star(std::size_t n, std::size_t centre)
{
  Edges edges;
  for(std::size_t i = 0; i < n; ++i)
    if(i != centre)
      edges.emplace_back(i, centre);
  return edges;
}

template <class K>
struct Spanning_graph_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  CGAL::Random rng{1414};

  // Runs into a triangulation holding other points first, then compares with CGAL.
  template <class DT = DT_with_info<K>, class EdgeRange>
  DFP::Statistics run(const Points& points, const EdgeRange& edges, bool exact = true)
  {
    DT dt;
    dt.insert(make_point<K>(-50., 7.));
    dt.insert(make_point<K>(-51., 7.));
    const DFP::Statistics s = DFP::delaunay_from_spanning_graph(points, edges, dt);
    if(exact) {
      check_is_cgal_delaunay(dt, points);
    } else {
      // Inexact predicates can leave edges their own in-circle test rejects (CGAL's own
      // build too): only the structure is promised, with every point in it.
      DFP_CHECK(dt.tds().is_valid());
      DFP_CHECK(dt.number_of_vertices() == smallest_indices(points).size());
    }
    DFP_CHECK(s.edges_in == std::size_t(std::distance(std::begin(edges), std::end(edges))));
    DFP_CHECK(s.points_reinserted == points.size());
    run_section_3<DT>(points, edges, exact);
    return s;
  }

  // The same with Strategy::section_3 (Section 3 as written): the same triangulation, never
  // a heuristic fallback (exact traits), the rounds of Theorem 3.3 when the points span a
  // triangle.
  template <class DT, class EdgeRange>
  void run_section_3(const Points& points, const EdgeRange& edges, bool exact)
  {
    Scope c("Strategy::section_3");
    DT dt;
    dt.insert(make_point<K>(-50., 7.));
    const DFP::Statistics s =
        DFP::delaunay_from_spanning_graph(points, edges, dt, DFP::parameters::strategy(DFP::Strategy::section_3));
    if(!exact) {
      DFP_CHECK(dt.tds().is_valid());
      DFP_CHECK(dt.number_of_vertices() == smallest_indices(points).size());
      return;
    }
    check_is_cgal_delaunay(dt, points);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.points_reinserted == points.size());
    if(dt.dimension() == 2) {
      DFP_CHECK_MSG(s.insertion_rounds == DFP::internal::theorem_3_3_divisors(points.size()).size(),
                    s.insertion_rounds);
      DFP_CHECK(s.largest_conflict_list <= s.conflict_list_entries);
    }
  }

  void graphs_on(const XYs& xy, bool exact = true)
  {
    const Points points = to_points<K>(xy);
    const std::size_t n = points.size();
    {
      Scope s("EMST");
      run(points, emst_of<K>(points), exact);
    }
    {
      Scope s("EMST, 5% wrong edges");
      run(points, with_wrong_edges(emst_of<K>(points), n / 20, n, rng), exact);
    }
    {
      Scope s("random tree");
      run(points, random_tree(n, rng), exact);
    }
    {
      Scope s("star");
      run(points, star(n, std::size_t(rng.get_int(0, int(n)))), exact);
    }
    {
      Scope s("path in random order");
      run(points, random_path(n, rng), exact);
    }
    {
      Scope s("all Delaunay edges");
      run(points, delaunay_edges<K>(points), exact);
    }
    {
      Scope s("Delaunay edges and random crossing edges, some twice");
      Edges edges = delaunay_edges<K>(points);
      for(std::size_t k = 0; k < n / 10 + 1; ++k) {
        const std::size_t a = std::size_t(rng.get_int(0, int(n))), b = std::size_t(rng.get_int(0, int(n)));
        if(a != b)
          edges.emplace_back(a, b);
      }
      const std::size_t m = edges.size();
      for(std::size_t k = 0; k < m; k += 7)
        edges.push_back(edges[k]);
      shuffle(edges, rng);
      run(points, edges, exact);
    }
    {
      // A combinatorial triangulation whose edges cross (Corollary 3.5): the Delaunay edges
      // with 5% of the points relabelled among themselves.
      Scope s("self-crossing triangulation");
      std::vector<std::size_t> chosen;
      for(std::size_t i = 0; i < n; ++i)
        if(rng.get_int(0, 20) == 0)
          chosen.push_back(i);
      const std::vector<std::size_t> label = permuted_among(n, chosen, rng);
      Edges edges;
      for(const Edge& e : delaunay_edges<K>(points))
        edges.emplace_back(label[e.first], label[e.second]);
      run(points, edges, exact);
    }
    {
      Scope s("two components");
      Edges tree = emst_of<K>(points);
      if(!tree.empty())
        tree.erase(tree.begin() + std::ptrdiff_t(tree.size() / 2));
      run(points, tree, exact);
    }
    {
      Scope s("no edges");
      const DFP::Statistics st = run(points, Edges(), exact);
      DFP_CHECK(n <= 2 || st.fell_back);
    }
  }

  void random_inputs()
  {
    for(std::size_t n : {1u, 2u, 3u, 4u, 10u, 100u, 2000u}) {
      Scope s("uniform, n = ", n);
      graphs_on(uniform_points(n, rng));
    }
    {
      Scope s("clustered");
      graphs_on(clustered_points(1500, rng));
    }
  }

  void degenerate_inputs()
  {
    {
      Scope s("grid 30 x 30 (co-circular quadruples)");
      graphs_on(grid_points(30, 30, rng));
    }
    {
      Scope s("lattice points on two circles and the centre");
      graphs_on(lattice_circle_points(65, rng, 25));
    }
    {
      Scope s("collinear");
      graphs_on(collinear_points(200, rng));
    }
    {
      Scope s("duplicates");
      graphs_on(with_duplicates(uniform_points(500, rng), 200, rng));
    }
    {
      Scope s("grid with duplicates");
      graphs_on(with_duplicates(grid_points(12, 12, rng), 60, rng));
    }
    {
      Scope s("huge coordinates");
      graphs_on(transformed(uniform_points(500, rng), 1e150, 3e150));
    }
    {
      Scope s("tiny coordinates");
      graphs_on(transformed(uniform_points(500, rng), 1e-150, -2e-150));
    }
    {
      Scope s("all points equal");
      graphs_on(XYs(20, XY{0.5, 0.25}));
    }
  }

  // Edge types other than std::pair, and a triangulation type without info.
  void edge_types()
  {
    const Points points = to_points<K>(uniform_points(300, rng));
    const Edges tree = emst_of<K>(points);
    std::vector<std::array<int, 2>> arrays;
    std::vector<std::vector<long>> vectors;
    std::vector<std::tuple<unsigned, unsigned>> tuples;
    for(const Edge& e : tree) {
      arrays.push_back({int(e.first), int(e.second)});
      vectors.push_back({long(e.first), long(e.second)});
      tuples.emplace_back(unsigned(e.first), unsigned(e.second));
    }
    Scope s("edge types");
    run(points, arrays);
    run(points, vectors);
    run(points, tuples);
    run<DT_plain<K>>(points, tree);
    run<DT_colored<K>>(points, tree);
  }
};

// The walks, not the fallbacks, locate the points when the tree is right; a random tree is
// detected and its points go to the spatial-order insertion.
void walks_are_used()
{
  CGAL::Random rng(77);
  using K = CGAL::Epick;
  const auto points = to_points<K>(uniform_points(30000, rng));
  Spanning_graph_test<K> t;
  {
    Scope s("EMST of 30000 points");
    const DFP::Statistics st = t.run(points, emst_of<K>(points));
    DFP_CHECK(!st.fell_back);
    DFP_CHECK(st.points_located + 64 > points.size());
    DFP_CHECK_MSG(st.faces_visited < 3 * st.points_located, st.faces_visited << " faces for " << st.points_located);
    DFP_CHECK_MSG(st.walk_fallbacks < points.size() / 100, st.walk_fallbacks);
    DFP_CHECK(st.insertion_rounds >= 2);
  }
  {
    // Told by the length of its edges before any work.
    Scope s("random tree on 30000 points");
    const DFP::Statistics st = t.run(points, random_tree(points.size(), rng));
    DFP_CHECK(st.fell_back);
    DFP_CHECK_MSG(st.points_located == 0, st.points_located);
  }
  {
    // Most edges short, but the walks from ancestors keep crossing wrong ones: told by the
    // walks of a round, the rest inserted in grid order.
    Scope s("EMST with 40% of its edges wrong, 30000 points");
    const DFP::Statistics st = t.run(points, with_wrong_edges(emst_of<K>(points), 12000, points.size(), rng));
    DFP_CHECK(st.fell_back);
    DFP_CHECK_MSG(st.points_located > 0 && st.points_located < points.size() / 2, st.points_located);
  }
}

// The faces entry point on self-crossing combinatorial triangulations (Corollary 3.5): the
// Delaunay faces with some points relabelled among themselves. By default they are repaired
// locally (or rebuilt); with Strategy::spanning_tree, built along a spanning tree of the
// faces' edges, the walks locating the points. Both equal CGAL's triangulation.
void faces_with_crossings()
{
  CGAL::Random rng(99);
  using K = CGAL::Epick;
  const auto points = to_points<K>(uniform_points(30000, rng));
  const std::size_t n = points.size();
  const Faces faces = delaunay_faces<K>(points);
  for(int per_mille : {0, 3, 50}) {
    std::vector<std::size_t> chosen;
    for(std::size_t i = 0; i < n; ++i)
      if(rng.get_int(0, 1000) < per_mille)
        chosen.push_back(i);
    const std::vector<std::size_t> label = permuted_among(n, chosen, rng);
    Faces crossing = faces;
    for(Face& f : crossing)
      f = {label[f[0]], label[f[1]], label[f[2]]};
    Scope s(chosen.size(), " of ", n, " points relabelled");
    {
      Scope c("default strategy");
      DT_with_info<K> dt;
      const DFP::Statistics st = DFP::delaunay_from_prediction(points, crossing, dt);
      check_is_cgal_delaunay(dt, points);
      check_statistics(st, crossing, points, dt);
      if(chosen.empty())
        DFP_CHECK(st.faces_certified == st.faces_in);
      if(per_mille == 3) // repaired locally, not rebuilt
        DFP_CHECK_MSG(!st.fell_back && st.faces_carved > 0 && st.points_reinserted >= chosen.size(),
                      to_string(st.outcome) << ", " << st.faces_carved << " carved, " << st.points_reinserted
                                         << " reinserted");
    }
    {
      Scope c("Strategy::spanning_tree");
      DT_with_info<K> dt;
      dt.insert(make_point<K>(-50., 7.)); // must be cleared
      const DFP::Statistics st = DFP::delaunay_from_prediction(
          points, crossing, dt, DFP::parameters::strategy(DFP::Strategy::spanning_tree));
      check_is_cgal_delaunay(dt, points);
      check_statistics(st, crossing, points, dt);
      DFP_CHECK(st.fell_back);
      DFP_CHECK_MSG(reason_is(st, DFP::Outcome::spanning_tree_requested), to_string(st.outcome));
      DFP_CHECK_MSG(st.points_located > n / 2, st.points_located);
      DFP_CHECK_MSG(st.faces_visited < 6 * st.points_located, st.faces_visited << " faces for " << st.points_located);
    }
  }
}

// Section 3 as written, inside: each round's samples are nested prefixes of the random order;
// every point outside the sample is located in a face of the sample's triangulation whose
// closure holds it; the conflict list of each face holds exactly the points outside the
// sample inside its circumcircle (checked against every pair, and against the kernel's
// in-circle test where the point is not on the circle); the statistics add up.
template <class K>
void conflict_lists_on(const XYs& xy, const Edges& edges)
{
  using Point = typename K::Point_2;
  const std::vector<Point> points = to_points<K>(xy);
  const std::size_t n = points.size();
  std::vector<std::uint32_t> ends;
  for(const Edge& e : edges)
    ends.insert(ends.end(), {std::uint32_t(e.first), std::uint32_t(e.second)});
  DT_with_info<K> dt;
  DFP::Statistics stats;
  std::size_t entries = 0, largest = 0, rounds_seen = 0;
  const K kernel;
  auto on_round = [&](const auto& rounds, const DFP::internal::Conflict_lists& lists) {
    ++rounds_seen;
    const auto& flat = rounds.flat();
    const std::size_t faces = flat.number_of_faces();
    DFP_CHECK(lists.offsets.size() == faces + 1);
    std::size_t bad_faces = 0, bad_locations = 0, wrong_entries = 0, kernel_disagrees = 0;
    for(std::size_t t = 0; t < faces; ++t)
      for(int i = 0; i < 3; ++i)
        if(flat.vertex(t, i) != flat.infinite && !rounds.in_sample(flat.vertex(t, i)))
          ++bad_faces;
    for(std::size_t r = 0; r < n; ++r) {
      if(rounds.in_sample(r))
        continue;
      const Point& p = flat.point(std::uint32_t(r));
      const std::size_t t = rounds.location()[r];
      int inf = -1;
      for(int i = 0; i < 3; ++i)
        if(flat.vertex(t, i) == flat.infinite)
          inf = i;
      if(inf >= 0) { // strictly outside the hull edge
        if(kernel.orientation_2_object()(flat.point(flat.vertex(t, (inf + 1) % 3)),
                                         flat.point(flat.vertex(t, (inf + 2) % 3)), p) != CGAL::LEFT_TURN)
          ++bad_locations;
      } else {
        for(int i = 0; i < 3; ++i)
          if(kernel.orientation_2_object()(flat.point(flat.vertex(t, i)), flat.point(flat.vertex(t, (i + 1) % 3)),
                                           p) == CGAL::RIGHT_TURN)
            ++bad_locations;
      }
      bool equals_vertex = false;
      for(int i = 0; i < 3; ++i)
        equals_vertex |= flat.vertex(t, i) != flat.infinite && flat.point(flat.vertex(t, i)) == p;
      if(equals_vertex != rounds.located_at_vertex(r))
        ++bad_locations;
    }
    for(std::size_t t = 0; t < faces; ++t) {
      std::vector<std::uint32_t> listed(lists.ranks.begin() + lists.offsets[t], lists.ranks.begin() + lists.offsets[t + 1]);
      std::sort(listed.begin(), listed.end());
      const bool finite = flat.vertex(t, 0) != flat.infinite && flat.vertex(t, 1) != flat.infinite &&
                          flat.vertex(t, 2) != flat.infinite;
      for(std::size_t r = 0; r < n; ++r) {
        if(rounds.in_sample(r) || rounds.located_at_vertex(r))
          continue;
        const Point& p = flat.point(std::uint32_t(r));
        const bool conflict = flat.in_conflict(std::uint32_t(t), p);
        if(conflict != std::binary_search(listed.begin(), listed.end(), std::uint32_t(r)))
          ++wrong_entries;
        if(finite) {
          const CGAL::Oriented_side side = kernel.side_of_oriented_circle_2_object()(
              flat.point(flat.vertex(t, 0)), flat.point(flat.vertex(t, 1)), flat.point(flat.vertex(t, 2)), p);
          if(side != CGAL::ON_ORIENTED_BOUNDARY && (side == CGAL::ON_POSITIVE_SIDE) != conflict)
            ++kernel_disagrees;
        }
      }
      entries += listed.size();
      largest = (std::max)(largest, listed.size());
    }
    DFP_CHECK_MSG(bad_faces == 0, bad_faces << " face corners outside the sample");
    DFP_CHECK_MSG(bad_locations == 0, bad_locations << " points not in the face they are located in");
    DFP_CHECK_MSG(wrong_entries == 0, wrong_entries << " (face, point) pairs listed wrongly");
    DFP_CHECK_MSG(kernel_disagrees == 0, kernel_disagrees << " conflicts the kernel's in-circle test denies");
  };
  DFP::internal::build_by_conflict_list_rounds(dt, points.begin(), n, ends, stats, on_round);
  check_is_cgal_delaunay(dt, points);
  DFP_CHECK_MSG(stats.conflict_list_entries == entries, stats.conflict_list_entries << " != " << entries);
  DFP_CHECK_MSG(stats.largest_conflict_list == largest, stats.largest_conflict_list << " != " << largest);
  DFP_CHECK_MSG(rounds_seen >= 1 && rounds_seen < stats.insertion_rounds, rounds_seen << " of " << stats.insertion_rounds);
  DFP_CHECK(stats.points_located > 0);
}

// The nested samples of Theorem 3.3: prefixes of one random order of the points, every point
// once, sample i holding at most |P^| / s_i points and the last one all.
void nested_samples()
{
  CGAL::Random rng(4242);
  for(std::size_t n : {1u, 5u, 100u, 5000u}) {
    Scope s("n = ", n);
    const Edges tree = random_tree(n, rng);
    std::vector<std::uint32_t> ends;
    for(const Edge& e : tree)
      ends.insert(ends.end(), {std::uint32_t(e.first), std::uint32_t(e.second)});
    const auto forest = DFP::internal::preorder_spanning_forest(DFP::internal::adjacency_of(ends, n));
    const std::vector<std::size_t> divisors = DFP::internal::theorem_3_3_divisors(n);
    DFP_CHECK(divisors.front() == std::max<std::size_t>(n, 1) && divisors.back() == 1);
    for(std::size_t i = 1; i < divisors.size(); ++i)
      DFP_CHECK(divisors[i] < divisors[i - 1]);
    const auto samples = DFP::internal::sample_multiset(forest, divisors, 7);
    std::size_t copies = 0;
    for(std::size_t r = 0; r < n; ++r)
      copies += std::max<std::size_t>(1, forest.degree[r]);
    DFP_CHECK(samples.end.size() == divisors.size());
    std::vector<std::uint32_t> sorted = samples.order;
    std::sort(sorted.begin(), sorted.end());
    DFP_CHECK(sorted.size() == n && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    for(std::size_t i = 0; i < divisors.size(); ++i) {
      DFP_CHECK(i == 0 || samples.end[i] >= samples.end[i - 1]);
      DFP_CHECK_MSG(samples.end[i] <= copies / divisors[i] + 1, samples.end[i] << " > " << copies / divisors[i]);
    }
    DFP_CHECK(samples.end.back() == n);
  }
}

void conflict_lists()
{
  CGAL::Random rng(515);
  using K = CGAL::Epick;
  {
    Scope s("uniform 400, EMST");
    const XYs xy = uniform_points(400, rng);
    conflict_lists_on<K>(xy, emst_of<K>(to_points<K>(xy)));
  }
  {
    Scope s("uniform 400, random tree");
    const XYs xy = uniform_points(400, rng);
    conflict_lists_on<K>(xy, random_tree(xy.size(), rng));
  }
  {
    Scope s("grid 14 x 14 with duplicates, EMST with wrong edges");
    const XYs xy = with_duplicates(grid_points(14, 14, rng), 40, rng);
    conflict_lists_on<K>(xy, with_wrong_edges(emst_of<K>(to_points<K>(xy)), 20, xy.size(), rng));
  }
  {
    Scope s("lattice points on circles, Epeck, Delaunay edges");
    const XYs xy = lattice_circle_points(40, rng, 10);
    conflict_lists_on<CGAL::Epeck>(xy, delaunay_edges<CGAL::Epeck>(to_points<CGAL::Epeck>(xy)));
  }
  {
    Scope s("collinear but one, no edges");
    XYs xy = collinear_points(150, rng);
    xy.push_back(XY{0.3, 0.9});
    conflict_lists_on<K>(xy, Edges());
  }
}

// Bad input: an end out of range (negative included) or a loop throws Invalid_prediction
// naming the edge, a non-finite point too, and the triangulation is left as it was.
void bad_input()
{
  using K = CGAL::Epick;
  CGAL::Random rng(5);
  const auto points = to_points<K>(uniform_points(50, rng));
  DT_with_info<K> dt;
  for(int k = 0; k < 5; ++k)
    dt.insert(make_point<K>(k, k * k))->info() = 100 + std::size_t(k);
  const auto before = geometry_of(dt);
  auto unchanged = [&] {
    bool ok = geometry_of(dt).vertices == before.vertices && geometry_of(dt).faces == before.faces;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      ok = ok && v->info() >= 100;
    return ok;
  };
  auto throws_naming = [&](const auto& pts, const auto& edges, const std::string& words) {
    try {
      DFP::delaunay_from_spanning_graph(pts, edges, dt);
    } catch(const DFP::Invalid_prediction& e) {
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  Edges tree = random_tree(points.size(), rng);
  {
    Scope s("end out of range");
    Edges bad = tree;
    bad[17].second = 50;
    DFP_CHECK(throws_naming(points, bad, "edge 17 has index 50"));
    DFP_CHECK(unchanged());
  }
  {
    Scope s("negative end");
    std::vector<std::array<int, 2>> bad;
    for(const Edge& e : tree)
      bad.push_back({int(e.first), int(e.second)});
    bad[3][0] = -2;
    DFP_CHECK(throws_naming(points, bad, "edge 3 has index -2"));
    DFP_CHECK(unchanged());
  }
  {
    Scope s("loop");
    Edges bad = tree;
    bad.emplace_back(9, 9);
    DFP_CHECK(throws_naming(points, bad, "joins index 9 to itself"));
    DFP_CHECK(unchanged());
  }
  {
    Scope s("non-finite point");
    auto bad = points;
    bad[31] = make_point<K>(std::nan(""), 0.);
    DFP_CHECK(throws_naming(bad, tree, "point 31"));
    DFP_CHECK(unchanged());
  }
}

// The preorder forest: parents come first, every tree edge is a graph edge, each subtree is
// a contiguous block of ranks, the degrees are the tree's, and every point has one rank.
void preorder_forest()
{
  CGAL::Random rng(31);
  for(int round = 0; round < 40; ++round) {
    const std::size_t n = std::size_t(rng.get_int(1, 400));
    Edges edges;
    const std::size_t m = std::size_t(rng.get_int(0, int(3 * n)));
    for(std::size_t k = 0; k < m; ++k) {
      const std::size_t a = std::size_t(rng.get_int(0, int(n))), b = std::size_t(rng.get_int(0, int(n)));
      if(a != b)
        edges.emplace_back(a, b);
    }
    Scope s("random graph ", round, ", n = ", n, ", m = ", edges.size());
    std::vector<std::uint32_t> ends;
    for(const Edge& e : edges) {
      ends.push_back(std::uint32_t(e.first));
      ends.push_back(std::uint32_t(e.second));
    }
    const auto graph = DFP::internal::adjacency_of(ends, n);
    const auto forest = DFP::internal::preorder_spanning_forest(graph);
    std::set<Edge> graph_edges;
    for(const Edge& e : edges) {
      graph_edges.insert(e);
      graph_edges.emplace(e.second, e.first);
    }
    std::vector<std::size_t> seen(n, 0), subtree(n, 1), degree(n, 0);
    bool parents_first = true, edges_ok = true;
    std::size_t roots = 0;
    for(std::size_t r = 0; r < n; ++r) {
      ++seen[forest.order[r]];
      const auto p = forest.parent[r];
      if(p == DFP::internal::no_rank) {
        ++roots;
        continue;
      }
      parents_first = parents_first && p < r;
      edges_ok = edges_ok && graph_edges.count(Edge(forest.order[p], forest.order[r])) == 1;
      ++degree[p];
      ++degree[r];
    }
    for(std::size_t r = n; r-- > 0;)
      if(forest.parent[r] != DFP::internal::no_rank && forest.parent[r] < r)
        subtree[forest.parent[r]] += subtree[r];
    // Preorder: the ranks after r that are in its subtree are exactly the next subtree[r] - 1.
    bool contiguous = true;
    for(std::size_t r = 0; r < n; ++r) {
      for(std::size_t c = r + 1; c < r + subtree[r] && c < n; ++c) {
        std::size_t a = c;
        while(a != DFP::internal::no_rank && a > r)
          a = forest.parent[a];
        contiguous = contiguous && a == r;
      }
    }
    DFP_CHECK(std::all_of(seen.begin(), seen.end(), [](std::size_t c) { return c == 1; }));
    DFP_CHECK(parents_first);
    DFP_CHECK(edges_ok);
    DFP_CHECK(contiguous);
    DFP_CHECK(forest.roots == roots);
    bool degrees_ok = true;
    for(std::size_t r = 0; r < n; ++r)
      degrees_ok = degrees_ok && degree[r] == forest.degree[r];
    DFP_CHECK(degrees_ok);
    // A forest with as many trees as the graph has components.
    Union_find uf(n);
    std::size_t components = n;
    for(const Edge& e : edges)
      components -= uf.join(e.first, e.second) ? 1 : 0;
    DFP_CHECK_MSG(roots == components, roots << " roots, " << components << " components");
  }
}

int main()
{
  DFP_RUN(preorder_forest());
  {
    Scope s("Epick");
    Spanning_graph_test<CGAL::Epick> t;
    DFP_RUN(t.random_inputs());
    DFP_RUN(t.degenerate_inputs());
    DFP_RUN(t.edge_types());
  }
  {
    Scope s("Epeck");
    Spanning_graph_test<CGAL::Epeck> t;
    DFP_RUN(t.graphs_on(uniform_points(300, t.rng)));
    DFP_RUN(t.graphs_on(lattice_circle_points(25, t.rng, 5)));
    DFP_RUN(t.graphs_on(with_duplicates(grid_points(8, 8, t.rng), 20, t.rng)));
  }
  {
    // Inexact: must terminate with a valid triangulation (exactness is not promised).
    Scope s("Simple_cartesian<double>");
    Spanning_graph_test<CGAL::Simple_cartesian<double>> t;
    DFP_RUN(t.graphs_on(uniform_points(1000, t.rng), false));
    DFP_RUN(t.graphs_on(jittered(grid_points(20, 20, t.rng), 1e-13, t.rng), false));
  }
  DFP_RUN(walks_are_used());
  DFP_RUN(faces_with_crossings());
  DFP_RUN(nested_samples());
  DFP_RUN(conflict_lists());
  DFP_RUN(bad_input());
  return finish("test_spanning_graph");
}
