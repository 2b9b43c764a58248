// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Strategy::theorem_4_1 (Theorem 4.1 as written, supercells.h): every result equals CGAL's
// build, and on points in general position the faces the theorem computes are DT(P)'s
// before any repair (the import certifies them with no failing edge, no flip, no hole); with
// the exact prediction every supercell is good and every predicted face kept; with wrong
// edges the bad supercells stay few (the paper: O(D)). The exact tests behind it: which site
// is nearer to a circumcentre, on ties, on huge coordinates (the intervals overflow and the
// exact path decides) and with Epeck. Degenerate inputs (grids, circles, collinear points,
// duplicates) run with every strategy in test_reliability.cpp.

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/voronoi_predicates.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

using namespace dfp_test;

namespace {

template <class K>
DFP::Statistics run_theorem_4_1(const std::vector<typename K::Point_2>& points, const Faces& faces)
{
  DT_with_info<K> dt;
  const DFP::Statistics s =
      DFP::delaunay_from_prediction(points, faces, dt, DFP::parameters::strategy(DFP::Strategy::theorem_4_1));
  check_is_cgal_delaunay(dt, points);
  if(dt.dimension() == 2) { // points on a line have no rounds: the prediction is used as it is
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.insertion_rounds == 3);
  }
  DFP_CHECK_MSG(s.bad_supercells <= s.supercells, s.bad_supercells << " of " << s.supercells);
  return s;
}

// The theorem's own faces are DT(P)'s: nothing for the certificate to repair.
void check_computed_exactly(const DFP::Statistics& s)
{
  DFP_CHECK_MSG(s.edges_not_locally_delaunay == 0 && s.flips == 0 && s.faces_carved == 0 && s.holes_refilled == 0,
                s.edges_not_locally_delaunay << " failing edges, " << s.flips << " flips, " << s.faces_carved
                                             << " carved, " << s.holes_refilled << " holes");
}

void general_position()
{
  CGAL::Random rng(4101);
  using K = CGAL::Epick;
  for(const std::size_t n : {std::size_t(20), std::size_t(700), std::size_t(20000)}) {
    Scope size("n = ", n);
    const auto points = to_points<K>(uniform_points(n, rng));
    const Faces exact = faces_by_info(indexed_delaunay<K>(points));
    {
      Scope c("exact prediction: every supercell good, every face kept");
      const DFP::Statistics s = run_theorem_4_1<K>(points, exact);
      check_computed_exactly(s);
      if(n >= 20000) {
        DFP_CHECK_MSG(s.supercells >= 10, s.supercells << " supercells");
        DFP_CHECK_MSG(s.bad_supercells == 0, s.bad_supercells << " bad supercells");
        DFP_CHECK_MSG(s.faces_certified == s.faces_in, s.faces_certified << " of " << s.faces_in << " kept");
        DFP_CHECK(s.walls > 0 && s.chain_edges > 0);
      }
    }
    if(n >= 20000) {
      Scope c("the exact faces listed clockwise: the same faces, every supercell good");
      const DFP::Statistics s = run_theorem_4_1<K>(points, reversed(exact));
      check_computed_exactly(s);
      DFP_CHECK_MSG(s.bad_supercells == 0, s.bad_supercells << " bad supercells");
    }
    {
      Scope c("random flips: few bad supercells");
      std::size_t done = 0;
      const Faces flipped = flipped_delaunay_faces<K>(points, n / 500 + 1, rng, &done);
      const DFP::Statistics s = run_theorem_4_1<K>(points, flipped);
      check_computed_exactly(s);
      if(n >= 20000) {
        // Each wrong edge spoils the supercells whose regions hold its two faces.
        DFP_CHECK_MSG(s.bad_supercells >= 1 && s.bad_supercells <= 4 * done,
                      s.bad_supercells << " bad supercells for " << done << " flips");
        DFP_CHECK(s.cells_computed > 0);
        DFP_CHECK(s.faces_certified < s.faces_in);
      }
    }
    {
      Scope c("points relabelled among themselves: long wrong edges, crossing faces");
      check_computed_exactly(run_theorem_4_1<K>(points, with_points_relabelled(exact, n, 50, rng)));
    }
    {
      Scope c("a PSLG with missing faces (Corollary 4.2)");
      check_computed_exactly(run_theorem_4_1<K>(points, with_faces_deleted(exact, n / 20 + 1, rng)));
    }
    {
      Scope c("random triples");
      check_computed_exactly(run_theorem_4_1<K>(points, random_triples(n, 2 * n, rng)));
    }
  }
}

// Degenerate points: the result is CGAL's, through the certificate's repair where a circle
// of DT(P) goes through sites of the sample (the manual says so).
void degenerate_points()
{
  CGAL::Random rng(4102);
  using K = CGAL::Epick;
  for(const auto& family : small_degenerate_families(rng)) {
    Scope c(family.first);
    const auto points = to_points<K>(family.second);
    run_theorem_4_1<K>(points, faces_by_info(indexed_delaunay<K>(points)));
  }
}

void epeck()
{
  CGAL::Random rng(4103);
  using K = CGAL::Epeck;
  const auto points = to_points<K>(uniform_points(2000, rng));
  check_computed_exactly(run_theorem_4_1<K>(points, flipped_delaunay_faces<K>(points, 10, rng)));
}

// compare_distances_to_circumcentre(): the sign of |x - u|^2 - |x - v|^2 for the circumcentre
// x of (a, b, c), against values worked out by hand, at scales where the interval filter
// decides and where it cannot (ties, and coordinates whose squares overflow).
void nearer_to_circumcentre()
{
  using P = CGAL::Epick::Point_2;
  using DFP::internal::compare_distances_to_circumcentre;
  // Powers of two keep every coordinate exact, down to denormals.
  for(const double scale : {1.0, 0x1p-500, 0x1p500, 0x1p1000, 0x1p-1040}) {
    Scope at("scale ", scale);
    auto p = [&](double x, double y) { return P(x * scale, y * scale); };
    // The unit square's triangle: x = (0.5, 0.5), all four corners at the same distance.
    const P a = p(0, 0), b = p(1, 0), c = p(1, 1);
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(0, 1), a) == 0);
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(0, 1), p(1, 1)) == 0);
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(0.5, 0.75), a) < 0);
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(2, 2), p(0, 1)) > 0);
    // Two points at distance 1 from x, then one of them moved by 2^-20 (2^-40 in the squares).
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(0.5, -0.5), p(0.5, 1.5)) == 0);
    DFP_CHECK(compare_distances_to_circumcentre(a, b, c, p(0.5 + 0x1p-20, -0.5), p(0.5, 1.5)) > 0);
  }
}

} // namespace

int main()
{
  DFP_RUN(nearer_to_circumcentre());
  DFP_RUN(general_position());
  DFP_RUN(degenerate_points());
  DFP_RUN(epeck());
  return finish("test_theorem_4_1");
}
