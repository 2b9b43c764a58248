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

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

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
    DFP_CHECK_MSG(!s.fell_back, "'" << s.fallback_reason << "' after " << s.flips << " flips; "
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
      const std::string reason = s.fallback_reason;
      DFP_CHECK_MSG(reason == "the flip budget was exhausted" ||
                        reason == "the edges failing the in-circle test would need more flips than the budget" ||
                        reason == "most sampled faces have sampled points inside their circumcircles",
                    reason);
    }
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
  return finish("test_triangulation_prediction");
}
