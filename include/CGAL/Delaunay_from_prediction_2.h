// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points: the Delaunay triangulation of points from a predicted triangulation.
// Pipeline, one module per stage:
//   check   internal/input_check.h        malformed input -> Invalid_prediction, nothing touched
//   import, certify, export (fused)
//           internal/import_prediction.h  index triples -> CGAL TDS, twins by counting sort,
//                                         in-circle test of each edge as its twins pair up
//           internal/tds_certify.h        the same certificate read off a CGAL triangulation
//   repair  internal/lawson_flip.h        Lawson flips seeded with the failing edges
//           internal/rebuild.h            CGAL insertion for points no face uses, from-scratch
//                                         fallbacks, in-place rebuilds keeping vertices

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_2_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/hull_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/import_prediction.h>
#include <CGAL/Delaunay_from_prediction/internal/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/lawson_flip.h>
#include <CGAL/Delaunay_from_prediction/internal/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/tds_certify.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

namespace internal {

// Default flip budget. Lawson's algorithm needs about as many flips as the prediction has
// wrong edges. A flip with its re-tests costs about half a point insertion of a rebuild
// (measured: ~300 ns against ~600 ns per point at 1e5-1e6 points), so n/2 wasted flips add
// at most about a quarter of a rebuild; a prediction that needs more (a plain
// Triangulation_2 of random points needs ~6n) is cheaper to rebuild.
inline std::size_t default_max_flips(std::size_t n) { return n / 2 + 64; }

// Statistics::fallback_reason when Lawson's algorithm would need, or needed, more flips than
// the budget.
constexpr const char* flip_budget_exhausted = "the flip budget was exhausted";

// The addresses of the objects behind `handles`, sorted, without repeats.
template <class Handle>
std::vector<const void*> sorted_addresses(const std::vector<Handle>& handles)
{
  std::vector<const void*> addresses(handles.size());
  for(std::size_t k = 0; k < handles.size(); ++k)
    addresses[k] = &*handles[k];
  std::sort(addresses.begin(), addresses.end());
  addresses.erase(std::unique(addresses.begin(), addresses.end()), addresses.end());
  return addresses;
}

// Number of distinct faces in `faces`, not counting those whose address is in `except`.
template <class Face_handle>
std::size_t count_distinct(const std::vector<Face_handle>& faces,
                           std::vector<const void*> except = std::vector<const void*>())
{
  const std::vector<const void*> addresses = sorted_addresses(faces);
  std::sort(except.begin(), except.end());
  std::size_t count = 0;
  for(const void* a : addresses)
    count += std::binary_search(except.begin(), except.end(), a) ? 0 : 1;
  return count;
}

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt`, using `faces` as a prediction of it.

The result is exactly the triangulation CGAL's `Delaunay_triangulation_2` builds from the same
points: co-circular ties are broken by CGAL's symbolic perturbation. The time it takes depends
on how good the prediction is. When `faces` is a triangulation of the points, it is certified
in linear time and repaired by Lawson flips that start only at its non-locally-Delaunay edges;
points used by no face are then inserted. Any other prediction (degenerate, inverted, crossing
or repeated faces, holes) is not an error but makes the call build from scratch
(`Statistics::fell_back`).

\tparam PointRange a random-access range of `DT::Point`.
\tparam FaceRange a range whose elements `t` give three integer indices `t[0]`, `t[1]`, `t[2]`
        into `points` (for example `std::array<int, 3>` or `std::vector<std::size_t>`).
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
        assignable from `std::size_t`, every vertex's `info()` is set to the index of its point
        (for duplicate points, the smallest of their indices).
\tparam NamedParameters a sequence of named parameters.

\param points the points.
\param faces the predicted triangles, in any orientation.
\param dt receives the result; cleared first.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the largest number of edge flips to make; past it the call finishes
      with a from-scratch build, so that its cost stays close to a rebuild even for a bad
      prediction or an inexact kernel that could make Lawson's algorithm cycle}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{half the number of points, plus 64}
  \cgalParamNEnd
  \cgalParamNBegin{screen_prediction}
    \cgalParamDescription{whether to draw 32 faces and 16 points at random first, and to build
      from scratch at once if more than half of the faces have a drawn point inside their
      circumcircle (a prediction that far from Delaunay would cost more to repair than to
      rebuild). Only used for at least 4096 points and faces with random access.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a point has a non-finite coordinate, or a face has an index out
        of range or repeats an index. Then `dt` is unchanged.
*/
template <class PointRange, class FaceRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_prediction(const PointRange& points, const FaceRange& faces, DT& dt,
                                    const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;

  Statistics stats;
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t number_of_faces = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  stats.faces_in = number_of_faces;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(n));
  const bool screen = choose_parameter(get_parameter(np, internal_np::screen_prediction), true);
  const auto& gt = dt.geom_traits();

  // Check, then import and certify into a fresh triangulation (Invalid_prediction is thrown
  // before `dt` is touched).
  internal::check_points_are_finite(point_at, n);
  DT result(gt);
  internal::Imported_prediction<DT> imported;
  if(screen && internal::fails_sampling_screen(gt, point_at, n, faces, number_of_faces)) {
    std::size_t k = 0, idx[3];
    for(const auto& face : faces)
      internal::read_face(face, k++, n, idx);
    imported.failure = "most sampled faces have sampled points inside their circumcircles";
  } else {
    internal::Prediction_importer<DT>::run(result, point_at, n, faces, number_of_faces, imported);
  }

  auto build_from_scratch = [&](const char* why) {
    stats.fell_back = true;
    stats.fallback_reason = why;
    stats.faces_certified = 0;
    stats.points_reinserted = 0;
    result.tds().clear(); // release the partial import before building anew
    imported = internal::Imported_prediction<DT>();
    DT fresh(gt);
    internal::build_from_scratch(fresh, point_at, n, stats);
    dt.swap(fresh);
    return stats;
  };
  stats.input_reordered = imported.reordered;
  if(imported.failure != nullptr)
    return build_from_scratch(imported.failure);
  stats.edges_tested = imported.edges_tested;
  stats.edges_not_locally_delaunay = imported.not_locally_delaunay.size();

  // Repair. Each failing edge is not Delaunay and a flip removes one edge, so Lawson's
  // algorithm needs at least as many flips as there are failing edges: past the budget, the
  // flips would be wasted.
  if(imported.not_locally_delaunay.size() > max_flips)
    return build_from_scratch(internal::flip_budget_exhausted);
  std::vector<Face_handle> touched;
  if(!internal::lawson_flip(result, imported.not_locally_delaunay, max_flips, stats.flips, touched))
    return build_from_scratch(internal::flip_budget_exhausted);

  // Points no face uses: duplicates of vertices, or points to insert.
  std::vector<std::size_t>& unused = imported.unused_points;
  stats.points_unused = unused.size();
  if(unused.empty()) {
    stats.faces_certified = result.number_of_faces() - internal::count_distinct(touched);
  } else {
    // A predicted face survives the insertions if it was never flipped and has no new
    // vertex (insertion recycles the faces it destroys for faces around the new vertex).
    const std::vector<const void*> modified = internal::sorted_addresses(touched);
    std::vector<const void*> new_vertices;
    internal::insert_points(result, point_at, unused, stats, &new_vertices);
    std::sort(new_vertices.begin(), new_vertices.end());
    auto is_new = [&](const Vertex_handle v) {
      return std::binary_search(new_vertices.begin(), new_vertices.end(), static_cast<const void*>(&*v));
    };
    stats.faces_certified = 0;
    for(auto f = result.finite_faces_begin(); f != result.finite_faces_end(); ++f)
      if(!std::binary_search(modified.begin(), modified.end(), static_cast<const void*>(&*f)) &&
         !is_new(f->vertex(0)) && !is_new(f->vertex(1)) && !is_new(f->vertex(2)))
        ++stats.faces_certified;
  }
  dt.swap(result);
  return stats;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
turns a CGAL triangulation into the Delaunay triangulation of its own vertices, in place.

The points of `tr` may have been moved with `Vertex::set_point()`, even so far that faces are
inverted or the dimension changes. Vertex handles and their `info()` survive; face handles need
not. A triangulation whose faces are all counterclockwise is certified in linear time; a
hull that is no longer convex is repaired by flips of hull edges; then Lawson flips start at
the non-locally-Delaunay edges. Otherwise (an inverted or flat face, or past the flip budget)
its faces are rebuilt around the same vertex objects (`Statistics::fell_back`).

\tparam Triangulation a `CGAL::Triangulation_2<Gt, Tds>` or `CGAL::Delaunay_triangulation_2<Gt, Tds>`,
        for any triangulation data structure.
\tparam NamedParameters a sequence of named parameters.

\param tr the triangulation.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the largest number of edge flips to make; past it the faces are
      rebuilt}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{half the number of vertices, plus 64}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if two vertices are at the same point, naming both (by their rank
        in finite-vertex order). Then `tr` is unchanged.
*/
template <class Triangulation, class NamedParameters = parameters::Default_named_parameters>
Statistics make_delaunay(Triangulation& tr, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Face_handle = typename Triangulation::Face_handle;

  Statistics stats;
  stats.faces_in = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(tr.number_of_vertices()));
  if(tr.number_of_vertices() == 0)
    return stats;

  std::vector<std::pair<Face_handle, int>> stack;
  bool hull_is_convex = false;
  const char* why = internal::certify_triangulation(tr, stack, stats.edges_tested, hull_is_convex);
  if(why == nullptr)
    stats.edges_not_locally_delaunay = stack.size();
  std::vector<const void*> hull_faces; // finite faces made by convexify_hull
  if(why == nullptr && !hull_is_convex &&
     !internal::convexify_hull(tr, stack, hull_faces, stats.flips))
    why = "the hull is not a convex polygon wound once, and no flip of hull edges makes it one";
  if(why == nullptr && hull_is_convex && stats.edges_not_locally_delaunay > max_flips)
    why = internal::flip_budget_exhausted; // at least one flip per failing edge: see above
  if(why == nullptr) {
    std::vector<Face_handle> touched;
    if(internal::lawson_flip(tr, stack, max_flips, stats.flips, touched)) {
      stats.faces_certified = stats.faces_in - internal::count_distinct(touched, hull_faces);
      return stats;
    }
    why = internal::flip_budget_exhausted;
  }
  stats.fell_back = true;
  stats.fallback_reason = why;
  internal::rebuild_keeping_vertices(tr, stats);
  return stats;
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_2_H
