// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 3 of the pipeline (certify) for a prediction that is already a CGAL triangulation
// (make_delaunay): the same certificate as for index triples, read off CGAL's TDS, whose
// combinatorics are a sphere by construction, so only the geometry is checked.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TDS_CERTIFY_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TDS_CERTIFY_H

#include <CGAL/Delaunay_from_prediction/internal/predicates.h>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether the hull of `tr` (dimension 2) is a convex polygon wound once counterclockwise.
// The hull is read in ccw order: the face outside hull edge u->v is (v, u, infinite).
template <class Triangulation>
bool hull_is_convex_and_wound_once(const Triangulation& tr)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  const auto infinite = tr.infinite_vertex();
  std::vector<const Point*> hull;
  const Face_handle start = infinite->face();
  Face_handle outside = start;
  do {
    const int i = outside->index(infinite);
    hull.push_back(&outside->vertex(cw(i))->point());
    outside = outside->neighbor(cw(i));
  } while(outside != start && hull.size() <= tr.number_of_vertices());
  return outside == start &&
         is_convex_ccw_cycle(tr.geom_traits(), hull.size(),
                             [&](std::size_t k) -> const Point& { return *hull[k]; });
}

// Returns null if every finite face of `tr` (dimension 2) is counterclockwise, after listing
// in `non_delaunay` every interior edge that fails the perturbed in-circle test; otherwise
// returns why not. If `bad_faces` is given, the faces that are not counterclockwise go there
// instead, and the pass goes on (null is returned; `hull_is_convex` is then only meaningful
// if `bad_faces` stays empty), unless more than `max_bad_faces` are found: then the pass
// stops at once and returns why. `hull_is_convex` tells whether the hull is a convex polygon wound once:
// then the argument of import_prediction.h (the TDS providing the twin pairing) shows that
// `tr` is a geometric triangulation of its vertices; if not, convexify_hull() may make it one.
// Reads only.
template <class Triangulation>
const char* certify_triangulation(
    const Triangulation& tr,
    std::vector<std::pair<typename Triangulation::Face_handle, int>>& non_delaunay,
    std::size_t& edges_tested, bool& hull_is_convex,
    std::vector<typename Triangulation::Face_handle>* bad_faces = nullptr,
    std::size_t max_bad_faces = 0)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  hull_is_convex = false;
  if(tr.dimension() < 2)
    return "the triangulation has dimension below 2";
  const auto& gt = tr.geom_traits();
  auto orientation = gt.orientation_2_object();
  const auto infinite = tr.infinite_vertex();
  const std::less<const void*> before;
  // The pass is bound by memory latency (a face, its three vertices and up to three
  // neighbours each): the vertices and neighbours of the face 16 ahead are prefetched.
  auto ahead = tr.finite_faces_begin();
  for(int k = 0; k < 16 && ahead != tr.finite_faces_end(); ++k)
    ++ahead;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f) {
    if(ahead != tr.finite_faces_end()) {
#if defined(__GNUC__)
      for(int k = 0; k < 3; ++k) {
        __builtin_prefetch(&*ahead->vertex(k));
        __builtin_prefetch(&*ahead->neighbor(k));
      }
#endif
      ++ahead;
    }
    const Point& p0 = f->vertex(0)->point();
    const Point& p1 = f->vertex(1)->point();
    const Point& p2 = f->vertex(2)->point();
    if(orientation(p0, p1, p2) != LEFT_TURN) {
      if(bad_faces == nullptr)
        return "a face is inverted or flat";
      bad_faces->push_back(f);
      if(bad_faces->size() > max_bad_faces)
        return "too many faces are inverted or flat for a local repair";
      continue;
    }
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      if(!before(&*f, &*g) || g->has_vertex(infinite))
        continue; // each interior edge once, from its face of lower address
      ++edges_tested;
      const Point& d = g->vertex(g->index(Face_handle(f)))->point();
      if(!is_locally_delaunay(gt, p0, p1, p2, d))
        non_delaunay.emplace_back(f, i);
    }
  }
  hull_is_convex = hull_is_convex_and_wound_once(tr);
  return nullptr;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TDS_CERTIFY_H
