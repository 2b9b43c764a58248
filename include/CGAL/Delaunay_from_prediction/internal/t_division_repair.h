// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Strategy::t_division of delaunay_from_prediction() and make_delaunay() (Theorem 2.1 of the
// paper): the bad regions of a t-division replaced and their inner vertices reinserted, when that
// costs less than a rebuild.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_T_DIVISION_REPAIR_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_T_DIVISION_REPAIR_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/duplicate_vertices.h>
#include <CGAL/Delaunay_from_prediction/internal/outcome.h>
#include <CGAL/Delaunay_from_prediction/internal/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/region_repair.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Budget of Strategy::t_division for n vertices, in point insertions (|V_B| plus four times
// the vertices to reinsert, see Region_repair::plan()): about a rebuild, n times this
// factor. A knob for tests only (one object in the whole program, set at run time), which
// raise it to reach the repair on small, badly damaged inputs.
inline double& t_division_budget_factor()
{
  static double factor = 1;
  return factor;
}
inline std::size_t t_division_budget(std::size_t n)
{
  const double budget = t_division_budget_factor() * double(n);
  const double most = double(std::size_t(-1) / 4);
  return budget < most ? std::size_t(budget) : std::size_t(-1) / 4;
}

// Strategy::t_division on the valid triangulation `tr` (region_repair.h): the faces in `bad`
// are not counterclockwise; the failing edges are those of `stack` (when `stack_fails`), or
// those of its edges that fail the in-circle test. Replaces the bad regions and reinserts
// their inner vertices, leaving the flips to the caller; returns Outcome::ok then, otherwise why not
// with `tr` untouched. With `check_duplicates`, returns first if a vertex to reinsert is at
// the point of another; otherwise `on_duplicate(v, w)` handles it as in reinsert_vertex_objects().
template <class Triangulation, class OnDuplicate, class MadeEarlier = bool (*)(const void*)>
Outcome repair_by_regions(Triangulation& tr, std::unique_ptr<Region_repair<Triangulation>>& regions,
                              const std::vector<typename Triangulation::Face_handle>& bad, bool hull_is_convex,
                              std::vector<std::pair<typename Triangulation::Face_handle, int>>& stack,
                              bool stack_fails, std::size_t region_size, std::vector<const void*>& modified,
                              Statistics& stats, bool check_duplicates, OnDuplicate on_duplicate,
                              MadeEarlier made_earlier = [](const void*) { return false; })
{
  const std::size_t n = tr.number_of_vertices();
  const auto& gt = tr.geom_traits();
  const auto infinite = tr.infinite_vertex();
  std::vector<std::pair<typename Triangulation::Face_handle, int>> failing;
  for(const auto& e : stack) {
    const auto f = e.first;
    const int i = e.second;
    const auto g = f->neighbor(i);
    if(f->has_vertex(infinite) || g->has_vertex(infinite))
      continue;
    if(stack_fails || !is_locally_delaunay(gt, f->vertex(i)->point(), f->vertex(ccw(i))->point(),
                                           f->vertex(cw(i))->point(), g->vertex(tr.tds().mirror_index(f, i))->point()))
      failing.push_back(e);
  }
  // m marks spread over the 2n/t regions spoil about m t / 2 faces and reinsert about 0.3 to
  // 0.45 m t points (measured at 1e5 and 1e6). Measured on top of the carve's own cost: about
  // 0.28 us per point for the division itself (regions, DT(V_B)) and 4.3 us per reinserted
  // point (1e5: 13,581 reinserted, 0.087 s more than the carve; 1e6: 13,134 reinserted, 0.34 s
  // more), against 0.75-0.86 us per point for a rebuild. Past m t = 0.15 n the division alone
  // would take the call past 1.1 times a rebuild (with the import of index triples, about 0.35
  // us per point, before it): say so before dividing, and let the carve finish.
  const std::size_t budget = t_division_budget(n);
  if(double(bad.size() + failing.size()) * double(region_size) > 0.15 * double(budget))
    return Outcome::t_division_over_budget;
  regions.reset(new Region_repair<Triangulation>(tr, region_size));
  for(const auto f : bad)
    regions->mark_bad_face(f);
  for(const auto& e : failing)
    regions->mark_failing_edge(e.first, e.second);
  if(!hull_is_convex)
    regions->mark_hull_if_not_convex();
  const Outcome why = regions->plan(budget);
  stats.regions = regions->regions();
  stats.bad_regions = regions->bad_regions();
  stats.boundary_vertices = regions->boundary_vertices();
  if(why != Outcome::ok)
    return why;
  if(check_duplicates && has_duplicate_of(tr, regions->detached()))
    return Outcome::duplicate_points;
  // Faces an earlier stage made (the carve's fill, the import's) are not predicted faces:
  // not counted as carved.
  stats.faces_carved += regions->faces_removed_if([&](const void* f) { return !made_earlier(f); });
  regions->commit(stack);
  regions->reinsert(stack, modified, on_duplicate);
  stats.holes_refilled += regions->holes();
  stats.points_reinserted += regions->detached().size();
  return Outcome::ok;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_T_DIVISION_REPAIR_H
