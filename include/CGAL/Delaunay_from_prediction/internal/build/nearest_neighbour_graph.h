// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The nearest-neighbour graph that BrioDC (brio_dc_delaunay(), Buchin and Mulzer) samples its
// gradation from: a grid of about two points a cell, crowded cells refined by grids of their own,
// and a search by rings of cells around each point.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_NEAREST_NEIGHBOUR_GRAPH_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_NEAREST_NEIGHBOUR_GRAPH_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/counting_sort.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
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
      end = cell + clamped_cell(a1, g.side_x) + 1;
      cell += clamped_cell(a0, g.side_x);
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
  const std::size_t near_row = clamped_cell(fy, g.side_y);
  for(std::size_t row = near_row; row < g.side_y && read < budget; ++row)
    if(!read_row(row))
      break;
  for(std::size_t row = near_row; row > 0 && read < budget; --row)
    if(!read_row(row - 1))
      break;
}

// A cell of nearest_neighbour_graph_in_frame() is refined when it holds more than this many
// points; a search reads at most this budget of points past its own cell.
constexpr std::size_t nng_crowded_cell = 32, nng_search_budget = 512;

// The grid of nearest_neighbour_graph_in_frame() over the bounding box of its points: about
// two points a cell, side_x x side_y cells, sx and sy cells per unit (0 along an axis of
// length 0).
struct Nng_grid_shape
{
  double xmin, ymin;
  std::size_t side_x, side_y;
  double sx, sy;
  double cell_width, cell_height;
  // A point beyond ring r of cells around its own is at least r of the shorter side away
  // (plus its distance to its cell's sides); a side of length 0 does not count.
  double shorter;
  std::size_t cells() const { return side_x * side_y; }
};

// The grid's shape for the m > 0 points xy[0..m): square cells of area 2 / density.
inline Nng_grid_shape nng_grid_shape(const double* xy, std::size_t m)
{
  // At most 4096 x 4096 cells (2^22 in a line): about two points a cell up to 2^25 points, and
  // the array of cell starts stays within 64 MB; denser cells are refined as crowded ones.
  constexpr double max_side = 4096, max_in_line = 1 << 22;
  const Box box = bounding_box_of_xy(xy, m);
  const double xmin = box.xmin, xmax = box.xmax, ymin = box.ymin, ymax = box.ymax;
  // In the frame nearest_neighbour_graph() gives, the box's larger side is 0 or between 2^-74
  // and 2^65; refined cells are smaller. A side below 2^-960 (a refined cell of points a few
  // subnormals apart near the origin) counts as 0: cells per unit would overflow, and the
  // squares of such differences underflow anyway.
  const double width = xmax - xmin > 0x1p-960 ? xmax - xmin : 0, height = ymax - ymin > 0x1p-960 ? ymax - ymin : 0;
  // Square cells of area 2 / density, sqrt(target * width / height) of them across (the
  // product width * height would underflow in small cells); a degenerate box gets a row or a
  // column of cells.
  const double target = (std::max)(1.0, double(m) / 2);
  std::size_t side_x = 1, side_y = 1;
  if(width > 0 && height > 0) {
    const double aspect = width / height; // an inf or 0 is clamped
    side_x = std::size_t((std::min)(max_side, (std::max)(1.0, std::floor(std::sqrt(target * aspect)))));
    side_y = std::size_t((std::min)(max_side, (std::max)(1.0, std::floor(std::sqrt(target / aspect)))));
  } else if(width > 0) {
    side_x = std::size_t((std::min)(max_in_line, target));
  } else if(height > 0) {
    side_y = std::size_t((std::min)(max_in_line, target));
  }
  const double sx = width > 0 ? double(side_x) / width : 0, sy = height > 0 ? double(side_y) / height : 0;
  const double cell_width = width > 0 ? width / double(side_x) : 0, cell_height = height > 0 ? height / double(side_y) : 0;
  const double shorter = cell_width > 0 && cell_height > 0 ? (std::min)(cell_width, cell_height)
                                                           : (std::max)(cell_width, cell_height);
  return Nng_grid_shape{xmin, ymin, side_x, side_y, sx, sy, cell_width, cell_height, shorter};
}

// Sorts the points xy[0..m) into the cells of `shape` (a counting sort, stable): writes to
// `order` the input position of each point in grid order, to `start` the first position of
// each cell (and m at the end).
inline void sort_into_cells(const double* xy, std::size_t m, const Nng_grid_shape& shape,
                            std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& start)
{
  std::vector<std::uint32_t> end;
  counting_sort(
      m, shape.cells(),
      [&](std::size_t k) {
        const double fx = (xy[2 * k] - shape.xmin) * shape.sx, fy = (xy[2 * k + 1] - shape.ymin) * shape.sy;
        return clamped_cell(fy, shape.side_y) * shape.side_x + clamped_cell(fx, shape.side_x);
      },
      [](std::size_t k) { return std::uint32_t(k); },
      [&](std::size_t position, std::uint32_t k) { order[position] = k; }, false, end);
  start.resize(end.size() + 1);
  start[0] = 0;
  std::copy(end.begin(), end.end(), start.begin() + 1);
}

// (Defined below; refine_crowded_cells() calls it on each crowded cell.)
inline void nearest_neighbour_graph_in_frame(const double* xy, std::size_t m, std::vector<std::uint32_t>& order,
                                             std::vector<std::uint32_t>& nn, int depth, Nng_cells* grid_out,
                                             bool parallel);

// Refines the crowded cells of the grid (cell c holds positions start[c] .. start[c + 1] - 1
// of `order`, coordinates `p`) by grids of their own, recorded in `grid`: their points are
// reordered in their grid's order and get their nearest neighbour within the cell, a first
// candidate (`nn`, squared distance in `best`) that the search over the whole grid improves.
inline void refine_crowded_cells(std::size_t m, int depth, const std::vector<std::uint32_t>& start,
                                 std::vector<std::uint32_t>& order, std::vector<double>& p,
                                 std::vector<std::uint32_t>& nn, std::vector<double>& best, Nng_cells& grid)
{
  const std::size_t cells = start.size() - 1;
  std::vector<std::uint32_t>& sub_of = grid.sub_of;
  std::vector<Nng_cells>& sub = grid.sub;
  std::vector<std::uint32_t> sub_order, sub_nn, moved;
  std::vector<double> sub_p;
  for(std::size_t c = 0; c < cells; ++c) {
    const std::size_t first = start[c], count = start[c + 1] - start[c];
    if(count <= nng_crowded_cell || count == m || depth >= max_grid_depth)
      continue;
    if(sub_of.empty())
      sub_of.assign(cells, no_rank);
    sub_of[c] = std::uint32_t(sub.size());
    sub.emplace_back();
    nearest_neighbour_graph_in_frame(p.data() + 2 * first, count, sub_order, sub_nn, depth + 1, &sub.back(), false);
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

// The searches of nearest_neighbour_graph_in_frame() over a grid whose crowded cells are
// refined: each point's own, reading the grid and writing only its own entries of `best` and
// `nn`, so blocks of cells can run on different threads.
struct Nng_search
{
  const double xmin, ymin, cell_width, cell_height, shorter;
  const std::size_t side_x, side_y, m;
  const std::vector<std::uint32_t>& start;
  const std::vector<double>& p; // coordinates in grid order
  const std::vector<std::uint32_t>& sub_of;
  const std::vector<Nng_cells>& sub;
  std::vector<double>& best;
  std::vector<std::uint32_t>& nn;

  // A cell of the grid, its low corner, and the 3 x 3 cells around it (fewer at the grid's
  // sides): columns col0 .. col1 of rows row0 .. row1.
  struct Cell_around
  {
    std::size_t c;
    long cx, cy;
    double cell_x0, cell_y0;
    std::size_t col0, col1, row0, row1;
  };

  bool refined(std::size_t c) const { return !sub_of.empty() && sub_of[c] != no_rank; }

  // The searches of the points of cells first .. last - 1.
  void search_cells(std::size_t first, std::size_t last) const
  {
    for(std::size_t c = first; c < last; ++c) {
      const long cx = long(c % side_x), cy = long(c / side_x);
      const double cell_x0 = xmin + double(cx) * cell_width, cell_y0 = ymin + double(cy) * cell_height;
      // The 3 x 3 cells around (fewer at the grid's sides): three runs of the grid order.
      const std::size_t col0 = std::size_t(cx > 0 ? cx - 1 : 0), col1 = (std::min)(std::size_t(cx) + 1, side_x - 1);
      const std::size_t row0 = std::size_t(cy > 0 ? cy - 1 : 0), row1 = (std::min)(std::size_t(cy) + 1, side_y - 1);
      const Cell_around cell{c, cx, cy, cell_x0, cell_y0, col0, col1, row0, row1};
      for(std::uint32_t k = start[c]; k < start[c + 1]; ++k)
        search_point(k, cell);
    }
  }

  // The search of point k, in `cell`: the cells around first, then its own cell, then rings
  // of cells until no nearer point can lie beyond.
  void search_point(std::uint32_t k, const Cell_around& cell) const
  {
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
      margin = (std::min)({margin, x - cell.cell_x0, cell.cell_x0 + cell_width - x});
    if(cell_height > 0)
      margin = (std::min)({margin, y - cell.cell_y0, cell.cell_y0 + cell_height - y});
    margin = (std::max)(0.0, margin);
    long r = 1;
    std::size_t read = 0;
    bool searched = false;
    if(!refined(cell.c))
      searched = read_cells_around(k, x, y, margin, cell, b, bk, r, read);
    if(!searched && r == 1) {
      if(!refined(cell.c)) { // (a cell is that large only when it holds every point: equal points)
        for(std::uint32_t j = start[cell.c]; j < start[cell.c + 1] && read < nng_search_budget && b > 0;
            ++j, ++read)
          consider(j);
        read = 0;
      }
      searched = b <= margin * margin;
    }
    if(!searched)
      read_rings(x, y, margin, cell, r, b, read, consider);
    if(bk == no_rank && m > 1) { // no other point read (not with finite coordinates): any will do
      bk = k == 0 ? 1 : k - 1;
      b = std::numeric_limits<double>::infinity();
    }
    best[k] = b;
    nn[k] = bk;
  }

  // The common case, for a cell not refined: the cells around are at most three runs of the
  // grid order (rows), read at once unless they are dense (then the rings read less). Returns
  // whether the search is over; when they were read, sets r = 2 and `read`.
  bool read_cells_around(std::uint32_t k, double x, double y, double margin, const Cell_around& cell, double& b,
                         std::uint32_t& bk, long& r, std::size_t& read) const
  {
    std::uint32_t run[3][2];
    std::size_t total = 0, runs = 0;
    for(std::size_t row = cell.row0; row <= cell.row1; ++row, ++runs) {
      run[runs][0] = start[row * side_x + cell.col0];
      run[runs][1] = start[row * side_x + cell.col1 + 1];
      total += run[runs][1] - run[runs][0];
    }
    if(total > 4 * nng_crowded_cell)
      return false; // dense cells around: the rings read less
    // On copies of b and bk: `consider` passes their addresses on, which would keep them in
    // memory in this, the hottest loop. Candidates read in increasing position need only the
    // strict comparison for the tie rule.
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
    r = 2;
    read = total;
    return b <= (shorter + margin) * (shorter + margin);
  }

  // Rings of cells from ring r on, until no nearer point can lie beyond the ring (or the
  // budget is spent), skipping the cells farther than the best candidate so far.
  template <class Consider>
  void read_rings(double x, double y, double margin, const Cell_around& cell, long r, const double& b,
                  std::size_t& read, Consider& consider) const
  {
    const long cx = cell.cx, cy = cell.cy;
    for(bool searched = false; !searched; ++r) {
      // Cells at Chebyshev distance r from (cx, cy).
      const long x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
      bool any_cell = false;
      for(long gy = (std::max)(0L, y0); gy <= (std::min)(long(side_y) - 1, y1) && read < nng_search_budget; ++gy) {
        const bool edge_row = gy == y0 || gy == y1;
        for(long gx = (std::max)(0L, x0); gx <= (std::min)(long(side_x) - 1, x1) && read < nng_search_budget;
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
          const std::size_t ring_cell = std::size_t(gy) * side_x + std::size_t(gx);
          if(refined(ring_cell)) {
            read_grid_near(sub[sub_of[ring_cell]], start[ring_cell], x, y, b, read, nng_search_budget, consider);
            continue;
          }
          const std::uint32_t last =
              (std::min)(start[ring_cell + 1], std::uint32_t(start[ring_cell] + (nng_search_budget - read)));
          for(std::uint32_t j = start[ring_cell]; j < last; ++j)
            consider(j);
          read += last - start[ring_cell];
        }
      }
      const double reach = double(r) * shorter + margin;
      searched = !any_cell || b <= reach * reach || read >= nng_search_budget || b == 0;
    }
  }
};

// The nearest-neighbour graph of the points xy[0..m) (coordinates in double, x and y
// interleaved), with a grid of about two points a cell over their bounding box, rows in
// order; a cell holding more than 32 points (clusters, a density varying by orders of
// magnitude) is refined by the same procedure on its points, up to depth 6. Writes to `order`
// the points in the grid order (refined cells in their own grid order): order[k] is the input
// position of the k-th point; and to `nn` the nearest neighbour of each, as a position in
// that order (no_rank for a single point). Each point's search reads the 3 x 3 cells around
// its own (when they hold at most 128 points), then rings of cells until no nearer point can
// lie beyond, skipping the cells farther than the best candidate so far, at most
// nng_search_budget points past its own cell (then the nearest point read is taken: equal
// points by the hundred); ties go to the smaller position in the order. A search that reaches
// a refined cell reads it through its grid (read_grid_near()), only the subcells within the
// circle of the best candidate. Double precision and the budget make the graph approximate in
// rare cases: it only guides the insertion, so that costs time, never correctness. `grid_out`,
// if given, receives the grid with its refined cells' grids (for the searches of its caller).
//
// Here on coordinates in a frame where no squared distance that matters overflows (see
// nearest_neighbour_graph()); `depth` counts the refinements. With `parallel`, the searches
// (each point's own, reading the grid and writing only its own entries) run in blocks of
// cells on TBB's threads; the graph is the same.
inline void nearest_neighbour_graph_in_frame(const double* xy, std::size_t m, std::vector<std::uint32_t>& order,
                                             std::vector<std::uint32_t>& nn, int depth, Nng_cells* grid_out,
                                             bool parallel = false)
{
  order.resize(m);
  nn.assign(m, no_rank);
  if(m == 0)
    return;
  // The points sorted into the grid's cells, crowded cells refined.
  const Nng_grid_shape shape = nng_grid_shape(xy, m);
  std::vector<std::uint32_t> start;
  sort_into_cells(xy, m, shape, order, start);
  std::vector<double> p(2 * m); // coordinates in grid order
  gather_coordinates(xy, order.data(), m, p.data());
  std::vector<double> best(m, std::numeric_limits<double>::infinity());
  Nng_cells grid; // this grid's refined cells (the rest is filled in at the end)
  refine_crowded_cells(m, depth, start, order, p, nn, best, grid);
  // Each point's search, in blocks of 4096 cells (about 8192 points).
  const Nng_search search{shape.xmin, shape.ymin, shape.cell_width, shape.cell_height, shape.shorter, shape.side_x,
                          shape.side_y, m, start, p, grid.sub_of, grid.sub, best, nn};
  constexpr std::size_t block_cells = 4096;
  for_each_range(parallel, shape.cells(), block_cells,
                 [&](std::size_t first, std::size_t last) { search.search_cells(first, last); });
  if(grid_out != nullptr) {
    grid.xmin = shape.xmin;
    grid.ymin = shape.ymin;
    grid.sx = shape.sx;
    grid.sy = shape.sy;
    grid.side_x = shape.side_x;
    grid.side_y = shape.side_y;
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
                                    std::vector<std::uint32_t>& nn, bool parallel = false)
{
  if(m == 0) {
    order.clear();
    nn.clear();
    return;
  }
  const Box box = bounding_box_of_xy(xy, m);
  const double scale = unit_scale(box);
  if(scale >= 0x1p-64 && scale <= 0x1p64)
    return nearest_neighbour_graph_in_frame(xy, m, order, nn, 0, nullptr, parallel);
  std::vector<double> scaled(xy, xy + 2 * m);
  for(double& c : scaled)
    c *= scale;
  nearest_neighbour_graph_in_frame(scaled.data(), m, order, nn, 0, nullptr, parallel);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_NEAREST_NEIGHBOUR_GRAPH_H
