// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Open_halfedges: the pairing of half-edges with their twins by undirected edge, for faces
// that arrive in a spatial order; used by the import of index triples in the plane
// (import_prediction.h) and on the torus (periodic/torus_triangulation.h).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_OPEN_HALFEDGES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_OPEN_HALFEDGES_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Half-edges waiting for their twin, filed under the edge's smaller endpoint u in a ring of
// per-vertex lists indexed by u modulo a power of two. Faces arrive in band order (sorted by
// smallest index, spatial_order.h), so the endpoints with waiting half-edges lie in a window
// narrower than the ring and a lookup is a scan of a few entries in cache. A list that is full,
// or whose ring slot is claimed by a later vertex, spills into a hash map; one bit per
// vertex says whether it has spilled, so that the table is only searched for those (hull
// half-edges wait forever and would otherwise keep it busy).
class Open_halfedges
{
public:
  // With `banded`, the faces come in band order (sorted by smallest index): a window of
  // 16 sqrt(n) lists, about eight rows of the reordering grid. Otherwise small inputs get one
  // list per vertex, and larger ones the window.
  explicit Open_halfedges(std::size_t n, bool banded = false)
  {
    const std::size_t window = (std::min)(n, std::size_t(16 * std::sqrt(double(n))) + 1024);
    const std::size_t wanted = !banded && n <= (std::size_t(1) << 16) ? n : window;
    std::size_t size = 64;
    while(size < wanted)
      size <<= 1;
    lists_.assign(size, List{none, 0, {}, {}});
    mask_ = size - 1;
    spilled_.assign(n / 64 + 1, 0);
  }

  // If the twin of the half-edge with endpoints u < x is open, closes it and returns true with
  // its code; otherwise opens this half-edge with `code` and returns false.
  bool take_or_open(std::uint32_t u, std::uint32_t x, std::uintptr_t code, std::uintptr_t& twin)
  {
    List& list = lists_[u & mask_];
    if(list.owner != u) {
      for(std::uint32_t k = 0; k < list.count; ++k)
        spill(list.owner, list.other[k], list.code[k]);
      list.owner = u;
      list.count = 0;
    }
    for(std::uint32_t k = 0; k < list.count; ++k)
      if(list.other[k] == x) {
        twin = list.code[k];
        --list.count;
        list.other[k] = list.other[list.count];
        list.code[k] = list.code[list.count];
        --open_;
        return true;
      }
    if(((spilled_[u >> 6] >> (u & 63)) & 1) != 0 &&
       spill_.take(edge_key(u, x), twin)) {
      --open_;
      return true;
    }
    ++open_;
    if(list.count < capacity) {
      list.other[list.count] = x;
      list.code[list.count] = code;
      ++list.count;
    } else {
      spill(u, x, code);
    }
    return false;
  }

  std::size_t size() const { return open_; }

  template <class Visit> // visit(smaller, larger, code)
  void for_each(Visit visit) const
  {
    for(const List& list : lists_)
      for(std::uint32_t k = 0; k < list.count; ++k)
        visit(list.owner, list.other[k], list.code[k]);
    spill_.for_each([&](std::uint64_t edge, std::uintptr_t code) {
      visit(std::uint32_t(edge >> 32), std::uint32_t(edge), code);
    });
  }

private:
  static constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  static constexpr std::uint32_t capacity = 6;
  struct List
  {
    std::uint32_t owner, count;
    std::uint32_t other[capacity];
    std::uintptr_t code[capacity];
  };
  static std::uint64_t edge_key(std::uint32_t smaller, std::uint32_t larger)
  {
    return std::uint64_t(smaller) << 32 | larger;
  }
  void spill(std::uint32_t u, std::uint32_t x, std::uintptr_t code)
  {
    spill_.insert(edge_key(u, x), code);
    spilled_[u >> 6] |= std::uint64_t(1) << (u & 63);
  }

  std::vector<List> lists_;
  std::size_t mask_ = 0, open_ = 0;
  // Overflow: keyed by the undirected edge (smaller index, larger index).
  Hash_map<std::uint64_t, std::uintptr_t> spill_{1u << 8};
  std::vector<std::uint64_t> spilled_; // one bit per vertex: has it spilled?
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IMPORT_OPEN_HALFEDGES_H
