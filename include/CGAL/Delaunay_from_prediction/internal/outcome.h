// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The outcome of every stage that may give up on a prediction (import, certification,
// repairs, flips, the spanning-tree engine), and the sentence a user reads for it in
// Statistics::fallback_reason. One list, so that code and tests compare outcomes, not text.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_OUTCOME_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_OUTCOME_H

#include <cstddef>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

enum class Outcome {
  ok, // the stage succeeded
  // Chosen by the caller or the traits.
  rebuild_requested,
  spanning_tree_requested,
  inexact_predicates,
  // The prediction, as the import reads it.
  too_many_indices,
  no_faces,
  screen_rejected,
  too_many_holes,
  holes_or_not_a_triangulation,
  degenerate_face,
  too_many_degenerate_faces,
  overlapping_faces,
  too_many_overlapping_faces,
  boundary_pinched,
  boundary_not_closed,
  boundary_with_holes,
  boundary_not_convex,
  // A CGAL triangulation (make_delaunay).
  dimension_below_2,
  inverted_face,
  too_many_inverted_faces,
  hull_not_convex,
  // The local repair (carve).
  damage_over_budget,
  holes_kept_growing,
  hole_over_budget,
  outer_boundary_not_ccw,
  carve_not_a_triangulation,
  duplicate_points,
  // The t-division repair.
  t_division_over_budget,
  bad_regions_too_large,
  boundary_vertices_collinear,
  every_region_bad,
  kept_faces_repeated,
  kept_faces_do_not_fit,
  // The build by the prediction's regions.
  too_few_regions,
  regions_interleave,
  regions_do_not_fit,
  // Flips.
  flip_budget_exhausted,
  too_many_failing_edges,
  // The spanning-tree engine.
  graph_too_many_components,
  tree_walks_missing,
  graph_edges_too_long,
  count_
};

// Statistics::fallback_reason of each outcome, in the order of Outcome. An inline variable:
// one array in the whole program, so that a reason can also be compared by address.
inline constexpr const char* fallback_reasons[] = {
    "",
    "the rebuild strategy was chosen",
    "the spanning_tree strategy was chosen",
    "the traits' predicates are not exact: the faces are decided by exact predicates on double coordinates",
    "too many points or faces for 32-bit indices",
    "there are no faces",
    "most sampled faces have sampled points inside their circumcircles",
    "too many holes for a local repair",
    "the faces leave holes, or do not form a triangulation of their vertices",
    "a face is degenerate (its points are collinear or equal)",
    "too many faces are degenerate",
    "two faces lie on the same side of an edge (overlapping or repeated faces)",
    "too many faces lie on the same side of an edge as others",
    "the boundary of the faces pinches at a vertex (not a single polygon)",
    "the boundary of the faces is not closed",
    "the boundary of the faces has several components (holes)",
    "the boundary of the faces is not a convex polygon wound once",
    "the triangulation has dimension below 2",
    "a face is inverted or flat",
    "too many faces are inverted or flat for a local repair",
    "the hull is not a convex polygon wound once, and no flip of hull edges makes it one",
    "the damage exceeds the budget of the local repair",
    "holes kept growing past the budget of the local repair",
    "a hole is larger than the budget of the local repair",
    "the outer boundary of the kept faces is not counterclockwise",
    "the kept faces and the filled holes do not form a triangulation",
    "two vertices are at the same point",
    "the damage would make the t-division cost more than a rebuild",
    "the bad regions of the t-division are too large for a local repair",
    "the boundary vertices of the t-division are collinear",
    "every region of the t-division is bad",
    "two kept faces have the same vertices",
    "the kept faces do not fit the triangulation of the boundary vertices",
    "the prediction is too small to be divided into regions",
    "the prediction's regions interleave too much to be triangulated apart",
    "the triangulations of the prediction's regions do not fit together",
    "the flip budget was exhausted",
    "the edges failing the in-circle test would need more flips than the budget",
    "the graph has too many components to guide the insertion",
    "the walks along the spanning tree kept missing",
    "the graph's edges are far longer than the spacing of the points",
};
static_assert(sizeof(fallback_reasons) / sizeof(fallback_reasons[0]) == std::size_t(Outcome::count_),
              "one reason per outcome");

inline const char* fallback_reason(Outcome outcome) { return fallback_reasons[std::size_t(outcome)]; }

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_OUTCOME_H
