// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The insertion engine: incremental Delaunay insertion (point_insertion.h: a walk, then the
// split and flips of the common case, CGAL's insertion for the rest), in a biased randomized
// grid order with the previous vertex as hint (CGAL's range insert does the same after a
// spatial_sort that costs a third of its time; the grid order is ten times cheaper and was
// measured 8-15% faster overall at 1e6 points), over point indices so that duplicates keep
// the smallest index. Used for points no face covers, for from-scratch
// fallbacks, and, through a transplant, for rebuilding a caller's triangulation in place
// while keeping its vertex objects.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REBUILD_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REBUILD_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/point_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/vertex_info.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Inserts the points of the given indices into the Delaunay triangulation `dt`, in biased
// randomized grid order (sort_along_grid; with `in_order`, the indices are in that order
// already), each located from the previous vertex. `on_vertex(index, vertex, is_new)` is
// called after each insertion; `is_new` is false when the point was already a vertex (a
// duplicate). Returns the number of new vertices.
template <class DT, class PointIterator, class OnVertex>
std::size_t insert_by_index(DT& dt, PointIterator points, std::vector<std::size_t>& indices,
                            OnVertex on_vertex, bool in_order = false)
{
  if(!in_order)
    sort_along_grid(indices, [&](std::size_t i) -> decltype(points[0]) { return points[i]; }, true);
  const std::size_t before = dt.number_of_vertices();
  typename DT::Face_handle hint;
  std::vector<std::pair<typename DT::Face_handle, int>> stack;
  for(std::size_t i : indices) {
    const std::size_t count = dt.number_of_vertices();
    const typename DT::Vertex_handle v = insert_near(dt, points[i], hint, stack);
    on_vertex(i, v, dt.number_of_vertices() != count);
    hint = v->face();
  }
  return dt.number_of_vertices() - before;
}

// Inserts the points of the given indices into `dt` (a Delaunay_triangulation_2 of the
// caller's type), setting info() to the point index, the smallest one for duplicates.
// If `new_vertices` is given, it receives the address of every vertex created.
template <class DT, class PointIterator>
void insert_points(DT& dt, PointIterator points, std::vector<std::size_t>& indices,
                   Statistics& stats, std::vector<const void*>* new_vertices = nullptr, bool in_order = false)
{
  std::size_t duplicates = 0;
  insert_by_index(dt, points, indices, [&](std::size_t i, auto v, bool is_new) {
    if(is_new) {
      set_index_info(v, i);
      if(new_vertices != nullptr)
        new_vertices->push_back(&*v);
    } else {
      merge_index_info(v, i);
      ++duplicates;
    }
  }, in_order);
  stats.points_reinserted += indices.size();
  stats.duplicate_points += duplicates;
}

// Builds DT(points) from scratch into `dt`, which holds no vertex. `grid_order`, if not
// empty, lists all the indices in grid order (the import had sorted them so): they
// are only dealt into rounds, not sorted again (about 0.03 s less at 1e6 points).
template <class DT, class PointIterator>
void build_from_scratch(DT& dt, PointIterator points, std::size_t n, Statistics& stats,
                        const std::vector<std::uint32_t>& grid_order = std::vector<std::uint32_t>())
{
  const bool in_order = grid_order.size() == n;
  std::vector<std::size_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = in_order ? grid_order[i] : i;
  if(in_order)
    deal_into_rounds(indices);
  insert_points(dt, points, indices, stats, nullptr, in_order);
}

// Replaces the faces of `tr` by those of DT(its vertices), keeping every vertex object (so
// vertex handles and info() survive). The new triangulation is built aside by the package's
// insertion (insert_by_index()), then transplanted face by face, any dimension included. If two vertices are at
// the same point, throws Invalid_prediction naming both, before `tr` is modified.
template <class Triangulation>
void rebuild_keeping_vertices(Triangulation& tr, Statistics& stats)
{
  using Gt = typename Triangulation::Geom_traits;
  using Point = typename Triangulation::Point;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  using Face_handle = typename Triangulation::Face_handle;
  using Aside_tds = Triangulation_data_structure_2<Triangulation_vertex_base_with_info_2<std::size_t, Gt>,
                                                   Triangulation_face_base_with_info_2<std::size_t, Gt>>;
  using Aside = Delaunay_triangulation_2<Gt, Aside_tds>;

  std::vector<Vertex_handle> vertices;
  std::vector<Point> points;
  vertices.reserve(tr.number_of_vertices());
  points.reserve(tr.number_of_vertices());
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    vertices.push_back(v);
    points.push_back(v->point());
  }
  const std::size_t n = vertices.size();
  if(n == 0)
    return;

  Aside aside(tr.geom_traits());
  std::vector<std::size_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = i;
  insert_by_index(aside, points.begin(), indices, [&](std::size_t i, auto v, bool is_new) {
    if(is_new) {
      v->info() = i;
      return;
    }
    const std::size_t j = v->info();
    std::ostringstream msg;
    msg << "Delaunay_from_prediction::make_delaunay: vertices " << (std::min)(i, j) << " and "
        << (std::max)(i, j) << " (in finite-vertex order) are both at ("
        << CGAL::to_double(points[i].x()) << ", " << CGAL::to_double(points[i].y()) << ")";
    throw Invalid_prediction(msg.str());
  });
  stats.points_reinserted += n;

  // Transplant. A face of dimension d has max(1, d + 1) vertex slots and d + 1 neighbors.
  auto& tds = tr.tds();
  const int dimension = aside.dimension();
  const int slots = (std::max)(1, dimension + 1);
  const int neighbors = (std::max)(0, dimension + 1);
  auto vertex_of = [&](typename Aside::Vertex_handle v) {
    return v == aside.infinite_vertex() ? tr.infinite_vertex() : vertices[v->info()];
  };
  tds.faces().clear();
  tds.set_dimension(dimension);
  std::vector<Face_handle> face_of;
  face_of.reserve(aside.tds().faces().size());
  for(auto f = aside.tds().faces().begin(); f != aside.tds().faces().end(); ++f) {
    f->info() = face_of.size();
    const Face_handle g = tds.create_face();
    for(int j = 0; j < slots; ++j)
      g->set_vertex(j, vertex_of(f->vertex(j)));
    face_of.push_back(g);
  }
  for(auto f = aside.tds().faces().begin(); f != aside.tds().faces().end(); ++f)
    for(int j = 0; j < neighbors; ++j)
      face_of[f->info()]->set_neighbor(j, face_of[f->neighbor(j)->info()]);
  for(auto v = aside.tds().vertices().begin(); v != aside.tds().vertices().end(); ++v)
    vertex_of(v)->set_face(face_of[v->face()->info()]);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_REBUILD_H
