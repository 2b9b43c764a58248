// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Spatial reordering of a prediction before its import. Points and faces that come in no
// spatial order (a shuffled mesh, a learned model's output) make every later pass read
// memory at random; points renumbered along a serpentine grid (a few points per cell) and
// faces sorted by their smallest new index make those passes touch a narrow band of memory
// instead. The grid uses floating-point coordinates only to choose an order: no result
// depends on it. Each step is skipped when a sample shows the input already in order (a
// mesh file written in mesh order, CGAL's own triangulations, Hilbert-sorted points).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_SPATIAL_ORDER_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_SPATIAL_ORDER_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/counting_sort.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// A grid cell with more points than this (the grids aim at four) is sorted again.
constexpr std::size_t crowded_cell = 64;

// The rounds of a biased randomized insertion order (BRIO): the next point is in round r with
// probability 7/8^(r+1), the last round taking the rest.
constexpr std::uint32_t brio_rounds = 8;
inline std::uint32_t brio_round(Splitmix64& random)
{
  std::uint32_t round = 0;
  for(std::uint64_t bits = random(); round + 1 < brio_rounds && (bits & 7) == 0; bits >>= 3)
    ++round;
  return round;
}

// The seed of the rounds: fixed, so that a build is the same from run to run.
constexpr std::uint64_t brio_seed = 0x5eed5eed5eedull;

// How often a crowded cell of sort_serpentine() is sorted again within itself: six levels
// resolve densities varying by 4^6 times the points per cell.
constexpr int max_grid_depth = 6;

// The point of index i of a random-access sequence: the reader of points that sort_along_grid()'s
// callers share, so that a program compiles the sort once per point iterator rather than once
// per call (each lambda has a type of its own). Not a Function_ref: an indirect call for each
// point read would slow the sort, which runs on every import and rebuild.
template <class PointIterator>
struct Point_of_index
{
  PointIterator points;
  decltype(auto) operator()(std::size_t i) const { return points[i]; }
};

// The coordinates, as doubles, of the point point_at(i) of index i, for sort_serpentine().
template <class PointAt>
struct Coordinates_reader
{
  const PointAt& point_at;
  void operator()(std::size_t i, double& x, double& y) const
  {
    const auto& p = point_at(i);
    x = CGAL::to_double(p.x());
    y = CGAL::to_double(p.y());
  }
};

// Writes to `out` the indices in [first, last) sorted along a serpentine grid over the
// bounding box of their points, about four points a cell, rows alternately left to right and
// right to left, so that consecutive indices name nearby points; then sorts each crowded cell
// the same way over its own box, up to max_grid_depth. Cells far above their share (clusters, a density varying by orders of
// magnitude) need it: a build of 1e6 points of density varying 10^8 times across the square
// (x = u^4, y = v^4) took 1.6 times CGAL's time without, 0.8 times with. With
// `biased_rounds` (depth 0 only), the points are first dealt into rounds (round r with
// probability 7/8^(r+1), fixed seed), listed from the sparsest, each round in grid order.
//
// With `parallel` (no biased rounds: their random draws are sequential), the bounding box and
// the sort run on TBB's threads (counting_sort()), with the same order. `point(i, x, y)` sets x
// and y to the coordinates of the point of index i (a Coordinates_reader).
template <class Parallel = std::false_type, class Reader>
void sort_serpentine(const std::uint32_t* first, const std::uint32_t* last, std::uint32_t* out, const Reader& point,
                     bool biased_rounds, int depth, Parallel in_parallel = Parallel())
{
  const std::size_t m = std::size_t(last - first);
  const auto parallel = parallel_argument<Parallel>(in_parallel && !biased_rounds);
  const std::size_t block = 1 << 16, blocks = (m + block - 1) / block;
  std::vector<Box> block_box(blocks);
  for_each_block(parallel, blocks, [&](std::size_t b) {
    Box& box = block_box[b];
    double x, y;
    for(std::size_t k = b * block, end = (std::min)(m, k + block); k < end; ++k) {
      point(std::size_t(first[k]), x, y);
      box.add(x, y);
    }
  });
  Box box;
  for(const Box& b : block_box)
    box.add(b);
  const std::size_t fit = std::size_t(std::sqrt(double(m) / 4));
  const std::size_t side = depth == 0 ? (std::min)(std::size_t(1) << 12, (std::max)(std::size_t(1), fit))
                                      : (std::max)(std::size_t(2), fit);
  const Cell_grid grid(box, side, side);
  const std::size_t cells = grid.cells();
  Splitmix64 random{brio_seed};
  std::vector<std::uint32_t> end;
  counting_sort(
      m, (biased_rounds ? brio_rounds : 1) * cells,
      [&](std::size_t k) {
        double x, y;
        point(std::size_t(first[k]), x, y);
        const std::size_t cx = grid.column(x), cy = grid.row(y);
        std::size_t cell = cy * side + ((cy & 1) ? side - 1 - cx : cx);
        if(biased_rounds) // (sequential: in item order)
          cell += (brio_rounds - 1 - brio_round(random)) * cells;
        return cell;
      },
      [&](std::size_t k) { return first[k]; }, [&](std::size_t position, std::uint32_t i) { out[position] = i; }, parallel,
      end);
  if(depth >= max_grid_depth)
    return;
  std::vector<std::uint32_t> crowded;
  for(std::size_t c = 0, begin = 0; c < end.size(); begin = end[c], ++c)
    if(end[c] - begin > crowded_cell && end[c] - begin < m) { // m: all equal points, no progress
      crowded.assign(out + begin, out + end[c]);
      sort_serpentine(crowded.data(), crowded.data() + crowded.size(), out + begin, point, false, depth + 1,
                      std::false_type());
    }
}

// Sorts `indices` (of points) along the serpentine grid (sort_serpentine()). With
// `biased_rounds`, in rounds: the biased randomized insertion order (BRIO) that keeps
// incremental insertion fast, at a tenth of the cost of spatial_sort's median splits.
// Indices of another type than std::uint32_t are sorted as 32-bit ones (no triangulation
// holds 2^32 points).
template <class Index, class PointAt, class Parallel = std::false_type>
void sort_along_grid(std::vector<Index>& indices, const PointAt& point_at, bool biased_rounds,
                     Parallel parallel = Parallel())
{
  if(indices.size() < 2)
    return;
  const Coordinates_reader<PointAt> read{point_at};
  if constexpr(std::is_same<Index, std::uint32_t>::value) {
    std::vector<std::uint32_t> sorted(indices.size());
    sort_serpentine(indices.data(), indices.data() + indices.size(), sorted.data(), read, biased_rounds, 0, parallel);
    indices.swap(sorted);
  } else {
    CGAL_precondition(indices.size() < std::size_t(std::uint32_t(-1)));
    std::vector<std::uint32_t> narrow(indices.begin(), indices.end()), sorted(indices.size());
    sort_serpentine(narrow.data(), narrow.data() + narrow.size(), sorted.data(), read, biased_rounds, 0, parallel);
    std::copy(sorted.begin(), sorted.end(), indices.begin());
  }
}

// Deals indices listed in a spatial order into the rounds of a biased randomized insertion
// order, the sparsest round first, keeping their order within each round: the order
// sort_along_grid() gives with `biased_rounds`, from a list already in grid order.
template <class Index>
void deal_into_rounds(std::vector<Index>& indices)
{
  Splitmix64 random{brio_seed};
  std::vector<std::uint8_t> round(indices.size());
  std::size_t start[brio_rounds + 1] = {};
  for(std::size_t k = 0; k < indices.size(); ++k) {
    round[k] = std::uint8_t(brio_rounds - 1 - brio_round(random));
    ++start[round[k] + 1];
  }
  for(std::uint32_t r = 1; r <= brio_rounds; ++r)
    start[r] += start[r - 1];
  std::vector<Index> dealt(indices.size());
  for(std::size_t k = 0; k < indices.size(); ++k)
    dealt[start[round[k]]++] = indices[k];
  indices.swap(dealt);
}

class Spatial_order
{
public:
  // Below this many points everything a pass touches fits in the first cache levels and
  // reordering gains nothing (measured at 1e3-4e3). Above it, a shuffled input imports
  // 1.3-1.5x faster after reordering (measured at 2e4-6e4 points: ratio to CGAL's build
  // 1.5-1.7 without, 2.2-2.3 with), so the threshold is low.
  static constexpr std::size_t min_points = 1u << 12;

  // Decides and applies the reordering: renumbers the indices in `triples` (3 per face) and
  // permutes the faces. Afterwards old_index(v) is the caller's index of new point index v.
  // With `parallel`, on TBB's threads, with the same result.
  template <class Gt, class PointIterator, class Parallel = std::false_type>
  void compute(const Gt&, PointIterator points, std::size_t n, std::vector<std::uint32_t>& triples,
               Parallel parallel = Parallel())
  {
    if(n < min_points || triples.size() < 3 * min_points)
      return;
    if(!points_look_ordered(triples, n))
      renumber_points(points, n, triples, parallel);
    if(!faces_look_ordered(triples, n))
      sort_faces(triples, n, parallel);
  }

  bool renumbered() const { return !old_of_.empty(); }
  bool faces_sorted() const { return faces_sorted_; }
  std::uint32_t old_index(std::uint32_t v) const { return old_of_.empty() ? v : old_of_[v]; }
  // The caller's indices in the new order (empty if not renumbered); the order is spent.
  std::vector<std::uint32_t> take_old_indices() { return std::move(old_of_); }

private:
  static constexpr std::size_t samples = 255;

  // Points are in spatial order if most faces have vertices with close indices. (CGAL's
  // spatial_sort is not: its multiscale rounds interleave far indices in space.)
  static bool points_look_ordered(const std::vector<std::uint32_t>& triples, std::size_t n)
  {
    const std::size_t faces = triples.size() / 3;
    std::vector<std::uint32_t> spans;
    for(std::size_t s = 0; s < samples; ++s) {
      const std::uint32_t* t = triples.data() + 3 * (s * faces / samples);
      spans.push_back((std::max)({t[0], t[1], t[2]}) - (std::min)({t[0], t[1], t[2]}));
    }
    std::nth_element(spans.begin(), spans.begin() + spans.size() / 2, spans.end());
    return spans[spans.size() / 2] <= std::uint32_t(4 * std::sqrt(double(n))) + 64;
  }

  // Faces are in band order if no face's smallest index falls more than a band width below
  // the largest smallest index seen before it: then a half-edge waits at most about a band
  // of faces for its twin, and the table of open half-edges stays small. One sequential pass.
  static bool faces_look_ordered(const std::vector<std::uint32_t>& triples, std::size_t n)
  {
    const std::uint32_t band = std::uint32_t(8 * std::sqrt(double(n))) + 64;
    std::uint32_t highest = 0;
    for(std::size_t k = 0; k < triples.size(); k += 3) {
      const std::uint32_t key = (std::min)({triples[k], triples[k + 1], triples[k + 2]});
      if(key + band < highest)
        return false;
      highest = (std::max)(highest, key);
    }
    return true;
  }

  template <class PointIterator, class Parallel>
  void renumber_points(PointIterator points, std::size_t n, std::vector<std::uint32_t>& triples, Parallel parallel)
  {
    old_of_.resize(n);
    const std::unique_ptr<std::uint32_t[]> new_of(new std::uint32_t[n]); // every entry written below
    constexpr std::size_t block = 1 << 16;
    for_each_range(parallel, n, block, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
        old_of_[i] = std::uint32_t(i);
    });
    sort_along_grid(old_of_, Point_of_index<PointIterator>{points}, false, parallel);
    for_each_range(parallel, n, block, [&](std::size_t first, std::size_t last) {
      for(std::size_t v = first; v < last; ++v)
        new_of[old_of_[v]] = std::uint32_t(v);
    });
    for_each_range(parallel, triples.size(), block, [&](std::size_t first, std::size_t last) {
      for(std::size_t k = first; k < last; ++k)
        triples[k] = new_of[triples[k]];
    });
  }

  // Counting sort of the faces by their smallest index (in groups of four indices).
  template <class Parallel>
  void sort_faces(std::vector<std::uint32_t>& triples, std::size_t n, Parallel parallel)
  {
    std::vector<std::uint32_t> sorted(triples.size()), end;
    counting_sort(
        triples.size() / 3, (n >> 2) + 1,
        [&](std::size_t f) {
          const std::uint32_t* t = triples.data() + 3 * f;
          return (std::min)({t[0], t[1], t[2]}) >> 2;
        },
        [&](std::size_t f) {
          const std::uint32_t* t = triples.data() + 3 * f;
          return std::array<std::uint32_t, 3>{t[0], t[1], t[2]};
        },
        [&](std::size_t position, const std::array<std::uint32_t, 3>& t) {
          std::uint32_t* to = sorted.data() + 3 * position;
          to[0] = t[0];
          to[1] = t[1];
          to[2] = t[2];
        },
        parallel, end);
    triples.swap(sorted);
    faces_sorted_ = true;
  }

  std::vector<std::uint32_t> old_of_; // new index -> caller's index; empty if not renumbered
  bool faces_sorted_ = false;
};

// Whether points listed in this order are spatially coherent: the median distance between
// 255 sampled consecutive points is at most 4 times the side of the area per point of their
// bounding box (CGAL's spatial sort, even in BRIO rounds, is; an order of insertion at random
// is not).
template <class PointAt>
bool order_looks_spatial(std::size_t n, PointAt point_at)
{
  if(n < 4096)
    return false; // small: sorting costs nothing
  const Spacing_sample sample = sample_spacing(n, point_at, [&](std::size_t s) {
    const std::size_t k = s * (n - 1) / 255;
    return std::pair<std::size_t, std::size_t>(k, k + 1);
  });
  return sample.median_squared_distance <= 16 * sample.area_per_point;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_SPATIAL_ORDER_H
