// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Theorem 5.4 of the paper in practical form (Strategy::regions): the prediction's faces
// divided into connected regions, each region's points triangulated on its own (on TBB's
// threads with Parallel_tag), the faces each region can vouch for kept, the rest (the seams
// between regions) triangulated again, the pieces joined and certified by
// triangulate_blocks() (block_parallel_build.h).
//
// The division (the paper's step 1). Regions are grown breadth-first over the prediction:
// from a seed point through the faces of each point reached to their corners, until the
// region holds its share of points or its component of the prediction is exhausted. A point
// belongs to the first region that reaches it: the paper's regions share their boundary
// vertices, here each point is in one region, so that each region's triangulation owns its
// vertices. Regions smaller than an eighth of the share (fragments squeezed between others)
// join a neighbouring region. Points in no face form one more block, whose faces are never
// kept.
//
// What is kept (steps 2 to 4). The paper keeps the edges of DT(V_gamma) that lie inside the
// region and lets the D-sensitive repair (Theorem 2.1) correct the O(d_cross sqrt t) wrong
// ones, which needs ray shooting along the region's boundary. Here a face of a region's
// triangulation is kept when its circumdisk covers only grid cells that hold no point or only
// points of its region (a grid of about two points per cell): then no other point lies in the
// disk and the face is a face of DT(P). Faces along region boundaries, and wherever regions
// interleave, are not kept; the seams' triangulation replaces them (step 5), and Lawson's
// flips repair the walls between the two (step 6). The seams grow with the prediction's error:
// a wrong prediction's regions interleave, over a width that d_cross bounds. When more than a
// quarter of the occupied cells hold points of two regions, the division is not worth
// triangulating and the call gives up before any triangulation.
//
// What is not the paper's: no recursion (each region is built by the package's insertion,
// the paper's base case, so the work is that of a build from scratch plus the seams, not
// O(n log* n + n log d_cross)); the grid certificate instead of ray shooting; the unknown
// d_cross is not guessed, the region size is fixed (default_prediction_region_size()), and a
// larger d_cross only makes the seams wider.
//
// Why it is robust: the grid and the disks are double arithmetic on scaled coordinates
// (grid.h) and only steer; whatever they say, triangulate_blocks() certifies the result by
// exact predicates or reports that the pieces do not fit (then the caller builds from
// scratch).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_PREDICTION_REGIONS_BUILD_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_PREDICTION_REGIONS_BUILD_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/dense_index.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/region_growing.h>
#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Default region size of Strategy::regions, in faces, for n points on `threads` threads: two
// regions per thread and at least four regions (so that the seams stay a small share), of at
// least 64 faces.
inline std::size_t default_prediction_region_size(std::size_t n, std::size_t threads)
{
  const std::size_t regions = 2 * (std::max)(std::size_t(2), threads);
  return (std::max)(std::size_t(64), 2 * n / regions);
}

// Grows the regions (see the file's comment) over the faces `triples` (three indices a face,
// each below n), of about `share` points each. region_of[i] is the region of point i, or
// no_region for a point in no face. Returns the number of regions.
inline std::size_t grow_prediction_regions(std::size_t n, const std::vector<std::uint32_t>& triples,
                                           std::size_t share, std::vector<std::uint32_t>& region_of)
{
  // The faces of each point, in compressed rows. (Listing each point's neighbours instead,
  // without the indirection through the faces, measured no faster: the traversal's cost is
  // its random accesses to region_of.)
  std::vector<std::uint32_t> first(n + 1, 0);
  for(const std::uint32_t v : triples)
    ++first[v + 1];
  for(std::size_t i = 0; i < n; ++i)
    first[i + 1] += first[i];
  std::vector<std::uint32_t> faces_of(triples.size());
  {
    std::vector<std::uint32_t> at(first.begin(), first.end() - 1);
    for(std::size_t k = 0; k < triples.size(); ++k)
      faces_of[at[triples[k]]++] = std::uint32_t(k / 3);
  }
  auto for_each_neighbour = [&](std::uint32_t p, auto&& body) {
    for(std::uint32_t k = first[p]; k < first[p + 1]; ++k)
      for(int j = 0; j < 3; ++j)
        if(!body(triples[3 * std::size_t(faces_of[k]) + std::size_t(j)]))
          return;
  };

  region_of.assign(n, no_region);
  std::vector<std::size_t> size;
  std::vector<std::uint32_t> queue;
  for(const std::uint32_t seed : triples) {
    if(region_of[seed] != no_region)
      continue;
    const std::uint32_t r = std::uint32_t(size.size());
    queue.assign(1, seed);
    region_of[seed] = r;
    for(std::size_t head = 0; head < queue.size() && queue.size() < share; ++head)
      for_each_neighbour(queue[head], [&](std::uint32_t q) {
        if(region_of[q] == no_region) {
          region_of[q] = r;
          queue.push_back(q);
        }
        return queue.size() < share;
      });
    size.push_back(queue.size());
  }

  // Fragments join the first region of full size found next to them.
  const std::size_t fragment = share / 8;
  std::vector<std::uint32_t> joins(size.size(), no_region);
  for(std::uint32_t p = 0; p < n; ++p) {
    const std::uint32_t r = region_of[p];
    if(r == no_region || size[r] >= fragment || joins[r] != no_region)
      continue;
    for_each_neighbour(p, [&](std::uint32_t q) {
      if(size[region_of[q]] >= fragment) {
        joins[r] = region_of[q];
        return false;
      }
      return true;
    });
  }
  // Regions numbered anew, without the joined fragments.
  std::vector<std::uint32_t> number(size.size(), no_region);
  std::uint32_t regions = 0;
  for(std::size_t r = 0; r < size.size(); ++r)
    if(joins[r] == no_region)
      number[r] = regions++;
  for(std::uint32_t& r : region_of)
    if(r != no_region)
      r = number[joins[r] == no_region ? r : joins[r]];
  return regions;
}

// Builds DT(points[0, n)) into `dt` (no vertex yet) from the prediction `triples` (three
// indices a face, each below n, as read by read_index_triples()) by regions of about
// `region_size` faces (see the file's comment), on TBB's threads when `parallel`. Every point
// is a vertex with its index as info(), duplicates merged (the smallest index kept). Returns
// Outcome::ok, or why not with `dt` still empty (then the caller builds from scratch).
// stats.regions and stats.boundary_vertices (the points triangulated again for the seams) are
// set whatever the outcome.
template <class DT, class PointIterator>
Outcome build_by_prediction_regions(DT& dt, PointIterator points, std::size_t n,
                                    const std::vector<std::uint32_t>& triples, std::size_t region_size,
                                    Statistics& stats, bool parallel)
{
  CGAL_precondition(dt.number_of_vertices() == 0);
  if(n < 3 || n >= std::size_t(no_region) || triples.empty())
    return Outcome::no_faces;
  std::vector<std::uint32_t> region_of;
  const std::size_t regions =
      grow_prediction_regions(n, triples, (std::max)(std::size_t(3), region_size / 2), region_of);
  stats.regions = regions;
  if(regions < 2)
    return Outcome::too_few_regions;

  // The points by region, the points in no face last (block `loose`).
  const std::size_t loose = regions;
  std::vector<Build_block> blocks(regions + 1);
  for(const std::uint32_t r : region_of)
    ++blocks[r == no_region ? loose : r].end;
  stats.points_unused = blocks[loose].end; // points in no face
  for(std::size_t b = 0, at = 0; b < blocks.size(); ++b) {
    blocks[b].begin = at;
    at += blocks[b].end;
    blocks[b].end = blocks[b].begin;
  }
  std::vector<std::uint32_t> order(n);
  for(std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t r = region_of[i];
    order[blocks[r == no_region ? loose : r].end++] = i;
  }

  // The grid of owners: about two points a cell, each cell empty, of one block, or mixed.
  const Box box = bounding_box(n, [&](std::size_t i) -> decltype(points[0]) { return points[i]; });
  const double scale = unit_scale(box);
  const double width = box.xmax * scale - box.xmin * scale, height = box.ymax * scale - box.ymin * scale;
  const double cells_wanted = double(n) / 2;
  // At most n + 1 cells a row or column (a very flat box), clamped in double: the ratio of the
  // sides of a box may be 1e300, and casting a double beyond std::size_t is undefined.
  auto cells_along = [&](double wanted) {
    return std::size_t((std::max)(1.0, (std::min)(std::ceil(wanted), double(n + 1))));
  };
  std::size_t columns = 1, rows = 1;
  if(width > 0 && height > 0) {
    columns = cells_along(std::sqrt(cells_wanted * width / height));
    rows = cells_along(std::sqrt(cells_wanted * height / width));
  } else if(width > 0) {
    columns = cells_along(cells_wanted);
  } else if(height > 0) {
    rows = cells_along(cells_wanted);
  }
  // On coordinates times `scale`, those of the circumdisks below.
  Box scaled_box;
  scaled_box.add(box.xmin * scale, box.ymin * scale);
  scaled_box.add(box.xmax * scale, box.ymax * scale);
  const Cell_grid grid(scaled_box, columns, rows);
  constexpr std::uint32_t empty = std::uint32_t(-1), mixed = std::uint32_t(-2);
  std::vector<std::uint32_t> owner(columns * rows, empty);
  std::size_t occupied = 0, mixed_cells = 0;
  for(std::size_t b = 0; b < blocks.size(); ++b)
    for(std::size_t k = blocks[b].begin; k < blocks[b].end; ++k) {
      const std::uint32_t i = order[k];
      std::uint32_t& o = owner[grid(CGAL::to_double(points[i].x()) * scale, CGAL::to_double(points[i].y()) * scale)];
      if(o == empty) {
        o = std::uint32_t(b);
        ++occupied;
      } else if(o != b && o != mixed) {
        o = mixed;
        ++mixed_cells;
      }
    }
  if(4 * mixed_cells > occupied)
    return Outcome::regions_interleave;

  // A face of block b is kept when its disk's cells are empty or b's (at most 64 of them: a
  // larger disk is a hull face, or one across a region, left to the seams).
  auto kept = [&](std::size_t b, const std::array<double, 2>& p, const std::array<double, 2>& q,
                  const std::array<double, 2>& r) {
    if(b == loose)
      return false;
    const Scaled_disk disk = scaled_circumdisk(p, q, r);
    if(!disk.finite())
      return false;
    const std::size_t c0 = grid.column(disk.x - disk.r), c1 = grid.column(disk.x + disk.r);
    const std::size_t r0 = grid.row(disk.y - disk.r), r1 = grid.row(disk.y + disk.r);
    if((c1 - c0 + 1) * (r1 - r0 + 1) > 64)
      return false;
    for(std::size_t row = r0; row <= r1; ++row)
      for(std::size_t column = c0; column <= c1; ++column) {
        const std::uint32_t o = owner[row * columns + column];
        if(o != empty && o != b)
          return false;
      }
    return true;
  };
  Block_build_counts counts;
  const bool fits = triangulate_blocks(dt, points, n, scale, order, blocks, kept, stats, parallel, &counts);
  stats.boundary_vertices = counts.seam_points;
  return fits ? Outcome::ok : Outcome::regions_do_not_fit;
}

// The finite faces of `tr` (dimension 2) as index triples, a vertex's index its rank among
// the finite vertices in iteration order (the order of rebuild_keeping_vertices()).
template <class Triangulation>
void finite_faces_as_index_triples(const Triangulation& tr, std::vector<std::uint32_t>& triples)
{
  const Dense_index<typename Triangulation::Triangulation_data_structure::Vertex_range> index(tr.tds().vertices());
  const std::size_t infinite = index.of(tr.infinite_vertex());
  triples.clear();
  triples.reserve(3 * tr.number_of_faces());
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    for(int i = 0; i < 3; ++i) {
      const std::size_t k = index.of(f->vertex(i));
      triples.push_back(std::uint32_t(k - (k > infinite ? 1 : 0)));
    }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_PREDICTION_REGIONS_BUILD_H
