// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points: the Delaunay triangulation of points from a predicted triangulation
// (delaunay_from_prediction(), make_delaunay()). The pipeline they drive (check, import and
// certify, local repair, flips, fallback) and one line per internal file: the manual's
// section "Architecture".

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_2_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/in_place_stages.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/index_triples_stages.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt`, using `faces` as a prediction of it.

The result is exactly the triangulation CGAL's `Delaunay_triangulation_2` builds from the same
points: co-circular ties are broken by CGAL's symbolic perturbation. The time it takes depends
on how good the prediction is. When `faces` is a triangulation of the points, it is certified
in \f$O(n + h \log h)\f$ time (\f$h\f$ hull edges, sorted to check the hull) and repaired by
Lawson flips that start only at its non-locally-Delaunay edges;
points used by no face are then inserted. Any other prediction (degenerate, crossing, repeated
or overlapping faces, holes, faces missing at the hull) is not an error: the faces that cannot
be kept are left out or carved, the holes retriangulated and the vertices left without a face
reinserted, then the flips run (see the user manual, "Local Repair"). A prediction too damaged
for that to pay off is rebuilt from scratch (`Statistics::fell_back`).

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: see \ref dfpParallel for what runs on several threads.
        The result is the same triangulation whatever the tag and the number of threads.
\tparam PointRange a random-access range of `DT::Point`.
\tparam FaceRange a range whose elements `t` give three integer indices `t[0]`, `t[1]`, `t[2]`
        into `points` (for example `std::array<int, 3>` or `std::vector<std::size_t>`).
\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
        assignable from `std::size_t`, every vertex's `info()` is set to the index of its point
        (for duplicate points, the smallest of their indices). A `CGAL::Triangulation_hierarchy_2`
        of one is kept as \cgal keeps it: the package fills its level 0, then samples the upper
        levels anew, as the hierarchy's own insertion samples them.
\tparam NamedParameters a sequence of named parameters.

\param points the points.
\param faces the predicted triangles, in any orientation.
\param dt receives the result; cleared first.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the largest number of edge flips to make; past it the call finishes
      with a from-scratch build, so that its cost stays close to a rebuild even for a bad
      prediction or an inexact kernel that could make Lawson's algorithm cycle. A prediction
      with more edges failing the in-circle test than this is rebuilt at once (each needs a
      flip); with the default, one with more than the default over 1.35 (Lawson's least
      measured number of flips per failing edge), estimated before the import from samples of
      a face list in spatial order, or counted or extrapolated from the first eighth of the
      import}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{three quarters of the number of points, plus 64}
  \cgalParamNEnd
  \cgalParamNBegin{screen_prediction}
    \cgalParamDescription{whether to draw 32 faces and 16 points at random first, and to build
      from scratch at once if more than half of the faces have a drawn point inside their
      circumcircle (a prediction that far from Delaunay would cost more to repair than to
      rebuild); with the default flip budget, also whether to estimate the failing edges from
      samples of the face list before the import and rebuild at once when they would exceed
      the budget over 1.35. Only used for at least 4096 points and 4096 faces.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{strategy}
    \cgalParamDescription{how the prediction is used, see `Strategy`}
    \cgalParamType{`Strategy`}
    \cgalParamDefault{`Strategy::automatic`}
  \cgalParamNEnd
  \cgalParamNBegin{region_size}
    \cgalParamDescription{the size of a region, in faces, for `Strategy::t_division` (the t of
      the paper's Theorem 2.1) and `Strategy::regions` (the faces grown into one region of
      points); ignored by the other strategies}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`Strategy::t_division`: n/32 for n points, at least 64 and at most 4096;
      `Strategy::regions`: 2n / (2 max(2, threads)), at least 64, that is two regions per thread
      and at least four (threads: 1, or TBB's number of threads with `CGAL::Parallel_tag`)}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{told of each stage of the call (`Stage`) as it begins and ends, on the
      calling thread only; a copy is called, unless given as `std::ref(v)`}
    \cgalParamType{a class with `stage_begin(Stage)` and `stage_end(Stage)`, see `Default_visitor`}
    \cgalParamDefault{`Default_visitor()`, which does nothing}
  \cgalParamNEnd
  \cgalParamNBegin{tuning}
    \cgalParamDescription{measured thresholds, for experiments and tests (see `Tuning`); the
      result is the same whatever they are}
    \cgalParamType{`Tuning`}
    \cgalParamDefault{`Tuning()`, the measured values}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a point has a non-finite coordinate, or a face has an index out
        of range or repeats an index. Then `dt` is unchanged.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
is built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class FaceRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_prediction(const PointRange& points, const FaceRange& faces, DT& dt,
                                    const NamedParameters& np = parameters::default_values())
{
  internal::check_point_range_type<PointRange, typename DT::Point>();
  internal::check_face_range_type<FaceRange>();
  constexpr bool parallel = internal::runs_in_parallel<ConcurrencyTag>();
  if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(
        dt, [&](auto& level0) { return delaunay_from_prediction<ConcurrencyTag>(points, faces, level0, np); });
  } else { // not instantiated for a hierarchy
    auto point_at = internal::point_iterator<typename DT::Point>(points);
    const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
    const internal::Pipeline_options options = internal::read_pipeline_options(np, n, parallel);
    auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
    internal::Index_triples_stages<DT, decltype(point_at), FaceRange,
                                   internal::Compiled_paths_of<NamedParameters, parallel>>
        stages(
        point_at, n, faces, std::size_t(std::distance(std::begin(faces), std::end(faces))), dt, options);
    return internal::run_prediction_pipeline(stages, options, internal::unwrap_visitor(visitor));
  } // not a hierarchy
}

/*!
\ingroup PkgDelaunayFromPredictionRef
turns a CGAL triangulation into the Delaunay triangulation of its own vertices, in place.

The points of `tr` may have been moved with `Vertex::set_point()`, even so far that faces are
inverted or the dimension changes. Vertex handles and their `info()` survive; face handles need
not. A triangulation whose faces are all counterclockwise is certified in linear time; a
hull that is no longer convex is repaired by flips of hull edges; then Lawson flips start at
the non-locally-Delaunay edges. Inverted or flat faces are first untangled by flips where one
flip makes them counterclockwise; the stars of the vertices of those that remain are carved,
the holes retriangulated and the carved vertices reinserted (the same vertex objects), all in
place (see the user manual, "Local Repair"). Past the budgets (too many inverted faces, too
much carving, too many flips), or when moves change the dimension, its faces are rebuilt around
the same vertex objects (`Statistics::fell_back`). Too many inverted faces is foreseen before any
other work from the first 2,048 faces of the face container (from 8,192 faces on), and again
during the certification, so that heavy moves cost about a rebuild (`Outcome::too_many_inverted_faces`).
With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the faces are
always rebuilt around the same vertex objects, decided by exact predicates on the coordinates
rounded to double (`Statistics::fell_back`): see \ref dfpInexactKernels.

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: see \ref dfpParallel for what runs on several threads.
        The result is the same triangulation whatever the tag and the number of threads.
\tparam Triangulation a `CGAL::Triangulation_2<Gt, Tds>` or `CGAL::Delaunay_triangulation_2<Gt, Tds>`,
        for any triangulation data structure, or a `CGAL::Triangulation_hierarchy_2` of one (its
        level 0 is repaired in place, then its upper levels are sampled anew at the moved points).
\tparam NamedParameters a sequence of named parameters.

\param tr the triangulation.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the largest number of edge flips to make; past it the faces are
      rebuilt}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{three quarters of the number of vertices, plus 64}
  \cgalParamNEnd
  \cgalParamNBegin{strategy}
    \cgalParamDescription{how the triangulation is used, see `Strategy`}
    \cgalParamType{`Strategy`}
    \cgalParamDefault{`Strategy::automatic`}
  \cgalParamNEnd
  \cgalParamNBegin{region_size}
    \cgalParamDescription{the size of a region, in faces, for `Strategy::t_division` and
      `Strategy::regions`, as for `delaunay_from_prediction()`, with n the number of vertices;
      ignored by the other strategies}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{as for `delaunay_from_prediction()`}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{as for `delaunay_from_prediction()`}
    \cgalParamType{see `Default_visitor`}
    \cgalParamDefault{`Default_visitor()`}
  \cgalParamNEnd
  \cgalParamNBegin{tuning}
    \cgalParamDescription{as for `delaunay_from_prediction()`}
    \cgalParamType{`Tuning`}
    \cgalParamDefault{`Tuning()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a vertex has a non-finite coordinate, or if two vertices are at
        the same point, naming the vertex or both (by their rank in finite-vertex order). Then
        `tr` is unchanged.
*/
template <class ConcurrencyTag = Sequential_tag, class Triangulation,
          class NamedParameters = parameters::Default_named_parameters>
Statistics make_delaunay(Triangulation& tr, const NamedParameters& np = parameters::default_values())
{
  constexpr bool parallel = internal::runs_in_parallel<ConcurrencyTag>();
  if constexpr(internal::is_triangulation_hierarchy<Triangulation>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(tr, [&](auto& level0) { return make_delaunay<ConcurrencyTag>(level0, np); });
  } else { // not instantiated for a hierarchy
    const internal::Pipeline_options options = internal::read_pipeline_options(np, tr.number_of_vertices(), parallel);
    auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
    internal::In_place_stages<Triangulation, internal::Compiled_paths_of<NamedParameters, parallel>> stages(tr,
                                                                                                      options);
    return internal::run_prediction_pipeline(stages, options, internal::unwrap_visitor(visitor));
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_2_H
