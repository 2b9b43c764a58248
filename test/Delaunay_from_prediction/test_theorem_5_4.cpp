// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Strategy::theorem_5_4 (Theorem 5.4 as written, region_recursion.h): every result equals
// CGAL's build, with the proof's first guess of d_cross and with guesses small enough that the
// recursion is several levels deep on a few thousand points. With the exact prediction no
// boundary edge is crossed and the completion G' is DT(P) itself (nothing for step 6 to
// repair); with a triangulation as prediction the completion's wrong edges stay within the
// proof's bound from the measured d_cross: each region gamma has at most 6 k + 2 |boundary|
// wrong edges in Y_gamma, k <= d_cross |boundary| the edges of DT(P) crossing its boundary.
// Degenerate inputs (grids, circles, collinear points, duplicates) run with every strategy in
// test_reliability.cpp too.

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/measures.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

using namespace dfp_test;

namespace {

bool verbose() { return std::getenv("DFP_TEST_VERBOSE") != nullptr; }

std::string describe(const DFP::Statistics& s)
{
  std::ostringstream out;
  out << s;
  return out.str();
}

// The first guesses tried: the proof's, and j = 0 and 1 (b = 2 and 4: base cases of 4 and 16
// faces), which make the recursion deep.
const int first_guesses[] = {-1, 0, 1};

template <class K>
DFP::Statistics run_theorem_5_4(const std::vector<typename K::Point_2>& points, const Faces& faces, int first_guess)
{
  DT_with_info<K> dt;
  DFP::Tuning tuning;
  tuning.d_cross_first_guess = first_guess;
  const DFP::Statistics s = DFP::delaunay_from_prediction(
      points, faces, dt, DFP::parameters::strategy(DFP::Strategy::theorem_5_4).tuning(tuning));
  check_is_cgal_delaunay(dt, points);
  check_statistics(s, faces, points, dt);
  DFP_CHECK_MSG(s.d_cross_guesses >= 1 || dt.dimension() < 2, describe(s)); // no face is flat: a guess

  return s;
}

// The exact prediction: G' is DT(P), its regions' boundaries crossed by no edge.
void check_nothing_to_repair(const DFP::Statistics& s)
{
  DFP_CHECK_MSG(!s.fell_back && s.boundary_crossings == 0 && s.edges_not_locally_delaunay == 0 && s.flips == 0 &&
                    s.faces_carved == 0 && s.holes_refilled == 0,
                describe(s));
  // From scratch in the base case; otherwise every predicted face kept.
  DFP_CHECK_MSG(s.faces_certified == (s.regions_per_level.empty() ? 0 : s.faces_in), describe(s));
}

void general_position()
{
  CGAL::Random rng(5401);
  using K = CGAL::Epick;
  for(const std::size_t n : {std::size_t(20), std::size_t(700), std::size_t(6000)}) {
    Scope size("n = ", n);
    const XYs xy = uniform_points(n, rng);
    const auto points = to_points<K>(xy);
    const Faces exact = faces_by_info(indexed_delaunay<K>(points));
    for(const int j : first_guesses) {
      Scope guess("first guess j = ", j);
      {
        Scope c("exact prediction");
        const DFP::Statistics s = run_theorem_5_4<K>(points, exact, j);
        check_nothing_to_repair(s);
        if(n >= 700 && j >= 0) {
          DFP_CHECK_MSG(s.regions_per_level.size() >= 2 && s.d_cross_guesses == 1, describe(s));
          DFP_CHECK_MSG(s.regions_per_level[0] >= 2, describe(s));
        }
        if(j < 0 && n < 200) // at most b^2 = 256 faces: the base case, from scratch
          DFP_CHECK_MSG(s.regions_per_level.empty(), describe(s));
      }
      if(n >= 700) {
        Scope c("the exact faces listed clockwise");
        check_nothing_to_repair(run_theorem_5_4<K>(points, reversed(exact), j));
      }
      {
        Scope c("random flips");
        const DFP::Statistics s = run_theorem_5_4<K>(points, flipped_delaunay_faces<K>(points, n / 50 + 1, rng), j);
        DFP_CHECK_MSG(!s.fell_back, describe(s));
      }
      {
        Scope c("points relabelled among themselves: long wrong edges, crossing faces");
        run_theorem_5_4<K>(points, with_points_relabelled(exact, n, 50, rng), j);
      }
      {
        Scope c("a PSLG with missing faces");
        run_theorem_5_4<K>(points, with_faces_deleted(exact, n / 20 + 1, rng), j);
      }
      {
        Scope c("random triples");
        run_theorem_5_4<K>(points, random_triples(n, 2 * n, rng), j);
      }
      {
        Scope c("moved points (0.5 spacing) with their old triangulation");
        const XYs moved = jittered(xy, 0.5 / std::sqrt(double(n)), rng);
        run_theorem_5_4<K>(to_points<K>(moved), exact, j);
      }
    }
  }
}

// The proof's counting argument, on the completion G' (the union of the kept Y_gamma) of a
// prediction that is a triangulation: D(G') <= sum over regions of 6 k + 2 |boundary|, with
// k <= d_cross |boundary|, so D(G') <= (6 d_cross + 2) times the boundary edges of level 0.
void wrong_edges_within_the_bound()
{
  CGAL::Random rng(5402);
  using K = CGAL::Epick;
  using Point = K::Point_2;
  const std::size_t n = 4000;
  const auto points = to_points<K>(uniform_points(n, rng));
  std::vector<std::pair<const char*, std::pair<const std::vector<Point>*, Faces>>> cases;
  cases.push_back({"random flips", {&points, flipped_delaunay_faces<K>(points, n / 10, rng)}});
  cases.push_back({"many random flips", {&points, flipped_delaunay_faces<K>(points, n, rng)}});
  for(const auto& c : cases) {
    Scope scope(c.first);
    const std::vector<Point>& p = *c.second.first;
    const Faces& g = c.second.second;
    const DFP::Prediction_measures of_g = DFP::prediction_measures(p, g);
    DFP_CHECK_MSG(of_g.is_triangulation, of_g.not_a_triangulation);
    std::vector<std::uint32_t> triples;
    for(const Face& f : g)
      triples.insert(triples.end(), {std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
    for(const int j : {0, 1, 2}) {
      Scope guess("first guess j = ", j);
      auto repair = [&](const std::vector<std::uint32_t>& global, const std::vector<std::uint32_t>& faces,
                        std::size_t budget, std::vector<std::uint32_t>& out, std::size_t& work) {
        std::vector<Point> local;
        for(const std::uint32_t k : global)
          local.push_back(p[k]);
        return DFP::internal::repair_region_completion<DT_plain<K>>(K(), local, faces, budget, out, work);
      };
      std::vector<std::uint32_t> completion;
      DFP::internal::Region_recursion_report report;
      DFP_CHECK(DFP::internal::completion_by_region_recursion(
          K(), [&](std::uint32_t k) -> const Point& { return p[k]; }, n, triples, repair, j, completion, report));
      DFP_CHECK_MSG(!report.counts.regions_per_level.empty(), report.counts.regions_per_level.size());
      Faces g_prime;
      std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
      for(std::size_t k = 0; k < completion.size(); k += 3) {
        g_prime.push_back({std::size_t(completion[k]), std::size_t(completion[k + 1]), std::size_t(completion[k + 2])});
        DFP_CHECK(CGAL::orientation(p[completion[k]], p[completion[k + 1]], p[completion[k + 2]]) == CGAL::LEFT_TURN);
        for(int i = 0; i < 3; ++i) // the kept triangles of different regions never overlap
          DFP_CHECK(directed.insert({completion[k + i], completion[k + (i + 1) % 3]}).second);
      }
      const DFP::Prediction_measures of_completion = DFP::prediction_measures(p, g_prime);
      const std::size_t bound = (6 * of_g.d_cross + 2) * report.counts.top_boundary_edges;
      if(verbose())
        std::cout << "  D(G) = " << of_g.D << ", d_cross = " << of_g.d_cross << ", D(G') = " << of_completion.D
                  << ", boundary edges " << report.counts.top_boundary_edges << ", crossings "
                  << report.counts.crossings << "\n";
      DFP_CHECK_MSG(of_completion.D <= bound, of_completion.D << " wrong edges, bound " << bound);
    }
  }
}

// Degenerate points: the result is CGAL's, through step 6's certificate and repair.
void degenerate_points()
{
  CGAL::Random rng(5403);
  using K = CGAL::Epick;
  for(const auto& family : small_degenerate_families(rng)) {
    Scope c(family.first);
    const auto points = to_points<K>(family.second);
    const Faces exact = faces_by_info(indexed_delaunay<K>(points));
    for(const int j : first_guesses) {
      Scope guess("first guess j = ", j);
      run_theorem_5_4<K>(points, exact, j);
      run_theorem_5_4<K>(points, random_triples(points.size(), points.size(), rng), j);
    }
  }
}

// Vertices of high degree, whose edges the recursion looks up in a hash map rather than by a
// scan of their triangles: a fan of a convex polygon from one vertex (a triangulation, far
// from Delaunay), and many random triples on few points (repeated directed edges).
void high_degree_vertices()
{
  CGAL::Random rng(5406);
  using K = CGAL::Epick;
  const std::size_t n = 400;
  XYs xy;
  for(std::size_t i = 0; i < n; ++i) {
    const double angle = 6.283185307179586 * double(i) / double(n), radius = 1 + rng.get_double(0, 1e-3);
    xy.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  const auto points = to_points<K>(xy);
  Faces fan;
  for(std::size_t i = 1; i + 1 < n; ++i)
    fan.push_back({0, i, i + 1});
  const auto few = to_points<K>(uniform_points(60, rng));
  for(const int j : first_guesses) {
    Scope guess("first guess j = ", j);
    {
      Scope c("fan");
      const DFP::Statistics s = run_theorem_5_4<K>(points, fan, j);
      DFP_CHECK_MSG(!s.regions_per_level.empty(), describe(s)); // the fan was divided
    }
    {
      Scope c("random triples on few points");
      run_theorem_5_4<K>(few, random_triples(few.size(), 3000, rng), j);
    }
  }
}

// Points moved by about one spacing under their old triangulation, from the first guess
// j = 0 (a cap of mu units of work): the regions' repairs pass it, the next guesses follow.
// With the exact prediction there is nothing to repair but the pockets between the regions
// and their hulls: the first guess holds.
void guesses_of_d_cross()
{
  CGAL::Random rng(5);
  using K = CGAL::Epick;
  const std::size_t n = 6000;
  const XYs xy = uniform_points(n, rng);
  const Faces old = faces_by_info(indexed_delaunay<K>(to_points<K>(xy)));
  const auto moved = to_points<K>(jittered(xy, 1.0 / std::sqrt(double(n)), rng));
  const DFP::Statistics s = run_theorem_5_4<K>(moved, old, 0);
  DFP_CHECK_MSG(s.d_cross_guesses >= 2, describe(s));
  const DFP::Statistics exact = run_theorem_5_4<K>(to_points<K>(xy), old, 0);
  DFP_CHECK_MSG(exact.d_cross_guesses == 1 && exact.regions_per_level.size() >= 3, describe(exact));
}

void epeck()
{
  CGAL::Random rng(5405);
  using K = CGAL::Epeck;
  const auto points = to_points<K>(uniform_points(1500, rng));
  for(const int j : first_guesses)
    run_theorem_5_4<K>(points, flipped_delaunay_faces<K>(points, 30, rng), j);
}

} // namespace

int main()
{
  DFP_RUN(general_position());
  DFP_RUN(wrong_edges_within_the_bound());
  DFP_RUN(degenerate_points());
  DFP_RUN(high_degree_vertices());
  DFP_RUN(guesses_of_d_cross());
  DFP_RUN(epeck());
  return finish("test_theorem_5_4");
}
