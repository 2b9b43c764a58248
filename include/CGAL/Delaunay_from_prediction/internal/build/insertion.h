// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The package's one insertion module: the visibility walk, the insertion of a point from a
// face near it (insert_near(): a walk, then in the common case of a point strictly inside a
// finite face the split and the flips around the new vertex with the package's filtered
// in-circle test, CGAL's insertion for the rest), its capped form with a grid fallback for
// insertions from hints (insert_walking_from(), Vertex_grid), and the reinsertion of vertex
// objects that keeps handles and info() (the repairs). The spanning-tree engine, imprecise
// points, split, BrioDC, the blocks of the parallel build and the points added to a
// triangulation insert here; the sequential builds from scratch run the same algorithm on
// flat arrays (flat_insertion.h).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_INSERTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_INSERTION_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>

#include <CGAL/Triangulation_2.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The walk cap of insert_near() that means none (but the bound against cycles).
constexpr std::size_t unbounded_walk = std::size_t(-1);

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
// (dimension 2), as Delaunay_triangulation_2::insert does: a new vertex splits f, then
// flip_around_new_vertex() (flips.h). The package's inline filter of the in-circle test is
// what makes this faster than CGAL's insertion. `stack` is scratch space.
template <class Triangulation>
typename Triangulation::Vertex_handle
insert_strictly_in_face(Triangulation& tr, const typename Triangulation::Point& q, typename Triangulation::Face_handle f,
                        std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack)
{
  const auto v = tr.tds().insert_in_face(f);
  v->set_point(q);
  flip_around_new_vertex(tr, v, stack);
  return v;
}

// Last vertex inserted in each cell of a uniform grid over the points' bounding box, at two
// resolutions (about 4 and 256 points a cell once all are in): where a walk from the tree
// hint is too long, the walk starts again from there. Coordinates are rounded to double
// only to pick a cell.
template <class Vertex_handle>
class Vertex_grid
{
public:
  template <class PointAt>
  Vertex_grid(std::size_t n, PointAt point_at)
  {
    if(n != 0)
      set_up(n, bounding_box(n, point_at));
  }

  // A grid for n points in `box` (points outside it fall in the border cells).
  Vertex_grid(std::size_t n, const Box& box)
  {
    if(n != 0)
      set_up(n, box);
  }

  template <class Point>
  void record(const Point& p, Vertex_handle v)
  {
    const std::size_t cx = fine_.column(CGAL::to_double(p.x())), cy = fine_.row(CGAL::to_double(p.y()));
    last_in_fine_[cy * fine_.columns() + cx] = v;
    last_in_coarse_[(cy / 8) * coarse_side_ + cx / 8] = v;
  }

  // A vertex inserted near p, or a null handle.
  template <class Point>
  Vertex_handle near(const Point& p) const
  {
    const std::size_t cx = fine_.column(CGAL::to_double(p.x())), cy = fine_.row(CGAL::to_double(p.y()));
    const Vertex_handle v = last_in_fine_[cy * fine_.columns() + cx];
    return v != Vertex_handle() ? v : last_in_coarse_[(cy / 8) * coarse_side_ + cx / 8];
  }

private:
  void set_up(std::size_t n, const Box& box)
  {
    // Coarse cells are 8 x 8 fine cells.
    coarse_side_ = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(n) / 256)));
    fine_ = Cell_grid(box, 8 * coarse_side_, 8 * coarse_side_);
    last_in_fine_.assign(fine_.cells(), Vertex_handle());
    last_in_coarse_.assign(coarse_side_ * coarse_side_, Vertex_handle());
  }

  Cell_grid fine_;
  std::size_t coarse_side_ = 1;
  std::vector<Vertex_handle> last_in_fine_, last_in_coarse_;
};

// The walk cap of a location from a hint among n points: about log2 n + 8 faces.
inline std::size_t walk_cap(std::size_t n)
{
  std::size_t cap = 8;
  for(std::size_t m = n; m > 1; m >>= 1)
    cap += 1;
  return cap;
}

// The one location-and-insertion step of the package: inserts q into the Delaunay
// triangulation `dt` (any dimension), located by a visibility walk from face `start` (a face
// near q as far as the caller knows: the previous insertion, a tree neighbour, a hint; null:
// CGAL's location). The walk is capped at `cap` faces; past it the walk starts again from
// the vertex `grid` holds near q (if a grid is given), uncapped. q strictly inside a finite
// face: split and flips here; on an edge or a vertex, outside the hull, dimension below 2:
// CGAL's insertion, located from where the walk stopped. Returns q's vertex (an existing one
// for a duplicate). If `stats` is given, the location is counted there (points_located,
// faces_visited, walk_fallbacks) when dt has dimension 2.
template <class DT, class Grid = Vertex_grid<typename DT::Vertex_handle>>
typename DT::Vertex_handle insert_near(DT& dt, const typename DT::Point& q, typename DT::Face_handle start,
                                       std::vector<std::pair<typename DT::Face_handle, int>>& stack,
                                       std::size_t cap = unbounded_walk, const Grid* grid = nullptr,
                                       Statistics* stats = nullptr)
{
  using Vertex_handle = typename DT::Vertex_handle;
  if(dt.dimension() < 2 || start == typename DT::Face_handle())
    return dt.insert(q, start);
  // Bounded only so that an inexact kernel cannot cycle; CGAL's locate finishes then.
  const std::size_t longest = 2 * dt.number_of_vertices() + 16;
  std::size_t steps = 0;
  int collinear = 0;
  bool found = walk_towards(dt, start, q, (std::min)(cap, longest), steps, collinear);
  if(!found && cap < longest) {
    if(stats != nullptr)
      ++stats->walk_fallbacks;
    if(grid != nullptr) {
      const Vertex_handle jump = grid->near(q);
      if(jump != Vertex_handle())
        start = jump->face();
    }
    found = walk_towards(dt, start, q, longest, steps, collinear);
  }
  if(stats != nullptr) {
    ++stats->points_located;
    stats->faces_visited += steps;
  }
  if(found && collinear == 0 && !start->has_vertex(dt.infinite_vertex()))
    return insert_strictly_in_face(dt, q, start, stack); // no need to locate again
  return dt.insert(q, start); // on an edge, a vertex, or outside: CGAL's locate decides
}

// insert_near() from the face of vertex `from`, with the walk cap and the grid of the
// insertions from hints (the spanning-tree engine, imprecise points, split, BrioDC).
template <class DT, class Grid>
typename DT::Vertex_handle insert_walking_from(DT& dt, const typename DT::Point& q, typename DT::Vertex_handle from,
                                               std::size_t cap, const Grid& grid,
                                               std::vector<std::pair<typename DT::Face_handle, int>>& flip_stack,
                                               Statistics& stats)
{
  return insert_near(dt, q, from->face(), flip_stack, cap, &grid, &stats);
}

// Inserts `vertices` (vertex objects with no face) into the valid triangulation `tr`, keeping
// each object, so that handles and info() survive: CGAL's location and insertion of the
// triangulation base class (no flips), then the vertex object insertion made is replaced by
// the old one in its faces. In a grid order, each located from the last, or from the face of
// `(*near)[k]` for vertices[k] when that is a vertex with a face (a former neighbour: a walk
// of a face or two instead of the ten or so between grid neighbours). The edges around
// each go on `stack` (Lawson's algorithm makes them Delaunay). `on_hit(f)` is called for the
// faces insertion destroys or splits, `on_created(f)` for the faces around each reinserted
// vertex, `on_duplicate(v, w)` instead of inserting v when its point is already vertex w's.
template <class Triangulation, class OnHit, class OnCreated, class OnDuplicate>
void reinsert_vertex_objects(Triangulation& tr, const std::vector<typename Triangulation::Vertex_handle>& vertices,
                             std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                             OnHit on_hit, OnCreated on_created, OnDuplicate on_duplicate,
                             const std::vector<typename Triangulation::Vertex_handle>* near = nullptr)
{
  using Base = Triangulation_2<typename Triangulation::Geom_traits, typename Triangulation::Triangulation_data_structure>;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Face_handle = typename Triangulation::Face_handle;
  using Point = typename Triangulation::Point;
  Base& base = static_cast<Base&>(tr);
  std::vector<std::size_t> order(vertices.size());
  for(std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  {
    // A copy of the points, read as every other caller's are (one sort compiled for all).
    std::vector<Point> points;
    points.reserve(vertices.size());
    for(const Vertex_handle& v : vertices)
      points.push_back(v->point());
    sort_along_grid(order, Point_of_index<const Point*>{points.data()}, false);
  }
  Face_handle hint = tr.infinite_vertex()->face();
  const Point* previous = nullptr; // the point inserted last, at `hint`
  // Only to choose where a walk starts. Halves and hypot: no overflow near 1e308, no
  // underflow to 0 near the smallest normal double.
  auto distance = [](const Point& a, const Point& b) {
    return std::hypot(CGAL::to_double(a.x()) / 2 - CGAL::to_double(b.x()) / 2,
                      CGAL::to_double(a.y()) / 2 - CGAL::to_double(b.y()) / 2);
  };
  for(const std::size_t k : order) {
    const Vertex_handle v = vertices[k];
    typename Base::Locate_type lt;
    int li = 0;
    // The vertex near v in the prediction is the better start, unless the prediction put v
    // far from where it is (a relabelled point: its neighbours in the prediction are
    // anywhere); then the last point inserted, before it in grid order, is nearer. With 0.3%
    // of the points of 1e6 relabelled, walks from those neighbours took a third of the call.
    if(near != nullptr && (*near)[k] != Vertex_handle() && (*near)[k]->face() != Face_handle() &&
       (previous == nullptr ||
        distance((*near)[k]->point(), v->point()) < distance(*previous, v->point())))
      hint = (*near)[k]->face();
    const Face_handle loc = base.locate(v->point(), lt, li, hint);
    if(lt == Base::VERTEX) {
      on_duplicate(v, loc->vertex(li));
      continue;
    }
    on_hit(loc);
    if(lt == Base::EDGE)
      on_hit(loc->neighbor(li));
    const Vertex_handle fresh = base.insert(v->point(), lt, loc, li);
    // Transplant: v takes the place of the vertex insertion made.
    Face_handle f = fresh->face();
    const Face_handle first = f;
    do {
      const int i = f->index(fresh);
      f->set_vertex(i, v);
      on_created(f);
      stack.emplace_back(f, i);
      stack.emplace_back(f, cw(i));
      f = f->neighbor(ccw(i));
    } while(f != first);
    v->set_face(first);
    tr.tds().delete_vertex(fresh);
    hint = first;
    previous = &v->point();
  }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_INSERTION_H
