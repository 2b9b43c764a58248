// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Kinetic_Delaunay_triangulation_2 on the torus. Included at the end of periodic_2.h: it calls
// the periodic overloads declared there.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_KINETIC_ACCESS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_KINETIC_ACCESS_H

#include <CGAL/Delaunay_from_prediction/periodic_2.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Kinetic_Delaunay_triangulation_2 on the torus: set_point() moves every copy of a vertex, the
// points must lie in the domain, and make_delaunay() keeps the vertex objects only when the
// triangulation is 1-sheeted before and after.
template <class Gt, class Tds>
struct Kinetic_access<Periodic_2_Delaunay_triangulation_2<Gt, Tds>>
{
  using DT = Periodic_2_Delaunay_triangulation_2<Gt, Tds>;

  static DT empty_like(const DT& dt) { return DT(dt.domain(), dt.geom_traits()); }
  template <class F>
  static void for_each_vertex(DT& dt, F f)
  {
    for(auto v = dt.tds().vertices().begin(); v != dt.tds().vertices().end(); ++v)
      f(typename DT::Vertex_handle(v));
  }
  template <class F>
  static void for_each_point_vertex(const DT& dt, F f)
  {
    for(auto v = dt.unique_vertices_begin(); v != dt.unique_vertices_end(); ++v)
      f(typename DT::Vertex_handle(v));
  }
  template <class PointRange>
  static void check_points(const DT& dt, const PointRange& points)
  {
    check_domain_width<Gt>(dt.domain());
    std::size_t i = 0;
    for(const auto& p : points)
      check_in_domain(p, dt.domain(), "point", i++);
  }
  template <class ConcurrencyTag, class NamedParameters>
  static std::pair<Statistics, bool> repair(DT& dt, const NamedParameters& np)
  {
    const bool was_1_sheeted = dt.is_1_cover();
    const Statistics stats = make_delaunay<ConcurrencyTag>(dt, np);
    return {stats, was_1_sheeted && dt.is_1_cover()};
  }
  template <class ConcurrencyTag, class PointRange, class FaceRange, class NamedParameters>
  static Statistics build(const PointRange& points, const FaceRange& faces, DT& dt, const NamedParameters& np)
  {
    return delaunay_from_prediction<ConcurrencyTag>(points, faces, dt, np);
  }
  // The triangles as index triples, but for those that repeat a point (only a 9-sheeted
  // covering has them; an index triple cannot say them).
  static std::vector<std::array<std::size_t, 3>> faces(const DT& dt)
  {
    std::vector<std::array<std::size_t, 3>> faces;
    for(const Indexed_periodic_triangle& t : indexed_periodic_triangles(dt))
      if(t.vertices[0] != t.vertices[1] && t.vertices[1] != t.vertices[2] && t.vertices[2] != t.vertices[0])
        faces.push_back(t.vertices);
    return faces;
  }
};

} // namespace internal

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_KINETIC_ACCESS_H
