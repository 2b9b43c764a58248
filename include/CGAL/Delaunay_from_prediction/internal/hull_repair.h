// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Repair of a hull that is no longer convex (make_delaunay after moves: a hull vertex that
// moved inwards, or nearly collinear hull points that moved a little) by flips of infinite
// edges. Each flip turns a reflex hull vertex b, between hull neighbours a and c, into an
// interior vertex: the infinite faces around the edge (b, infinite) become the finite face
// (a, c, b), counterclockwise because b turned right, and the infinite face of the new hull
// edge a->c.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_HULL_REPAIR_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_HULL_REPAIR_H

#include <CGAL/Delaunay_from_prediction/internal/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/tds_certify.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Walks the hull of `tr` (dimension 2, every finite face ccw) and flips away reflex vertices
// until the hull is convex. Why the result is a triangulation although the hull before may
// not have been a simple polygon: every face is still ccw, so by the argument of
// import_prediction.h the faces tile the plane with multiplicity equal to the winding number
// of the hull; the final check that the hull is a convex polygon wound once makes that 1.
// On success the new finite faces' edges are pushed on `stack` (they may not be locally
// Delaunay), their addresses into `created`, and true is returned; otherwise every flip is
// undone and false returned (the caller's triangulation is as it was).
template <class Triangulation>
bool convexify_hull(Triangulation& tr,
                    std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                    std::vector<const void*>& created, std::size_t& flips)
{
  using Face_handle = typename Triangulation::Face_handle;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  auto& tds = tr.tds();
  auto orientation = tr.geom_traits().orientation_2_object();
  const Vertex_handle infinite = tr.infinite_vertex();

  std::size_t hull_size = 0;
  {
    Face_handle f = infinite->face();
    do {
      ++hull_size;
      f = f->neighbor(cw(f->index(infinite)));
    } while(f != infinite->face());
  }

  // Infinite face f holds hull edge a->b with a = f->vertex(cw(i)), b = f->vertex(ccw(i)),
  // i the index of the infinite vertex; f->neighbor(cw(i)) holds the next hull edge b->c and
  // f->neighbor(ccw(i)) the previous one.
  std::vector<std::pair<Face_handle, Vertex_handle>> done; // (finite face made, its b)
  Face_handle f = infinite->face();
  // Whether no hull vertex near b but a, b, c lies in the closed triangle (a, c, b): then the
  // face (a, c, b) is an ear of the pocket between the hull and its convex hull, and adding
  // it overlaps no face. A pocket of a simple polygon always has such an ear at a reflex
  // vertex (two-ears theorem: of two disjoint ears, one is not at the lid), so the flips go
  // on until the hull is convex. Only the 32 hull vertices on either side of b are tested:
  // a pocket's ear is tested against its own pocket; a far part of the hull reaching into
  // the ear would make the hull wind twice, which the final check rejects (correctness never
  // rests on this test, only the chance that the flips succeed).
  auto is_empty_ear = [&](Face_handle from, Vertex_handle a, Vertex_handle b, Vertex_handle c) {
    auto inside = [&](Vertex_handle v) {
      return v != a && v != b && v != c && orientation(a->point(), c->point(), v->point()) != RIGHT_TURN &&
             orientation(c->point(), b->point(), v->point()) != RIGHT_TURN &&
             orientation(b->point(), a->point(), v->point()) != RIGHT_TURN;
    };
    Face_handle ahead = from, behind = from;
    for(int k = 0; k < 32; ++k) {
      ahead = ahead->neighbor(cw(ahead->index(infinite)));   // hull edges after a->b
      behind = behind->neighbor(ccw(behind->index(infinite))); // and before it
      if(inside(ahead->vertex(ccw(ahead->index(infinite)))) ||
         inside(behind->vertex(cw(behind->index(infinite)))))
        return false;
      if(ahead == behind)
        break;
    }
    return true;
  };
  std::size_t unchanged = 0;
  // Each step passes a vertex (at most hull_size in a row) or flips one away: at most about
  // hull_size^2 steps.
  const std::size_t max_steps = (hull_size + 2) * (hull_size + 2);
  for(std::size_t steps = 0; unchanged < hull_size && steps < max_steps; ++steps) {
    const int i = f->index(infinite);
    const Face_handle g = f->neighbor(cw(i));
    const Vertex_handle a = f->vertex(cw(i)), b = f->vertex(ccw(i));
    const Vertex_handle c = g->vertex(ccw(g->index(infinite)));
    if(hull_size <= 3 || orientation(a->point(), b->point(), c->point()) != RIGHT_TURN ||
       tds.is_edge(a, c) || !is_empty_ear(f, a, b, c)) {
      f = g;
      ++unchanged;
      continue;
    }
    tds.flip(f, cw(i)); // the edge (b, infinite)
    const Face_handle inside = f->has_vertex(infinite) ? g : f;
    const Face_handle outside = inside == f ? g : f;
    done.emplace_back(inside, b);
    --hull_size;
    unchanged = 0;
    // Step back: a may have become reflex.
    f = outside->neighbor(ccw(outside->index(infinite)));
  }

  if(!hull_is_convex_and_wound_once(tr)) {
    for(auto it = done.rbegin(); it != done.rend(); ++it)
      tds.flip(it->first, it->first->index(it->second)); // the edge (a, c) back to (b, infinite)
    return false;
  }
  for(const auto& made : done) {
    created.push_back(&*made.first);
    for(int k = 0; k < 3; ++k)
      stack.emplace_back(made.first, k);
  }
  flips += done.size();
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_HULL_REPAIR_H
