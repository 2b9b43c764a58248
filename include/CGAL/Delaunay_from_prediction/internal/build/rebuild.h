// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Builds from scratch: Lawson's insertion on flat arrays (flat_insertion.h) in a biased
// randomized grid order, each point located from the previous one (CGAL's range insert does
// the same after a spatial_sort that costs a third of its time; the grid order is ten times
// cheaper), over point indices so that duplicates keep the smallest index, the faces then
// written into the triangulation; dimensions 0 and 1 by the package's insertion into the
// triangulation (insertion.h). Used for from-scratch fallbacks and for rebuilding a caller's
// triangulation in place while keeping its vertex and face objects; insert_points() adds
// points to a triangulation (the points no face covers).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REBUILD_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REBUILD_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/build/flat_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The vertex of each rank of a flat triangulation, handles[order[k]] (handles[k] without an
// order): one type for the writes of a program, so that Flat_delaunay::write_faces() is
// compiled once (code_size.h).
template <class Vertex_handle>
struct Vertex_of_rank
{
  const Vertex_handle* handles;
  const std::size_t* order; // may be null
  Vertex_handle operator()(std::uint32_t k) const { return order != nullptr ? handles[order[k]] : handles[k]; }
};

// Writes the flat triangulation of all n stored ranks into `dt` (no vertex): a vertex per
// representative rank, then on_vertex(index_of(rank), vertex, is_new) for every rank, the
// representatives first.
template <class DT, class Gt, class IndexOf, class OnVertex>
void write_flat_triangulation(DT& dt, const Flat_delaunay<Gt>& flat, std::size_t n, IndexOf index_of,
                              OnVertex on_vertex)
{
  std::vector<typename DT::Vertex_handle> vertex(n);
  for(std::size_t k = 0; k < n; ++k)
    if(flat.representative(k) == k) {
      vertex[k] = dt.tds().create_vertex();
      vertex[k]->set_point(flat.point(std::uint32_t(k)));
    }
  flat.write_faces(dt.tds(), dt.infinite_vertex(),
                   Vertex_of_rank<typename DT::Vertex_handle>{vertex.data(), nullptr});
  for(std::size_t k = 0; k < n; ++k) // the new vertices first: a duplicate may have the smaller rank
    if(flat.representative(k) == k)
      on_vertex(index_of(k), vertex[k], true);
  for(std::size_t k = 0; k < n; ++k)
    if(flat.representative(k) != k)
      on_vertex(index_of(k), vertex[flat.representative(k)], false);
}

// The points of an insertion order, points[order[k]]: one type for the flat builds of a
// program, so that Flat_delaunay::build() is compiled once (code_size.h).
template <class PointIterator>
struct Points_in_order
{
  PointIterator points;
  const std::size_t* order;
  decltype(auto) operator()(std::size_t k) const { return points[order[k]]; }
};

// Builds DT(points[indices[0]], points[indices[1]], ...) into `dt`, which holds no vertex, on
// flat arrays (flat_insertion.h), inserted in the order of `indices`: the vertices are created
// in that order, the faces written, then `on_vertex(index, vertex, is_new)` is called for
// each new vertex's index in that order, then for the others (`is_new` false: a point equal
// to an earlier one). Returns
// false, with `dt` untouched, when the points span no triangle.
template <class DT, class PointIterator, class OnVertex>
bool build_on_flat_arrays(DT& dt, PointIterator points, const std::vector<std::size_t>& indices, OnVertex on_vertex)
{
  CGAL_precondition(dt.number_of_vertices() == 0);
  const std::size_t n = indices.size();
  Flat_delaunay<typename DT::Geom_traits> flat(dt.geom_traits());
  if(!flat.build(n, Points_in_order<PointIterator>{points, indices.data()}))
    return false;
  write_flat_triangulation(dt, flat, n, [&](std::size_t k) { return indices[k]; }, on_vertex);
  return true;
}

// Inserts the points of the given indices into the Delaunay triangulation `dt`, in biased
// randomized grid order (sort_along_grid; with `in_order`, the indices are in that order
// already), each by insert_near() from the previous vertex. `on_vertex(index, vertex, is_new)`
// is called after each insertion; `is_new` is false when the point was already a vertex (a
// duplicate). Returns the number of new vertices.
template <class DT, class PointIterator, class OnVertex>
std::size_t insert_by_index(DT& dt, PointIterator points, std::vector<std::size_t>& indices,
                            OnVertex on_vertex, bool in_order = false)
{
  if(!in_order)
    sort_along_grid(indices, Point_of_index<PointIterator>{points}, true);
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

// Copies the faces of the Delaunay triangulation `aside` into the TDS of `tr`, whose faces
// are dropped: `vertex_of(aside vertex)` gives the vertex of `tr` for each vertex of `aside`
// (the infinite one included; called on several threads with `parallel`). A face of dimension d
// has max(1, d + 1) vertex slots and d + 1 neighbors. Numbers the faces of `aside` in their
// info() when they have one. With
// `parallel`, the faces are created in chunks on TBB's threads, each in a container of its own
// (CGAL's containers are not thread-safe), spliced in chunk order, and linked on TBB's threads.
template <class Aside, class Triangulation, class VertexOf, class Parallel = std::false_type>
void transplant(Aside& aside, Triangulation& tr, VertexOf vertex_of, Parallel parallel = Parallel())
{
  using Face_handle = typename Triangulation::Face_handle;
  using Face_range = typename Triangulation::Triangulation_data_structure::Face_range;
  auto& tds = tr.tds();
  const int dimension = aside.dimension();
  const int slots = (std::max)(1, dimension + 1);
  const int neighbors = (std::max)(0, dimension + 1);
  const std::size_t m = aside.tds().faces().size();
  std::vector<typename Aside::Face_handle> from;
  from.reserve(m);
  // The number of each face of `aside`: its info() when it has one (the builds aside), a
  // table otherwise (the triangulations of collinear points, small).
  constexpr bool numbered_by_info = has_index_info<typename Aside::Face>::value;
  Hash_map<const void*, std::size_t> number(numbered_by_info ? 0 : 2 * m + 16);
  for(auto f = aside.tds().faces().begin(); f != aside.tds().faces().end(); ++f) {
    if constexpr(numbered_by_info)
      f->info() = from.size();
    else
      number.insert(&*f, from.size());
    from.push_back(f);
  }
  auto number_of = [&](typename Aside::Face_handle f) -> std::size_t {
    if constexpr(numbered_by_info)
      return f->info();
    else
      return *number.find(&*f);
  };
  std::vector<Face_handle> face_of(m);
  constexpr std::size_t chunk_size = std::size_t(1) << 15;
  const std::size_t chunks = parallel ? (m + chunk_size - 1) / chunk_size : 1;
  std::vector<Face_range> created(chunks > 1 ? chunks : 0);
  tds.faces().clear();
  tds.set_dimension(dimension);
  const auto in_chunks = parallel_argument<Parallel>(chunks > 1);
  for_each_block(in_chunks, chunks, [&](std::size_t c) {
    for(std::size_t k = c * m / chunks, end = (c + 1) * m / chunks; k < end; ++k) {
      const Face_handle g = chunks > 1 ? created[c].emplace() : tds.create_face();
      for(int j = 0; j < slots; ++j)
        g->set_vertex(j, vertex_of(from[k]->vertex(j)));
      face_of[k] = g;
    }
  });
  for(Face_range& range : created)
    tds.faces().merge(range);
  for_each_block(in_chunks, chunks, [&](std::size_t c) {
    for(std::size_t k = c * m / chunks, end = (c + 1) * m / chunks; k < end; ++k)
      for(int j = 0; j < neighbors; ++j)
        face_of[k]->set_neighbor(j, face_of[number_of(from[k]->neighbor(j))]);
  });
  for(auto v = aside.tds().vertices().begin(); v != aside.tds().vertices().end(); ++v)
    vertex_of(v)->set_face(face_of[number_of(v->face())]);
}

// The traits whose predicates decide the faces for traits whose predicates are not exact:
// Epick's (exact, filtered) on the coordinates rounded to double, which is no rounding for
// Simple_cartesian<double>.
using Deciding_gt = Exact_predicates_inexact_constructions_kernel;
using Deciding_tds = Triangulation_data_structure_2<Triangulation_vertex_base_with_info_2<std::size_t, Deciding_gt>,
                                                    Triangulation_face_base_with_info_2<std::size_t, Deciding_gt>>;
using Deciding_dt = Delaunay_triangulation_2<Deciding_gt, Deciding_tds>;

// The Delaunay triangulation of points[0, n) by exact predicates on their coordinates rounded
// to double, built into `aside` by the package's insertion; every vertex's info() is the
// smallest index of its point, and `on_duplicate(i, j)` is called for a point i equal to the point j of
// a vertex (before anything else happens to it). (CGAL's own insertion with inexact
// predicates, tried first, lost points, left invalid triangulations and crashed on almost
// collinear points: it cannot be relied on.) Returns the vertex of each point.
template <class PointIterator, class OnDuplicate>
std::vector<Deciding_dt::Vertex_handle> build_deciding(Deciding_dt& aside, PointIterator points, std::size_t n,
                                                       OnDuplicate on_duplicate)
{
  std::vector<Deciding_gt::Point_2> rounded;
  rounded.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    rounded.emplace_back(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()));
  std::vector<std::size_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = i;
  std::vector<Deciding_dt::Vertex_handle> vertex(n);
  auto on_vertex = [&](std::size_t i, auto v, bool is_new) {
    vertex[i] = v;
    if(is_new) {
      v->info() = i;
    } else {
      on_duplicate(i, v->info());
      v->info() = (std::min)(v->info(), i); // the smallest index of the point
    }
  };
  sort_along_grid(indices, Point_of_index<const Deciding_gt::Point_2*>{rounded.data()}, true);
  if(!build_on_flat_arrays(aside, rounded.begin(), indices, on_vertex))
    insert_by_index(aside, rounded.begin(), indices, on_vertex, true);
  return vertex;
}

// For traits whose predicates are not exact (predicates.h), where the package's flips
// and walks, and CGAL's own insertion too, can cycle, crash or lose points: fills the
// Delaunay triangulation `dt` (cleared) with points[0, n), its faces decided by exact
// predicates (build_deciding()), its vertices holding the caller's points. Calls
// `on_vertex(index, vertex, is_new)` for every point in index order (is_new false for a
// duplicate of an earlier point).
template <class DT, class PointIterator, class OnVertex>
void insert_with_exact_predicates(DT& dt, PointIterator points, std::size_t n, OnVertex on_vertex)
{
  using Vertex_handle = typename DT::Vertex_handle;
  dt.clear();
  if(n == 0)
    return;
  Deciding_dt aside;
  const std::vector<Deciding_dt::Vertex_handle> at = build_deciding(aside, points, n, [](std::size_t, std::size_t) {});
  std::vector<Vertex_handle> vertex(n);
  for(auto v = aside.finite_vertices_begin(); v != aside.finite_vertices_end(); ++v) {
    const Vertex_handle w = dt.tds().create_vertex();
    w->set_point(points[v->info()]);
    vertex[v->info()] = w;
  }
  transplant(aside, dt, [&](Deciding_dt::Vertex_handle v) {
    return v == aside.infinite_vertex() ? dt.infinite_vertex() : vertex[v->info()];
  });
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t first = at[i]->info();
    on_vertex(i, vertex[first], first == i);
  }
}

// Builds DT(points) from scratch into `dt`, which holds no vertex, on flat arrays
// (build_on_flat_arrays()). `grid_order`, if not
// empty, lists all the indices in grid order (the import had sorted them so): they
// are only dealt into rounds, not sorted again (about 0.03 s less at 1e6 points). With
// traits whose predicates are not exact, by insert_with_exact_predicates().
template <class DT, class PointIterator>
void build_from_scratch(DT& dt, PointIterator points, std::size_t n, Statistics& stats,
                        const std::vector<std::uint32_t>& grid_order = std::vector<std::uint32_t>())
{
  if constexpr(decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    insert_with_exact_predicates(dt, points, n, [&](std::size_t i, auto v, bool is_new) {
      record_index_info(v, i, is_new, stats.duplicate_points);
    });
    stats.points_reinserted += n;
    return;
  }
  const bool in_order = grid_order.size() == n;
  std::vector<std::size_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = in_order ? grid_order[i] : i;
  if(in_order)
    deal_into_rounds(indices);
  else
    sort_along_grid(indices, Point_of_index<PointIterator>{points}, true);
  std::size_t duplicates = 0;
  if(!build_on_flat_arrays(dt, points, indices, [&](std::size_t i, auto v, bool is_new) {
       record_index_info(v, i, is_new, duplicates);
     })) {
    insert_points(dt, points, indices, stats, nullptr, true); // all collinear: dimension 0 or 1
    return;
  }
  stats.points_reinserted += n;
  stats.duplicate_points += duplicates;
}

// The whole build of an entry point for traits whose predicates are not exact:
// build_from_scratch(), recorded in `stats` as a fallback.
template <class DT, class PointIterator>
void build_with_exact_predicates(DT& dt, PointIterator points, std::size_t n, Statistics& stats)
{
  static_assert(decides_by_exact_predicates<typename DT::Geom_traits>::value);
  build_from_scratch(dt, points, n, stats);
  stats.points_reinserted = n;
  stats.fell_back = true;
  stats.outcome = Outcome::inexact_predicates;
}

// The exception of rebuild_keeping_vertices() for two vertices at one point, built out of
// line (code_size.h).
[[noreturn]] CGAL_DFP_RARELY_RUN inline void throw_vertices_at_one_point(std::size_t i, std::size_t j, double x,
                                                                        double y)
{
  std::ostringstream msg;
  msg << "Delaunay_from_prediction::make_delaunay: vertices " << (std::min)(i, j) << " and " << (std::max)(i, j)
      << " (in finite-vertex order) are both at (" << x << ", " << y << ")";
  throw Invalid_prediction(msg.str());
}

// rebuild_keeping_vertices() for points that span no triangle (dimension 0 or 1): inserted
// one by one aside, then transplanted. `duplicates(i, j)` throws for two vertices at one point.
template <class Triangulation, class Duplicates>
CGAL_DFP_RARELY_RUN void rebuild_collinear_keeping_vertices(
    Triangulation& tr, const std::vector<typename Triangulation::Vertex_handle>& vertices,
    const typename Triangulation::Point* points, std::vector<std::size_t>& indices, Duplicates duplicates)
{
  // On tr's own data structure: for a Delaunay_triangulation_2, tr's own type, so that no
  // second triangulation type is compiled for this rare case.
  using Line = Delaunay_triangulation_2<typename Triangulation::Geom_traits,
                                        typename Triangulation::Triangulation_data_structure>;
  Line line(tr.geom_traits());
  Hash_map<const void*, std::size_t> index_of(2 * indices.size() + 16);
  insert_by_index(line, points, indices, [&](std::size_t i, auto v, bool is_new) {
    if(!is_new)
      duplicates(i, *index_of.find(&*v)); // throws; tr untouched
    index_of.insert(&*v, i);
  });
  transplant(line, tr, [&](typename Line::Vertex_handle v) {
    return v == line.infinite_vertex() ? tr.infinite_vertex() : vertices[*index_of.find(&*v)];
  });
}

// Replaces the faces of `tr` by those of DT(its vertices), keeping every vertex object (so
// vertex handles and info() survive). The new triangulation is built on flat arrays and
// written into tr's own face objects (Flat_delaunay::write_faces(); dimensions 0 and 1: built
// aside by insert_by_index(); with inexact predicates, by exact ones: build_deciding()), then
// transplanted face by face. If two vertices are at the same point (for inexact predicates: by the traits'
// compare_xy, before any insertion), throws Invalid_prediction naming both, before `tr` is modified.
// `build_aside(aside, points, n)`, if given, may build the triangulation aside instead (with
// vertex info the point index), returning false when it did not; one that lost a point (two at
// the same point) is built again by the insertion, which names them. Without
// `or_by_insertion`, a triangulation `build_aside` did not build leaves `tr` as it is, and
// false is returned; otherwise true.
template <class Triangulation, class BuildAside = std::nullptr_t>
bool rebuild_keeping_vertices(Triangulation& tr, Statistics& stats, BuildAside build_aside = nullptr,
                              bool or_by_insertion = true)
{
  using Gt = typename Triangulation::Geom_traits;
  using Point = typename Triangulation::Point;
  using Vertex_handle = typename Triangulation::Vertex_handle;
  // The triangulation `build_aside` builds, vertices and faces numbered in their info().
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
    return true;

  const Point* point_at = points.data();
  auto duplicates = [&](std::size_t i, std::size_t j) {
    throw_vertices_at_one_point(i, j, CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()));
  };
  std::vector<std::size_t> indices(n);
  for(std::size_t i = 0; i < n; ++i)
    indices[i] = i;
  if constexpr(decides_by_exact_predicates<Gt>::value) {
    // Duplicates by the traits' exact comparison of coordinates, before any insertion, not
    // by what an inexact insertion happens to do.
    auto compare_xy = tr.geom_traits().compare_xy_2_object();
    std::sort(indices.begin(), indices.end(), [&](std::size_t i, std::size_t j) {
      const Comparison_result c = compare_xy(points[i], points[j]);
      return c == SMALLER || (c == EQUAL && i < j);
    });
    for(std::size_t k = 1; k < n; ++k)
      if(compare_xy(points[indices[k - 1]], points[indices[k]]) == EQUAL)
        duplicates(indices[k - 1], indices[k]);
    for(std::size_t i = 0; i < n; ++i)
      indices[i] = i;
  }
  stats.points_reinserted += n;
  if constexpr(decides_by_exact_predicates<Gt>::value) {
    // Faces decided by exact predicates (build_deciding()): the same vertex objects, none lost.
    Deciding_dt exact;
    build_deciding(exact, point_at, n, duplicates); // only where rounding to double merged two points
    transplant(exact, tr, [&](Deciding_dt::Vertex_handle v) {
      return v == exact.infinite_vertex() ? tr.infinite_vertex() : vertices[v->info()];
    });
  } else {
    if constexpr(!std::is_same<BuildAside, std::nullptr_t>::value) {
      Aside aside(tr.geom_traits());
      const bool ran = build_aside(aside, points.begin(), n);
      if(ran && aside.number_of_vertices() == n) {
        transplant(aside, tr, [&](typename Aside::Vertex_handle v) {
          return v == aside.infinite_vertex() ? tr.infinite_vertex() : vertices[v->info()];
        }, true); // on several threads
        return true;
      }
      if(ran) // a point lost: the insertion below names the two at the same point
        or_by_insertion = true;
    }
    if(!or_by_insertion)
      return false;
    // On flat arrays (flat_insertion.h), written into tr's own face objects.
    sort_along_grid(indices, Point_of_index<const Point*>{point_at}, true);
    Flat_delaunay<Gt> flat(tr.geom_traits());
    if(flat.build(n, Points_in_order<const Point*>{point_at, indices.data()})) {
      for(std::size_t k = 0; k < n; ++k)
        if(flat.representative(k) != k)
          duplicates(indices[flat.representative(k)], indices[k]); // throws; tr untouched
      flat.write_faces(tr.tds(), tr.infinite_vertex(), Vertex_of_rank<Vertex_handle>{vertices.data(), indices.data()});
      return true;
    }
    rebuild_collinear_keeping_vertices(tr, vertices, point_at, indices, duplicates);
  }
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REBUILD_H
