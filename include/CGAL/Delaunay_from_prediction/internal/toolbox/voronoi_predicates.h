// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The two tests of Theorem 4.1 (supercells.h) that involve Voronoi vertices, which are
// constructed points: which of two sites is nearer to the circumcentre of a triangle (the
// cell that owns a Delaunay triangle), and the order of the crossings along a Voronoi edge of
// a sample (the lower envelope on a wall). Why they are exact: each is the sign of a
// polynomial in the input coordinates (the circumcentres' denominators, twice the
// orientation of a counterclockwise triangle, are positive and multiplied out), evaluated
// first in interval arithmetic, whose enclosure is certain whenever it excludes 0 (overflow
// gives infinite bounds, hence no decision), and otherwise exactly, with GMP's big floats
// (or the kernel's own number type when its coordinates are not doubles, as with Epeck).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VORONOI_PREDICATES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VORONOI_PREDICATES_H

#ifdef CGAL_USE_GMP
#include <CGAL/Gmpzf.h>
#else
#include <CGAL/MP_Float.h>
#endif
#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#include <type_traits>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

using Voronoi_interval = Interval_nt<false>;

// The exact number type the tests fall back on for coordinates of type FT: for doubles,
// GMP's integers times a power of two (every expression here is a polynomial: no division,
// hence no gcd to normalise a fraction).
template <class FT>
#ifdef CGAL_USE_GMP
using Voronoi_exact = std::conditional_t<std::is_same<FT, double>::value, Gmpzf, FT>;
#else
using Voronoi_exact = std::conditional_t<std::is_same<FT, double>::value, MP_Float, FT>;
#endif

// A coordinate in NT: an enclosing interval, or the exact value.
template <class NT, class FT>
NT voronoi_number(const FT& x)
{
  if constexpr(std::is_same<NT, Voronoi_interval>::value)
    return NT(to_interval(x));
  else
    return NT(x);
}

// The sign of an interval that decides it, 2 when it does not.
inline int certain_sign(const Voronoi_interval& v)
{
  if(v.inf() > 0)
    return 1;
  if(v.sup() < 0)
    return -1;
  if(v.inf() == 0 && v.sup() == 0)
    return 0;
  return 2;
}

// The sign of expression(NT()) for a polynomial expression of the coordinates (type FT):
// filtered by intervals, exact otherwise.
template <class FT, class Expression>
int exact_sign(const Expression& expression)
{
  {
    Protect_FPU_rounding<true> upward;
    const int s = certain_sign(expression(Voronoi_interval()));
    if(s != 2)
      return s;
  }
  return int(CGAL::sign(expression(Voronoi_exact<FT>())));
}

// Twice the circumcentre of the counterclockwise triangle (a, b, c) relative to a, as
// (nx, ny) / d with d = 2 orientation > 0.
template <class NT, class Point>
void circumcentre_from_first(const Point& a, const Point& b, const Point& c, NT& nx, NT& ny, NT& d)
{
  using FT = std::decay_t<decltype(a.x())>;
  const NT ax = voronoi_number<NT, FT>(a.x()), ay = voronoi_number<NT, FT>(a.y());
  const NT bx = voronoi_number<NT, FT>(b.x()) - ax, by = voronoi_number<NT, FT>(b.y()) - ay;
  const NT cx = voronoi_number<NT, FT>(c.x()) - ax, cy = voronoi_number<NT, FT>(c.y()) - ay;
  const NT b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  d = NT(2) * (bx * cy - by * cx);
  nx = cy * b2 - by * c2;
  ny = bx * c2 - cx * b2;
}

// The sign of |x - u|^2 - |x - v|^2, x the circumcentre of the counterclockwise triangle
// (a, b, c): negative when u is nearer to x. The difference times d = 2 orientation(a, b, c)
// is d (|u'|^2 - |v'|^2) - 2 n . (u' - v'), with ' relative to a: degree 4.
template <class Point>
int compare_distances_to_circumcentre(const Point& a, const Point& b, const Point& c, const Point& u, const Point& v)
{
  using FT = std::decay_t<decltype(a.x())>;
  return exact_sign<FT>([&](auto zero) {
    using NT = decltype(zero);
    NT nx, ny, d;
    circumcentre_from_first(a, b, c, nx, ny, d);
    const NT ax = voronoi_number<NT, FT>(a.x()), ay = voronoi_number<NT, FT>(a.y());
    const NT ux = voronoi_number<NT, FT>(u.x()) - ax, uy = voronoi_number<NT, FT>(u.y()) - ay;
    const NT vx = voronoi_number<NT, FT>(v.x()) - ax, vy = voronoi_number<NT, FT>(v.y()) - ay;
    return d * (ux * ux + uy * uy - vx * vx - vy * vy) - NT(2) * (nx * (ux - vx) + ny * (uy - vy));
  });
}

// A wall: the Voronoi edge of a sample's Delaunay edge, from the circumcentre of the
// counterclockwise face (a, b, c) on its right to the circumcentre of the face (a2, b2, c2)
// on its left, or, when the left face is infinite, the ray from the first circumcentre along
// `ray` (the left normal of the hull edge, given by its two ends). A point y on it is
// nearest to the site p minimising g_p(y) = |p|^2 - 2 y.p; along the wall, y = c + l e with
// l in [0, 1] (segment) or [0, inf) (ray), g_p is the line A_p + l B_p, here scaled by a
// positive factor common to all p.
// The wall lies on the bisector of its edge's ends, which are as near as each other all along
// it; a point on the wall belongs to the cell of the end of smaller rank, `low`. So the sites
// that matter are those just on the other end's side (`high`): the wall is moved towards
// `high` by an infinitesimal e, which adds e T_p to g_p with the tilt T_p = -2 (high - low).p,
// a second key wherever the lines tie.
template <class Point>
struct Voronoi_wall
{
  Point a, b, c;       // the right face
  Point a2, b2, c2;    // the left face, if `segment`
  Point from, to;      // the hull edge whose left normal is the ray, if not `segment`
  Point low, high;     // the edge's ends, by rank
  bool segment = true;

  template <class NT>
  struct Frame
  {
    NT ax, ay, d, nx, ny; // the start: (nx, ny) / d relative to (ax, ay)
    NT ex, ey, scale;     // the direction times d (times the left face's d2), and d2 (1)
  };

  template <class NT>
  Frame<NT> frame() const
  {
    using FT = std::decay_t<decltype(a.x())>;
    Frame<NT> f;
    f.ax = voronoi_number<NT, FT>(a.x());
    f.ay = voronoi_number<NT, FT>(a.y());
    circumcentre_from_first(a, b, c, f.nx, f.ny, f.d);
    if(segment) {
      NT nx2, ny2, d2;
      circumcentre_from_first(a2, b2, c2, nx2, ny2, d2);
      const NT sx = voronoi_number<NT, FT>(a2.x()) - f.ax, sy = voronoi_number<NT, FT>(a2.y()) - f.ay;
      // d d2 (c_left - c_right), relative coordinates
      f.ex = f.d * (d2 * sx + nx2) - d2 * f.nx;
      f.ey = f.d * (d2 * sy + ny2) - d2 * f.ny;
      f.scale = d2;
    } else {
      const NT wx = voronoi_number<NT, FT>(to.x()) - voronoi_number<NT, FT>(from.x());
      const NT wy = voronoi_number<NT, FT>(to.y()) - voronoi_number<NT, FT>(from.y());
      f.ex = -wy * f.d;
      f.ey = wx * f.d;
      f.scale = NT(1);
    }
    return f;
  }

  // The line of site p, both coefficients times d (and d2 for a segment), and its tilt.
  template <class NT>
  void line(const Frame<NT>& f, const Point& p, NT& intercept, NT& slope, NT& tilt) const
  {
    using FT = std::decay_t<decltype(a.x())>;
    const NT px = voronoi_number<NT, FT>(p.x()) - f.ax, py = voronoi_number<NT, FT>(p.y()) - f.ay;
    intercept = f.scale * (f.d * (px * px + py * py) - NT(2) * (f.nx * px + f.ny * py));
    slope = NT(-2) * (f.ex * px + f.ey * py);
    const NT hx = voronoi_number<NT, FT>(high.x()) - voronoi_number<NT, FT>(low.x());
    const NT hy = voronoi_number<NT, FT>(high.y()) - voronoi_number<NT, FT>(low.y());
    tilt = NT(-2) * (hx * px + hy * py);
  }
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VORONOI_PREDICATES_H
