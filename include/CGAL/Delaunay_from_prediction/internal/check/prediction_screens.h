// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 2 of the pipeline for index triples: two cheap screens that reject a prediction the
// import would give up on (far from Delaunay, or too many faces missing) before any linear
// pass is paid for. Only speed depends on them, never the result.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_PREDICTION_SCREENS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_PREDICTION_SCREENS_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Sampling screen: a cheap test that rejects a prediction far from Delaunay before any
// linear pass. It draws 32 faces and 16 points at random (fixed seed) and counts the faces
// whose circumcircle strictly contains a drawn point. A face of a prediction anywhere near
// DT(P) has a nearly empty circumcircle, so a drawn point falls inside with probability about
// (points inside)/n; a random triple's circle holds a constant fraction of P. The prediction
// is rejected when more than half of the drawn faces are hit. Only speed depends on this
// decision, never the result.
template <class Gt, class PointIterator>
bool fails_sampling_screen(const Gt& gt, PointIterator points, std::size_t n, const std::vector<std::uint32_t>& triples)
{
  constexpr int drawn_faces = 32, drawn_points = 16;
  const std::size_t number_of_faces = triples.size() / 3;
  if(n < 4096 || number_of_faces < 4096)
    return false;
  Splitmix64 random{0x5eed5eedull};
  auto orientation = gt.orientation_2_object();
  auto in_circle = gt.side_of_oriented_circle_2_object();
  int hit_faces = 0, drawn = 0;
  for(int s = 0; s < drawn_faces; ++s) {
    const std::uint32_t* idx = &triples[3 * std::size_t(random() % number_of_faces)];
    const auto& p = points[idx[0]];
    const auto& q = points[idx[1]];
    const auto& r = points[idx[2]];
    const Orientation o = orientation(p, q, r);
    if(o == COLLINEAR)
      continue;
    ++drawn;
    for(int t = 0; t < drawn_points; ++t) {
      const std::size_t k = std::size_t(random() % n);
      if(k == idx[0] || k == idx[1] || k == idx[2])
        continue;
      const Oriented_side side = in_circle(p, q, r, points[k]);
      if(side != ON_ORIENTED_BOUNDARY && int(side) == int(o)) {
        ++hit_faces;
        break;
      }
    }
  }
  return drawn > 0 && 2 * hit_faces > drawn;
}

// Whether the prediction's edges that fail the in-circle test (each needs a flip) are likely
// more than `limit`, told from samples of the face list before the spatial ordering and the
// import are paid for. Eight windows of consecutive faces, spread over the list, are read;
// within each, the faces are turned counterclockwise and their half-edges paired through a
// hash map, and every edge whose two faces are in the window is tested. A face list in any
// spatially coherent order (a mesher's, CGAL's face iteration, the previous frame's) pairs most
// of its edges within a window; a list in random order pairs few, and then nothing is
// concluded. The failing fraction of the tested edges times the 3F/2 edges of F faces is the
// estimate. At most 8,192 faces are read: about 0.5% of a certified prediction's import at
// 10^6 points.
// Robustness: the tests are plain double arithmetic, not the traits' predicates (with Epick's
// filtered predicates the sampling cost about twice as much per face), because the answer
// only steers: a wrong sign, or an edge skipped where a determinant overflows, underflows to
// zero or is not finite (coordinates near 1e+-150 and beyond), changes the estimate, never
// the result (the import's own exact count, extrapolated from its first eighth, is the second
// check, and a rebuild is always correct).
template <class PointIterator>
bool failing_edges_exceed(PointIterator points, std::size_t n, const std::vector<std::uint32_t>& triples,
                          std::size_t limit)
{
  const std::size_t F = triples.size() / 3;
  if(n < 4096 || F < 4096 || double(limit) >= 1.5 * double(F))
    return false;
  constexpr std::size_t windows = 8;
  // A sixty-fourth of the faces, between 256 and 1024 per window.
  const std::size_t window_faces = (std::min)(std::size_t(1024), (std::max)(std::size_t(256), F / (64 * windows)));
  Hash_map<std::uint64_t, std::uint64_t> apex_of(4 * window_faces); // half-edge (a, b) -> c of face abc
  auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
  auto x = [&](std::uint32_t v) { return CGAL::to_double(points[v].x()); };
  auto y = [&](std::uint32_t v) { return CGAL::to_double(points[v].y()); };
  std::size_t tested = 0, failing = 0;
  for(std::size_t w = 0; w < windows; ++w) {
    apex_of.clear();
    const std::size_t first = (std::min)(F - window_faces, (2 * w + 1) * F / (2 * windows));
    for(std::size_t f = first; f < first + window_faces; ++f) {
      std::uint32_t v[3] = {triples[3 * f], triples[3 * f + 1], triples[3 * f + 2]};
      const double o = (x(v[1]) - x(v[0])) * (y(v[2]) - y(v[0])) - (y(v[1]) - y(v[0])) * (x(v[2]) - x(v[0]));
      if(!(o != 0 && std::isfinite(o)))
        continue; // flat, or beyond double's range: not sampled
      if(o < 0)
        std::swap(v[1], v[2]);
      for(int j = 0; j < 3; ++j) {
        const std::uint32_t a = v[j], b = v[(j + 1) % 3], c = v[(j + 2) % 3];
        std::uint64_t apex;
        if(apex_of.take(key(b, a), apex)) { // the face on the other side of edge ab
          const std::uint32_t d = std::uint32_t(apex);
          // In-circle determinant of d against the counterclockwise face abc, d at the origin.
          const double ax = x(a) - x(d), ay = y(a) - y(d), bx = x(b) - x(d), by = y(b) - y(d);
          const double cx = x(c) - x(d), cy = y(c) - y(d);
          const double det = (ax * ax + ay * ay) * (bx * cy - by * cx) - (bx * bx + by * by) * (ax * cy - ay * cx) +
                             (cx * cx + cy * cy) * (ax * by - ay * bx);
          if(!std::isfinite(det))
            continue;
          ++tested;
          failing += det > 0 ? 1 : 0;
        } else
          apex_of.insert(key(a, b), c);
      }
    }
  }
  if(tested < 1024)
    return false;
  return double(failing) * 1.5 * double(F) > double(limit) * double(tested);
}

// Whether at most `max_hull` of `candidates` (sorted here) lie on the boundary of their
// convex hull, exactly, with the traits' predicates: the hull of the candidates (Andrew's
// monotone chain), then the candidates on its boundary (vertices and points on its edges,
// which are hull vertices of a triangulation too). Rarely run: only when many points lie
// near the hull (missing_faces_exceed()).
template <class Gt, class Point>
CGAL_DFP_RARELY_RUN bool hull_points_at_most(const Gt& gt, std::vector<Point>& candidates, std::size_t max_hull)
{
  auto orientation = orientation_called_out_of_line(gt);
  auto compare_xy = compare_xy_called_out_of_line(gt);
  std::sort(candidates.begin(), candidates.end(),
            [&](const Point& p, const Point& q) { return compare_xy(p, q) == SMALLER; });
  std::vector<const Point*> hull;
  for(int pass = 0; pass < 2; ++pass) { // lower chain left to right, upper right to left
    const std::size_t base = hull.size();
    for(std::size_t k = 0; k < candidates.size(); ++k) {
      const Point& p = candidates[pass == 0 ? k : candidates.size() - 1 - k];
      while(hull.size() >= base + 2 && orientation(*hull[hull.size() - 2], *hull.back(), p) != LEFT_TURN)
        hull.pop_back();
      hull.push_back(&p);
    }
    hull.pop_back(); // the last point starts the other chain
  }
  if(hull.size() < 3 || hull.size() > max_hull)
    return false;
  std::size_t h = 0;
  for(const Point& p : candidates)
    for(std::size_t k = 0; k < hull.size(); ++k)
      if(orientation(*hull[k], *hull[(k + 1) % hull.size()], p) == COLLINEAR) {
        ++h;
        break;
      }
  return h <= max_hull;
}

// Whether the faces surely lack more than `limit` faces of a triangulation of the points
// they use, told before the spatial ordering and the import are paid for (about a quarter
// of a rebuild at 1e6 points). By Euler's formula, F faces forming a disk with holes on V
// vertices, whose boundary cycles have L_0 (outer) and L_1, L_2, ... (holes) edges, satisfy
//   2V - 2 - F = L_0 + sum over the holes of (L_i - 2),
// and L_0 >= h, the number of points on the hull of the V points. So excess = 2V - 2 - F - h
// is 0 for a triangulation and counts the missing faces: one per scattered deleted face,
// between a third of and all the open half-edges of the holes (more for several pieces).
// The import gives up past n/4 open half-edges; with holes of three or four edges that is
// an excess of about n/12: the tolerant import passes a limit of n/8. A vertex where two
// fans meet only lowers the excess. Costs nothing for a prediction with more than
// 2n - limit faces; otherwise a pass over the triples and two over the points: the points
// not inside the octagon of their extremes in 8 directions (Akl-Toussaint) are the only
// candidates for the hull, whose boundary points are then counted exactly.
template <class Gt, class PointIterator>
bool missing_faces_exceed(const Gt& gt, PointIterator points, std::size_t n, const std::vector<std::uint32_t>& triples,
                          std::size_t limit)
{
  using Point = typename Gt::Point_2;
  const std::size_t F = triples.size() / 3;
  if(F + limit + 2 >= 2 * n)
    return false;
  std::vector<std::uint64_t> used(n / 64 + 1, 0);
  for(const std::uint32_t v : triples)
    used[v >> 6] |= std::uint64_t(1) << (v & 63);
  std::size_t V = 0;
  for(const std::uint64_t word : used)
    V += std::size_t(std::bitset<64>(word).count());
  if(F + limit + 2 >= 2 * V)
    return false;
  auto is_used = [&](std::size_t v) { return ((used[v >> 6] >> (v & 63)) & 1) != 0; };
  // The used points extreme in 8 directions, in counterclockwise order of the directions
  // (+x, +x+y, +y, -x+y, -x, -x-y, -y, +x-y): a convex polygon inside the hull.
  const double dir[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  double best[8] = {}, ex[8][2] = {}; // (set by the first used point: initialized for the compiler)
  bool any = false;
  for(std::size_t v = 0; v < n; ++v) {
    if(!is_used(v))
      continue;
    const double x = CGAL::to_double(points[v].x()), y = CGAL::to_double(points[v].y());
    for(int k = 0; k < 8; ++k) {
      const double d = dir[k][0] * x + dir[k][1] * y;
      if(!any || d > best[k]) {
        best[k] = d;
        ex[k][0] = x;
        ex[k][1] = y;
      }
    }
    any = true;
  }
  if(!any)
    return false;
  // Every hull vertex is on or outside that polygon: only the points not inside it by a
  // margin far above the rounding of the cross products can be (about 1.4 sqrt(n) of
  // uniform points in a square, the slivers along its sides). Stops when there are so many
  // that the count below would cost more than it can save.
  const double extent = (std::max)(best[0] + best[4], best[2] + best[6]); // width or height
  const double margin = 1e-9 * extent * extent;
  // The margin must dominate the rounding of the cross products: where it or an extreme
  // overflows (coordinates near 1e154 and beyond) or underflows (near the smallest normal
  // double), no conclusion; this test only spares the import, never decides the result.
  for(const double b : best)
    if(!std::isfinite(b))
      return false;
  if(!(margin >= (std::numeric_limits<double>::min)() && margin <= (std::numeric_limits<double>::max)()))
    return false;
  const std::size_t max_hull = 2 * V - 2 - F - limit; // h above this: no conclusion
  const std::size_t max_candidates = 16 * std::size_t(std::sqrt(double(n))) + 1024;
  std::vector<Point> candidates;
  for(std::size_t v = 0; v < n && candidates.size() <= max_candidates; ++v) {
    if(!is_used(v))
      continue;
    const double x = CGAL::to_double(points[v].x()), y = CGAL::to_double(points[v].y());
    bool inside = true;
    for(int k = 0; k < 8 && inside; ++k) {
      const double* a = ex[k];
      const double* b = ex[(k + 1) & 7];
      inside = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]) > margin;
      if(a[0] == b[0] && a[1] == b[1])
        inside = true; // the same point extreme in two directions: no edge
    }
    if(!inside)
      candidates.push_back(points[v]);
  }
  if(candidates.size() > max_candidates) // the list is cut short
    return false;
  if(candidates.size() <= max_hull)
    return true;
  return hull_points_at_most(gt, candidates, max_hull);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_PREDICTION_SCREENS_H
