// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Disjoint sets over 0..n-1: Kruskal's algorithm of the EMST, the merge of small regions of
// the t-division; the tests and benchmarks build spanning trees with it too.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_UNION_FIND_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_UNION_FIND_H

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Path halving, no ranks: join(a, b) hangs a's root under b's.
struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  }
  // Whether a and b were in different sets (they are in one now).
  bool join(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    parent[a] = b;
    return true;
  }
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_UNION_FIND_H
