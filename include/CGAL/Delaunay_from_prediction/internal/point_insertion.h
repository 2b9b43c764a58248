// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Inserting one point into a Delaunay triangulation from a face near it: a visibility walk
// to the face that holds the point, then, in the common case of a point strictly inside a
// finite face, the split and the flips around the new vertex with the package's filtered
// in-circle test; any other case (on an edge or a vertex, outside the hull, dimension below
// 2) is left to CGAL's insertion. Used by the from-scratch builds of rebuild.h and by the
// spanning-tree insertion.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_POINT_INSERTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_POINT_INSERTION_H

#include <CGAL/Delaunay_from_prediction/internal/predicates.h>

#include <CGAL/enum.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Visibility walk in the Delaunay triangulation `dt` (dimension 2) from face `f` towards q:
// crosses an edge whenever q is strictly on its far side. Returns true when it stops, with
// `f` a finite face whose closure holds q (then `collinear` counts the edges of f whose line
// holds q: 0 means q is strictly inside) or an infinite face (q is outside the hull, or on
// it); false after `cap` steps, with `f` where it is. On a Delaunay triangulation the
// visibility walk cannot cycle (the lifting map orders the faces); the cap also bounds it
// with an inexact kernel. `steps` counts the faces entered. Robust: every decision is an
// orientation of the traits.
template <class DT>
bool walk_towards(const DT& dt, typename DT::Face_handle& f, const typename DT::Point& q, std::size_t cap,
                  std::size_t& steps, int& collinear)
{
  using Face_handle = typename DT::Face_handle;
  auto orientation = dt.geom_traits().orientation_2_object();
  const auto infinite = dt.infinite_vertex();
  if(f->has_vertex(infinite))
    f = f->neighbor(f->index(infinite));
  Face_handle previous;
  for(std::size_t k = 0;; ++k) {
    bool moved = false;
    collinear = 0;
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      if(g == previous)
        continue; // q is strictly on this side: that is why the walk crossed it
      const Orientation o = orientation(f->vertex(ccw(i))->point(), f->vertex(cw(i))->point(), q);
      if(o == RIGHT_TURN) {
        previous = f;
        f = g;
        moved = true;
        break;
      }
      collinear += (o == COLLINEAR);
    }
    if(!moved)
      return true;
    ++steps;
    if(f->has_vertex(infinite))
      return true;
    if(k + 1 >= cap)
      return false;
  }
}

// Inserts q, strictly inside the finite face `f` of the Delaunay triangulation `tr`
// (dimension 2), as Delaunay_triangulation_2::insert does: a new vertex splits f, then the
// edges opposite it are flipped while q is inside the circumcircle of the face beyond them
// (the perturbed test, so the result is CGAL's). Only those edges can fail (Lawson's
// argument for one insertion), so only they are queued; a face beyond a hull edge is never
// flipped, q being strictly inside the hull. The package's inline filter of the in-circle
// test is what makes this faster than CGAL's insertion. `stack` is scratch space.
template <class Triangulation>
typename Triangulation::Vertex_handle
insert_strictly_in_face(Triangulation& tr, const typename Triangulation::Point& q, typename Triangulation::Face_handle f,
                        std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack)
{
  const auto& gt = tr.geom_traits();
  auto& tds = tr.tds();
  const auto infinite = tr.infinite_vertex();
  const auto v = tds.insert_in_face(f);
  v->set_point(q);
  stack.clear();
  auto g = v->face();
  for(int k = 0; k < 3; ++k) {
    const int i = g->index(v);
    stack.emplace_back(g, i);
    g = g->neighbor(ccw(i));
  }
  while(!stack.empty()) {
    const auto face = stack.back().first;
    const int i = stack.back().second;
    stack.pop_back();
    const auto n = face->neighbor(i);
    if(n->has_vertex(infinite) ||
       side_of_oriented_circle_perturbed(gt, n->vertex(0)->point(), n->vertex(1)->point(), n->vertex(2)->point(), q) !=
           ON_POSITIVE_SIDE)
      continue;
    // After the flip face = (v, b, d) keeps v at slot i, and n = (d, c, v).
    tds.flip(face, i);
    stack.emplace_back(face, i);
    stack.emplace_back(n, n->index(v));
  }
  return v;
}

// Inserts q into the Delaunay triangulation `dt` (any dimension), starting the search at
// face `start` (a face near q, or null): returns its vertex, an existing one if q is one.
template <class DT>
typename DT::Vertex_handle insert_near(DT& dt, const typename DT::Point& q, typename DT::Face_handle start,
                                       std::vector<std::pair<typename DT::Face_handle, int>>& stack)
{
  if(dt.dimension() < 2 || start == typename DT::Face_handle())
    return dt.insert(q, start);
  std::size_t steps = 0;
  int collinear = 0;
  // Bounded only so that an inexact kernel cannot cycle; CGAL's locate finishes then.
  const bool found = walk_towards(dt, start, q, 2 * dt.number_of_vertices() + 16, steps, collinear);
  if(found && collinear == 0 && !start->has_vertex(dt.infinite_vertex()))
    return insert_strictly_in_face(dt, q, start, stack);
  return dt.insert(q, start);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_POINT_INSERTION_H
