// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point: BrioDC (K. Buchin, W. Mulzer, "Linear-time Delaunay triangulations simplified"):
// the Delaunay triangulation by a biased randomized insertion order whose samples meet every
// component of the nearest-neighbour graph, each point inserted after a walk along its
// nearest-neighbour graph edges from a point already inserted.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H
#define CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/random.h>
#include <CGAL/Delaunay_from_prediction/internal/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/vertex_info.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// p[2k], p[2k + 1] = xy[2 order[k]], xy[2 order[k] + 1] for k < m. Out of line: inlined into
// the graph's function below, GCC 12 vectorizes these random reads into a loop twice as slow.
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
inline void gather_coordinates(const double* xy, const std::uint32_t* order, std::size_t m, double* p)
{
  for(std::size_t k = 0; k < m; ++k) {
    const std::uint32_t o = order[k];
    const double px = xy[2 * o], py = xy[2 * o + 1];
    p[2 * k] = px;
    p[2 * k + 1] = py;
  }
}

// The nearest-neighbour graph of the points xy[0..m) (coordinates in double, x and y
// interleaved), with a grid of about two points a cell over their bounding box, rows in
// order; a cell holding more than 32 points (clusters, a density varying by orders of
// magnitude) is refined by the same procedure on its points, up to depth 6. Writes to `order`
// the points in the grid order (refined cells in their own grid order): order[k] is the input
// position of the k-th point; and to `nn` the nearest neighbour of each, as a position in
// that order (no_rank for a single point). Each point's search reads the 3 x 3 cells around
// its own (when they hold at most 128 points), then rings of cells until no nearer point can
// lie beyond, skipping the cells farther than the best candidate so far, at most `budget`
// points past its own cell (then the nearest point read is taken: equal points by the
// hundred); ties go to the smaller position in the order. A search that reaches a refined
// cell reads it through its grid (read_grid_near()), only the subcells within the circle of
// the best candidate. Double precision and the budget make the graph approximate in rare
// cases: it only guides the insertion, so that costs time, never correctness. `grid_out`, if
// given, receives the grid with its refined cells' grids (for the searches of its caller).
// A grid of nearest_neighbour_graph(): the points of cell c are positions start[c] ..
// start[c + 1] - 1 of its order, cells row-major; a refined cell c has its own grid
// sub[sub_of[c]], whose positions count from start[c] (sub_of is empty when no cell is).
struct Nng_cells
{
  double xmin = 0, ymin = 0, sx = 0, sy = 0;
  std::size_t side_x = 1, side_y = 1;
  std::vector<std::uint32_t> start;
  std::vector<std::uint32_t> sub_of;
  std::vector<Nng_cells> sub;
};

// Calls consider(j) on the points of grid `g` (positions from `base`) that may be within
// sqrt(b) of (x, y), b being the best squared distance so far (it shrinks as they are
// read): row by row from the row nearest the point, in each row the cells that meet the
// circle, refined cells through their own grids. So a dense grid next to a sparse point is
// not read whole (with no candidate yet, the nearest row is read whole and gives one), and
// the rows and cells visited are those the circle meets. Stops once `read` reaches `budget`.
// Cell bounds get a rounding slack: a point's cell comes from a rounded division.
template <class Consider>
void read_grid_near(const Nng_cells& g, std::uint32_t base, double x, double y, const double& b,
                    std::size_t& read, std::size_t budget, Consider& consider)
{
  const double row_height = g.sy > 0 ? 1 / g.sy : 0, column_width = g.sx > 0 ? 1 / g.sx : 0;
  // Reads row `row` if it meets the circle; false if it lies beyond (rows past it too).
  auto read_row = [&](std::size_t row) {
    const double row_y0 = g.ymin + double(row) * row_height, slack = 1e-9 * row_height;
    const double dy = (std::max)({0.0, row_y0 - slack - y, y - (row_y0 + row_height + slack)});
    if(dy * dy > b)
      return false;
    const double w = std::sqrt(b - dy * dy) + 1e-9 * column_width; // infinite with no candidate
    std::size_t cell = row * g.side_x, end = cell + g.side_x;
    if(g.sx > 0) {
      const double a0 = (x - w - g.xmin) * g.sx, a1 = (x + w - g.xmin) * g.sx;
      end = cell + std::size_t(a1 > 0 ? (std::min)(a1, double(g.side_x - 1)) : 0) + 1;
      cell += std::size_t(a0 > 0 ? (std::min)(a0, double(g.side_x - 1)) : 0);
    }
    while(cell < end && read < budget) {
      std::size_t run_end = end; // a run of cells not refined: one range of positions
      if(!g.sub_of.empty())
        for(run_end = cell; run_end < end && g.sub_of[run_end] == no_rank;)
          ++run_end;
      const std::uint32_t from = base + g.start[cell];
      const std::uint32_t to = (std::min)(base + g.start[run_end], std::uint32_t(from + (budget - read)));
      for(std::uint32_t j = from; j < to; ++j)
        consider(j);
      read += to - from;
      cell = run_end;
      if(cell < end && read < budget) {
        read_grid_near(g.sub[g.sub_of[cell]], base + g.start[cell], x, y, b, read, budget, consider);
        ++cell;
      }
    }
    return true;
  };
  // From the row nearest the point up, then down, each way until a row beyond the circle.
  const double fy = (y - g.ymin) * g.sy;
  const std::size_t near_row = std::size_t(fy > 0 ? (std::min)(fy, double(g.side_y - 1)) : 0);
  for(std::size_t row = near_row; row < g.side_y && read < budget; ++row)
    if(!read_row(row))
      break;
  for(std::size_t row = near_row; row > 0 && read < budget; --row)
    if(!read_row(row - 1))
      break;
}

// nearest_neighbour_graph() on coordinates in a frame where no squared distance that matters
// overflows (see there); `depth` counts the refinements.
inline void nearest_neighbour_graph_in_frame(const double* xy, std::size_t m, std::vector<std::uint32_t>& order,
                                             std::vector<std::uint32_t>& nn, int depth, Nng_cells* grid_out)
{
  constexpr std::size_t crowded = 32, budget = 512;
  order.resize(m);
  nn.assign(m, no_rank);
  if(m == 0)
    return;
  double xmin = xy[0], xmax = xy[0], ymin = xy[1], ymax = xy[1];
  for(std::size_t k = 1; k < m; ++k) {
    xmin = (std::min)(xmin, xy[2 * k]);
    xmax = (std::max)(xmax, xy[2 * k]);
    ymin = (std::min)(ymin, xy[2 * k + 1]);
    ymax = (std::max)(ymax, xy[2 * k + 1]);
  }
  // In the frame nearest_neighbour_graph() gives, the box's larger side is 0 or between 2^-74
  // and 2^65; refined cells are smaller. A side below 2^-960 (a refined cell of points a few subnormals apart near the origin) counts as
  // 0: cells per unit would overflow, and the squares of such differences underflow anyway.
  const double width = xmax - xmin > 0x1p-960 ? xmax - xmin : 0, height = ymax - ymin > 0x1p-960 ? ymax - ymin : 0;
  // Square cells of area 2 / density, sqrt(target * width / height) of them across (the
  // product width * height would underflow in small cells); a degenerate box gets a row or a
  // column of cells.
  const double target = (std::max)(1.0, double(m) / 2);
  std::size_t side_x = 1, side_y = 1;
  if(width > 0 && height > 0) {
    const double aspect = width / height; // an inf or 0 is clamped
    side_x = std::size_t((std::min)(4096.0, (std::max)(1.0, std::floor(std::sqrt(target * aspect)))));
    side_y = std::size_t((std::min)(4096.0, (std::max)(1.0, std::floor(std::sqrt(target / aspect)))));
  } else if(width > 0) {
    side_x = std::size_t((std::min)(double(1 << 22), target));
  } else if(height > 0) {
    side_y = std::size_t((std::min)(double(1 << 22), target));
  }
  const double sx = width > 0 ? double(side_x) / width : 0, sy = height > 0 ? double(side_y) / height : 0;
  const double cell_width = width > 0 ? width / double(side_x) : 0, cell_height = height > 0 ? height / double(side_y) : 0;
  // A point beyond ring r of cells around its own is at least r of the shorter side away
  // (plus its distance to its cell's sides); a side of length 0 does not count.
  const double shorter = cell_width > 0 && cell_height > 0 ? (std::min)(cell_width, cell_height)
                                                           : (std::max)(cell_width, cell_height);
  const std::size_t cells = side_x * side_y;
  std::vector<std::uint32_t> key(m), start(cells + 1, 0);
  auto cell_of = [&](double x, double y, long& cx, long& cy) {
    const double fx = (x - xmin) * sx, fy = (y - ymin) * sy;
    cx = long(fx > 0 ? (std::min)(fx, double(side_x - 1)) : 0);
    cy = long(fy > 0 ? (std::min)(fy, double(side_y - 1)) : 0);
  };
  for(std::size_t k = 0; k < m; ++k) {
    long cx, cy;
    cell_of(xy[2 * k], xy[2 * k + 1], cx, cy);
    key[k] = std::uint32_t(std::size_t(cy) * side_x + std::size_t(cx));
    ++start[key[k] + 1];
  }
  for(std::size_t c = 0; c < cells; ++c)
    start[c + 1] += start[c];
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for(std::size_t k = 0; k < m; ++k)
      order[fill[key[k]]++] = std::uint32_t(k);
  }
  std::vector<double> p(2 * m); // coordinates in grid order
  gather_coordinates(xy, order.data(), m, p.data());
  std::vector<double> best(m, std::numeric_limits<double>::infinity());
  Nng_cells grid; // this grid's refined cells (the rest is filled in at the end)
  std::vector<std::uint32_t>& sub_of = grid.sub_of;
  std::vector<Nng_cells>& sub = grid.sub;
  auto refined = [&](std::size_t c) { return !sub_of.empty() && sub_of[c] != no_rank; };
  {
    std::vector<std::uint32_t> sub_order, sub_nn, moved;
    std::vector<double> sub_p;
    for(std::size_t c = 0; c < cells; ++c) {
      const std::size_t first = start[c], count = start[c + 1] - start[c];
      if(count <= crowded || count == m || depth >= 6)
        continue;
      if(sub_of.empty())
        sub_of.assign(cells, no_rank);
      sub_of[c] = std::uint32_t(sub.size());
      sub.emplace_back();
      nearest_neighbour_graph_in_frame(p.data() + 2 * first, count, sub_order, sub_nn, depth + 1, &sub.back());
      moved.assign(order.begin() + std::ptrdiff_t(first), order.begin() + std::ptrdiff_t(first + count));
      sub_p.assign(p.begin() + std::ptrdiff_t(2 * first), p.begin() + std::ptrdiff_t(2 * (first + count)));
      for(std::size_t a = 0; a < count; ++a) {
        order[first + a] = moved[sub_order[a]];
        p[2 * (first + a)] = sub_p[2 * sub_order[a]];
        p[2 * (first + a) + 1] = sub_p[2 * sub_order[a] + 1];
      }
      for(std::size_t a = 0; a < count; ++a) {
        if(sub_nn[a] == no_rank)
          continue;
        const std::size_t b = first + sub_nn[a];
        nn[first + a] = std::uint32_t(b);
        const double dx = p[2 * b] - p[2 * (first + a)], dy = p[2 * b + 1] - p[2 * (first + a) + 1];
        best[first + a] = dx * dx + dy * dy;
      }
    }
  }
  for(std::size_t c = 0; c < cells; ++c) {
    const long cx = long(c % side_x), cy = long(c / side_x);
    const double cell_x0 = xmin + double(cx) * cell_width, cell_y0 = ymin + double(cy) * cell_height;
    // The 3 x 3 cells around (fewer at the grid's sides): three runs of the grid order.
    const std::size_t col0 = std::size_t(cx > 0 ? cx - 1 : 0), col1 = (std::min)(std::size_t(cx) + 1, side_x - 1);
    const std::size_t row0 = std::size_t(cy > 0 ? cy - 1 : 0), row1 = (std::min)(std::size_t(cy) + 1, side_y - 1);
    for(std::uint32_t k = start[c]; k < start[c + 1]; ++k) {
      const double x = p[2 * k], y = p[2 * k + 1];
      double b = best[k];
      std::uint32_t bk = nn[k];
      // Branch-free: whether a candidate is nearer is not predictable.
      auto consider = [&](std::uint32_t j) {
        const double dx = p[2 * j] - x, dy = p[2 * j + 1] - y;
        const double d = dx * dx + dy * dy;
        // (Never the point itself; `&` and `|`: no branch on the comparisons.)
        const bool nearer = (j != k) & ((d < b) | ((d == b) & (j < bk)));
        b = nearer ? d : b;
        bk = nearer ? j : bk;
      };
      // The distance from the point to the sides of its cell (a degenerate axis aside).
      double margin = std::numeric_limits<double>::infinity();
      if(cell_width > 0)
        margin = (std::min)({margin, x - cell_x0, cell_x0 + cell_width - x});
      if(cell_height > 0)
        margin = (std::min)({margin, y - cell_y0, cell_y0 + cell_height - y});
      margin = (std::max)(0.0, margin);
      long r = 1;
      std::size_t read = 0;
      bool searched = false;
      if(!refined(c)) {
        // The common case: the cells around are at most three runs of the grid order (rows).
        std::uint32_t run[3][2];
        std::size_t total = 0, runs = 0;
        for(std::size_t row = row0; row <= row1; ++row, ++runs) {
          run[runs][0] = start[row * side_x + col0];
          run[runs][1] = start[row * side_x + col1 + 1];
          total += run[runs][1] - run[runs][0];
        }
        if(total <= 4 * crowded) { // else dense cells around: the rings below read less
          // On copies of b and bk: `consider` passes their addresses on, which would keep
          // them in memory in this, the hottest loop. Candidates read in increasing position
          // need only the strict comparison for the tie rule.
          double fast_b = b;
          std::uint32_t fast_bk = bk;
          for(std::size_t t = 0; t < runs; ++t)
            for(std::uint32_t j = run[t][0]; j < run[t][1]; ++j) {
              const double dx = p[2 * j] - x, dy = p[2 * j + 1] - y;
              const double d = j != k ? dx * dx + dy * dy : std::numeric_limits<double>::infinity();
              const bool nearer = d < fast_b;
              fast_b = nearer ? d : fast_b;
              fast_bk = nearer ? j : fast_bk;
            }
          b = fast_b;
          bk = fast_bk;
          searched = b <= (shorter + margin) * (shorter + margin);
          r = 2;
          read = total;
        }
      }
      if(!searched && r == 1) {
        if(!refined(c)) { // (a cell is that large only when it holds every point: equal points)
          for(std::uint32_t j = start[c]; j < start[c + 1] && read < budget && b > 0; ++j, ++read)
            consider(j);
          read = 0;
        }
        searched = b <= margin * margin;
      }
      for(; !searched; ++r) {
        // Cells at Chebyshev distance r from (cx, cy).
        const long x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
        bool any_cell = false;
        for(long gy = (std::max)(0L, y0); gy <= (std::min)(long(side_y) - 1, y1) && read < budget; ++gy) {
          const bool edge_row = gy == y0 || gy == y1;
          for(long gx = (std::max)(0L, x0); gx <= (std::min)(long(side_x) - 1, x1) && read < budget;
              gx += (edge_row || gx == x1) ? 1 : (std::max)(1L, x1 - gx)) {
            any_cell = true;
            // A cell farther than the best candidate is skipped (its box enlarged by a rounding
            // slack: a point's cell comes from a rounded division).
            const double bx = xmin + double(gx) * cell_width, by = ymin + double(gy) * cell_height;
            const double ex = 1e-9 * cell_width, ey = 1e-9 * cell_height;
            const double ddx = (std::max)({0.0, bx - ex - x, x - (bx + cell_width + ex)});
            const double ddy = (std::max)({0.0, by - ey - y, y - (by + cell_height + ey)});
            const double cell_distance2 = ddx * ddx + ddy * ddy;
            if(cell_distance2 > b)
              continue;
            const std::size_t cell = std::size_t(gy) * side_x + std::size_t(gx);
            if(refined(cell)) {
              read_grid_near(sub[sub_of[cell]], start[cell], x, y, b, read, budget, consider);
              continue;
            }
            const std::uint32_t last = (std::min)(start[cell + 1], std::uint32_t(start[cell] + (budget - read)));
            for(std::uint32_t j = start[cell]; j < last; ++j)
              consider(j);
            read += last - start[cell];
          }
        }
        const double reach = double(r) * shorter + margin;
        searched = !any_cell || b <= reach * reach || read >= budget || b == 0;
      }
      if(bk == no_rank && m > 1) { // no other point read (not with finite coordinates): any will do
        bk = k == 0 ? 1 : k - 1;
        b = std::numeric_limits<double>::infinity();
      }
      best[k] = b;
      nn[k] = bk;
    }
  }
  if(grid_out != nullptr) {
    grid.xmin = xmin;
    grid.ymin = ymin;
    grid.sx = sx;
    grid.sy = sy;
    grid.side_x = side_x;
    grid.side_y = side_y;
    grid.start.swap(start);
    *grid_out = std::move(grid);
  }
}

// The nearest-neighbour graph of the points xy[0..m) (see nearest_neighbour_graph_in_frame()).
// Robust at any scale: if the box's larger side is not within 2^-64 .. 2^64 (squares of
// distances would overflow to inf at 1e160, underflow to 0 at 1e-160, a width of the box
// overflows between -1e308 and 1e308), the search runs on a copy of the coordinates scaled
// by unit_scale() of the box, a power of two (exact), where the box's side is about 1: then
// only points closer than 2^-511 of the box tie at distance 0. A tie, an approximate or
// arbitrary neighbour only changes the insertion order: every point gets a neighbour other
// than itself (for m > 1), so the graph is a functional graph whose every component has a
// cycle, as the sampling of brio_dc_delaunay() needs.
inline void nearest_neighbour_graph(const double* xy, std::size_t m, std::vector<std::uint32_t>& order,
                                    std::vector<std::uint32_t>& nn)
{
  if(m == 0) {
    order.clear();
    nn.clear();
    return;
  }
  Box box{xy[0], xy[0], xy[1], xy[1]};
  for(std::size_t k = 1; k < m; ++k) {
    box.xmin = (std::min)(box.xmin, xy[2 * k]);
    box.xmax = (std::max)(box.xmax, xy[2 * k]);
    box.ymin = (std::min)(box.ymin, xy[2 * k + 1]);
    box.ymax = (std::max)(box.ymax, xy[2 * k + 1]);
  }
  const double scale = unit_scale(box);
  if(scale >= 0x1p-64 && scale <= 0x1p64)
    return nearest_neighbour_graph_in_frame(xy, m, order, nn, 0, nullptr);
  std::vector<double> scaled(xy, xy + 2 * m);
  for(double& c : scaled)
    c *= scale;
  nearest_neighbour_graph_in_frame(scaled.data(), m, order, nn, 0, nullptr);
}

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt` by BrioDC (K. Buchin, W. Mulzer,
"Linear-time Delaunay triangulations simplified"): a randomized incremental construction whose
insertion order is a gradation of samples \f$P = S_0 \supseteq S_1 \supseteq \dots \supseteq S_\ell\f$.
On the cycle of every connected component of the nearest-neighbour graph \f$N(S_i)\f$ two
points are matched, and \f$S_{i+1}\f$ holds one of them, chosen at random (so it meets every
component), and every other point of \f$S_i\f$ with probability \f$q\f$ (named parameter
`sample_probability`). The points of \f$S_i \setminus S_{i+1}\f$ are inserted component by
component, each located by a walk that starts at the vertex of its neighbour in \f$N(S_i)\f$
inserted before it.

The paper samples with \f$q = 1/2\f$; the default here is \f$q = 1/8\f$, 10-24% less time on
every distribution measured (fewer levels, hence fewer graphs and fewer sweeps over the
triangulation), with walks as short (see the user manual). The paper's proof of Theorem 2
bounds the chance that a triangle with \f$s\f$ conflicting points appears by the chance that
none of them is sampled, \f$2^{-s}\f$; with \f$q\f$ it is at most \f$\max(1 - q, 1/2)^s\f$ (a
matched point is kept with probability 1/2), which keeps the sum over triangles linear for
any fixed \f$q > 0\f$, with a constant that grows as \f$q\f$ shrinks. That adaptation is ours,
not the paper's.
A sample that keeps more than 31/32 of the points of its level (\f$q\f$ near 1 on points whose
graph has few components: equal points, a geometric progression) is the last one, inserted by
\cgal's insertion: else the samples would number about one per point.

The nearest-neighbour graphs are computed with a uniform grid of about two points a cell,
crowded cells refined by grids of their own down to 6 levels (not \cgal's spatial searching,
and not the linear-time algorithm of Chan that the paper's Theorem 1 cites; the grid's cells
also order the insertion for locality), with distances in double precision (on coordinates
scaled by a power of two to their bounding box where squared distances would overflow or
underflow) and a search reading at most 512 points. The graph is exact (compared with a
brute-force search in the tests, on uniform, clustered, graded, grid, collinear and duplicate
points) unless a search runs out of its 512 points (hundreds of points at equal or nearly equal
positions) or points lie closer than \f$2^{-511}\f$ of the bounding box's size: then the
neighbour is approximate, which costs time, never correctness: every point is inserted. Each
point is located by a visibility walk from its neighbour's vertex; a walk longer than about
\f$\log_2 n + 8\f$ faces starts again, uncapped, from a vertex inserted near the point.

Complexity: the paper's Theorem 2 gives expected \f$O(n + f(n))\f$ time, \f$f(n)\f$ the time of
a nearest-neighbour graph, for its sampling probability 1/2 and straight walks along the graph's
edges. This function departs from that setting (grid graph, capped visibility walks with a grid
restart, \f$q = 1/8\f$ by default): no bound is proven for it. Its walks were measured at
1.75-2.24 faces per point at \f$10^5\f$ and \f$10^6\f$ points (see the user manual).

The result is exactly the triangulation \cgal's `Delaunay_triangulation_2` builds from the same
points (co-circular ties broken by \cgal's symbolic perturbation).

\tparam PointRange a random-access range of `DT::Point`.
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
        assignable from `std::size_t`, every vertex's `info()` is set to the index of its point
        (for duplicate points, the smallest of their indices). A `CGAL::Triangulation_hierarchy_2`
        of one is kept as in `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters.

\param points the points.
\param dt receives the result; cleared first.
\param np optional named parameters among the following ones:
\cgalNamedParamsBegin
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the samples}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{a fixed seed}
  \cgalParamNEnd
  \cgalParamNBegin{sample_probability}
    \cgalParamDescription{the probability \f$q\f$ that a point not matched on its component's cycle is
                          in the next sample (`Delaunay_from_prediction::parameters::sample_probability()`)}
    \cgalParamType{`double`, in \f$(0, 1]\f$}
    \cgalParamDefault{1/8 (the paper's value is 1/2)}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did: `points_located`, `faces_visited` (divided by `points_located`: the
         mean length of a walk), `walk_fallbacks`, `insertion_rounds` (the number of samples),
         `points_reinserted` (every point), `duplicate_points`.
\throws Invalid_prediction if a point has a non-finite coordinate, or there are \f$2^{32} - 1\f$
        points or more; `std::invalid_argument` if `sample_probability` is not in \f$(0, 1]\f$.
        Then `dt` is unchanged.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
is built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class PointRange, class DT, class NamedParameters = parameters::Default_named_parameters>
Statistics brio_dc_delaunay(const PointRange& points, DT& dt, const NamedParameters& np = parameters::default_values())
{
  if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(dt, [&](auto& level0) { return brio_dc_delaunay(points, level0, np); });
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Point = typename DT::Point;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  const auto point_begin = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  internal::check_points_are_finite(point_begin, n);
  if(n >= std::size_t(internal::no_rank))
    throw Invalid_prediction("Delaunay_from_prediction: 2^32 - 1 points or more are not supported by brio_dc_delaunay");
  const std::uint64_t seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0xb410dcu);
  const double probability = double(choose_parameter(get_parameter(np, internal_np::sample_probability), 0.125));
  if(!(probability > 0 && probability <= 1)) {
    std::ostringstream message;
    message << "Delaunay_from_prediction: brio_dc_delaunay's sample_probability must be in (0, 1]; it is "
            << probability;
    throw std::invalid_argument(message.str());
  }
  Statistics stats;
  dt.clear();
  stats.points_reinserted = n;
  if(n == 0)
    return stats;
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    internal::build_with_exact_predicates(dt, point_begin, n, stats); // inexact predicates: decided by exact ones
    return stats;
  }
  // The points, gathered (every later pass reads them by index).
  std::vector<Point> point(point_begin, point_begin + std::ptrdiff_t(n));

  // The gradation, from S_0 = P down: each level in grid order, with its nearest-neighbour
  // graph (positions within the level) and which of its points are in the next sample.
  struct Level
  {
    std::vector<std::uint32_t> members;     // point indices, in grid order
    std::vector<std::uint32_t> nn;          // nearest neighbour, by position
    std::vector<unsigned char> in_next;     // in S_{i+1}
  };
  std::vector<Level> levels;
  std::vector<std::uint32_t> original;   // the caller's index of each point (after renumbering)
  std::vector<Vertex_handle> vertex(n); // the vertex of each point, once inserted
  internal::Vertex_grid<Vertex_handle> vertex_grid(n, [&](std::size_t i) -> const Point& { return point[i]; });
  internal::Splitmix64 random{seed + 0xb410dcull};
  {
    std::vector<std::uint32_t> members(n);
    for(std::size_t i = 0; i < n; ++i)
      members[i] = std::uint32_t(i);
    std::vector<double> xy;
    std::vector<std::uint32_t> order;
    while(members.size() > 64) {
      Level level;
      const std::size_t m = members.size();
      xy.resize(2 * m);
      for(std::size_t k = 0; k < m; ++k) {
        xy[2 * k] = CGAL::to_double(point[members[k]].x());
        xy[2 * k + 1] = CGAL::to_double(point[members[k]].y());
      }
      internal::nearest_neighbour_graph(xy.data(), m, order, level.nn);
      level.members.resize(m);
      for(std::size_t k = 0; k < m; ++k)
        level.members[k] = members[order[k]];
      if(levels.empty()) {
        // Renumber the points in the grid order of the first level: every later pass then
        // reads `point` and `vertex` in nearly increasing order, where the input order would
        // make each read a cache miss.
        std::vector<Point> sorted(n);
        for(std::size_t k = 0; k < n; ++k)
          sorted[k] = point[level.members[k]];
        point.swap(sorted);
        original.swap(level.members);
        level.members.resize(n);
        for(std::size_t k = 0; k < n; ++k)
          level.members[k] = std::uint32_t(k);
      }
      members.clear();
      // A matching of two points on the cycle of each component of the graph (a functional
      // graph: each component is a tree hanging from one cycle, two mutual neighbours unless
      // neighbours were approximate); one point of each pair goes to the sample, every other
      // point with the sampling probability (1/8 by default).
      level.in_next.assign(m, 2); // 2: not decided
      std::vector<std::uint32_t> state(m, 0);
      for(std::uint32_t s = 0; s < m; ++s) {
        if(state[s] != 0)
          continue;
        // Follow the neighbours from s until a point seen before: on this path (a new cycle)
        // or in an earlier one (a tree hanging from a known component).
        std::uint32_t u = s;
        while(state[u] == 0) {
          state[u] = s + 1;
          u = level.nn[u];
        }
        if(state[u] == s + 1) { // a new cycle through u: match u with its neighbour
          // (A cycle of one point, which nearest_neighbour_graph() never gives, keeps it.)
          const std::uint32_t v = level.nn[u];
          const bool keep_u = v == u || (random() & 1) != 0;
          level.in_next[u] = keep_u ? 1 : 0;
          if(v != u)
            level.in_next[v] = keep_u ? 0 : 1;
        }
      }
      for(std::uint32_t k = 0; k < m; ++k) {
        if(level.in_next[k] == 2) // (uniform() < 1: probability 1 keeps every point)
          level.in_next[k] = random.uniform() < probability ? 1 : 0;
        if(level.in_next[k])
          members.push_back(level.members[k]);
      }
      levels.push_back(std::move(level));
      // A sample that barely shrinks (sample_probability near 1, whose graph has few
      // components: equal points, a geometric progression) would make one level per point or
      // so, quadratic time: it is the last sample instead.
      if(members.size() > m - m / 32)
        break;
    }
    // The last sample, small (or one that did not shrink): inserted first, by CGAL's insertion.
    stats.insertion_rounds = levels.size() + 1;
    Face_handle hint;
    for(std::uint32_t i : members) {
      const std::size_t count = dt.number_of_vertices();
      const Vertex_handle v = dt.insert(point[i], hint);
      hint = v->face();
      internal::record_index_info(v, original.empty() ? i : original[i], dt.number_of_vertices() != count,
                                  stats.duplicate_points);
      vertex[i] = v;
      vertex_grid.record(point[i], v);
    }
  }
  const std::size_t cap = internal::walk_cap(n);
  std::vector<std::pair<Face_handle, int>> flip_stack;
  // From the coarsest level down: the points not in the next sample, component by component
  // in grid order of their first sampled point, each from its graph neighbour (depth-first
  // along the graph's edges, both directions).
  std::vector<std::uint32_t> children_start, children, stack;
  std::vector<unsigned char> done;
  // Inserts point i, located by a walk from vertex `from` (or by CGAL's location without one).
  auto insert = [&](std::uint32_t i, Vertex_handle from) {
    const std::size_t count = dt.number_of_vertices();
    const Vertex_handle v = from != Vertex_handle()
                                ? internal::insert_walking_from(dt, point[i], from, cap, vertex_grid, flip_stack, stats)
                                : dt.insert(point[i]);
    internal::record_index_info(v, original[i], dt.number_of_vertices() != count, stats.duplicate_points);
    vertex[i] = v;
    vertex_grid.record(point[i], v);
  };
  for(std::size_t l = levels.size(); l-- > 0;) {
    const Level& level = levels[l];
    const std::size_t m = level.members.size();
    children_start.assign(m + 1, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      ++children_start[level.nn[k] + 1];
    for(std::size_t k = 0; k < m; ++k)
      children_start[k + 1] += children_start[k];
    children.resize(m);
    {
      std::vector<std::uint32_t> fill(children_start.begin(), children_start.end() - 1);
      for(std::uint32_t k = 0; k < m; ++k)
        children[fill[level.nn[k]]++] = k;
    }
    done.assign(m, 0);
    for(std::uint32_t k = 0; k < m; ++k)
      done[k] = level.in_next[k];
    for(std::uint32_t s = 0; s < m; ++s) {
      if(!level.in_next[s] || done[s] == 2)
        continue;
      done[s] = 2; // 2: its neighbours were pushed
      stack.assign(1, s);
      while(!stack.empty()) {
        const std::uint32_t u = stack.back();
        stack.pop_back();
        auto visit = [&](std::uint32_t w) {
          if(done[w] == 2)
            return;
          if(done[w] == 0) // insert w, located from u
            insert(level.members[w], vertex[level.members[u]]);
          done[w] = 2;
          stack.push_back(w);
        };
        visit(level.nn[u]);
        for(std::uint32_t c = children_start[u]; c < children_start[u + 1]; ++c)
          visit(children[c]);
      }
    }
    // Every component of the graph has a point in the next sample (the matching on its
    // cycle), so the search above reached every point; whatever the graph, a point it did not
    // reach is inserted here, so that none is dropped.
    for(std::uint32_t w = 0; w < m; ++w)
      if(done[w] == 0)
        insert(level.members[w], vertex_grid.near(point[level.members[w]]));
  }
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_BRIO_DC_H
