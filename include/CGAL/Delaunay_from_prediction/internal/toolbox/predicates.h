// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The two geometric tests every stage shares: the symbolically perturbed in-circle test
// that decides local Delaunayhood exactly as CGAL's Delaunay_triangulation_2 does, and the
// check that a closed chain of boundary vertices is a convex polygon wound once.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_PREDICATES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_PREDICATES_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>
#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

inline int ccw(int i) { return i == 2 ? 0 : i + 1; }
inline int cw(int i) { return i == 0 ? 2 : i - 1; }

// The traits' orientation and lexicographic comparison called out of line, as function
// objects with the traits' call syntax: for the code outside the hot loops (the repairs, the
// hull, the ear clipping), where Epick's predicates would inline a copy of their static filter
// at every call, code that every program compiles (code_size.h) for no measurable speed.
template <class Gt, class Point>
CGAL_DFP_OUT_OF_LINE Orientation orientation_out_of_line(const Gt& gt, const Point& p, const Point& q, const Point& r)
{
  return gt.orientation_2_object()(p, q, r);
}
template <class Gt, class Point>
CGAL_DFP_OUT_OF_LINE Comparison_result compare_xy_out_of_line(const Gt& gt, const Point& p, const Point& q)
{
  return gt.compare_xy_2_object()(p, q);
}
template <class Gt>
struct Orientation_out_of_line
{
  const Gt& gt;
  template <class Point>
  Orientation operator()(const Point& p, const Point& q, const Point& r) const
  {
    return orientation_out_of_line(gt, p, q, r);
  }
};
template <class Gt>
struct Compare_xy_out_of_line
{
  const Gt& gt;
  template <class Point>
  Comparison_result operator()(const Point& p, const Point& q) const
  {
    return compare_xy_out_of_line(gt, p, q);
  }
};
template <class Gt>
Orientation_out_of_line<Gt> orientation_called_out_of_line(const Gt& gt)
{
  return {gt};
}
template <class Gt>
Compare_xy_out_of_line<Gt> compare_xy_called_out_of_line(const Gt& gt)
{
  return {gt};
}

// Detects kernels whose coordinates are doubles and whose predicates are exact (Epick):
// for them side_of_oriented_circle_perturbed() first tries an inline floating-point filter.
template <class Gt, class = void>
struct has_exact_double_predicates : std::false_type {};
template <class Gt>
struct has_exact_double_predicates<Gt, std::void_t<typename Gt::FT, decltype(Gt::Has_filtered_predicates)>>
    : std::bool_constant<std::is_same<typename Gt::FT, double>::value && bool(Gt::Has_filtered_predicates)> {};

// Sign of the in-circle determinant of (p, q, r, s) in double precision when it is certain,
// 0 when it is not. Why this is robust: with the differences and products rounded to
// double, the computed determinant is within 1.2e-15 times the permanent (the same
// expression on absolute values) of the exact one (Shewchuk's first-stage bound for
// incircle, (10 + 96 eps) eps); underflow adds at most 1e-200 absolute error while every
// difference is below 1e50, and larger differences (or overflow: inf/NaN fail both tests)
// go to the exact predicate. Only the decision to skip the kernel's exact test depends on
// floating point; a returned sign is always the exact one.
inline int certain_in_circle_sign(double px, double py, double qx, double qy, double rx, double ry,
                                  double sx, double sy)
{
  const double adx = px - sx, ady = py - sy, bdx = qx - sx, bdy = qy - sy, cdx = rx - sx,
               cdy = ry - sy;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, cdxady = cdx * ady, adxcdy = adx * cdy,
               adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy,
               clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  const double max_difference = (std::max)((std::max)((std::max)(std::fabs(adx), std::fabs(ady)),
                                                      (std::max)(std::fabs(bdx), std::fabs(bdy))),
                                           (std::max)(std::fabs(cdx), std::fabs(cdy)));
  if(!(max_difference <= 1e50))
    return 0;
  const double bound = 1.2e-15 * permanent + 1e-200;
  return det > bound ? 1 : (-det > bound ? -1 : 0);
}

// Side of `s` with respect to the circle through the ccw triangle (p, q, r), with exact
// ties broken by the symbolic perturbation of Devillers and Teillaud that CGAL's
// Delaunay_triangulation_2 uses (`side_of_oriented_circle(..., true)`): the points are
// conceptually lifted by amounts that decrease very fast along the lexicographic (x, y)
// order, so the sign of the perturbed determinant is the sign of its first non-zero
// coefficient, read off from the lexicographically largest point down. Never returns
// ON_ORIENTED_BOUNDARY. Robust because every decision is a sign of an exact predicate of
// the traits or an exact coordinate comparison. Out of line: the hot loops only reach it
// when the floating-point filter below cannot decide.
template <class Gt, class Point>
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
Oriented_side exact_side_of_oriented_circle_perturbed(const Gt& gt, const Point& p, const Point& q,
                                                      const Point& r, const Point& s)
{
  const Oriented_side os = gt.side_of_oriented_circle_2_object()(p, q, r, s);
  if(os != ON_ORIENTED_BOUNDARY)
    return os;

  // Exactly co-circular: sort the four points lexicographically (insertion sort on pointers).
  const Point* sorted[4] = {&p, &q, &r, &s};
  auto compare_xy = gt.compare_xy_2_object();
  for(int i = 1; i < 4; ++i)
    for(int j = i; j > 0 && compare_xy(*sorted[j], *sorted[j - 1]) == SMALLER; --j)
      std::swap(sorted[j], sorted[j - 1]);

  auto orientation = gt.orientation_2_object();
  for(int i = 3; i > 0; --i) {
    // The largest point's monomial leads; s leading means "outside" since (p, q, r) is ccw.
    if(sorted[i] == &s)
      return ON_NEGATIVE_SIDE;
    Orientation o = COLLINEAR;
    if(sorted[i] == &r)
      o = orientation(p, q, s);
    else if(sorted[i] == &q)
      o = orientation(p, s, r);
    else
      o = orientation(s, q, r);
    if(o != COLLINEAR)
      return Oriented_side(o);
  }
  return ON_NEGATIVE_SIDE;
}

// The same, with the inline floating-point filter first for kernels with exact predicates
// on double coordinates.
template <class Gt, class Point>
inline Oriented_side side_of_oriented_circle_perturbed(const Gt& gt, const Point& p, const Point& q,
                                                       const Point& r, const Point& s)
{
  if constexpr(has_exact_double_predicates<Gt>::value) {
    const int sign = certain_in_circle_sign(p.x(), p.y(), q.x(), q.y(), r.x(), r.y(), s.x(), s.y());
    if(sign != 0)
      return Oriented_side(sign);
  }
  return exact_side_of_oriented_circle_perturbed(gt, p, q, r, s);
}

// An interior edge shared by the ccw triangle (p, q, r) and a triangle whose third vertex is
// `s` is locally Delaunay iff s is not inside the (perturbed) circle through p, q, r.
template <class Gt, class Point>
bool is_locally_delaunay(const Gt& gt, const Point& p, const Point& q, const Point& r,
                         const Point& s)
{
  return side_of_oriented_circle_perturbed(gt, p, q, r, s) != ON_POSITIVE_SIDE;
}

// Checks that the closed chain point(0), ..., point(m-1) (then back to point(0)) bounds a
// convex region wound exactly once counterclockwise: every turn is a left turn or a straight
// continuation, and the edge directions sweep exactly one full turn. Exact: orientations
// come from the traits, and the turn count only compares coordinates. A chain whose
// direction never decreases and turns through exactly 2*pi is a convex, simple polygon.
template <class Gt, class PointAt>
bool is_convex_ccw_cycle(const Gt& gt, std::size_t m, PointAt point)
{
  if(m < 3)
    return false;
  auto orientation = gt.orientation_2_object();
  auto compare_xy = gt.compare_xy_2_object();
  auto compare_x = gt.compare_x_2_object();
  auto compare_y = gt.compare_y_2_object();
  // Direction a->b lies in the upper half-turn [0, pi) iff b is above a, or level and right.
  auto upper = [&](const auto& a, const auto& b) {
    const Comparison_result cy = compare_y(b, a);
    return cy == LARGER || (cy == EQUAL && compare_x(b, a) == LARGER);
  };
  std::size_t wraps = 0;
  for(std::size_t k = 0; k < m; ++k) {
    const auto& a = point(k);
    const auto& b = point((k + 1) % m);
    const auto& c = point((k + 2) % m);
    const Orientation o = orientation(a, b, c);
    if(o == RIGHT_TURN)
      return false;
    if(o == COLLINEAR) {
      const Comparison_result ab = compare_xy(a, b);
      if(ab == EQUAL || ab != compare_xy(b, c))
        return false; // a zero-length edge or a U-turn
    }
    // Each turn is less than pi, so the sweep passes direction 0 exactly when it goes from the
    // lower half-turn to the upper one.
    if(!upper(a, b) && upper(b, c))
      ++wraps;
  }
  return wraps == 1;
}

// Whether the hull of `tr` (dimension 2) is a convex polygon wound once counterclockwise.
// The hull is read in ccw order: the face outside hull edge u->v is (v, u, infinite).
template <class Triangulation>
bool hull_is_convex_and_wound_once(const Triangulation& tr)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  const auto infinite = tr.infinite_vertex();
  std::vector<const Point*> hull;
  const Face_handle start = infinite->face();
  Face_handle outside = start;
  do {
    const int i = outside->index(infinite);
    hull.push_back(&outside->vertex(cw(i))->point());
    outside = outside->neighbor(cw(i));
  } while(outside != start && hull.size() <= tr.number_of_vertices());
  return outside == start &&
         is_convex_ccw_cycle(tr.geom_traits(), hull.size(),
                             [&](std::size_t k) -> const Point& { return *hull[k]; });
}

// has_exact_predicates<Gt>: whether the orientation and in-circle predicates of the traits
// `Gt` are exact, so that the package's own algorithms (Lawson flips, walks, certificates,
// carving) may rely on them being consistent. True when the traits declare filtered
// predicates (`Gt::Has_filtered_predicates`: Epick, Epeck, any Filtered_kernel) or when
// their number type is exact (`Algebraic_structure_traits<Gt::FT>::Is_exact`, e.g.
// Simple_cartesian<Gmpq>). decides_by_exact_predicates<Gt>: traits that are not, on 2D
// kernel points (Simple_cartesian<double>); the entry points then decide the faces by
// Epick's exact predicates on the coordinates rounded to double (rebuild.h: build_deciding()),
// since CGAL's own insertion with such traits was seen to lose points, leave invalid
// triangulations and crash on almost collinear points.

template <class Gt, class = void>
struct declares_filtered_predicates : std::false_type {};

template <class Gt>
struct declares_filtered_predicates<Gt, std::void_t<decltype(Gt::Has_filtered_predicates)>>
    : std::integral_constant<bool, bool(Gt::Has_filtered_predicates)> {};

template <class Gt, class = void>
struct has_exact_number_type : std::false_type {};

template <class Gt>
struct has_exact_number_type<Gt, std::void_t<typename Algebraic_structure_traits<typename Gt::FT>::Is_exact>>
    : std::is_same<typename Algebraic_structure_traits<typename Gt::FT>::Is_exact, Tag_true> {};

template <class Gt>
struct has_exact_predicates
    : std::integral_constant<bool, declares_filtered_predicates<Gt>::value || has_exact_number_type<Gt>::value> {};

// Whether the entry points decide the faces by Epick's predicates on the coordinates rounded to
// double (rebuild.h) instead of the traits' own: their predicates are not exact, and their
// points are 2D points of a kernel, whose x() and y() are what the predicates read. (Points of
// other traits, e.g. 3D points under Projection_traits_xz_3, have no such coordinates: those
// traits are used as they are.)
template <class Gt>
struct decides_by_exact_predicates
    : std::integral_constant<bool, !has_exact_predicates<Gt>::value &&
                                       std::is_same<typename Gt::Point_2,
                                                    typename Kernel_traits<typename Gt::Point_2>::Kernel::Point_2>::value> {};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_PREDICATES_H
