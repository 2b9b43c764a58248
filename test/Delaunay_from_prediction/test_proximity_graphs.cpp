// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The Euclidean minimum spanning tree, relative neighbourhood graph and Gabriel graph from a
// predicted graph (Corollaries 3.6 and 3.7), and the tree from predicted faces (Theorem 5.5),
// against references computed from their
// definitions: brute force over all pairs (and all third points) on small inputs, and over
// the edges of CGAL's Delaunay triangulation with every point as a possible blocker on
// larger ones. Ties (grids, co-circular lattice points, collinear points) and duplicate
// points follow the documented rules; exact and filtered kernels; bad input throws.

#include <CGAL/Delaunay_from_prediction/proximity_graphs.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/prediction_models.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <numeric>

using namespace dfp_test;

using Edge = std::pair<std::size_t, std::size_t>;
using Edges = std::vector<Edge>;

template <class K>
struct Proximity_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  CGAL::Random rng{4242};
  K kernel;

  // Candidate pairs: all pairs of representatives (small inputs), or the edges of CGAL's
  // Delaunay triangulation (every edge of the three graphs is one, see the header).
  Edges candidates(const Points& points, const std::vector<std::size_t>& rep, bool all_pairs)
  {
    Edges pairs;
    if(all_pairs) {
      for(std::size_t i = 0; i < points.size(); ++i)
        for(std::size_t j = i + 1; j < points.size(); ++j)
          if(rep[i] == i && rep[j] == j)
            pairs.emplace_back(i, j);
      return pairs;
    }
    const auto dt = indexed_delaunay<K>(points);
    if(dt.dimension() >= 1)
      for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        const std::size_t a = rep[e->first->vertex(dt.ccw(e->second))->info()];
        const std::size_t b = rep[e->first->vertex(dt.cw(e->second))->info()];
        pairs.emplace_back((std::min)(a, b), (std::max)(a, b));
      }
    return pairs;
  }

  std::vector<std::size_t> representatives(const Points& points)
  {
    const auto first = smallest_indices(points);
    std::vector<std::size_t> rep(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      rep[i] = first.at(points[i]);
    return rep;
  }

  // Kruskal under the documented order: exact length, then the index pair.
  Edges reference_emst(const Points& points, bool all_pairs)
  {
    const auto rep = representatives(points);
    Edges pairs = candidates(points, rep, all_pairs);
    auto cmp = kernel.compare_distance_2_object();
    std::sort(pairs.begin(), pairs.end(), [&](const Edge& a, const Edge& b) {
      const auto c = cmp(points[a.first], points[a.second], points[b.first], points[b.second]);
      return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
    });
    DFP::internal::Union_find sets(points.size());
    Edges tree;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(rep[i] != i && sets.join(i, rep[i]))
        tree.emplace_back(rep[i], i);
    for(const Edge& e : pairs)
      if(sets.join(e.first, e.second))
        tree.push_back(e);
    std::sort(tree.begin(), tree.end());
    return tree;
  }

  // The candidate pairs p q that no point r removes, every point tested against the
  // definition (removes(p, q, r)).
  template <class Removes>
  Edges reference_graph(const Points& points, bool all_pairs, Removes removes)
  {
    const auto rep = representatives(points);
    Edges graph;
    for(const Edge& e : candidates(points, rep, all_pairs)) {
      const Point& p = points[e.first];
      const Point& q = points[e.second];
      bool empty = true;
      for(std::size_t r = 0; r < points.size() && empty; ++r)
        empty = !removes(p, q, points[r]);
      if(empty)
        graph.push_back(e);
    }
    std::sort(graph.begin(), graph.end());
    graph.erase(std::unique(graph.begin(), graph.end()), graph.end());
    return graph;
  }

  Edges reference_rng(const Points& points, bool all_pairs)
  {
    auto cmp = kernel.compare_distance_2_object();
    return reference_graph(points, all_pairs, [&](const Point& p, const Point& q, const Point& r) {
      return cmp(p, r, p, q) == CGAL::SMALLER && cmp(q, r, q, p) == CGAL::SMALLER;
    });
  }

  Edges reference_gabriel(const Points& points, bool all_pairs)
  {
    auto angle = kernel.angle_2_object();
    auto equal = kernel.equal_2_object();
    return reference_graph(points, all_pairs, [&](const Point& p, const Point& q, const Point& r) {
      return !equal(r, p) && !equal(r, q) && angle(p, r, q) != CGAL::ACUTE;
    });
  }

  template <class EdgeRange>
  void check_all(const Points& points, const EdgeRange& prediction, bool all_pairs)
  {
    Edges emst, rng_graph, gabriel;
    DFP::euclidean_minimum_spanning_tree_from_prediction(points, prediction, std::back_inserter(emst));
    DFP::relative_neighborhood_graph_from_prediction(points, prediction, std::back_inserter(rng_graph));
    DFP::gabriel_graph_from_prediction(points, prediction, std::back_inserter(gabriel));
    const Edges expected_emst = reference_emst(points, all_pairs);
    const Edges expected_rng = reference_rng(points, all_pairs);
    const Edges expected_gabriel = reference_gabriel(points, all_pairs);
    DFP_CHECK_MSG(emst == expected_emst, emst.size() << " edges vs " << expected_emst.size());
    DFP_CHECK_MSG(rng_graph == expected_rng, rng_graph.size() << " edges vs " << expected_rng.size());
    DFP_CHECK_MSG(gabriel == expected_gabriel, gabriel.size() << " edges vs " << expected_gabriel.size());
    DFP_CHECK(emst.size() + 1 == (std::max)(points.size(), std::size_t(1)));
    DFP_CHECK(std::is_sorted(emst.begin(), emst.end()));
    // EMST within RNG within Gabriel, on the representatives.
    Edges emst_distinct;
    const auto rep = representatives(points);
    for(const Edge& e : emst)
      if(rep[e.first] == e.first && rep[e.second] == e.second)
        emst_distinct.push_back(e);
    DFP_CHECK(std::includes(rng_graph.begin(), rng_graph.end(), emst_distinct.begin(), emst_distinct.end()));
    DFP_CHECK(std::includes(gabriel.begin(), gabriel.end(), rng_graph.begin(), rng_graph.end()));
  }

  // Predictions: a path in random order (wrong almost everywhere), the exact EMST, the EMST
  // with some edges replaced, a star.
  void on(const XYs& xy, bool all_pairs)
  {
    const Points points = to_points<K>(xy);
    const std::size_t n = points.size();
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    shuffle(order, rng);
    Edges path;
    for(std::size_t k = 1; k < n; ++k)
      path.emplace_back(order[k - 1], order[k]);
    {
      Scope s("path in random order");
      check_all(points, path, all_pairs);
    }
    const Edges emst = reference_emst(points, false);
    {
      Scope s("exact EMST");
      check_all(points, emst, all_pairs);
    }
    {
      Scope s("EMST with wrong edges");
      Edges wrong = emst;
      for(std::size_t k = 0; k < wrong.size(); k += 5)
        if(wrong[k].first != order[k])
          wrong[k].second = order[k];
      check_all(points, wrong, all_pairs);
    }
    {
      // Theorem 5.5: the tree from predicted faces, the Delaunay faces and a tenth of their
      // edges flipped, with the default strategy and Strategy::regions, each concurrency.
      const Edges expected = reference_emst(points, all_pairs);
      const std::vector<DFP::Indexed_triangle> dt_faces = DFP::delaunay_triangles(points);
      const std::vector<DFP::Indexed_triangle> flipped = DFP::k_flip_prediction(points, n / 10 + 1, n);
      for(const auto* faces : {&dt_faces, &flipped})
        for(bool regions : {false, true})
          for_each_concurrency([&] {
            Scope s(faces == &dt_faces ? "Delaunay faces" : "flipped faces", regions ? ", regions" : "");
            Edges got;
            with_concurrency([&](auto tag) {
              if(regions)
                DFP::euclidean_minimum_spanning_tree_from_predicted_faces<decltype(tag)>(
                    points, *faces, std::back_inserter(got), DFP::parameters::strategy(DFP::Strategy::regions));
              else
                DFP::euclidean_minimum_spanning_tree_from_predicted_faces<decltype(tag)>(points, *faces,
                                                                                         std::back_inserter(got));
              return 0;
            });
            DFP_CHECK_MSG(got == expected, got.size() << " edges vs " << expected.size());
          });
    }
    {
      Scope s("star");
      std::vector<std::array<int, 2>> star;
      for(std::size_t i = 1; i < n; ++i)
        star.push_back({0, int(i)});
      check_all(points, star, all_pairs);
    }
  }

  void all(bool large)
  {
    for(std::size_t n : {1u, 2u, 3u, 5u, 60u}) {
      Scope s("uniform, n = ", n);
      on(uniform_points(n, rng), true);
    }
    {
      Scope s("grid 9 x 7 (equal lengths everywhere)");
      on(grid_points(9, 7, rng), true);
    }
    {
      Scope s("lattice points on a circle and the centre");
      on(lattice_circle_points(25, rng, 5), true);
    }
    {
      Scope s("collinear");
      on(collinear_points(40, rng), true);
    }
    {
      Scope s("duplicates");
      on(with_duplicates(uniform_points(50, rng), 15, rng), true);
    }
    {
      Scope s("grid with duplicates");
      on(with_duplicates(grid_points(6, 6, rng), 10, rng), true);
    }
    if(large) {
      {
        Scope s("uniform, 2500 points");
        on(uniform_points(2500, rng), false);
      }
      {
        Scope s("clustered, 2000 points");
        on(clustered_points(2000, rng), false);
      }
      {
        Scope s("grid 40 x 40");
        on(grid_points(40, 40, rng), false);
      }
    }
  }
};

void bad_input()
{
  using K = CGAL::Epick;
  CGAL::Random rng(9);
  const auto points = to_points<K>(uniform_points(20, rng));
  Edges out;
  DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] {
    DFP::euclidean_minimum_spanning_tree_from_prediction(points, Edges{{0, 20}}, std::back_inserter(out));
  }));
  DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] {
    DFP::relative_neighborhood_graph_from_prediction(points, Edges{{3, 3}}, std::back_inserter(out));
  }));
  DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] {
    DFP::gabriel_graph_from_prediction(points, std::vector<std::array<int, 2>>{{-1, 2}}, std::back_inserter(out));
  }));
  DFP_CHECK(out.empty());
}

int main()
{
  {
    Scope s("Epick");
    DFP_RUN(Proximity_test<CGAL::Epick>().all(true));
  }
  {
    Scope s("Epeck");
    DFP_RUN(Proximity_test<CGAL::Epeck>().all(false));
  }
  DFP_RUN(bad_input());
  return finish("test_proximity_graphs");
}
