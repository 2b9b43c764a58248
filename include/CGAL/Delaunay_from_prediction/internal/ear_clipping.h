// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Ear clipping of a polygon: the one polygon triangulator of the package, used to fill the
// holes of a carved prediction (carve_repair.h) and the faces of a predicted planar graph
// (Delaunay_from_predicted_edges_2.h).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EAR_CLIPPING_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EAR_CLIPPING_H

#include <CGAL/enum.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Triangulates the polygon with vertices point(0), ..., point(m-1), counterclockwise, into
// m - 2 ears (a, b, c) of positions, each counterclockwise. An ear is cut at b when (a, b, c)
// is counterclockwise and no other vertex of the remaining polygon lies in it or on its
// boundary; a simple polygon always has one (two-ears theorem), so the clipping succeeds on
// every simple counterclockwise polygon. Returns false, with no ears, when it gets stuck (the
// polygon is not simple, or not counterclockwise). Robust: exact orientation tests only, so a
// returned ear is truly counterclockwise. O(m^2) tests in the worst case; callers bound m.
// `prev` and `next` are scratch space (reused across calls to spare allocations).
template <class Gt, class PointOf>
bool clip_ears(const Gt& gt, std::size_t m, PointOf point, std::vector<std::array<std::size_t, 3>>& ears,
               std::vector<std::size_t>& prev, std::vector<std::size_t>& next)
{
  ears.clear();
  if(m < 3)
    return false;
  auto orientation = gt.orientation_2_object();
  prev.resize(m);
  next.resize(m);
  for(std::size_t p = 0; p < m; ++p) {
    prev[p] = (p + m - 1) % m;
    next[p] = (p + 1) % m;
  }
  std::size_t remaining = m, b = 0, tried = 0;
  while(remaining >= 3) {
    const std::size_t a = prev[b], c = next[b];
    const auto& pa = point(a);
    const auto& pb = point(b);
    const auto& pc = point(c);
    bool ear = orientation(pa, pb, pc) == LEFT_TURN;
    if(ear && remaining > 3)
      for(std::size_t q = next[c]; q != a; q = next[q]) {
        const auto& pq = point(q);
        if(orientation(pa, pb, pq) != RIGHT_TURN && orientation(pb, pc, pq) != RIGHT_TURN &&
           orientation(pc, pa, pq) != RIGHT_TURN) {
          ear = false;
          break;
        }
      }
    if(!ear) {
      b = c;
      if(++tried > remaining) {
        ears.clear();
        return false;
      }
      continue;
    }
    ears.push_back({a, b, c});
    next[a] = c;
    prev[c] = a;
    --remaining;
    tried = 0;
    b = a; // a may have become an ear
  }
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EAR_CLIPPING_H
