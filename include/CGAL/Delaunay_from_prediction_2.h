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
#include <CGAL/Delaunay_from_prediction/internal/repair/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/t_division_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/import/tds_certify.h>

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
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;

  Statistics stats;
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t number_of_faces = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  stats.faces_in = number_of_faces;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(n));
  const bool screen = choose_parameter(get_parameter(np, internal_np::screen_prediction), true);
  const Strategy strategy = choose_parameter(get_parameter(np, internal_np::strategy), Strategy::automatic);
  const std::size_t region_size = choose_parameter(
      get_parameter(np, internal_np::region_size),
      strategy == Strategy::regions ? internal::default_prediction_region_size(n, parallel ? internal::available_threads() : 1)
                                    : internal::default_region_size(n));
  const auto& gt = dt.geom_traits();
  const Tuning tuning = choose_parameter(get_parameter(np, internal_np::tuning), Tuning());
  auto visitor_value = choose_parameter<Default_visitor>(get_parameter(np, internal_np::visitor));
  auto& visitor = internal::unwrap_visitor(visitor_value);

  // Check, then import and certify into a fresh triangulation (Invalid_prediction is thrown
  // before `dt` is touched).
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    // Inexact predicates (internal/toolbox/predicates.h): the faces are only checked (malformed
    // ones throw), the faces are decided by exact predicates (rebuild.h).
    visitor.stage_begin(Stage::check);
    internal::check_points_are_finite(point_at, n);
    std::size_t k = 0, idx[3];
    for(const auto& face : faces)
      internal::read_face(face, k++, n, idx);
    visitor.stage_end(Stage::check);
    visitor.stage_begin(Stage::rebuild);
    DT built(gt);
    internal::build_with_exact_predicates(built, point_at, n, stats);
    dt.swap(built);
    visitor.stage_end(Stage::rebuild);
    return stats;
  }
  constexpr bool default_flip_budget = parameters::is_default_parameter<NamedParameters, internal_np::max_flips_t>::value;
  return internal::delaunay_from_index_triples(point_at, n, faces, number_of_faces, dt, max_flips, default_flip_budget,
                                               screen, strategy, region_size, stats, parallel, tuning, visitor);
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
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Face_handle = typename Triangulation::Face_handle;

  Statistics stats;
  stats.faces_in = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(tr.number_of_vertices()));
  const Strategy strategy = choose_parameter(get_parameter(np, internal_np::strategy), Strategy::automatic);
  const Tuning tuning = choose_parameter(get_parameter(np, internal_np::tuning), Tuning());
  auto visitor_value = choose_parameter<Default_visitor>(get_parameter(np, internal_np::visitor));
  auto& visitor = internal::unwrap_visitor(visitor_value);
  if(tr.number_of_vertices() == 0)
    return stats;
  visitor.stage_begin(Stage::check);
  internal::check_vertices_are_finite(tr); // throws before `tr` is touched
  visitor.stage_end(Stage::check);
  // Inexact predicates (internal/toolbox/predicates.h): flips, walks and certificates could
  // cycle or corrupt; the faces are rebuilt around the same vertices, decided by exact predicates.
  if constexpr(internal::decides_by_exact_predicates<typename Triangulation::Geom_traits>::value) {
    stats.fell_back = true;
    stats.outcome = Outcome::inexact_predicates;
    visitor.stage_begin(Stage::rebuild);
    internal::rebuild_keeping_vertices(tr, stats); // leaves `tr` as it is when it throws
    visitor.stage_end(Stage::rebuild);
    return stats;
  }

  const bool carve = strategy == Strategy::automatic || strategy == Strategy::carve;
  const bool divide = strategy == Strategy::t_division;
  const std::size_t region_size = choose_parameter(
      get_parameter(np, internal_np::region_size),
      strategy == Strategy::regions
          ? internal::default_prediction_region_size(tr.number_of_vertices(),
                                                               parallel ? internal::available_threads() : 1)
          : internal::default_region_size(tr.number_of_vertices()));
  // With `parallel`, a rebuild builds aside in blocks (block_parallel_build.h).
  const std::size_t blocks = parallel ? internal::default_block_count(tr.number_of_vertices(),
                                                                      internal::available_threads(), tuning)
                                      : 1;
  auto build_aside_in_blocks = [&](auto& aside, auto points, std::size_t n) {
    Statistics ignored;
    return blocks > 1 && internal::build_in_blocks(aside, points, n, ignored, blocks);
  };
  if(strategy == Strategy::regions && tr.dimension() == 2 && tr.number_of_vertices() < std::size_t(internal::no_region)) {
    // Theorem 5.4 in practical form (prediction_regions_build.h): the faces of `tr` are the
    // prediction; the triangulation is built aside by regions, then put on the same vertices.
    internal::rebuild_by_prediction_regions(tr, region_size, stats, parallel, build_aside_in_blocks, visitor);
    return stats;
  }

  std::vector<std::pair<Face_handle, int>> stack;
  std::vector<Face_handle> bad;
  bool hull_is_convex = false;
  const std::size_t max_bad = internal::default_carve_limits(tr.number_of_vertices()).max_bad_faces;
  // Every flip until the triangulation is certified again (inline, untangling) is logged: if
  // the rebuild below finds two vertices at the same point, they are undone before it
  // throws, so that `tr` is left as it was (a carve rolled back updates the log).
  internal::Flip_log<Triangulation> flips_before_carve;
  std::vector<Face_handle> touched;
  // Lawson's flips start during certification, except for the t-division, which plans its
  // regions from the edges that fail in the prediction as given, and in parallel, where the
  // faces are only read while they are certified, block by block (tds_certify.h).
  const bool flip_inline = !divide && !parallel;
  internal::Inline_flips<Triangulation> inline_flips{max_flips, stats.flips, touched, flips_before_carve};
  Outcome why = Outcome::rebuild_requested; // Strategy::rebuild, spanning_tree: the prediction is not used
  if(strategy != Strategy::rebuild && strategy != Strategy::spanning_tree) {
    visitor.stage_begin(Stage::certify);
    if((carve || divide) && internal::inverted_faces_exceed_early(tr, max_bad)) {
      why = Outcome::too_many_inverted_faces; // told from a sample, before any test or flip (tds_certify.h)
    } else if(parallel) {
      why = internal::certify_faces_in_blocks(tr, stack, stats.edges_tested, carve || divide ? &bad : nullptr, max_bad);
      hull_is_convex = why == Outcome::ok && internal::hull_is_convex_and_wound_once(tr);
    } else {
      why = internal::certify_triangulation(tr, stack, stats.edges_tested, hull_is_convex,
                                            carve || divide ? &bad : nullptr, max_bad,
                                            flip_inline ? &inline_flips : nullptr);
    }
    visitor.stage_end(Stage::certify);
  }
  if(why == Outcome::ok)
    stats.edges_not_locally_delaunay = flip_inline ? inline_flips.edges_failing : stack.size();
  // Lawson needs at least a flip per failing edge: past the budget, the flips are wasted.
  if(why == Outcome::ok && stats.edges_not_locally_delaunay > max_flips)
    why = Outcome::flip_budget_exhausted;
  // Faces that are not ccw: first untangled by flips, then the rest carved (carve_repair.h).
  if(why == Outcome::ok && divide) {
    // Theorem 2.1 (t_division_repair.h). If it does not pay or cannot be planned, `tr` is
    // untouched and the carve takes over; if the flip budget runs out, `tr` is a valid
    // triangulation of the same vertices, rebuilt below.
    std::unique_ptr<internal::T_division_repair<Triangulation>> regions;
    std::vector<const void*> modified;
    visitor.stage_begin(Stage::t_division);
    why = internal::repair_by_t_division(tr, regions, bad, hull_is_convex, stack, true, region_size,
                                      tuning.t_division_budget_factor, modified, stats, true, [](auto, auto) {
                                        CGAL_assertion_msg(false, "duplicates were ruled out before");
                                      });
    visitor.stage_end(Stage::t_division);
    if(why == Outcome::ok) {
      // Reinserted points make a few flips each, as in any incremental construction: they
      // count on top of the budget for the repair of the prediction.
      visitor.stage_begin(Stage::flips);
      const bool flipped = internal::lawson_flip(tr, stack, max_flips + 4 * regions->detached().size(), stats.flips,
                                                 touched, parallel);
      visitor.stage_end(Stage::flips);
      if(flipped) {
        stats.faces_certified = stats.faces_in - stats.faces_carved -
                                internal::count_distinct_addresses<typename Triangulation::Face>(
                                    modified, touched, 0, [&](const void* f) { return !regions->is_created(f); });
        return stats;
      }
      why = Outcome::flip_budget_exhausted;
    } else {
      // Not worth dividing, or no plan: `tr` is untouched, the carve below takes over.
      why = Outcome::ok;
    }
  }
  if(why == Outcome::ok && !bad.empty()) {
    const std::size_t inline_flipped = flips_before_carve.size();
    visitor.stage_begin(Stage::untangle);
    internal::untangle_by_flips(tr, bad, stack, flips_before_carve, touched, parallel);
    visitor.stage_end(Stage::untangle);
    stats.flips += flips_before_carve.size() - inline_flipped;
    if(!bad.empty()) {
      why = internal::carve_in_place(tr, bad, stack, touched, flips_before_carve, max_flips, stats, parallel, visitor);
      if(why == Outcome::ok)
        return stats;
      if(why == Outcome::flip_budget_exhausted)
        flips_before_carve.clear(); // the carve was committed: a triangulation again, nothing to undo
    }
  }
  if(why == Outcome::ok) {
    visitor.stage_begin(Stage::flips);
    std::vector<const void*> hull_faces; // finite faces made by convexify_hull
    if(!hull_is_convex && !internal::convexify_hull(tr, stack, hull_faces, stats.flips)) {
      why = Outcome::hull_not_convex;
    } else if(internal::lawson_flip(tr, stack, max_flips, stats.flips, touched, parallel)) {
      stats.faces_certified = stats.faces_in - internal::count_distinct(touched, hull_faces);
      visitor.stage_end(Stage::flips);
      return stats;
    } else {
      why = Outcome::flip_budget_exhausted;
      flips_before_carve.clear(); // a triangulation again: no duplicates, nothing to undo
    }
    visitor.stage_end(Stage::flips);
  }
  stats.fell_back = true;
  stats.outcome = why;
  stats.faces_certified = 0;
  stats.points_reinserted = 0;
  visitor.stage_begin(Stage::rebuild);
  try {
    internal::rebuild_keeping_vertices(tr, stats, build_aside_in_blocks); // leaves `tr` as it is when it throws
  } catch(const Invalid_prediction&) {
    internal::undo_flips(tr, flips_before_carve);
    throw;
  }
  visitor.stage_end(Stage::rebuild);
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_2_H
