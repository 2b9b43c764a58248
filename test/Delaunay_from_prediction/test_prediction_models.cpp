// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The prediction generators of prediction_models.h:
//  - every generator is a function of its seed (same seed, same output; other seeds, other
//    outputs);
//  - the ones that promise a triangulation give one (counterclockwise faces, certified by
//    prediction_measures() and by delaunay_from_prediction() without falling back);
//  - the rho model keeps exactly its sampled edges (Delaunay edges, all in the result, a
//    fraction close to rho), rho = 1 gives DT(P), and the adversarial completion leaves no
//    flippable locally Delaunay edge outside R; random_flip with rho = 1 gives DT(P);
//  - k flips: D <= k, k = 0 gives DT(P), k = 1 gives D = 1;
//  - moved points, deleted faces, self-crossing labelings, random triples;
//  - the list-merging (Figure 2) and sorting (Figure 1) configurations: sizes, a
//    triangulation, D_local = O(k) with the tight constant, D = Theta(n), and DT(P) joining
//    x-consecutive list points (the reduction);
//  - invalid arguments throw, and degenerate point sets (no triangle) crash nothing.
// Epick throughout, Epeck for a subset.

#include <CGAL/Delaunay_from_prediction/prediction_models.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using namespace dfp_test;
using Measures = DFP::Prediction_measures;
using Edge = std::pair<std::size_t, std::size_t>;

Edge edge(std::size_t a, std::size_t b) { return a < b ? Edge(a, b) : Edge(b, a); }

std::set<Edge> edges_of(const Faces& faces)
{
  std::set<Edge> edges;
  for(const Face& f : faces)
    for(int j = 0; j < 3; ++j)
      edges.insert(edge(f[j], f[(j + 1) % 3]));
  return edges;
}

// Faces as sets of index triples, for comparing two lists regardless of order and rotation.
std::vector<Face> sorted_triples(const Faces& faces)
{
  std::vector<Face> out;
  for(Face f : faces) {
    std::sort(f.begin(), f.end());
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string describe(const Measures& m)
{
  std::ostringstream out;
  out << "n=" << m.points << " F=" << m.faces << " tri=" << m.is_triangulation << " D=" << m.D
      << " D_local=" << m.D_local << " D_cross=" << m.D_cross << " d_cross=" << m.d_cross
      << " D_vio=" << m.D_vio << " D_flip_upper=" << (m.D_flip_upper ? std::to_string(*m.D_flip_upper) : "none")
      << " >2 faces=" << m.edges_with_more_than_two_faces;
  if(!m.not_a_triangulation.empty())
    out << " (" << m.not_a_triangulation << ")";
  return out.str();
}

template <class K>
struct Models_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;

  CGAL::Random rng{4242};

  // --- Helpers ------------------------------------------------------------------------------

  // Faces with indices in range and three different indices each.
  static bool valid_triples(const Faces& faces, std::size_t n)
  {
    for(const Face& f : faces)
      if(f[0] >= n || f[1] >= n || f[2] >= n || f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
        return false;
    return true;
  }

  // `faces` is a proper triangulation of `points` (distinct points), certified three ways:
  // every face counterclockwise (as the generators promise), prediction_measures() says it is
  // a triangulation, and delaunay_from_prediction() uses it without falling back or inserting
  // a point and returns CGAL's DT.
  void check_triangulation(const Points& points, const Faces& faces)
  {
    DFP_CHECK(valid_triples(faces, points.size()));
    if(!valid_triples(faces, points.size()))
      return;
    std::size_t not_ccw = 0;
    for(const Face& f : faces)
      not_ccw += CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::LEFT_TURN;
    DFP_CHECK_MSG(not_ccw == 0, not_ccw << " faces not counterclockwise");
    const Measures m = DFP::prediction_measures(points, faces);
    DFP_CHECK_MSG(m.is_triangulation, describe(m));
    DT_with_info<K> dt;
    const DFP::Statistics st = DFP::delaunay_from_prediction(
        points, faces, dt, DFP::parameters::max_flips(std::numeric_limits<std::size_t>::max()));
    DFP_CHECK_MSG(!st.fell_back, to_string(st.outcome));
    DFP_CHECK_MSG(st.points_unused == 0, st.points_unused);
    DFP_CHECK_MSG(st.flips == (m.D_flip_upper ? *m.D_flip_upper : std::size_t(-1)), st.flips << "; " << describe(m));
    check_is_cgal_delaunay(dt, points);
  }

  bool is_delaunay(const Points& points, const Faces& faces)
  {
    return sorted_triples(faces) == sorted_triples(DFP::delaunay_triangles(points));
  }

  // An interior edge of `faces` (a triangulation) with its two opposite vertices.
  struct Interior_edge
  {
    std::size_t a, b, c, d; // faces (a, b, c) ccw and (b, a, d) ccw
  };
  static std::vector<Interior_edge> interior_edges(const Points& points, const Faces& faces)
  {
    std::map<Edge, std::vector<std::pair<Face, std::size_t>>> around; // edge -> (ccw face, opposite)
    for(Face f : faces) {
      if(CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) == CGAL::RIGHT_TURN)
        std::swap(f[1], f[2]);
      for(int j = 0; j < 3; ++j)
        around[edge(f[(j + 1) % 3], f[(j + 2) % 3])].emplace_back(f, j);
    }
    std::vector<Interior_edge> out;
    for(const auto& [e, list] : around)
      if(list.size() == 2) {
        const Face& f = list[0].first;
        const std::size_t j = list[0].second;
        const Face& g = list[1].first;
        out.push_back({f[(j + 1) % 3], f[(j + 2) % 3], f[j], g[list[1].second]});
      }
    return out;
  }

  // --- Determinism --------------------------------------------------------------------------

  // gen(seed) is the same for the same seed, and takes at least `min_distinct` values over
  // seeds 1..6.
  template <class Result>
  void deterministic(const char* name, const std::function<Result(std::uint64_t)>& gen,
                     std::size_t min_distinct = 5)
  {
    Scope s(name);
    std::vector<Result> outputs;
    std::string not_reproduced;
    for(std::uint64_t seed = 1; seed <= 6; ++seed) {
      const Result a = gen(seed), b = gen(seed);
      if(!(a == b))
        not_reproduced += " " + std::to_string(seed);
      outputs.push_back(a);
    }
    DFP_CHECK_MSG(not_reproduced.empty(), "two calls with the same seed differ, for seeds" << not_reproduced);
    std::sort(outputs.begin(), outputs.end());
    const std::size_t distinct = std::size_t(std::unique(outputs.begin(), outputs.end()) - outputs.begin());
    DFP_CHECK_MSG(distinct >= min_distinct, distinct << " different results for 6 seeds");
  }

  void determinism(const Points& points)
  {
    const std::size_t n = points.size();
    const Faces dt = DFP::delaunay_triangles(points);
    DFP_CHECK(dt == DFP::delaunay_triangles(points));
    using R = Faces;
    deterministic<R>("random_flip_prediction", [&](std::uint64_t s) { return DFP::random_flip_prediction(points, 0.6, s); });
    deterministic<R>("k_flip_prediction", [&](std::uint64_t s) { return DFP::k_flip_prediction(points, 7, s); });
    deterministic<R>("rho_model_prediction, adversarial", [&](std::uint64_t s) {
      return DFP::rho_model_prediction(points, 0.5, s, DFP::Completion::adversarial);
    });
    deterministic<R>("rho_model_prediction, random", [&](std::uint64_t s) {
      return DFP::rho_model_prediction(points, 0.5, s, DFP::Completion::random);
    });
    deterministic<std::vector<Edge>>("rho_model_prediction, kept edges", [&](std::uint64_t s) {
      std::vector<Edge> kept;
      DFP::rho_model_prediction(points, 0.5, s, DFP::Completion::random, &kept);
      return kept;
    });
    deterministic<R>("moved_points_prediction", [&](std::uint64_t s) { return DFP::moved_points_prediction(points, 0.3, s); });
    deterministic<R>("delete_faces", [&](std::uint64_t s) { return DFP::delete_faces(dt, 0.3, s); });
    deterministic<R>("self_crossing_prediction", [&](std::uint64_t s) { return DFP::self_crossing_prediction(points, 5, s); });
    deterministic<R>("random_triples", [&](std::uint64_t s) { return DFP::random_triples(n, n, s); });
    deterministic<std::pair<Points, Faces>>("merging_lists_configuration", [&](std::uint64_t s) {
      const auto instance = DFP::merging_lists_configuration<K>(4, 6, s);
      return std::make_pair(instance.points, instance.faces);
    });
    deterministic<std::pair<Points, Faces>>("sorting_configuration", [&](std::uint64_t s) {
      const auto instance = DFP::sorting_configuration<K>(20, s);
      return std::make_pair(instance.points, instance.faces);
    });
    // The kept-edges out-parameter changes nothing, and is cleared first.
    std::vector<Edge> kept = {{7, 3}, {1, 1}};
    const Faces with = DFP::rho_model_prediction(points, 0.4, 9, DFP::Completion::adversarial, &kept);
    const Faces without = DFP::rho_model_prediction(points, 0.4, 9, DFP::Completion::adversarial);
    DFP_CHECK(with == without);
    DFP_CHECK(std::find(kept.begin(), kept.end(), Edge(7, 3)) == kept.end());
  }

  // --- Generators that promise a triangulation ----------------------------------------------

  void triangulations(const Points& points)
  {
    std::uint64_t seed = 100;
    {
      Scope s("delaunay_triangles");
      const Faces dt = DFP::delaunay_triangles(points);
      check_triangulation(points, dt);
      DFP_CHECK(sorted_triples(dt) == sorted_triples(delaunay_faces<K>(points)));
    }
    for(double rho : {0.0, 0.3, 0.7, 1.0}) {
      Scope s("random_flip_prediction, rho = ", rho);
      const Faces faces = DFP::random_flip_prediction(points, rho, seed++);
      check_triangulation(points, faces);
      if(rho == 1.0)
        DFP_CHECK(is_delaunay(points, faces));
    }
    for(std::size_t k : {0, 1, 10, 100, 1000}) {
      Scope s("k_flip_prediction, k = ", k);
      check_triangulation(points, DFP::k_flip_prediction(points, k, seed++));
    }
    for(double rho : {0.0, 0.2, 0.5, 0.9, 1.0})
      for(DFP::Completion c : {DFP::Completion::adversarial, DFP::Completion::random}) {
        Scope s("rho_model_prediction, rho = ", rho, c == DFP::Completion::adversarial ? ", adversarial" : ", random");
        check_triangulation(points, DFP::rho_model_prediction(points, rho, seed++, c));
      }
  }

  // --- The rho model --------------------------------------------------------------------------

  void rho_model(const Points& points, bool check_fraction)
  {
    const Faces dt = DFP::delaunay_triangles(points);
    const std::set<Edge> dt_edges = edges_of(dt);
    const double m = double(dt_edges.size());
    std::uint64_t seed = 500;
    for(double rho : {0.0, 0.1, 0.5, 0.9, 1.0})
      for(DFP::Completion c : {DFP::Completion::adversarial, DFP::Completion::random}) {
        Scope s("rho = ", rho, c == DFP::Completion::adversarial ? ", adversarial" : ", random");
        std::vector<Edge> kept;
        const Faces faces = DFP::rho_model_prediction(points, rho, seed++, c, &kept);
        const std::set<Edge> result_edges = edges_of(faces);
        // R: sorted pairs (smaller first), no repeats, all Delaunay, all kept in the result.
        DFP_CHECK(std::is_sorted(kept.begin(), kept.end()));
        DFP_CHECK(std::adjacent_find(kept.begin(), kept.end()) == kept.end());
        std::size_t not_dt = 0, lost = 0, reversed_pairs = 0;
        for(const Edge& e : kept) {
          reversed_pairs += e.first >= e.second;
          not_dt += dt_edges.count(e) == 0;
          lost += result_edges.count(e) == 0;
        }
        DFP_CHECK(reversed_pairs == 0);
        DFP_CHECK_MSG(not_dt == 0, not_dt << " kept edges are not Delaunay");
        DFP_CHECK_MSG(lost == 0, lost << " of " << kept.size() << " kept edges are not in the result");
        // The fraction kept: Binomial(m, rho); 6 standard deviations (and at least 3 edges).
        if(check_fraction) {
          const double sigma = std::sqrt(m * rho * (1 - rho));
          DFP_CHECK_MSG(std::fabs(double(kept.size()) - rho * m) <= 6 * sigma + 3,
                        kept.size() << " of " << m << " edges kept for rho = " << rho);
        }
        if(rho == 0.0)
          DFP_CHECK(kept.empty());
        if(rho == 1.0) {
          DFP_CHECK(kept.size() == dt_edges.size());
          DFP_CHECK(is_delaunay(points, faces));
        }
        if(c == DFP::Completion::adversarial) {
          // No edge outside R is both flippable (strictly convex quadrilateral) and locally
          // Delaunay (perturbed in-circle test, CGAL's own).
          DT_with_info<K> any;
          const std::set<Edge> kept_set(kept.begin(), kept.end());
          std::size_t flippable_locally_delaunay = 0, flippable = 0;
          for(const Interior_edge& e : interior_edges(points, faces)) {
            if(kept_set.count(edge(e.a, e.b)) != 0)
              continue;
            const Point &a = points[e.a], &b = points[e.b], &c3 = points[e.c], &d = points[e.d];
            // (a, b, c) and (b, a, d) ccw; the quadrilateral a d b c is strictly convex iff
            // the other diagonal c-d separates a and b strictly.
            if(CGAL::orientation(c3, d, a) == CGAL::COLLINEAR || CGAL::orientation(c3, d, b) == CGAL::COLLINEAR ||
               CGAL::orientation(c3, d, a) == CGAL::orientation(c3, d, b))
              continue;
            ++flippable;
            if(any.side_of_oriented_circle(a, b, c3, d, true) != CGAL::ON_POSITIVE_SIDE)
              ++flippable_locally_delaunay;
          }
          DFP_CHECK_MSG(flippable_locally_delaunay == 0,
                        flippable_locally_delaunay << " of " << flippable << " flippable edges outside R are locally Delaunay");
        }
      }
  }

  // --- k flips ------------------------------------------------------------------------------

  void k_flips(const Points& points)
  {
    DFP_CHECK(is_delaunay(points, DFP::k_flip_prediction(points, 0, 3)));
    std::uint64_t seed = 900;
    for(std::size_t k : {1, 2, 3, 10, 50, 300}) {
      for(int trial = 0; trial < 3; ++trial) {
        Scope s("k = ", k, ", trial ", trial);
        const Faces faces = DFP::k_flip_prediction(points, k, seed++);
        const Measures m = DFP::prediction_measures(points, faces);
        DFP_CHECK_MSG(m.is_triangulation, describe(m));
        // A flip changes one edge: D <= D_flip <= k. (Lawson's algorithm may need more than
        // k flips: D_flip_upper is not bounded by k.)
        DFP_CHECK_MSG(m.D <= k, describe(m));
        if(k == 1) // one flip of a Delaunay edge: its replacement crosses it, so is not Delaunay
          DFP_CHECK_MSG(m.D == 1 && m.D_flip_upper == std::optional<std::size_t>(1), describe(m));
        if(k >= 10 && 10 * k <= m.edges) // few random flips among many edges rarely meet
          DFP_CHECK_MSG(2 * m.D >= k, describe(m));
      }
    }
  }

  // --- Order-k Delaunay triangulations ------------------------------------------------------

  void order_k(const Points& points, bool general_position)
  {
    DFP_CHECK(is_delaunay(points, DFP::order_k_prediction(points, 0, 3)));
    std::uint64_t seed = 950;
    for(std::size_t k : {1, 2, 5, 20}) {
      Scope s("k = ", k);
      const Faces faces = DFP::order_k_prediction(points, k, seed++);
      const Measures m = DFP::prediction_measures(points, faces);
      DFP_CHECK_MSG(m.is_triangulation && m.d_vio <= k, describe(m));
      if(general_position) // m draws: many flips pass the test
        DFP_CHECK_MSG(m.D > 0 && (k < 5 || m.d_vio > 1), describe(m));
    }
    // With k past n every convex flip passes: the random-flip model with rho = 0, draw for draw.
    DFP_CHECK(DFP::order_k_prediction(points, points.size(), 77) == DFP::random_flip_prediction(points, 0.0, 77));
  }

  // --- Moved points -------------------------------------------------------------------------

  void moved_points(const Points& points)
  {
    const std::size_t n = points.size();
    {
      Scope s("noise 0");
      const Faces faces = DFP::moved_points_prediction(points, 0.0, 5);
      DFP_CHECK(is_delaunay(points, faces));
      DFP_CHECK(faces == DFP::delaunay_triangles(points));
    }
    std::size_t D_small = 0;
    for(double noise : {0.01, 0.1, 1.0, 10.0}) {
      Scope s("noise ", noise);
      const Faces faces = DFP::moved_points_prediction(points, noise, 6);
      DFP_CHECK(valid_triples(faces, n));
      std::set<std::size_t> used;
      for(const Face& f : faces)
        used.insert(f.begin(), f.end());
      DFP_CHECK_MSG(used.size() == n, used.size() << " of " << n << " points used");
      DFP_CHECK(faces.size() <= 2 * n - 5 && faces.size() >= n - 2);
      const Measures m = DFP::prediction_measures(points, faces);
      if(noise == 0.01)
        D_small = m.D;
      if(noise == 10.0) // moved by ten times their spacing: far from DT(P)
        DFP_CHECK_MSG(m.D > 0 && m.D > D_small, describe(m) << "; with noise 0.01, D = " << D_small);
    }
  }

  // --- Holes, crossings, random triples -----------------------------------------------------

  void holes(const Points& points)
  {
    const Faces dt = DFP::delaunay_triangles(points);
    DFP_CHECK(DFP::delete_faces(dt, 0.0, 1) == dt);
    DFP_CHECK(DFP::delete_faces(dt, 1.0, 1).empty());
    const double F = double(dt.size());
    for(double fraction : {0.05, 0.25, 0.5}) {
      Scope s("delete_faces, fraction ", fraction);
      const Faces kept = DFP::delete_faces(dt, fraction, 77);
      const double deleted = F - double(kept.size());
      const double sigma = std::sqrt(F * fraction * (1 - fraction));
      DFP_CHECK_MSG(std::fabs(deleted - fraction * F) <= 6 * sigma + 3, deleted << " of " << F << " deleted");
      // The kept faces are the input's, in order.
      std::size_t at = 0;
      for(const Face& f : kept) {
        while(at < dt.size() && dt[at] != f)
          ++at;
        ++at;
      }
      DFP_CHECK_MSG(at <= dt.size(), "the kept faces are not a subsequence of the input");
      const Measures m = DFP::prediction_measures(points, kept);
      DFP_CHECK_MSG(!m.is_triangulation && m.D == 0, describe(m));
    }
  }

  void self_crossing(const Points& points)
  {
    const std::size_t n = points.size();
    const Faces dt = DFP::delaunay_triangles(points);
    DFP_CHECK(DFP::self_crossing_prediction(points, 0, 1) == dt);
    std::size_t not_triangulations = 0, trials = 0;
    for(std::size_t swaps : {1, 5, 50})
      for(std::uint64_t seed = 1; seed <= 6; ++seed) {
        Scope s("self_crossing_prediction, swaps ", swaps, ", seed ", seed);
        const Faces faces = DFP::self_crossing_prediction(points, swaps, seed);
        DFP_CHECK(faces.size() == dt.size());
        DFP_CHECK(valid_triples(faces, n));
        // A relabelling of DT(P): same number of points used, and every edge has at most
        // two faces (exactly as many as in DT(P) have one and two).
        std::set<std::size_t> used;
        std::map<Edge, std::size_t> count;
        for(const Face& f : faces) {
          used.insert(f.begin(), f.end());
          for(int j = 0; j < 3; ++j)
            ++count[edge(f[j], f[(j + 1) % 3])];
        }
        DFP_CHECK(used.size() == n);
        std::size_t once = 0, twice = 0, more = 0;
        for(const auto& kv : count)
          (kv.second == 1 ? once : kv.second == 2 ? twice : more) += 1;
        DFP_CHECK_MSG(more == 0, more << " edges with more than two faces");
        DFP_CHECK(once + twice == edges_of(dt).size());
        const Measures m = DFP::prediction_measures(points, faces);
        DFP_CHECK_MSG(m.edges_with_more_than_two_faces == 0, describe(m));
        ++trials;
        not_triangulations += !m.is_triangulation;
      }
    // "Usually" not a triangulation: a swap of two points two edges apart inverts a face.
    DFP_CHECK_MSG(4 * not_triangulations >= 3 * trials, not_triangulations << " of " << trials);
  }

  void triples()
  {
    for(std::size_t n : {3, 4, 50, 1000}) {
      Scope s("random_triples, n = ", n);
      const Faces faces = DFP::random_triples(n, 5 * n, 11);
      DFP_CHECK(faces.size() == 5 * n);
      DFP_CHECK(valid_triples(faces, n));
      if(n == 50) { // 250 triples, 750 draws: every index drawn (P(miss one) < 50 e^-15)
        std::set<std::size_t> used;
        for(const Face& f : faces)
          used.insert(f.begin(), f.end());
        DFP_CHECK(used.size() == n);
      }
    }
    DFP_CHECK(DFP::random_triples(10, 0, 1).empty());
  }

  // --- Figures 1 and 2 ----------------------------------------------------------------------

  // List points of merging_lists_configuration(k, m): row j is L_j (index j(m+1)) then its
  // list (j(m+1) + 1 .. j(m+1) + m); the k - 1 apexes follow.
  void merging(std::size_t k, std::size_t m, std::uint64_t seed, bool measure)
  {
    Scope s("merging_lists_configuration(", k, ", ", m, ")");
    const auto instance = DFP::merging_lists_configuration<K>(k, m, seed);
    const Points& P = instance.points;
    DFP_CHECK(P.size() == k * (m + 1) + k - 1);
    // The rows: one y per row, increasing with j; lists sorted in x, right of L_j.
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t t = 1; t <= m; ++t) {
        const std::size_t i = j * (m + 1) + t;
        DFP_CHECK(P[i].y() == P[j * (m + 1)].y());
        DFP_CHECK(P[i - 1].x() < P[i].x());
      }
    // Reduction: DT(P) joins consecutive list points of the merged x order.
    std::vector<std::size_t> list;
    for(std::size_t j = 0; j < k; ++j)
      for(std::size_t t = 1; t <= m; ++t)
        list.push_back(j * (m + 1) + t);
    std::sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) { return P[a].x() < P[b].x(); });
    const std::set<Edge> dt_edges = edges_of(DFP::delaunay_triangles(P));
    std::size_t missing = 0, ties = 0;
    for(std::size_t i = 0; i + 1 < list.size(); ++i) {
      if(P[list[i]].x() == P[list[i + 1]].x()) {
        ++ties; // equal numbers: their order is not defined
        continue;
      }
      missing += dt_edges.count(edge(list[i], list[i + 1])) == 0;
    }
    DFP_CHECK_MSG(missing == 0, missing << " consecutive pairs of the merged order are not Delaunay edges");
    DFP_CHECK(ties <= 1);
    if(!measure)
      return;
    check_triangulation(P, instance.faces);
    // D_local: measured exactly 2(k - 1) for every k, m and seed tried (k = 2..32, m =
    // 1..20): the two long edges L_j A_j and L_{j+1} A_j from each apex to the left ends of
    // its two rows are not locally Delaunay; every row, fan and right-end edge is. So
    // D_local = Theta(k), with the tight constant 2.
    // D: every pair of x-consecutive list points on different rows is a Delaunay edge that
    // G lacks (G has no edge between two rows' lists), and with random lists about
    // (1 - 1/k) km pairs are: D >= km/2 for k >= 4 (measured >= 0.6 km at m >= 5).
    const Measures r = DFP::prediction_measures(P, instance.faces);
    DFP_CHECK_MSG(r.D_local <= 2 * (k - 1) && r.D_local >= k - 1, describe(r));
    if(k >= 4)
      DFP_CHECK_MSG(2 * r.D >= k * m, describe(r));
    std::size_t cross_row = 0;
    for(std::size_t i = 0; i + 1 < list.size(); ++i)
      cross_row += list[i] / (m + 1) != list[i + 1] / (m + 1);
    DFP_CHECK_MSG(r.D >= cross_row, describe(r) << "; " << cross_row << " row changes in the merged order");
  }

  void figures()
  {
    std::uint64_t seed = 1;
    for(std::size_t k : {2, 3, 4, 5, 8})
      for(std::size_t m : {1, 2, 7, 20})
        merging(k, m, seed++, true);
    merging(16, 12, seed++, true);
    merging(16, 200, seed++, false);
    merging(64, 40, seed++, false);
    for(std::size_t n : {2, 3, 10, 60}) {
      Scope s("sorting_configuration(", n, ")");
      const auto sorting = DFP::sorting_configuration<K>(n, 33);
      const auto merging1 = DFP::merging_lists_configuration<K>(n, 1, 33);
      DFP_CHECK(sorting.points == merging1.points && sorting.faces == merging1.faces);
      DFP_CHECK(sorting.points.size() == 3 * n - 1);
      check_triangulation(sorting.points, sorting.faces);
      const Measures r = DFP::prediction_measures(sorting.points, sorting.faces);
      DFP_CHECK_MSG(r.D_local <= 2 * (n - 1), describe(r));
      if(n >= 4)
        DFP_CHECK_MSG(2 * r.D >= n, describe(r));
    }
    merging(400, 1, seed++, false); // sorting 400 numbers
  }

  // --- Bad arguments and degenerate point sets ----------------------------------------------

  void bad_arguments(const Points& points)
  {
    auto throws_invalid_argument = [](const auto& f) { return throws_exception<std::invalid_argument>(f); };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for(double rho : {-0.1, 1.5, nan}) {
      Scope s("rho = ", rho);
      DFP_CHECK(throws_invalid_argument([&] { DFP::random_flip_prediction(points, rho, 1); }));
      DFP_CHECK(throws_invalid_argument([&] { DFP::rho_model_prediction(points, rho, 1); }));
      DFP_CHECK(throws_invalid_argument([&] { DFP::delete_faces(Faces{{0, 1, 2}}, rho, 1); }));
    }
    DFP_CHECK(throws_invalid_argument([] { DFP::random_triples(2, 5, 1); }));
    DFP_CHECK(throws_invalid_argument([] { DFP::merging_lists_configuration<K>(1, 5, 1); }));
    DFP_CHECK(throws_invalid_argument([] { DFP::merging_lists_configuration<K>(3, 0, 1); }));
    DFP_CHECK(throws_invalid_argument([] { DFP::sorting_configuration<K>(1, 1); }));
  }

  // Every generator on point sets with no triangle, or with duplicates, and the measures of
  // what it returns: no crash (each in a child process), and sensible output.
  void degenerate_inputs()
  {
    const std::pair<const char*, XYs> inputs[] = {
        {"no point", {}},
        {"one point", {{0.5, 0.5}}},
        {"two points", {{0.5, 0.5}, {1.5, 0.5}}},
        {"three collinear points", {{0, 0}, {1, 1}, {2, 2}}},
        {"collinear points", collinear_points(20, rng)},
        {"all points equal", XYs(10, XY{0.25, 0.5})},
        {"two distinct points, copies", with_duplicates({{0.5, 0.5}, {1.5, 0.5}}, 6, rng)},
        {"three points", {{0, 0}, {1, 0}, {0, 1}}},
        {"four points in convex position", {{0, 0}, {2, 0}, {2, 1}, {0, 3}}},
        {"uniform with duplicates", with_duplicates(uniform_points(60, rng), 20, rng)},
        {"grid with duplicates", with_duplicates(grid_points(6, 6, rng), 10, rng)},
    };
    for(const auto& [name, xy] : inputs) {
      Scope scope(name);
      const Points points = to_points<K>(xy);
      const std::size_t n = points.size();
      std::vector<std::pair<std::string, std::function<Faces()>>> generators = {
          {"delaunay_triangles", [&] { return DFP::delaunay_triangles(points); }},
          {"random_flip_prediction", [&] { return DFP::random_flip_prediction(points, 0.5, 1); }},
          {"k_flip_prediction, k = 0", [&] { return DFP::k_flip_prediction(points, 0, 1); }},
          {"k_flip_prediction, k = 3", [&] { return DFP::k_flip_prediction(points, 3, 1); }},
          {"rho_model_prediction, adversarial", [&] { return DFP::rho_model_prediction(points, 0.3, 1); }},
          {"rho_model_prediction, random",
           [&] { return DFP::rho_model_prediction(points, 0.3, 1, DFP::Completion::random); }},
          {"moved_points_prediction", [&] { return DFP::moved_points_prediction(points, 0.5, 1); }},
          {"self_crossing_prediction", [&] { return DFP::self_crossing_prediction(points, 3, 1); }},
          {"delete_faces", [&] { return DFP::delete_faces(DFP::delaunay_triangles(points), 0.3, 1); }},
      };
      if(n >= 3)
        generators.emplace_back("random_triples", [&] { return DFP::random_triples(n, n, 1); });
      // Each generator in a child process first; then its output, and prediction_measures()
      // on it (in a child too), once per distinct output.
      const bool no_triangle = DFP::delaunay_triangles(points).empty();
      std::set<Faces> measured;
      for(const auto& [what, gen] : generators) {
        Scope s(what);
        if(!survives([&] { gen(); })) {
          DFP_CHECK_MSG(false, what << " crashed on " << name);
          continue;
        }
        const Faces faces = gen();
        DFP_CHECK(valid_triples(faces, n));
        if(no_triangle && what != "random_triples" && what != "moved_points_prediction")
          DFP_CHECK_MSG(faces.empty(), faces.size() << " faces");
        if(measured.insert(faces).second)
          DFP_CHECK_MSG(survives([&] { DFP::prediction_measures(points, faces); }),
                        "prediction_measures crashed on " << name << " with the " << faces.size()
                                                          << " faces of " << what);
      }
    }
  }

  // --- All ------------------------------------------------------------------------------------

  void all(std::size_t n, bool full)
  {
    const Points uniform = to_points<K>(uniform_points(n, rng));
    const int side = int(std::sqrt(double(n)));
    const Points grid = to_points<K>(grid_points(side, side, rng));
    {
      Scope s("determinism, uniform");
      DFP_RUN(determinism(uniform));
    }
    {
      Scope s("determinism, grid");
      DFP_RUN(determinism(grid));
    }
    const std::pair<const char*, Points> sets[] = {
        {"uniform", uniform},
        {"clustered", to_points<K>(clustered_points(n, rng))},
        {"integer grid", grid},
        {"lattice points on two circles and the centre", to_points<K>(lattice_circle_points(1105, rng, 65))},
        {"three rows", to_points<K>(grid_points(int(n / 3), 3, rng))},
        {"uniform + 1e15", to_points<K>(transformed(uniform_points(n, rng, 0., 1000.), 1., 1e15))},
        {"uniform * 1e-15", to_points<K>(transformed(uniform_points(n, rng), 1e-15, 0.))},
    };
    for(const auto& [name, points] : sets) {
      Scope s(name, " (", points.size(), " points)");
      DFP_RUN(triangulations(points));
      DFP_RUN(rho_model(points, false));
      DFP_RUN(k_flips(points));
      DFP_RUN(order_k(points, std::string(name) == "uniform" || std::string(name) == "clustered"));
      DFP_RUN(moved_points(points));
      DFP_RUN(holes(points));
      DFP_RUN(self_crossing(points));
      if(!full)
        break;
    }
    {
      // The fraction of kept edges, on a few thousand edges.
      Scope s("rho model on ", 5 * n, " uniform points");
      DFP_RUN(rho_model(to_points<K>(uniform_points(5 * n, rng)), true));
    }
    {
      Scope s("k flips on four points in convex position");
      const Points quad = to_points<K>({{0, 0}, {2, 0}, {2, 1}, {0, 3}});
      for(std::size_t k : {1, 2, 3, 8}) {
        const Faces faces = DFP::k_flip_prediction(quad, k, k);
        const Measures m = DFP::prediction_measures(quad, faces);
        // One flippable edge, flipped k times: DT(P) for even k, the other diagonal for odd.
        DFP_CHECK_MSG(m.is_triangulation && m.D == k % 2, describe(m));
      }
    }
    DFP_RUN(triples());
    DFP_RUN(figures());
    DFP_RUN(bad_arguments(uniform));
    DFP_RUN(degenerate_inputs());
  }
};

int main()
{
  {
    Scope scope("Epick");
    Models_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all(300, true);
  }
  {
    Scope scope("Epeck");
    Models_test<CGAL::Exact_predicates_exact_constructions_kernel>().all(60, false);
  }
  return finish("test_prediction_models");
}
