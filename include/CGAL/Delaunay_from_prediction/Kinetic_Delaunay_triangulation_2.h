// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Kinetic_Delaunay_triangulation_2: the Delaunay triangulation of indexed points that move,
// one vertex per point index, repaired in place by make_delaunay() at each move, or rebuilt
// with the previous triangulation as the prediction when points merge or split, in the plane or
// on the torus (periodic_2.h specializes Kinetic_access). The one place where that rule is
// written: dfp kinetic and the Python classes use it.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_KINETIC_DELAUNAY_TRIANGULATION_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_KINETIC_DELAUNAY_TRIANGULATION_2_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/enum.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// What Kinetic_Delaunay_triangulation_2 asks of its triangulation type, for a
// Delaunay_triangulation_2; periodic_2.h specializes it for Periodic_2_Delaunay_triangulation_2.
template <class DT>
struct Kinetic_access
{
  // An empty triangulation with the traits of `dt`.
  static DT empty_like(const DT& dt) { return DT(dt.geom_traits()); }
  // Calls f(v) for every vertex holding a point index in info() (every copy of a vertex, where
  // the triangulation keeps copies).
  template <class F>
  static void for_each_vertex(DT& dt, F f)
  {
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      f(v);
  }
  // Calls f(v) for each vertex once (no copies).
  template <class F>
  static void for_each_point_vertex(const DT& dt, F f)
  {
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      f(v);
  }
  // Throws Invalid_prediction naming the first point that the triangulation cannot hold.
  template <class PointRange>
  static void check_points(const DT&, const PointRange& points)
  {
    check_points_are_finite(std::begin(points), std::size(points));
  }
  // make_delaunay(); the second member: whether the vertex objects survived.
  template <class ConcurrencyTag, class NamedParameters>
  static std::pair<Statistics, bool> repair(DT& dt, const NamedParameters& np)
  {
    return {make_delaunay<ConcurrencyTag>(dt, np), true};
  }
  template <class ConcurrencyTag, class PointRange, class FaceRange, class NamedParameters>
  static Statistics build(const PointRange& points, const FaceRange& faces, DT& dt, const NamedParameters& np)
  {
    return delaunay_from_prediction<ConcurrencyTag>(points, faces, dt, np);
  }
  // The faces as index triples: the prediction of a rebuild.
  static std::vector<std::array<std::size_t, 3>> faces(const DT& dt) { return faces_of(dt); }
};

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
keeps the Delaunay triangulation of `n` indexed points that move: the kinetic loop of a
simulation, written once.

Each point index has one vertex (`vertex(i)`); the indices of equal points share one vertex,
whose `info()` is the smallest of them, as `delaunay_from_prediction()` sets it. `move(points)`
gives every index its new point and makes the triangulation the Delaunay triangulation of the
new points, which is exactly the triangulation \cgal's `Delaunay_triangulation_2` builds from
them. It decides once, by this rule, how:

- <b>In place</b> (the usual case): every vertex gets its new point (`set_point()`) and
  `make_delaunay()` repairs the triangulation, whatever the moves (inverted faces, a change of
  dimension). Vertex handles and `info()` survive.
- <b>Rebuilt when points merge</b>: two vertices moved onto one point. `make_delaunay()`
  refuses (a vertex would have to go), and the triangulation is rebuilt by
  `delaunay_from_prediction()` with its own faces as the prediction; the equal points then
  share a vertex.
- <b>Rebuilt when points split</b>: indices that shared a vertex (equal points) no longer have
  equal points. A vertex cannot be split in place, so the triangulation is rebuilt the same way.
  While equal points stay equal, the move stays in place.

After a rebuild, vertex handles are new (`last_move_rebuilt()` says so).

Errors: `move()` throws `Invalid_prediction` for a point count other than `n` or a non-finite
coordinate (naming the point), before anything changes. Another exception during a rebuild
(out of memory) leaves the points moved but the triangulation possibly not Delaunay: call
`build()` again.

On the torus (`DT` a `CGAL::Periodic_2_Delaunay_triangulation_2`, with
`<CGAL/Delaunay_from_prediction/periodic_2.h>` included): the points must lie in the domain of
the triangulation given to the constructor (`move()` throws `Invalid_prediction` naming the
first point outside it, or for a period the periodic functions refuse, before anything changes); `set_point()` moves every copy of a vertex of
a 9-sheeted covering; a move that finds or leaves the covering 9-sheeted counts as a rebuild (new
vertex objects).

\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>` or a
        `CGAL::Periodic_2_Delaunay_triangulation_2<Gt, Tds>` whose vertices have an `info()`
        assignable from `std::size_t` (for example with
        `CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Gt>`).

\cgalHeading{Example}
\code
DFP::Kinetic_Delaunay_triangulation_2<DT> kdt;
kdt.build(points);                       // the Delaunay triangulation of the first frame
for(each frame) {
  DFP::Statistics s = kdt.move(next_points);            // repaired in place, or rebuilt
  const DT& dt = kdt.triangulation();   // v->info(): the index of v's point
}
\endcode
*/
template <class DT>
class Kinetic_Delaunay_triangulation_2
{
  static_assert(internal::has_index_info<typename DT::Vertex>::value,
                "Kinetic_Delaunay_triangulation_2 needs vertices with an info() assignable from std::size_t");

public:
  /// the triangulation type.
  using Triangulation = DT;
  /// the point type.
  using Point = typename DT::Point;
  /// the vertex handle type.
  using Vertex_handle = typename DT::Vertex_handle;

  /// an empty triangulation of no points.
  Kinetic_Delaunay_triangulation_2() = default;
  /// an empty triangulation of no points, whose triangulations are made with the traits of `dt`
  /// (and, for a periodic triangulation, its domain); `dt` is only read.
  /// \param dt a triangulation whose traits (and domain) are used.
  explicit Kinetic_Delaunay_triangulation_2(const DT& dt) : dt_(Access::empty_like(dt)) {}
  // Not copyable: the vertex handles by index point into the triangulation held.
  Kinetic_Delaunay_triangulation_2(const Kinetic_Delaunay_triangulation_2&) = delete;
  Kinetic_Delaunay_triangulation_2& operator=(const Kinetic_Delaunay_triangulation_2&) = delete;

  /// builds the Delaunay triangulation of `points` (a random-access range of `Point`) with
  /// `delaunay_from_prediction()`, using `faces` as the prediction (an empty range: none), and
  /// takes it. Its named parameters are those of `delaunay_from_prediction()`. On an exception
  /// (`Invalid_prediction` for a malformed prediction or point), `*this` is unchanged.
  /// \param points the points; point index `i` is `points[i]`.
  /// \param faces the predicted triangles, index triples into `points`.
  /// \param np optional named parameters, as for `delaunay_from_prediction()`.
  /// \returns the statistics of `delaunay_from_prediction()`.
  template <class ConcurrencyTag = Sequential_tag, class PointRange, class FaceRange,
            class NamedParameters = parameters::Default_named_parameters>
  Statistics build(const PointRange& points, const FaceRange& faces,
                   const NamedParameters& np = parameters::default_values())
  {
    DT dt = Access::empty_like(dt_);
    const Statistics stats = Access::template build<ConcurrencyTag>(points, faces, dt, np);
    take(dt, points, stats.duplicate_points > 0);
    last_move_rebuilt_ = false;
    return stats;
  }

  /// builds the Delaunay triangulation of `points` from scratch (no prediction).
  /// \param points the points; point index `i` is `points[i]`.
  /// \returns the statistics of the build.
  template <class ConcurrencyTag = Sequential_tag, class PointRange>
  Statistics build(const PointRange& points)
  {
    return build<ConcurrencyTag>(points, std::vector<std::array<std::size_t, 3>>());
  }

  /// takes `dt`, the Delaunay triangulation of `points` as `delaunay_from_prediction()` or
  /// another of the package's functions built it (every vertex's `info()` the smallest index of
  /// its point), for example one built from a predicted graph. `dt` is left empty.
  /// Throws `Invalid_prediction`, and changes nothing, if an `info()` is out of range, is not the
  /// index of the vertex's point, or if a point is at no vertex.
  /// \param dt the triangulation taken (left empty).
  /// \param points the points it triangulates; point index `i` is `points[i]`.
  template <class PointRange>
  void assign(DT& dt, const PointRange& points)
  {
    const std::size_t n = std::size(points);
    Access::for_each_point_vertex(dt, [&](Vertex_handle v) {
      const std::size_t i = static_cast<std::size_t>(v->info());
      if(i >= n || !equal(v->point(), points[i], dt)) {
        std::ostringstream msg;
        msg << "Kinetic_Delaunay_triangulation_2::assign(): a vertex has info() " << i
            << ", which is not the index of its point among the " << n << " points";
        throw Invalid_prediction(msg.str());
      }
    });
    take(dt, points, dt.number_of_vertices() < n);
    dt.clear();
    last_move_rebuilt_ = false;
  }

  /// gives point index `i` the point `points[i]` for every `i` and makes the triangulation the
  /// Delaunay triangulation of the new points: in place, or rebuilt, by the rule in the class
  /// description. `points` must have `number_of_points()` points. The named parameters go to
  /// `make_delaunay()`, and to `delaunay_from_prediction()` for a rebuild.
  /// \param points the new points; point index `i` moves to `points[i]`.
  /// \param np optional named parameters, as for `make_delaunay()`.
  /// \returns the statistics of the call that did the work.
  template <class ConcurrencyTag = Sequential_tag, class PointRange,
            class NamedParameters = parameters::Default_named_parameters>
  Statistics move(const PointRange& points, const NamedParameters& np = parameters::default_values())
  {
    const std::size_t n = std::size(points);
    if(n != vertex_of_.size()) {
      std::ostringstream msg;
      msg << "Kinetic_Delaunay_triangulation_2::move(): " << n << " points given, the triangulation has "
          << vertex_of_.size();
      throw Invalid_prediction(msg.str());
    }
    Access::check_points(dt_, points); // before anything changes
    if(!shares_vertices_ || equal_points_stay_equal(points)) {
      Access::for_each_vertex(dt_, [&](Vertex_handle v) { v->set_point(points[static_cast<std::size_t>(v->info())]); });
      try {
        const std::pair<Statistics, bool> repaired = Access::template repair<ConcurrencyTag>(dt_, np);
        last_move_rebuilt_ = !repaired.second;
        if(last_move_rebuilt_) { // new vertex objects (a periodic triangulation not 1-sheeted)
          DT rebuilt = Access::empty_like(dt_);
          rebuilt.swap(dt_);
          take(rebuilt, points, shares_vertices_);
        }
        return repaired.first;
      } catch(const Invalid_prediction&) {
        // Two vertices moved onto one point (the only refusal left, the points having been
        // checked). The connectivity is as it was: a good prediction for the rebuild.
      }
    }
    const Statistics stats = build<ConcurrencyTag>(points, Access::faces(dt_), np);
    last_move_rebuilt_ = true;
    return stats;
  }

  /// the triangulation: `v->info()` is the (smallest) index of `v`'s point.
  /// \returns the triangulation.
  const DT& triangulation() const { return dt_; }

  /// `n`, the number of point indices (0 before `build()`).
  /// \returns the number of point indices.
  std::size_t number_of_points() const { return vertex_of_.size(); }

  /// the vertex of point index `i` (shared by equal points).
  /// \param i a point index.
  /// \returns the vertex of point `i`.
  /// \pre `i < number_of_points()`
  Vertex_handle vertex(std::size_t i) const
  {
    CGAL_precondition(i < vertex_of_.size());
    return vertex_of_[i];
  }

  /// the point of index `i`.
  /// \param i a point index, less than `number_of_points()`.
  /// \returns the point of index `i`.
  const Point& point(std::size_t i) const { return vertex(i)->point(); }

  /// whether some indices share a vertex (equal points).
  /// \returns `true` if some indices share a vertex.
  bool has_shared_vertices() const { return shares_vertices_; }

  /// whether the last `move()` rebuilt the triangulation (points merged or split) instead of
  /// repairing it in place.
  /// \returns `true` if the last `move()` rebuilt the triangulation.
  bool last_move_rebuilt() const { return last_move_rebuilt_; }

private:
  using Access = internal::Kinetic_access<DT>;

  template <class P, class Q>
  static bool equal(const P& p, const Q& q, const DT& dt)
  {
    return dt.geom_traits().compare_xy_2_object()(p, q) == CGAL::EQUAL;
  }

  // Whether the indices that share a vertex still have equal points.
  template <class PointRange>
  bool equal_points_stay_equal(const PointRange& points) const
  {
    for(std::size_t i = 0; i < vertex_of_.size(); ++i) {
      const std::size_t held = static_cast<std::size_t>(vertex_of_[i]->info());
      if(held != i && !equal(points[i], points[held], dt_))
        return false;
    }
    return true;
  }

  // Takes `dt` (swapped in: `dt` is left with the previous triangulation) and records the vertex of
  // each index; with duplicates, an index without its own vertex gets that of the smallest
  // equal index (found by a lexicographic sort). Throws before changing anything if a point is
  // at no vertex.
  template <class PointRange>
  void take(DT& dt, const PointRange& points, bool has_duplicates)
  {
    const std::size_t n = std::size(points);
    std::vector<Vertex_handle> vertex_of(n);
    std::vector<bool> has_vertex(n, false);
    Access::for_each_point_vertex(dt, [&](Vertex_handle v) {
      const std::size_t i = static_cast<std::size_t>(v->info());
      vertex_of[i] = v;
      has_vertex[i] = true;
    });
    if(has_duplicates) {
      std::vector<std::size_t> order(n);
      std::iota(order.begin(), order.end(), std::size_t(0));
      const auto compare_xy = dt.geom_traits().compare_xy_2_object();
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const CGAL::Comparison_result c = compare_xy(points[a], points[b]);
        return c == CGAL::SMALLER || (c == CGAL::EQUAL && a < b);
      });
      // In each run of equal points the smallest index comes first and holds the vertex.
      for(std::size_t k = 0; k < n; ++k) {
        const std::size_t i = order[k];
        if(k > 0 && compare_xy(points[order[k - 1]], points[i]) == CGAL::EQUAL)
          vertex_of[i] = vertex_of[order[k - 1]];
        else if(!has_vertex[i])
          throw Invalid_prediction("Kinetic_Delaunay_triangulation_2: point " + std::to_string(i) +
                                   " is at no vertex of the triangulation");
      }
    } else if(std::find(has_vertex.begin(), has_vertex.end(), false) != has_vertex.end()) {
      const std::size_t i = std::size_t(std::find(has_vertex.begin(), has_vertex.end(), false) - has_vertex.begin());
      throw Invalid_prediction("Kinetic_Delaunay_triangulation_2: point " + std::to_string(i) +
                               " is at no vertex of the triangulation");
    }
    dt_.swap(dt);
    vertex_of_.swap(vertex_of);
    shares_vertices_ = has_duplicates;
  }

  DT dt_;
  std::vector<Vertex_handle> vertex_of_; // by point index
  bool shares_vertices_ = false;         // some indices share a vertex (equal points)
  bool last_move_rebuilt_ = false;
};

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_KINETIC_DELAUNAY_TRIANGULATION_2_H
