// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The package's one grid: bounding boxes, the scale that keeps double arithmetic finite at
// any coordinates, the cells of an axis, clamped, and the grid of cells over a box
// (Cell_grid). Used by the spatial order, the vertex grid of hinted insertion, the cells of
// the flips on several threads, the owner grid of the regions build, the carve's crossing
// test and BrioDC's nearest-neighbour cells; points are bucketed into cells by
// toolbox/counting_sort.h. Double arithmetic here only steers (which cell, which start): no
// result depends on it.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_GRID_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_GRID_H

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The bounding box of points in double coordinates, the one place it is computed. Empty (no
// point added) until add() is called.
struct Box
{
  double xmin = std::numeric_limits<double>::infinity(), xmax = -std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity(), ymax = -std::numeric_limits<double>::infinity();

  void add(double x, double y)
  {
    xmin = (std::min)(xmin, x);
    xmax = (std::max)(xmax, x);
    ymin = (std::min)(ymin, y);
    ymax = (std::max)(ymax, y);
  }
  void add(const Box& b)
  {
    xmin = (std::min)(xmin, b.xmin);
    xmax = (std::max)(xmax, b.xmax);
    ymin = (std::min)(ymin, b.ymin);
    ymax = (std::max)(ymax, b.ymax);
  }
  bool is_empty() const { return !(xmin <= xmax && ymin <= ymax); }
};

// The box of points point_at(0), ..., point_at(n - 1), read as doubles.
template <class PointAt>
Box bounding_box(std::size_t n, PointAt point_at)
{
  Box b;
  for(std::size_t k = 0; k < n; ++k)
    b.add(CGAL::to_double(point_at(k).x()), CGAL::to_double(point_at(k).y()));
  return b;
}

// The box of m points given as interleaved coordinates xy[2k], xy[2k + 1].
inline Box bounding_box_of_xy(const double* xy, std::size_t m)
{
  Box b;
  for(std::size_t k = 0; k < m; ++k)
    b.add(xy[2 * k], xy[2 * k + 1]);
  return b;
}

// Coordinates near 1e+-300 are valid input, and double arithmetic on them fails three ways:
// a width of the box overflows (points at -1e308 and 1e308), squared distances overflow (at
// 1e160) or underflow to 0 (at 1e-160: distinct points tie at distance 0), and a number of
// cells divided by a subnormal width is inf (then (x - xmin) * inf is NaN at x = xmin, and
// casting inf or NaN to an integer is undefined). Wherever double arithmetic only steers (a
// grid cell, a hint, a guess), it runs on coordinates scaled by unit_scale() of their box:
// a power of two, so the scaled coordinates are exact (but below 2^-1022 of the box, where
// nothing is steered), and the box's larger side becomes about 1, so that no difference and
// no square of one overflows, and squares underflow only for points closer than 2^-511 of
// the box (a spread no grid resolves anyway). Every result decision is left to the kernel's
// exact predicates.

// A power of two s such that the larger side of the box, times s, is in [1, 2] (or in
// [2^-74, 2^-72] for a box whose sides are only a few subnormals: s is at most 2^1000); 1 for
// a box that is a point or is not finite. Exact on any finite box: a side that overflows is
// measured on halved coordinates.
inline double unit_scale(double xmin, double xmax, double ymin, double ymax)
{
  const double side = (std::max)(xmax - xmin, ymax - ymin);
  int exponent = 0;
  if(side <= (std::numeric_limits<double>::max)()) {
    if(!(side > 0))
      return 1;
    exponent = std::ilogb(side);
  } else {
    const double half = (std::max)(xmax * 0.5 - xmin * 0.5, ymax * 0.5 - ymin * 0.5);
    if(!(half <= (std::numeric_limits<double>::max)()))
      return 1;
    exponent = std::ilogb(half) + 1;
  }
  return std::ldexp(1.0, -(std::max)(exponent, -1000));
}

inline double unit_scale(const Box& b) { return unit_scale(b.xmin, b.xmax, b.ymin, b.ymax); }

// The squared distance of two points, in double, on coordinates times `scale` (unit_scale()
// of a box holding the points, so that it neither overflows nor underflows but for points
// closer than 2^-511 of the box): for choosing where a search starts, never for a decision
// the result depends on.
template <class Point>
double squared_distance_in_double(const Point& a, const Point& b, double scale)
{
  const double dx = CGAL::to_double(a.x()) * scale - CGAL::to_double(b.x()) * scale;
  const double dy = CGAL::to_double(a.y()) * scale - CGAL::to_double(b.y()) * scale;
  return dx * dx + dy * dy;
}

// The cell of a coordinate f counted in cells from the grid's low end, for a grid of `cells`
// cells (at least 1): floor(f) clamped to [0, cells - 1]; the guard `f > 0` maps -inf and NaN
// to cell 0 and the clamp maps inf to the last before the cast (casting either is undefined).
inline std::size_t clamped_cell(double f, std::size_t cells)
{
  return std::size_t(f > 0 ? (std::min)(f, double(cells - 1)) : 0);
}

// The cells of one axis of a grid: `cells` equal cells over [lo, hi], coordinates beyond
// falling in the end cells. Robust for any lo <= hi: the coordinates are scaled by
// unit_scale() of the interval first, so the number of cells per unit is finite for a
// subnormal width and a width that overflows, and (x - lo) * cells per unit is never NaN,
// while a width of 0 gives 0 cells per unit (one cell); clamped_cell() does the rest.
struct Grid_axis
{
  double scale = 1, lo = 0, per_unit = 0;
  std::size_t cells = 1;

  Grid_axis() = default;
  Grid_axis(double lo_, double hi_, std::size_t cells_)
      : scale(unit_scale(lo_, hi_, 0, 0)), lo(lo_ * scale), cells(cells_)
  {
    const double width = hi_ * scale - lo;
    per_unit = width > 0 ? double(cells) / width : 0;
  }

  std::size_t operator()(double x) const { return clamped_cell((x * scale - lo) * per_unit, cells); }
};

// A grid of columns x rows cells over a (non-empty) box, numbered row by row; points outside
// the box fall in the border cells. Robust at any scale (Grid_axis). The one grid of the
// package: every structure that buckets points into cells is made of it, but BrioDC's
// nearest-neighbour cells, whose search needs the cells' sides in a frame normalized
// beforehand (build/nearest_neighbour_graph.h).
struct Cell_grid
{
  Grid_axis column, row;

  Cell_grid() = default;
  Cell_grid(const Box& box, std::size_t columns, std::size_t rows)
      : column(box.xmin, box.xmax, columns), row(box.ymin, box.ymax, rows)
  {}

  std::size_t columns() const { return column.cells; }
  std::size_t rows() const { return row.cells; }
  std::size_t cells() const { return column.cells * row.cells; }
  std::size_t operator()(double x, double y) const { return row(y) * column.cells + column(x); }
  template <class Point>
  std::size_t cell_of(const Point& p) const
  {
    return (*this)(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }
};

// Whether pairs of points (consecutive points of an order, the ends of edges) are about as
// close as the points' spacing, judged on a sample: the median squared distance of the 255
// pairs of point indices pair_at(0..254), and the area per point of the bounding box of the
// n points, both on coordinates scaled by unit_scale() of the box (neither overflows).
struct Spacing_sample
{
  double median_squared_distance, area_per_point;
};
template <class PointAt, class PairAt>
Spacing_sample sample_spacing(std::size_t n, PointAt point_at, PairAt pair_at)
{
  const Box box = bounding_box(n, point_at);
  const double scale = unit_scale(box);
  std::vector<double> squared(255);
  for(std::size_t s = 0; s < squared.size(); ++s) {
    const std::pair<std::size_t, std::size_t> ends = pair_at(s);
    squared[s] = squared_distance_in_double(point_at(ends.first), point_at(ends.second), scale);
  }
  std::nth_element(squared.begin(), squared.begin() + 127, squared.end());
  return Spacing_sample{squared[127],
                        (box.xmax * scale - box.xmin * scale) * (box.ymax * scale - box.ymin * scale) / double(n)};
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_GRID_H
