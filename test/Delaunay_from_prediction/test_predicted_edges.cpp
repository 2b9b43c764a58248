// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// delaunay_from_predicted_edges(): a prediction given as edges (Corollary 4.2 of the paper).
// The edges of CGAL's DT with 0%, 1%, 10% and 30% missing, with crossing edges added, repeated and
// reversed, as pairs and as arrays; on uniform, grid (co-circular) and collinear points, with
// duplicates. The result must be CGAL's triangulation, with info() the point index; with
// little damage, the call must not fall back. Malformed edges throw and leave dt unchanged.

#include <CGAL/Delaunay_from_predicted_edges_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>

#include <array>
#include <utility>
#include <vector>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using DT = DT_with_info<K>;
using Edges = std::vector<std::pair<int, int>>;

Edges delaunay_edges(const std::vector<Point>& points)
{
  const DT dt = indexed_delaunay<K>(points);
  Edges edges;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    edges.emplace_back(int(e->first->vertex(DT::ccw(e->second))->info()),
                       int(e->first->vertex(DT::cw(e->second))->info()));
  return edges;
}

Edges without_some(const Edges& edges, double fraction, std::uint64_t seed)
{
  DFP::internal::Splitmix64 random{seed};
  Edges kept;
  for(const auto& e : edges)
    if(random.uniform() >= fraction)
      kept.push_back(random.below(2) == 0 ? e : std::make_pair(e.second, e.first));
  return kept;
}

template <class EdgeRange>
DFP::Statistics run(const std::vector<Point>& points, const EdgeRange& edges)
{
  DT dt;
  const DFP::Statistics s = DFP::delaunay_from_predicted_edges(points, edges, dt);
  DFP_CHECK(check_is_cgal_delaunay(dt, points));
  DFP_CHECK_MSG((s.outcome == DFP::Outcome::ok) == !s.fell_back, to_string(s.outcome));
  return s;
}

int main()
{
  CGAL::Random rng(20261126);
  const std::vector<Point> uniform = to_points<K>(uniform_points(4000, rng));

  {
    const Edges all = delaunay_edges(uniform);
    const DFP::Statistics s = run(uniform, all);
    // The separating triangles around vertices of degree 3 overlap the faces there: what the
    // importer leaves out is carved and refilled by ear clipping, whose diagonals depend on
    // where a hole's tracing starts, so a few flips may follow (one per carved face at most).
    DFP_CHECK_MSG(!s.fell_back && s.flips <= s.faces_carved && s.faces_carved <= s.faces_in / 20,
                  "the whole DT: " << to_string(s.outcome) << " carved " << s.faces_carved << ", flips " << s.flips);
    // Each missing edge opens a hole of 4 half-edges: past about n/4 of those (here about 2%
    // of the edges missing) the call rebuilds by design; exact either way.
    for(double missing : {0.01, 0.1, 0.3}) {
      const DFP::Statistics t = run(uniform, without_some(all, missing, 7));
      if(missing <= 0.01)
        DFP_CHECK_MSG(!t.fell_back && t.holes_refilled > 0, "1% missing: " << to_string(t.outcome));
    }
    Edges crossing = without_some(all, 0.01, 8);
    DFP::internal::Splitmix64 random{9};
    for(int k = 0; k < 10; ++k)
      crossing.emplace_back(int(random.below(uniform.size())), int(random.below(uniform.size())));
    crossing.erase(std::remove_if(crossing.begin(), crossing.end(), [](const auto& e) { return e.first == e.second; }),
                   crossing.end());
    const DFP::Statistics c = run(uniform, crossing);
    DFP_CHECK_MSG(!c.fell_back, "crossing edges: " << to_string(c.outcome));
    Edges twice = all;
    twice.insert(twice.end(), all.begin(), all.end());
    run(uniform, twice);
    std::vector<std::array<std::size_t, 2>> as_arrays;
    for(const auto& e : all)
      as_arrays.push_back({std::size_t(e.second), std::size_t(e.first)});
    run(uniform, as_arrays);
    run(uniform, Edges()); // no edge: a rebuild
  }

  // Degenerate point sets: co-circular grid (predicted from jittered positions), collinear
  // points, duplicates.
  {
    const std::vector<Point> grid = to_points<K>(grid_points(40, 30, rng));
    const std::vector<Point> jittered_grid = to_points<K>(jittered(grid_points(40, 30, rng), 0.05, rng));
    run(grid, delaunay_edges(jittered_grid));
    run(grid, without_some(delaunay_edges(grid), 0.2, 11));
    const std::vector<Point> line = to_points<K>(collinear_points(200, rng));
    Edges chain;
    for(int i = 0; i + 1 < 200; ++i)
      chain.emplace_back(i, i + 1);
    run(line, chain);
    const std::vector<Point> dup = to_points<K>(with_duplicates(uniform_points(500, rng), 50, rng));
    run(dup, without_some(delaunay_edges(dup), 0.1, 12));
  }

  // Malformed edges throw, naming the edge, and leave dt as it was.
  {
    DT dt = indexed_delaunay<K>(uniform);
    const std::size_t before = dt.number_of_faces();
    DFP_CHECK((throws_exception<DFP::Invalid_prediction>([&] {
      DFP::delaunay_from_predicted_edges(uniform, Edges{{0, 1}, {2, int(uniform.size())}}, dt);
    })));
    DFP_CHECK((throws_exception<DFP::Invalid_prediction>([&] {
      DFP::delaunay_from_predicted_edges(uniform, Edges{{0, 1}, {-1, 2}}, dt);
    })));
    DFP_CHECK((throws_exception<DFP::Invalid_prediction>([&] {
      DFP::delaunay_from_predicted_edges(uniform, Edges{{3, 3}}, dt);
    })));
    DFP_CHECK(dt.number_of_faces() == before && dt.is_valid());
  }
  return finish("test_predicted_edges");
}
