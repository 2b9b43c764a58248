// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Whether a repair's detached vertices include one at the point of another vertex: the local
// repairs of delaunay_from_prediction() and make_delaunay() check it before they commit.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_DUPLICATE_VERTICES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_DUPLICATE_VERTICES_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether two of `tr`'s finite vertices, one of them in `candidates`, are at the same point.
// Coordinates that are doubles are compared bit for bit through a hash table of the
// candidates (one pass over the vertices, a few ns each); other number types by an exact
// binary search among the sorted candidates.
template <class Triangulation>
bool has_duplicate_of(const Triangulation& tr,
                      const std::vector<typename Triangulation::Vertex_handle>& candidates)
{
  using Point = typename Triangulation::Point;
  if(candidates.empty())
    return false;
  if constexpr(std::is_same<std::decay_t<decltype(CGAL::to_double(std::declval<Point>().x()))>, double>::value &&
               std::is_same<std::decay_t<decltype(std::declval<Point>().x())>, double>::value) {
    auto bits = [](double x) {
      x = (x == 0) ? 0.0 : x; // -0 == +0
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      return b;
    };
    std::size_t size = 64;
    int log_size = 6;
    while(size < 4 * candidates.size()) {
      size <<= 1;
      ++log_size;
    }
    struct Slot { std::uint64_t x, y; const void* v; };
    std::vector<Slot> table(size, Slot{0, 0, nullptr});
    auto hash = [](std::uint64_t x, std::uint64_t y) { return (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full); };
    auto slot_of = [&](std::uint64_t x, std::uint64_t y, std::uint64_t h) {
      std::size_t i = std::size_t(h) & (size - 1);
      while(table[i].v != nullptr && (table[i].x != x || table[i].y != y))
        i = (i + 1) & (size - 1);
      return i;
    };
    // The table outgrows the caches (24 bytes a slot); a filter of 4 bits a slot, by other
    // bits of the hash, stays in them and turns away almost every vertex before the table.
    const int log_filter = log_size + 2;
    std::vector<std::uint64_t> filter((std::size_t(1) << log_filter) / 64 + 1, 0);
    auto filter_bit = [&](std::uint64_t h) { return std::size_t(h >> (64 - log_filter)); };
    for(const auto& v : candidates) {
      const std::uint64_t x = bits(v->point().x()), y = bits(v->point().y()), h = hash(x, y);
      Slot& s = table[slot_of(x, y, h)];
      if(s.v != nullptr)
        return true;
      s = Slot{x, y, &*v};
      filter[filter_bit(h) >> 6] |= std::uint64_t(1) << (filter_bit(h) & 63);
    }
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const std::uint64_t x = bits(v->point().x()), y = bits(v->point().y()), h = hash(x, y);
      if(((filter[filter_bit(h) >> 6] >> (filter_bit(h) & 63)) & 1) == 0)
        continue;
      const Slot& s = table[slot_of(x, y, h)];
      if(s.v != nullptr && s.v != &*v)
        return true;
    }
    return false;
  } else {
    auto less = [&](const Point& a, const Point& b) { return compare_xy_out_of_line(tr.geom_traits(), a, b) == SMALLER; };
    std::vector<std::pair<Point, const void*>> sorted;
    for(const auto& v : candidates)
      sorted.emplace_back(v->point(), &*v);
    std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) { return less(a.first, b.first); });
    for(std::size_t k = 1; k < sorted.size(); ++k)
      if(!less(sorted[k - 1].first, sorted[k].first))
        return true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const auto it = std::lower_bound(sorted.begin(), sorted.end(), v->point(),
                                       [&](const auto& a, const Point& p) { return less(a.first, p); });
      if(it != sorted.end() && !less(v->point(), it->first) && it->second != &*v)
        return true;
    }
    return false;
  }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REPAIR_DUPLICATE_VERTICES_H
