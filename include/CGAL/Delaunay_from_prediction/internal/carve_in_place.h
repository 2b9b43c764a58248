// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The local repair of make_delaunay() for faces that are not counterclockwise: the stars of
// their vertices carved, the holes filled, the vertices reinserted, then Lawson's flips.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CARVE_IN_PLACE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CARVE_IN_PLACE_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/duplicate_vertices.h>
#include <CGAL/Delaunay_from_prediction/internal/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/outcome.h>
#include <CGAL/Delaunay_from_prediction/internal/sort_addresses.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// make_delaunay's local repair of a triangulation with faces that are not counterclockwise
// (`bad`): carves the stars of their vertices, fills the holes, reinserts those vertices
// (same objects), then flips. Returns Outcome::ok on success; otherwise why not, with `tr` either
// as it was (the carve did not fit the budget, or the result would not be a triangulation:
// rolled back) or a valid triangulation of the same vertices (the flip budget ran out).
// Never throws for duplicates: it returns first, and the caller's rebuild names them.
template <class Triangulation>
Outcome carve_in_place(Triangulation& tr, const std::vector<typename Triangulation::Face_handle>& bad,
                           std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                           std::vector<typename Triangulation::Face_handle>& touched,
                           Flip_log<Triangulation>& flip_log, std::size_t max_flips, Statistics& stats)
{
  using Face_handle = typename Triangulation::Face_handle;
  Carve_repair<Triangulation> carve(tr, true);
  // A face inverted by moves usually has one vertex that crossed the opposite edge, the
  // longest one: carving that vertex's star leaves a simple hole (its old link) in most
  // cases, at a third of the faces of carving all three stars. Holes that are not simple are
  // widened by the rounds of plan(). Only the amount carved depends on this choice.
  for(const Face_handle f : bad) {
    int crossing = 0;
    double longest = -1;
    for(int i = 0; i < 3; ++i) {
      const auto& p = f->vertex(ccw(i))->point();
      const auto& q = f->vertex(cw(i))->point();
      // Halves and hypot: no overflow near 1e308, no underflow to 0 near the smallest
      // normal double (only the amount carved depends on it).
      const double length = std::hypot(CGAL::to_double(p.x()) / 2 - CGAL::to_double(q.x()) / 2,
                                       CGAL::to_double(p.y()) / 2 - CGAL::to_double(q.y()) / 2);
      if(length > longest) {
        longest = length;
        crossing = i;
      }
    }
    carve.carve_star(f->vertex(crossing));
  }
  Outcome why = carve.plan(default_carve_limits(tr.number_of_vertices()));
  stats.carve_rounds = carve.rounds();
  if(why != Outcome::ok)
    return why;
  if(has_duplicate_of(tr, carve.detached()))
    return Outcome::duplicate_points;
  carve.commit(stack);
  if(!carve.finish_hull(stack, stats.flips)) {
    carve.rollback(flip_log); // the flips before the carve can still be undone
    return Outcome::carve_not_a_triangulation;
  }
  std::vector<const void*> modified;
  carve.reinsert(stack, modified, [](auto, auto) {
    CGAL_assertion_msg(false, "duplicates were ruled out before the carve");
  });
  stats.faces_carved = carve.faces_removed();
  stats.holes_refilled = carve.holes();
  stats.points_reinserted = carve.detached().size();
  if(!lawson_flip(tr, stack, max_flips, stats.flips, touched))
    return Outcome::flip_budget_exhausted;
  // The predicted faces modified: those flipped (before the carve or after it) that were
  // neither carved nor made by the repair, and those insertion split.
  stats.faces_certified =
      stats.faces_in - stats.faces_carved -
      count_distinct_addresses<typename Triangulation::Face>(
          modified, touched, 0, [&](const void* f) { return !carve.is_removed(f) && !carve.is_created(f); });
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CARVE_IN_PLACE_H
