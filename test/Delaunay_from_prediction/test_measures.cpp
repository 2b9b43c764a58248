// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// prediction_measures() (measures.h), the closeness measures of Table 1 of the paper:
//  - hand-built cases whose every measure is worked out in the comments: a co-circular
//    quadrilateral with the wrong diagonal, fans of points in convex position on a parabola,
//    a co-circular 4x4 grid with some diagonals swapped, two small non-triangulations, and
//    the list-merging configuration of Figure 2 (D_local = O(k) while D = Theta(n));
//  - an independent brute-force reference (O(n^2) and O(n^3) loops over the definitions,
//    with CGAL's Delaunay_triangulation_2 and the kernel's predicates only) compared field by
//    field with prediction_measures() on random, degenerate (grids, co-circular lattice points,
//    points on a circle, collinear sets, duplicates, 1e15 offsets, 1e-15 scales) and
//    non-triangulation predictions, from every generator of prediction_models.h and more;
//  - the relations of Section 1.3: D_local <= D <= D_flip <= D_cross and D = D_missing for a
//    triangulation, and "every measure is 0 iff G = DT(P)";
//  - malformed input throws Invalid_prediction; the max_flips named parameter.
// Epick for everything, Epeck for a smaller subset.

#include <CGAL/Delaunay_from_prediction/measures.h> // first: the header is self-contained
#include <CGAL/Delaunay_from_prediction/prediction_models.h>

#include "test_util.h"

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>

#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

using namespace dfp_test;
using Measures = DFP::Prediction_measures;

// ---------------------------------------------------------------------------------------------
// The reference: every measure from its definition, by brute force.
// ---------------------------------------------------------------------------------------------

struct Reference
{
  std::size_t points = 0, faces = 0, edges = 0, delaunay_edges = 0;
  bool is_triangulation = false;
  std::string why_not;
  std::size_t D = 0, D_missing = 0, D_cross = 0, d_cross = 0, D_vio = 0, d_vio = 0;
  // D_local of an edge whose two faces lie on the same side of it (only in a
  // non-triangulation) could depend on which face is read as "the other face": the
  // definition (fourth point inside the circumcircle of the other face) is not symmetric
  // there. measures.h counts such an edge if either reading fails (D_local_max); the
  // reference also keeps the other reading (D_local_min). For faces on opposite sides both
  // readings agree.
  std::size_t D_local_min = 0, D_local_max = 0;
  std::size_t degenerate_faces = 0, edges_with_more_than_two_faces = 0;
  std::size_t same_side_edges = 0; // edges whose D_local reading is ambiguous
};

template <class FT>
CGAL::Exact_rational exact_coordinate(const FT& v)
{
  // Every test coordinate is a double, so this conversion is exact; checked.
  const double d = CGAL::to_double(v);
  DFP_CHECK_MSG(FT(d) == v, "a coordinate is not a double: the exact area test needs one");
  return CGAL::Exact_rational(d);
}

// Twice the signed area of (a, b, c), exactly.
template <class Point>
CGAL::Exact_rational twice_area(const Point& a, const Point& b, const Point& c)
{
  const CGAL::Exact_rational ax = exact_coordinate(a.x()), ay = exact_coordinate(a.y());
  const CGAL::Exact_rational bx = exact_coordinate(b.x()), by = exact_coordinate(b.y());
  const CGAL::Exact_rational cx = exact_coordinate(c.x()), cy = exact_coordinate(c.y());
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// Computes everything but D_flip (whose exact value is NP-hard to get) from the definitions
// of Table 1 and the conventions of measures.h: points at the same position are the point of
// smallest index; edges are counted once; the perturbed in-circle test is CGAL's own
// Triangulation_2::side_of_oriented_circle(p0, p1, p2, p, true) on a ccw triangle; a crossing
// is a pair of edges whose relative interiors meet in one point. Faces must be valid (indices
// in range, three different indices).
template <class K>
Reference reference_measures(const std::vector<typename K::Point_2>& P, const Faces& faces)
{
  using Point = typename K::Point_2;
  using Pair = std::pair<std::size_t, std::size_t>;
  using Triple = std::array<std::size_t, 3>;
  Reference r;
  const std::size_t n = P.size();
  r.points = n;
  r.faces = faces.size();

  // Canonical index of every point: the smallest index at its position.
  std::map<Point, std::size_t> first;
  for(std::size_t i = 0; i < n; ++i)
    first.emplace(P[i], i);
  std::vector<std::size_t> canon(n);
  std::vector<std::size_t> distinct;
  std::vector<std::pair<Point, std::size_t>> distinct_points;
  for(std::size_t i = 0; i < n; ++i) {
    canon[i] = first.at(P[i]);
    if(canon[i] == i) {
      distinct.push_back(i);
      distinct_points.emplace_back(P[i], i);
    }
  }

  // DT(P), vertex info the canonical index; its edges, hull edges and area.
  DT_with_info<K> dt;
  dt.insert(distinct_points.begin(), distinct_points.end());
  auto key = [](std::size_t a, std::size_t b) { return a < b ? Pair(a, b) : Pair(b, a); };
  std::set<Pair> dt_edges, hull_edges;
  if(dt.dimension() >= 1)
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const Pair k = key(e->first->vertex(dt.ccw(e->second))->info(),
                         e->first->vertex(dt.cw(e->second))->info());
      dt_edges.insert(k);
      if(dt.dimension() == 2 &&
         (dt.is_infinite(e->first) || dt.is_infinite(e->first->neighbor(e->second))))
        hull_edges.insert(k);
    }
  r.delaunay_edges = dt_edges.size();
  CGAL::Exact_rational hull_area = 0;
  if(dt.dimension() == 2)
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      hull_area += twice_area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());

  const auto orientation = dt.geom_traits().orientation_2_object();
  // Strictly inside the perturbed circumcircle of the ccw triangle t.
  auto inside = [&](const Triple& t, std::size_t s) {
    return dt.side_of_oriented_circle(P[t[0]], P[t[1]], P[t[2]], P[s], true) == CGAL::ON_POSITIVE_SIDE;
  };

  // G's faces in canonical indices, ccw; degenerate ones flagged.
  std::vector<Triple> g;
  std::vector<bool> degenerate;
  for(const Face& f : faces) {
    Triple t{canon[f[0]], canon[f[1]], canon[f[2]]};
    bool flat = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    if(!flat) {
      const CGAL::Orientation o = orientation(P[t[0]], P[t[1]], P[t[2]]);
      flat = o == CGAL::COLLINEAR;
      if(o == CGAL::RIGHT_TURN)
        std::swap(t[1], t[2]);
    }
    g.push_back(t);
    degenerate.push_back(flat);
  }

  // Edge -> (face, opposite vertex) for every listing of the edge by a face. A face with two
  // points at the same position, (a, a', c), lists the edge ac twice (as a'c and as ca).
  std::map<Pair, std::vector<Pair>> incidences;
  for(std::size_t k = 0; k < g.size(); ++k)
    for(int j = 0; j < 3; ++j) {
      const std::size_t a = g[k][(j + 1) % 3], b = g[k][(j + 2) % 3];
      if(a != b)
        incidences[key(a, b)].emplace_back(k, g[k][j]);
    }
  r.edges = incidences.size();
  for(const auto& [e, list] : incidences) {
    if(dt_edges.count(e) == 0)
      ++r.D;
    if(list.size() > 2) {
      ++r.edges_with_more_than_two_faces;
    } else if(list.size() == 2) {
      const std::size_t f1 = list[0].first, c = list[0].second;
      const std::size_t f2 = list[1].first, d = list[1].second;
      if(!degenerate[f1] && !degenerate[f2] && c != d) {
        const bool d_in_f1 = inside(g[f1], d), c_in_f2 = inside(g[f2], c);
        const auto oc = orientation(P[e.first], P[e.second], P[c]);
        const auto od = orientation(P[e.first], P[e.second], P[d]);
        if(oc != od) {
          // Faces on both sides: the perturbed test is the sign of one alternating 4x4
          // determinant, so both readings agree (a check of this reference).
          DFP_CHECK_MSG(d_in_f1 == c_in_f2, "reference: in-circle asymmetric across edge " << e.first
                                                                                         << "-" << e.second);
          r.D_local_min += d_in_f1;
          r.D_local_max += d_in_f1;
        } else {
          ++r.same_side_edges;
          r.D_local_min += d_in_f1 && c_in_f2;
          r.D_local_max += d_in_f1 || c_in_f2;
        }
      }
    }
  }
  for(const Pair& e : dt_edges)
    r.D_missing += incidences.count(e) == 0;

  // D_cross, d_cross: every (edge of G, edge of DT) pair; a crossing is proper (all four
  // orientations non-zero and opposite in pairs). Touching at a point (a vertex of one edge
  // on the other, or a shared endpoint) and collinear overlap are not crossings.
  std::vector<Pair> dt_edge_list(dt_edges.begin(), dt_edges.end());
  std::vector<CGAL::Bbox_2> dt_boxes;
  for(const Pair& e : dt_edge_list)
    dt_boxes.push_back(P[e.first].bbox() + P[e.second].bbox());
  for(const auto& [e, list] : incidences) {
    const std::size_t a = e.first, b = e.second;
    const CGAL::Bbox_2 box = P[a].bbox() + P[b].bbox();
    std::size_t crossings = 0;
    for(std::size_t k = 0; k < dt_edge_list.size(); ++k) {
      const std::size_t c = dt_edge_list[k].first, d = dt_edge_list[k].second;
      if(c == a || c == b || d == a || d == b || !CGAL::do_overlap(box, dt_boxes[k]))
        continue;
      const auto o1 = orientation(P[a], P[b], P[c]), o2 = orientation(P[a], P[b], P[d]);
      if(o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o1 == o2)
        continue;
      const auto o3 = orientation(P[c], P[d], P[a]), o4 = orientation(P[c], P[d], P[b]);
      if(o3 == CGAL::COLLINEAR || o4 == CGAL::COLLINEAR || o3 == o4)
        continue;
      ++crossings;
    }
    if(dt_edges.count(e) != 0)
      DFP_CHECK_MSG(crossings == 0, "reference: two Delaunay edges cross");
    r.D_cross += crossings;
    r.d_cross = (std::max)(r.d_cross, crossings);
  }

  // D_vio, d_vio: every distinct point against every distinct non-degenerate face of G.
  std::set<Triple> seen;
  bool repeated_face = false;
  for(std::size_t k = 0; k < g.size(); ++k) {
    Triple sorted = g[k];
    std::sort(sorted.begin(), sorted.end());
    if(!seen.insert(sorted).second) {
      repeated_face = true;
      continue;
    }
    if(degenerate[k]) {
      ++r.degenerate_faces;
      continue;
    }
    std::size_t count = 0;
    for(const std::size_t s : distinct)
      if(s != g[k][0] && s != g[k][1] && s != g[k][2] && inside(g[k], s))
        ++count;
    r.D_vio += count;
    r.d_vio = (std::max)(r.d_vio, count);
  }

  // Is G a triangulation of P? Sufficient and necessary, for distinct points all used and
  // non-degenerate faces: each edge has at most one face on each side, an edge with faces
  // on one side only is an edge of the convex hull, and the areas add up to the hull's
  // (then the faces cover the hull exactly once away from their edges, which forbids
  // overlaps, a vertex wound twice round, and a point inside an edge or a face).
  auto fail = [&](const char* why) {
    if(r.why_not.empty())
      r.why_not = why;
  };
  if(n < 3 || faces.empty())
    fail("fewer than three points or no face");
  if(distinct.size() != n)
    fail("duplicate points");
  std::vector<bool> used(n, false);
  for(const Face& f : faces)
    used[f[0]] = used[f[1]] = used[f[2]] = true;
  if(std::count(used.begin(), used.end(), false) > 0)
    fail("unused point");
  if(std::count(degenerate.begin(), degenerate.end(), true) > 0)
    fail("degenerate face");
  if(repeated_face)
    fail("repeated face");
  if(r.why_not.empty()) {
    for(const auto& [e, list] : incidences) {
      std::size_t left = 0, right = 0;
      for(const Pair& fv : list)
        (orientation(P[e.first], P[e.second], P[fv.second]) == CGAL::LEFT_TURN ? left : right) += 1;
      if(left > 1 || right > 1)
        fail("two faces on the same side of an edge");
      else if((left == 0 || right == 0) && hull_edges.count(e) == 0)
        fail("a boundary edge that is not a hull edge");
    }
    CGAL::Exact_rational area = 0;
    for(const Triple& t : g)
      area += twice_area(P[t[0]], P[t[1]], P[t[2]]);
    if(area != hull_area)
      fail("the faces' area is not the hull's");
  }
  r.is_triangulation = r.why_not.empty();
  return r;
}

// ---------------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------------

std::string describe(const Measures& m)
{
  std::ostringstream out;
  out << "n=" << m.points << " F=" << m.faces << " E=" << m.edges << " E_DT=" << m.delaunay_edges
      << " tri=" << m.is_triangulation << " D=" << m.D << " D_missing=" << m.D_missing
      << " D_local=" << m.D_local << " D_cross=" << m.D_cross << " d_cross=" << m.d_cross
      << " D_vio=" << m.D_vio << " d_vio=" << m.d_vio << " D_flip_upper=";
  if(m.D_flip_upper)
    out << *m.D_flip_upper;
  else
    out << "none";
  out << " degenerate=" << m.degenerate_faces << " >2 faces=" << m.edges_with_more_than_two_faces;
  if(!m.not_a_triangulation.empty())
    out << " (" << m.not_a_triangulation << ")";
  return out.str();
}

// Relations that hold for every prediction (the inequalities only for a triangulation).
void check_relations(const Measures& m)
{
  DFP_CHECK_MSG(m.is_triangulation == m.not_a_triangulation.empty(), describe(m));
  DFP_CHECK_MSG(m.D_flip_lower == m.D, describe(m));
  DFP_CHECK_MSG(m.d_cross <= m.D_cross && (m.d_cross == 0) == (m.D_cross == 0), describe(m));
  DFP_CHECK_MSG(m.d_vio <= m.D_vio && (m.d_vio == 0) == (m.D_vio == 0), describe(m));
  DFP_CHECK_MSG(m.D <= m.edges && m.D_missing <= m.delaunay_edges, describe(m));
  if(m.is_triangulation) {
    // Section 1.3: D_local <= D <= D_flip <= D_cross (Hanke, Ottmann and Schuierer: Lawson's
    // algorithm makes at most D_cross flips), and D = D_missing (all triangulations of P have
    // the same number of edges).
    DFP_CHECK_MSG(m.D == m.D_missing, describe(m));
    DFP_CHECK_MSG(m.edges == m.delaunay_edges, describe(m));
    DFP_CHECK_MSG(m.D_local <= m.D, describe(m));
    DFP_CHECK_MSG(m.D_flip_upper.has_value(), describe(m));
    if(m.D_flip_upper) {
      DFP_CHECK_MSG(m.D <= *m.D_flip_upper, describe(m));
      DFP_CHECK_MSG(*m.D_flip_upper <= m.D_cross, describe(m));
    }
    DFP_CHECK_MSG(m.degenerate_faces == 0 && m.edges_with_more_than_two_faces == 0, describe(m));
    DFP_CHECK_MSG(m.faces + m.points + 1 == m.edges + 2 || m.points < 3, describe(m)); // Euler
    // Every measure is 0 exactly when G = DT(P).
    const bool is_dt = m.D == 0;
    DFP_CHECK_MSG((m.D_local == 0) == is_dt, describe(m));
    DFP_CHECK_MSG((m.D_cross == 0) == is_dt, describe(m));
    DFP_CHECK_MSG((m.D_vio == 0) == is_dt, describe(m));
    DFP_CHECK_MSG((m.D_flip_upper == std::optional<std::size_t>(0)) == is_dt, describe(m));
  } else {
    DFP_CHECK_MSG(!m.D_flip_upper.has_value(), describe(m));
  }
}

// prediction_measures() against the reference, field by field; returns the measures.
template <class K>
Measures compare_with_reference(const std::vector<typename K::Point_2>& points, const Faces& faces)
{
  if(std::getenv("DFP_VERBOSE") != nullptr)
    std::cerr << "case: " << where() << std::endl;
  Measures m;
  try {
    m = DFP::prediction_measures(points, faces);
  } catch(const std::exception& e) {
    DFP_CHECK_MSG(false, "prediction_measures threw: " << e.what());
    return m;
  }
  const Reference r = reference_measures<K>(points, faces);
  const std::string got = describe(m);
  DFP_CHECK_MSG(m.points == r.points, got);
  DFP_CHECK_MSG(m.faces == r.faces, got);
  DFP_CHECK_MSG(m.edges == r.edges, got << "; reference " << r.edges);
  DFP_CHECK_MSG(m.delaunay_edges == r.delaunay_edges, got << "; reference " << r.delaunay_edges);
  DFP_CHECK_MSG(m.is_triangulation == r.is_triangulation,
                got << "; reference says " << (r.is_triangulation ? "triangulation" : r.why_not));
  DFP_CHECK_MSG(m.D == r.D, got << "; reference " << r.D);
  DFP_CHECK_MSG(m.D_missing == r.D_missing, got << "; reference " << r.D_missing);
  DFP_CHECK_MSG(m.D_local == r.D_local_max,
                got << "; reference " << r.D_local_max << " (either reading of folded faces)");
  DFP_CHECK_MSG(m.D_cross == r.D_cross, got << "; reference " << r.D_cross);
  DFP_CHECK_MSG(m.d_cross == r.d_cross, got << "; reference " << r.d_cross);
  DFP_CHECK_MSG(m.D_vio == r.D_vio, got << "; reference " << r.D_vio);
  DFP_CHECK_MSG(m.d_vio == r.d_vio, got << "; reference " << r.d_vio);
  DFP_CHECK_MSG(m.degenerate_faces == r.degenerate_faces, got << "; reference " << r.degenerate_faces);
  DFP_CHECK_MSG(m.edges_with_more_than_two_faces == r.edges_with_more_than_two_faces,
                got << "; reference " << r.edges_with_more_than_two_faces);
  if(r.is_triangulation)
    DFP_CHECK(r.same_side_edges == 0);
  check_relations(m);
  return m;
}

// Expected values of a hand-built case.
struct Expected
{
  std::size_t points, faces, edges, delaunay_edges;
  bool is_triangulation;
  std::size_t D, D_missing, D_local, D_cross, d_cross, D_vio, d_vio;
  std::optional<std::size_t> D_flip_upper;
  std::size_t degenerate_faces, edges_with_more_than_two_faces;
};

void check_expected(const Measures& m, const Expected& e)
{
  const std::string got = describe(m);
  DFP_CHECK_MSG(m.points == e.points, got);
  DFP_CHECK_MSG(m.faces == e.faces, got);
  DFP_CHECK_MSG(m.edges == e.edges, got);
  DFP_CHECK_MSG(m.delaunay_edges == e.delaunay_edges, got);
  DFP_CHECK_MSG(m.is_triangulation == e.is_triangulation, got);
  DFP_CHECK_MSG(m.D == e.D, got);
  DFP_CHECK_MSG(m.D_missing == e.D_missing, got);
  DFP_CHECK_MSG(m.D_local == e.D_local, got);
  DFP_CHECK_MSG(m.D_cross == e.D_cross, got);
  DFP_CHECK_MSG(m.d_cross == e.d_cross, got);
  DFP_CHECK_MSG(m.D_vio == e.D_vio, got);
  DFP_CHECK_MSG(m.d_vio == e.d_vio, got);
  DFP_CHECK_MSG(m.D_flip_lower == e.D, got);
  DFP_CHECK_MSG(m.D_flip_upper == e.D_flip_upper, got);
  DFP_CHECK_MSG(m.degenerate_faces == e.degenerate_faces, got);
  DFP_CHECK_MSG(m.edges_with_more_than_two_faces == e.edges_with_more_than_two_faces, got);
}

// ---------------------------------------------------------------------------------------------
// The tests
// ---------------------------------------------------------------------------------------------

template <class K>
struct Measures_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;

  CGAL::Random rng{20260}; // test_util's generators
  std::uint64_t seed = 1;  // the package's generators

  Measures check(const Points& points, const Faces& faces, const Expected& e)
  {
    Measures m;
    DFP_RUN(m = compare_with_reference<K>(points, faces));
    check_expected(m, e);
    return m;
  }

  // --- Four co-circular points --------------------------------------------------------------
  // Both diagonals are Delaunay without perturbation; CGAL's perturbation picks one (asked
  // of CGAL, not assumed). With G = the other diagonal: 4 points, 2 faces, 5 edges in each
  // triangulation; the wrong diagonal is the one edge of G not in DT (D = D_missing = 1); it
  // is not locally Delaunay (the perturbed lifting of 4 points in convex position makes
  // exactly one diagonal locally Delaunay: D_local = 1); it crosses the other diagonal at one
  // point (D_cross = d_cross = 1); each face of G has the fourth point inside its perturbed
  // circle (the edge test read from either face; D_vio = 2, d_vio = 1); one flip repairs it.
  void cocircular_quadrilaterals()
  {
    const XYs shapes[] = {
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}},     // unit square
        {{0, 0}, {4, 0}, {4, 2}, {0, 2}},     // rectangle
        {{-1, 0}, {0, -1}, {1, 0}, {0, 1}},   // diamond (ties in x)
        {{5, 0}, {0, 5}, {-3, -4}, {4, -3}},  // on x^2 + y^2 = 25, not symmetric (ccw order)
    };
    for(const XYs& xy : shapes) {
      Scope scope("co-circular quadrilateral (", xy[0].x, ", ", xy[0].y, "), (", xy[1].x, ", ",
                  xy[1].y, "), ...");
      const Points points = to_points<K>(xy);
      const auto dt = indexed_delaunay<K>(points);
      bool has02 = false, has13 = false;
      for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        const std::size_t a = e->first->vertex(dt.ccw(e->second))->info();
        const std::size_t b = e->first->vertex(dt.cw(e->second))->info();
        has02 = has02 || (std::min(a, b) == 0 && std::max(a, b) == 2);
        has13 = has13 || (std::min(a, b) == 1 && std::max(a, b) == 3);
      }
      DFP_CHECK_MSG(has02 != has13, "CGAL's DT has exactly one diagonal");
      const Faces diagonal02 = {{0, 1, 2}, {0, 2, 3}}, diagonal13 = {{0, 1, 3}, {1, 2, 3}};
      const Faces& right = has02 ? diagonal02 : diagonal13;
      const Faces& wrong = has02 ? diagonal13 : diagonal02;
      {
        Scope s("G = DT");
        //                points faces edges E_DT tri  D  Dm Dl Dc dc Dv dv flips   deg >2
        check(points, right, {4, 2, 5, 5, true, 0, 0, 0, 0, 0, 0, 0, std::size_t(0), 0, 0});
        check(points, reversed(right), {4, 2, 5, 5, true, 0, 0, 0, 0, 0, 0, 0, std::size_t(0), 0, 0});
      }
      {
        Scope s("G = the other diagonal");
        check(points, wrong, {4, 2, 5, 5, true, 1, 1, 1, 1, 1, 2, 1, std::size_t(1), 0, 0});
        check(points, reversed(wrong), {4, 2, 5, 5, true, 1, 1, 1, 1, 1, 2, 1, std::size_t(1), 0, 0});
      }
      {
        // Both diagonals at once: 4 faces covering the square twice. Edges: 4 sides
        // + 2 diagonals = 6; D = 1 (the wrong diagonal), D_missing = 0. Each side has two
        // faces on the same side (D_local counts an edge there if either reading fails).
        // The diagonals cross once (D_cross = d_cross = 1). Faces of G: the two right ones
        // hold no point, the two wrong ones one each (D_vio = 2, d_vio = 1).
        Scope s("G = both diagonals (overlapping faces)");
        Faces both = wrong;
        both.insert(both.end(), right.begin(), right.end());
        const Measures m = compare_with_reference<K>(points, both);
        DFP_CHECK_MSG(!m.is_triangulation && m.edges == 6 && m.D == 1 && m.D_missing == 0 &&
                          m.D_cross == 1 && m.d_cross == 1 && m.D_vio == 2 && m.d_vio == 1 &&
                          !m.D_flip_upper && m.edges_with_more_than_two_faces == 0,
                      describe(m));
      }
    }
  }

  // --- Convex position: points on the parabola y = x^2, x = 0, 1, ..., 6 ----------------------
  // A circle meets y = x^2 where x^4 + (1 - 2b) x^2 - 2a x + c = 0: no x^3 term, so its four
  // intersections sum to 0 and the circle through the points at x1 < x2 < x3 (all >= 0) meets
  // the parabola again at x4 = -(x1 + x2 + x3) < 0. A point x >= 0 of the parabola is inside
  // the circle iff (x - x1)(x - x2)(x - x3)(x - x4) < 0, i.e. iff x < x1 or x2 < x < x3.
  // (No four of these points are co-circular: x4 is negative.)
  // So triangle (i, j, k) is empty iff i = 0 and k = j + 1: DT(P) is the fan from point 0,
  // with diagonals 0-2, 0-3, 0-4, 0-5 and the 7 hull edges (11 edges, 5 faces).
  void parabola_fans()
  {
    XYs xy;
    for(int x = 0; x <= 6; ++x)
      xy.push_back({double(x), double(x * x)});
    const Points points = to_points<K>(xy);
    auto fan = [](std::size_t v) { // the fan from v: triangles (v, j, j+1), j and j+1 != v
      Faces faces;
      for(std::size_t j = 0; j < 7; ++j) {
        const std::size_t a = j, b = (j + 1) % 7;
        if(a != v && b != v)
          faces.push_back({v, a, b});
      }
      return faces;
    };
    {
      Scope s("parabola, fan from 0 = DT(P)");
      check(points, fan(0), {7, 5, 11, 11, true, 0, 0, 0, 0, 0, 0, 0, std::size_t(0), 0, 0});
    }
    {
      // Fan from 3: faces (3,0,1), (3,1,2), (3,4,5), (3,5,6), (3,6,0); diagonals 3-0, 3-1, 3-5,
      // 3-6, of which 3-0 is in DT(P): D = D_missing = 3.
      // D_local: 3-0 is Delaunay. 3-1 (faces 013, 123): 2 is inside circle(0,1,3) (1 < 2 < 3):
      // not locally Delaunay. 3-5 (faces 345, 356): 6 inside circle(3,4,5) needs 6 < 3 or
      // 4 < 6 < 5: no, locally Delaunay although wrong. 3-6 (faces 356, 360): 0 inside
      // circle(3,5,6) (0 < 3): not locally Delaunay. D_local = 2 < D.
      // D_cross: in convex position two chords cross iff their ends interleave. 1-3 crosses
      // 0-2; 3-5 crosses 0-4; 3-6 crosses 0-4 and 0-5. D_cross = 4, d_cross = 2.
      // D_vio: circle(0,1,3) holds {2}; circle(1,2,3) {0}; circle(3,4,5) {0,1,2};
      // circle(3,5,6) {0,1,2}; circle(0,3,6) {4,5}: D_vio = 1+1+3+3+2 = 10, d_vio = 3.
      // Lawson: only 1-3 and 3-6 are flippable non-locally-Delaunay edges; 1-3 -> 0-2, 3-6 ->
      // 0-5, after which 3-5 (faces 345, 035) has 0 inside circle(3,4,5) and goes to 0-4. No
      // other edge is ever non-locally Delaunay (a DT edge never is), so 3 flips in any order.
      Scope s("parabola, fan from 3");
      check(points, fan(3), {7, 5, 11, 11, true, 3, 3, 2, 4, 2, 10, 3, std::size_t(3), 0, 0});
    }
    {
      // Fan from 6: diagonals 6-1, 6-2, 6-3, 6-4, none in DT(P): D = D_missing = 4.
      // D_local: 6-j (faces (j-1, j, 6), (j, j+1, 6)) has j+1 inside circle(j-1, j, 6) since
      // j < j+1 < 6 for j <= 4: all 4 not locally Delaunay.
      // D_cross: 6-j crosses 0-k iff j < k < 6, k in 2..5: 4 + 3 + 2 + 1 = 10, d_cross = 4.
      // D_vio: circle(j, j+1, 6) holds the x < j and the j+1 < x < 6: j + (4 - j) = 4 points,
      // for each of the 5 faces: D_vio = 20, d_vio = 4.
      // D_flip is 4 (flip 6-1, 6-2, 6-3, 6-4 in that order); Lawson's count depends on the
      // order it tries edges: between D = 4 and D_cross = 10.
      Scope s("parabola, fan from 6");
      const Measures m = check(points, fan(6), {7, 5, 11, 11, true, 4, 4, 4, 10, 4, 20, 4, lawson_flips(points, fan(6)), 0, 0});
      DFP_CHECK_MSG(m.D_flip_upper && *m.D_flip_upper >= 4 && *m.D_flip_upper <= 10, describe(m));
    }
    {
      // The max_flips named parameter: the fan from 3 needs 3 flips. A budget of 3 gives
      // D_flip_upper = 3; a budget of 2 leaves it empty and changes nothing else.
      Scope s("parabola, fan from 3, max_flips");
      const Measures three = DFP::prediction_measures(points, fan(3), DFP::parameters::max_flips(std::size_t(3)));
      check_expected(three, {7, 5, 11, 11, true, 3, 3, 2, 4, 2, 10, 3, std::size_t(3), 0, 0});
      const Measures two = DFP::prediction_measures(points, fan(3), DFP::parameters::max_flips(std::size_t(2)));
      check_expected(two, {7, 5, 11, 11, true, 3, 3, 2, 4, 2, 10, 3, std::nullopt, 0, 0});
      const Measures zero = DFP::prediction_measures(points, fan(0), DFP::parameters::max_flips(std::size_t(0)));
      check_expected(zero, {7, 5, 11, 11, true, 0, 0, 0, 0, 0, 0, 0, std::size_t(0), 0, 0});
    }
  }

  // Lawson's count for G, as prediction_measures reports it (for the one case where it is
  // bounded, not fixed, and checked by range).
  static std::optional<std::size_t> lawson_flips(const Points& points, const Faces& faces)
  {
    return DFP::prediction_measures(points, faces).D_flip_upper;
  }

  // --- The 4x4 integer grid -----------------------------------------------------------------
  // Every unit square is co-circular and its circle holds no other grid point (the nearest
  // other ones are at distance sqrt(5/2) > sqrt(1/2) from its centre), so the unperturbed
  // Delaunay subdivision is the 9 squares and CGAL's perturbation adds one diagonal to each
  // (asked of CGAL). 16 points, 18 faces, 24 sides + 9 diagonals = 33 edges.
  // G = DT(P) with the diagonals of a set S of squares swapped: D = D_missing = |S|; each
  // swapped diagonal is not locally Delaunay (perturbed) while a side is (the fourth point
  // across it is at distance sqrt(5/2) from the circle's centre): D_local = |S|; each swapped
  // diagonal crosses only its square's other diagonal: D_cross = |S|, d_cross = [S != {}];
  // each face of a swapped square has exactly its square's fourth corner inside its perturbed
  // circle: D_vio = 2|S|, d_vio = [S != {}]; Lawson flips exactly the |S| swapped diagonals.
  void grid4()
  {
    XYs xy;
    for(int x = 0; x < 4; ++x)
      for(int y = 0; y < 4; ++y)
        xy.push_back({double(x), double(y)});
    const Points points = to_points<K>(xy);
    auto index = [](int x, int y) { return std::size_t(4 * x + y); };
    const auto dt = indexed_delaunay<K>(points);
    std::set<std::pair<std::size_t, std::size_t>> dt_edges;
    for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
      const std::size_t a = e->first->vertex(dt.ccw(e->second))->info();
      const std::size_t b = e->first->vertex(dt.cw(e->second))->info();
      dt_edges.emplace(std::min(a, b), std::max(a, b));
    }
    DFP_CHECK(dt_edges.size() == 33);
    // rising[x][y]: CGAL's diagonal of square (x, y) goes from (x, y) to (x+1, y+1).
    bool rising[3][3];
    for(int x = 0; x < 3; ++x)
      for(int y = 0; y < 3; ++y) {
        rising[x][y] = dt_edges.count({index(x, y), index(x + 1, y + 1)}) != 0;
        const bool falling = dt_edges.count({index(x, y + 1), index(x + 1, y)}) != 0;
        DFP_CHECK_MSG(rising[x][y] != falling, "square " << x << ", " << y << " has one diagonal");
      }
    const std::vector<std::pair<const char*, std::vector<int>>> subsets = {
        {"none", {}},
        {"one", {4}},
        {"corner", {0}},
        {"checkerboard", {0, 2, 4, 6, 8}},
        {"all", {0, 1, 2, 3, 4, 5, 6, 7, 8}},
    };
    for(const auto& [name, swapped] : subsets) {
      Scope s("4x4 grid, diagonals swapped: ", name);
      Faces faces;
      for(int x = 0; x < 3; ++x)
        for(int y = 0; y < 3; ++y) {
          const bool swap = std::find(swapped.begin(), swapped.end(), 3 * x + y) != swapped.end();
          const std::size_t a = index(x, y), b = index(x + 1, y), c = index(x + 1, y + 1), d = index(x, y + 1);
          if(rising[x][y] != swap) { // diagonal a-c
            faces.push_back({a, b, c});
            faces.push_back({a, c, d});
          } else { // diagonal b-d
            faces.push_back({a, b, d});
            faces.push_back({b, c, d});
          }
        }
      const std::size_t k = swapped.size(), any = k > 0 ? 1 : 0;
      check(points, faces, {16, 18, 33, 33, true, k, k, k, k, any, 2 * k, any, k, 0, 0});
      check(points, shuffled(faces, rng), {16, 18, 33, 33, true, k, k, k, k, any, 2 * k, any, k, 0, 0});
    }
  }

  // --- Small non-triangulations ---------------------------------------------------------------
  // a = (0,0), b = (4,0), c = (0,3), d = (1,1) inside abc. DT(P): abd, bcd, cad (6 edges).
  // circle(a,b,c) has centre (2, 1.5), radius^2 6.25: d (distance^2 3.25) is inside.
  // circle(a,b,d) has centre (2,-1), radius^2 5: c (distance^2 20) is outside.
  void small_non_triangulations()
  {
    const Points points = to_points<K>({{0, 0}, {4, 0}, {0, 3}, {1, 1}});
    {
      // G = {abc}: d unused. Edges ab, bc, ca, all hull edges of DT: D = 0, D_missing = 3,
      // no edge with two faces (D_local = 0), no crossing, D_vio = d_vio = 1 (d in abc's circle).
      Scope s("hull triangle, inner point unused");
      check(points, {{0, 1, 2}}, {4, 1, 3, 6, false, 0, 3, 0, 0, 0, 1, 1, std::nullopt, 0, 0});
    }
    {
      // G = {abc, abd}: overlapping, both faces above ab. Edges ab, bc, ca, bd, da, all in DT:
      // D = 0, D_missing = 1 (cd). D_vio = 1 (d in circle(abc); c not in circle(abd)).
      // D_local of ab: d is inside circle(abc) but c is outside circle(abd): the definition
      // gives 1 or 0 depending on which face is "the" face; both orders are listed.
      Scope s("overlapping triangles");
      const Measures m1 = compare_with_reference<K>(points, {{0, 1, 2}, {0, 1, 3}});
      const Measures m2 = compare_with_reference<K>(points, {{0, 1, 3}, {0, 1, 2}});
      for(const Measures& m : {m1, m2})
        DFP_CHECK_MSG(!m.is_triangulation && m.edges == 5 && m.delaunay_edges == 6 && m.D == 0 &&
                          m.D_missing == 1 && m.D_local <= 1 && m.D_cross == 0 && m.D_vio == 1 &&
                          m.d_vio == 1 && !m.D_flip_upper,
                      describe(m));
    }
    {
      // G = DT(P) plus the hull triangle abc: ab has faces abd and abc, both above it (same for
      // bc and ca: ambiguous D_local, left to the reference's range); ad, bd, cd have two faces
      // on opposite sides and are Delaunay. Edges: 6, all in DT: D = D_missing = 0; no
      // crossing; D_vio = d_vio = 1 (abc holds d); not a triangulation.
      Scope s("DT plus the hull triangle");
      Faces faces = delaunay_faces<K>(points);
      faces.push_back({0, 1, 2});
      const Measures m = compare_with_reference<K>(points, faces);
      DFP_CHECK_MSG(!m.is_triangulation && m.edges == 6 && m.D == 0 && m.D_missing == 0 &&
                        m.D_local <= 3 && m.D_cross == 0 && m.D_vio == 1 && m.d_vio == 1,
                    describe(m));
    }
    {
      // Degenerate faces and a duplicate point: P = a(0,0), b(2,2), c(2,0), m(1,1) (on ab),
      // a'(0,0) = a. DT(P): m splits the hull edge ab: triangles acm, mcb; edges am, mb, bc,
      // ca, cm: 5.
      // G = {a m b (collinear), a' b c (abc through the duplicate), a a' c (flat: two points
      // at the same position)}; in canonical indices amb (degenerate), abc, aac (degenerate).
      // Edges: am, mb, ab, bc, ca (aa' is no edge): 5. D = 1 (ab), D_missing = 1 (cm).
      // D_vio: circle(abc) has the right angle at c, so its centre is the midpoint m of ab:
      // m is inside. D_vio = d_vio = 1. Distinct degenerate faces: amb and aac, 2.
      // ab is listed twice (amb, abc) but amb is degenerate: D_local = 0.
      // ca is listed three times: by abc, and twice by aac (as a'c and as ca): 1 edge with
      // more than two faces. D_cross: ab passes through m (touching cm there, not crossing).
      Scope s("degenerate faces and a duplicate point");
      const Points p5 = to_points<K>({{0, 0}, {2, 2}, {2, 0}, {1, 1}, {0, 0}});
      check(p5, {{0, 3, 1}, {4, 1, 2}, {0, 4, 2}}, {5, 3, 5, 5, false, 1, 1, 0, 0, 0, 1, 1, std::nullopt, 2, 1});
    }
    {
      // An edge of G through a point: P = a(0,0), b(4,0), c(2,2), d(2,-3), m(2,0) (m on ab and
      // on cd; no four points co-circular). The only triangulation, so DT(P): the 4 triangles
      // at m; edges: 4 hull sides + am, bm, cm, dm = 8. G = {abc, bad}: edges ab (through m,
      // wrong), bc, ca, ad, db: D = 1, D_missing = 4 (am, bm, cm, dm). ab touches cm and dm
      // at m and contains am and bm: D_cross = 0 although D = 1 (G leaves m unused).
      // circle(abc): centre m, radius 2: holds m, not d (distance 3). circle(bad): centre
      // (2, -5/6), radius^2 4 + 25/36: holds m (distance 5/6), not c (distance 17/6).
      // D_vio = 2, d_vio = 1; ab's faces are on both sides and d is outside circle(abc):
      // D_local = 0.
      Scope s("an edge of G through a point");
      const Points p5 = to_points<K>({{0, 0}, {4, 0}, {2, 2}, {2, -3}, {2, 0}});
      check(p5, {{0, 1, 2}, {1, 0, 3}}, {5, 2, 5, 8, false, 1, 4, 0, 0, 0, 2, 1, std::nullopt, 0, 0});
    }
  }

  // --- Figure 2: merging k lists ----------------------------------------------------------
  // D_local counts only O(k) edges near the ends of the rows (the dotted edges of Figure 2):
  // per gap between two rows, the two long edges L_j A_j and L_{j+1} A_j from the apex to
  // the left ends of the rows fail the in-circle test, every row and fan edge passes it, so
  // D_local <= 2(k - 1) (measured: exactly 2(k - 1); test_prediction_models has the details).
  // DT(P) joins consecutive points of the merged x order, most of which lie on different
  // rows (G has no edge between two lists): D >= km/2 for k >= 4 (expected (1 - 1/k) km).
  void merging_lists()
  {
    const std::size_t ks[] = {2, 3, 4, 6, 8};
    const std::size_t ms[] = {1, 5, 12, 25};
    for(std::size_t k : ks)
      for(std::size_t m : ms) {
        if(k * m > 200)
          continue; // keep D_cross (about n^2 / 8) and the reference cheap
        Scope s("merging ", k, " lists of ", m);
        const auto instance = DFP::merging_lists_configuration<K>(k, m, seed++);
        DFP_CHECK(instance.points.size() == k * (m + 1) + k - 1);
        const Measures r = compare_with_reference<K>(instance.points, instance.faces);
        DFP_CHECK_MSG(r.is_triangulation, describe(r));
        DFP_CHECK_MSG(r.D_local <= 2 * (k - 1) && r.D_local >= k - 1, describe(r));
        if(k >= 4)
          DFP_CHECK_MSG(2 * r.D >= k * m, describe(r));
      }
  }

  // --- Malformed input ------------------------------------------------------------------------
  void malformed()
  {
    const Points points = to_points<K>({{0, 0}, {1, 0}, {0, 1}, {1, 1}});
    auto throws = [&](const auto& faces) {
      return throws_exception<DFP::Invalid_prediction>([&] { DFP::prediction_measures(points, faces); });
    };
    DFP_CHECK(throws(Faces{{0, 1, 4}}));
    DFP_CHECK(throws(Faces{{0, 1, 2}, {1, 2, std::size_t(-1)}}));
    DFP_CHECK(throws(Faces{{0, 1, 1}}));
    DFP_CHECK(throws(Faces{{2, 1, 2}}));
    DFP_CHECK(throws(Faces{{3, 3, 3}}));
    DFP_CHECK(throws(std::vector<std::array<int, 3>>{{0, 1, 2}, {0, -1, 2}}));
    DFP_CHECK(throws(std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 1}}));
    DFP_CHECK(!throws(std::vector<std::array<int, 3>>{{0, 1, 2}, {1, 3, 2}}));
    DFP_CHECK(!throws(Faces{}));
    if constexpr(std::is_same<typename K::FT, double>::value) { // no NaN in an exact number type
      Points bad = points;
      bad.push_back(make_point<K>(std::numeric_limits<double>::quiet_NaN(), 0.));
      DFP_CHECK(throws_exception<DFP::Invalid_prediction>([&] { DFP::prediction_measures(bad, Faces{{0, 1, 2}}); }));
    }
  }

  // --- Every generator, and other predictions, against the reference ----------------------
  // `full`: also the costly generators (adversarial completion with small rho).
  void predictions(const char* name, const Points& points, bool full = true)
  {
    Scope scope(name, " (", points.size(), " points)");
    const std::size_t n = points.size();
    const Faces dt = DFP::delaunay_triangles(points);
    // The package's DT is CGAL's, face for face.
    {
      Faces a = dt, b = delaunay_faces<K>(points);
      for(Face& f : a)
        f = canonical(f);
      for(Face& f : b)
        f = canonical(f);
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      const auto first = smallest_indices(points);
      for(Face& f : b) // test_util's indices of duplicates are any one of them
        f = canonical(Face{first.at(points[f[0]]), first.at(points[f[1]]), first.at(points[f[2]])});
      std::sort(b.begin(), b.end());
      DFP_CHECK(a == b);
    }
    std::set<std::size_t> distinct;
    for(const auto& kv : smallest_indices(points))
      distinct.insert(kv.second);
    const bool all_distinct = distinct.size() == n;
    if(distinct.size() < 2 && !all_distinct) {
      // Fewer than two distinct points, with copies: prediction_measures dereferences the
      // null face handle DT::locate() returns in dimension 0 (reported as a bug). Check that
      // it survives, in a child process, then stop.
      for(const Faces& faces : {Faces(), n >= 3 ? Faces{{0, 1, 2}} : Faces()}) {
        const Points copy = points;
        DFP_CHECK_MSG(survives([&] { DFP::prediction_measures(copy, faces); }),
                      "prediction_measures crashed on " << n << " copies of one point, " << faces.size() << " faces");
      }
      return;
    }
    const bool planar = !dt.empty();
    auto run = [&](const char* what, const Faces& faces) {
      Scope s(what);
      Measures m;
      DFP_RUN(m = compare_with_reference<K>(points, faces));
      return m;
    };
    {
      const Measures m = run("G = DT(P)", dt);
      if(planar && all_distinct)
        DFP_CHECK_MSG(m.is_triangulation && m.D == 0 && m.D_missing == 0 && m.D_local == 0 &&
                          m.D_cross == 0 && m.D_vio == 0 && m.d_vio == 0 &&
                          m.D_flip_upper == std::optional<std::size_t>(0),
                      describe(m));
      else
        DFP_CHECK_MSG(!m.is_triangulation, describe(m));
      run("G = DT(P), shuffled", shuffled(dt, rng));
      run("G = DT(P), reversed", reversed(dt));
      const Measures twice = run("G = DT(P) listed twice", listed_twice(dt));
      DFP_CHECK_MSG(!twice.is_triangulation, describe(twice));
    }
    if(planar) {
      // One flip: D = D_missing = D_local = D_cross = d_cross = D_flip = 1 (the new edge lies
      // inside the quadrilateral, where only the old diagonal is); D_vio >= 2 (each new face
      // holds the opposite corner).
      const Faces one = DFP::k_flip_prediction(points, 1, seed++);
      const Measures m = run("k_flip_prediction, k = 1", one);
      if(all_distinct && m.D > 0)
        DFP_CHECK_MSG(m.is_triangulation && m.D == 1 && m.D_missing == 1 && m.D_local == 1 &&
                          m.D_cross == 1 && m.d_cross == 1 && m.D_vio >= 2 && m.d_vio >= 1 &&
                          m.D_flip_upper == std::optional<std::size_t>(1),
                      describe(m));
      std::size_t done = 0;
      const Faces mine = flipped_delaunay_faces<K>(points, 1, rng, &done);
      const Measures m2 = run("test_util's one random flip", mine);
      if(all_distinct && done == 1)
        DFP_CHECK_MSG(m2.is_triangulation && m2.D == 1 && m2.D_local == 1 && m2.D_cross == 1 &&
                          m2.D_vio >= 2 && m2.D_flip_upper == std::optional<std::size_t>(1),
                      describe(m2));
    }
    for(std::size_t k : {std::size_t(0), std::size_t(5), n / 4 + 1}) {
      if(!planar && k > 0)
        continue; // k_flip_prediction(k >= 1) divides by zero without a triangle: see test_prediction_models
      const Measures m = run(("k_flip_prediction, k = " + std::to_string(k)).c_str(),
                             DFP::k_flip_prediction(points, k, seed++));
      DFP_CHECK_MSG(m.D <= k, describe(m));
      DFP_CHECK_MSG(m.is_triangulation == (planar && all_distinct), describe(m));
    }
    for(double rho : {1.0, 0.9, 0.5, 0.0}) {
      const Measures m = run(("random_flip_prediction, rho = " + std::to_string(rho)).c_str(),
                             DFP::random_flip_prediction(points, rho, seed++));
      DFP_CHECK_MSG(m.is_triangulation == (planar && all_distinct), describe(m));
      DFP_CHECK_MSG(m.D_flip_upper || !m.is_triangulation, describe(m));
    }
    for(double rho : {1.0, 0.8, 0.3, 0.0})
      for(DFP::Completion completion : {DFP::Completion::adversarial, DFP::Completion::random}) {
        if(!full && rho < 0.5 && completion == DFP::Completion::adversarial)
          continue;
        const std::string what = "rho_model_prediction, rho = " + std::to_string(rho) +
                                 (completion == DFP::Completion::adversarial ? ", adversarial" : ", random");
        const Measures m = run(what.c_str(), DFP::rho_model_prediction(points, rho, seed++, completion));
        DFP_CHECK_MSG(m.is_triangulation == (planar && all_distinct), describe(m));
      }
    for(double noise : {0.0, 0.05, 0.5})
      run(("moved_points_prediction, noise = " + std::to_string(noise)).c_str(),
          DFP::moved_points_prediction(points, noise, seed++));
    {
      const Faces holes = DFP::delete_faces(dt, 0.1, seed++);
      const Measures m = run("delete_faces, 10%", holes);
      if(holes.size() < dt.size())
        DFP_CHECK_MSG(!m.is_triangulation, describe(m));
    }
    for(std::size_t swaps : {1, 20}) {
      const Measures m = run(("self_crossing_prediction, swaps = " + std::to_string(swaps)).c_str(),
                             DFP::self_crossing_prediction(points, swaps, seed++));
      DFP_CHECK_MSG(m.edges_with_more_than_two_faces == 0, describe(m));
    }
    if(n >= 3)
      for(std::size_t count : {n / 2 + 1, 2 * n}) {
        const Measures m = run(("random_triples, " + std::to_string(count)).c_str(),
                               DFP::random_triples(n, count, seed++));
        DFP_CHECK_MSG(!m.is_triangulation, describe(m));
      }
    {
      const Faces t2 = faces_by_info(indexed_triangulation<K>(points));
      const Measures m = run("a plain Triangulation_2", t2);
      DFP_CHECK_MSG(m.is_triangulation == (planar && all_distinct), describe(m));
    }
    if(n >= 6) {
      const Faces half = delaunay_faces<K>(Points(points.begin(), points.begin() + std::ptrdiff_t(n / 2)));
      const Measures m = run("DT of the first half of the points", half);
      DFP_CHECK_MSG(!m.is_triangulation, describe(m));
    }
    if(planar) {
      Faces extra = dt;
      extra.push_back(dt.front());
      const Measures m = run("DT(P) with one face listed twice", extra);
      DFP_CHECK_MSG(!m.is_triangulation, describe(m));
    }
    run("no face", Faces());
  }

  void point_sets(std::size_t n, bool full)
  {
    for(int trial = 0; trial < 3; ++trial)
      predictions("uniform", to_points<K>(uniform_points(trial == 1 ? n / 3 : n, rng)), full);
    predictions("uniform, small", to_points<K>(uniform_points(12, rng)), full);
    predictions("clustered", to_points<K>(clustered_points(n, rng)), full);
    const int side = int(std::sqrt(double(n)) * 0.8);
    predictions("integer grid", to_points<K>(grid_points(side, side, rng)), full);
    predictions("integer grid, 3 rows (collinear-heavy)", to_points<K>(grid_points(int(n / 6), 3, rng)), full);
    predictions("lattice points of x^2+y^2=1105^2 and the centre (co-circular)",
                to_points<K>(lattice_circle_points(1105, rng)), full);
    predictions("lattice points of two concentric circles", to_points<K>(lattice_circle_points(1105, rng, 65)), full);
    {
      XYs circle;
      for(std::size_t i = 0; i < n / 3; ++i) {
        const double t = 6.283185307179586 * double(i) / double(n / 3);
        circle.push_back({std::cos(t), std::sin(t)});
      }
      predictions("points on a circle (rounded)", to_points<K>(circle), full);
    }
    {
      // Points on three lines through a common point, plus uniform points.
      XYs xy = uniform_points(n / 3, rng, -1., 1.);
      for(std::size_t i = 0; i < n / 6; ++i) {
        const double t = double(i) / double(n / 6) * 2. - 1.;
        xy.push_back({t, 0.});
        xy.push_back({0., t});
        xy.push_back({t, t});
      }
      shuffle(xy, rng);
      predictions("three lines and uniform points", to_points<K>(xy), full);
    }
    predictions("all collinear", to_points<K>(collinear_points(n / 8 + 3, rng)), full);
    predictions("uniform with duplicates", to_points<K>(with_duplicates(uniform_points(n / 2, rng), n / 6, rng)), full);
    predictions("grid with duplicates", to_points<K>(with_duplicates(grid_points(8, 8, rng), 20, rng)), full);
    predictions("uniform in [0, 1000]^2 + 1e15", to_points<K>(transformed(uniform_points(n / 2, rng, 0., 1000.), 1., 1e15)), full);
    predictions("integer grid + 1e15", to_points<K>(transformed(grid_points(9, 9, rng), 1., 1e15)), full);
    predictions("uniform * 1e-15", to_points<K>(transformed(uniform_points(n / 2, rng), 1e-15, 0.)), full);
    predictions("integer grid * 2^-50", to_points<K>(transformed(grid_points(9, 9, rng), std::ldexp(1., -50), 0.)), full);
    predictions("3 points", to_points<K>({{0, 0}, {1, 0}, {0, 1}}), full);
    predictions("3 collinear points", to_points<K>({{0, 0}, {1, 1}, {2, 2}}), full);
    predictions("all points equal", to_points<K>(XYs(10, XY{0.25, 0.5})), full);
  }

  // --- Above 4096 points -----------------------------------------------------------------------
  // delaunay_from_prediction() screens large predictions and rebuilds at once when they look
  // bad; prediction_measures() must not let that hide Lawson's count. No reference here (too
  // many points for it): the relations and the values a few flips must give. (The plain
  // Triangulation_2 is one the screen rejects: most of its circumcircles hold many points;
  // its D_vio, about 1.4e7 at 5000 points, is what the measuring costs.)
  void large(std::size_t n)
  {
    Scope scope("large: ", n, " uniform points");
    const Points points = to_points<K>(uniform_points(n, rng));
    const std::pair<const char*, Faces> cases[] = {
        {"random_flip_prediction, rho = 0", DFP::random_flip_prediction(points, 0.0, 5)},
        {"a plain Triangulation_2", faces_by_info(indexed_triangulation<K>(points))},
        {"k_flip_prediction, k = 1", DFP::k_flip_prediction(points, 1, 6)},
    };
    for(const auto& [what, faces] : cases) {
      Scope s(what);
      const Measures m = DFP::prediction_measures(points, faces);
      check_relations(m);
      DFP_CHECK_MSG(m.is_triangulation && m.D_flip_upper && m.D > 0, describe(m));
    }
    const Measures one = DFP::prediction_measures(points, cases[2].second);
    DFP_CHECK_MSG(one.D == 1 && one.D_local == 1 && one.D_cross == 1 && one.D_flip_upper == std::optional<std::size_t>(1),
                  describe(one));
  }

  void all(std::size_t n, bool full)
  {
    DFP_RUN(cocircular_quadrilaterals());
    DFP_RUN(parabola_fans());
    DFP_RUN(grid4());
    DFP_RUN(small_non_triangulations());
    DFP_RUN(merging_lists());
    DFP_RUN(malformed());
    DFP_RUN(point_sets(n, full));
    if(full)
      DFP_RUN(large(5000));
  }
};

int main()
{
  {
    Scope scope("Epick");
    Measures_test<CGAL::Exact_predicates_inexact_constructions_kernel>().all(300, true);
  }
  {
    Scope scope("Epeck");
    Measures_test<CGAL::Exact_predicates_exact_constructions_kernel>().all(80, false);
  }
  return finish("test_measures");
}
