// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// A prediction that is a valid but far from Delaunay triangulation: a plain
// CGAL::Triangulation_2 of the points (points inserted one by one, in their order). Repairing
// it takes about 2-6 n flips, more than the default budget (n/2 + 64, past which a rebuild is
// cheaper), so:
//  - with a budget large enough and the screen off, it is repaired by flips alone (fell_back
//    false, at least one flip per wrong edge), and the result is CGAL's DT;
//  - with default parameters the result is CGAL's DT too, and if the call falls back, the
//    reason is the flip budget (spent, or the failing edges would exceed it) or the sampling
//    screen, never a failed certification.
// The failing-edge screen (failing_edges_exceed(), read before the import): it flags a
// rho-model prediction with the adversarial completion (about 1.6 n wrong edges, the default
// budget allows 0.56 n failing edges) and passes DT(P) and DT(P) with 1% of its edges flipped;
// with the faces in random order it concludes nothing; a budget the caller sets keeps its
// exact meaning (the screen does not run).

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/prediction_models.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Points = std::vector<K::Point_2>;

void check_plain_triangulation(const Points& points, CGAL::Random& rng)
{
  const Faces faces = shuffled(faces_by_info(indexed_triangulation<K>(points)), rng);
  const std::size_t wrong = edges_not_in_delaunay<K>(faces, points);
  DFP_CHECK(wrong > 0);
  {
    DT_with_info<K> dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(
        points, faces, dt,
        DFP::parameters::max_flips(100 * points.size(), DFP::parameters::screen_prediction(false)));
    check_is_cgal_delaunay(dt, points);
    check_statistics(s, faces, points, dt);
    DFP_CHECK_MSG(!s.fell_back, "'" << to_string(s.outcome) << "' after " << s.flips << " flips; "
                                    << wrong << " edges not in the DT, n = " << points.size());
    DFP_CHECK(s.flips >= wrong);
    DFP_CHECK(s.points_unused == 0);
  }
  {
    DT_with_info<K> dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt);
    check_is_cgal_delaunay(dt, points);
    check_statistics(s, faces, points, dt);
    if(s.fell_back) {
      DFP_CHECK_MSG(s.outcome == DFP::Outcome::flip_budget_exhausted ||
                        s.outcome == DFP::Outcome::too_many_failing_edges ||
                        s.outcome == DFP::Outcome::screen_rejected,
                    to_string(s.outcome));
    }
  }
}

void check_failing_edge_screen(const Points& points, CGAL::Random& rng)
{
  const std::size_t n = points.size();
  const std::size_t limit = DFP::internal::max_failing_edges(DFP::internal::default_max_flips(n));
  auto triples_of = [](const std::vector<DFP::Indexed_triangle>& triangles) {
    std::vector<std::uint32_t> t;
    for(const DFP::Indexed_triangle& f : triangles)
      for(const std::size_t v : f)
        t.push_back(std::uint32_t(v));
    return t;
  };
  auto exceeds = [&](const std::vector<DFP::Indexed_triangle>& triangles) {
    return DFP::internal::failing_edges_exceed(points.begin(), n, triples_of(triangles), limit);
  };
  const std::vector<DFP::Indexed_triangle> bad =
      DFP::rho_model_prediction(points, 0.1, 17, DFP::Completion::adversarial);
  const std::size_t wrong = edges_not_in_delaunay<K>(bad, points);
  DFP_CHECK_MSG(wrong > limit, wrong << " wrong edges, limit " << limit);
  DFP_CHECK(exceeds(bad));
  DFP_CHECK(!exceeds(DFP::random_flip_prediction(points, 1.0, 17)));  // DT(P) itself
  DFP_CHECK(!exceeds(DFP::random_flip_prediction(points, 0.99, 17))); // 1% of its edges flipped
  std::vector<DFP::Indexed_triangle> shuffled_bad = bad;
  std::shuffle(shuffled_bad.begin(), shuffled_bad.end(), std::mt19937(std::uint32_t(rng.get_int(0, 1 << 30))));
  DFP_CHECK(!exceeds(shuffled_bad)); // too few edges pair within a window: no conclusion
  {
    // Default parameters: rebuilt before the import (nothing reordered), equal to CGAL's.
    DT_with_info<K> dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, bad, dt);
    check_is_cgal_delaunay(dt, points);
    DFP_CHECK(s.fell_back);
    DFP_CHECK_MSG(s.outcome == DFP::Outcome::too_many_failing_edges, to_string(s.outcome));
    DFP_CHECK(!s.input_reordered && s.edges_tested == 0);
  }
  {
    // The caller's budget, larger than the flips needed: repaired by flips, no screen.
    DT_with_info<K> dt;
    const DFP::Statistics s =
        DFP::delaunay_from_prediction(points, bad, dt, DFP::parameters::max_flips(100 * n));
    check_is_cgal_delaunay(dt, points);
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.flips >= wrong);
  }
}

int main()
{
  CGAL::Random rng(1789);
  for(std::size_t n : {std::size_t(30), std::size_t(300), std::size_t(3000), std::size_t(6000)}) {
    {
      Scope scope("Triangulation_2 of ", n, " uniform points");
      DFP_RUN(check_plain_triangulation(to_points<K>(uniform_points(n, rng)), rng));
    }
    {
      Scope scope("Triangulation_2 of ", n, " clustered points");
      DFP_RUN(check_plain_triangulation(to_points<K>(clustered_points(n, rng)), rng));
    }
  }
  for(std::size_t n : {std::size_t(20000), std::size_t(60000)}) {
    Scope scope("failing-edge screen, ", n, " uniform points");
    DFP_RUN(check_failing_edge_screen(to_points<K>(uniform_points(n, rng)), rng));
  }
  return finish("test_triangulation_prediction");
}
