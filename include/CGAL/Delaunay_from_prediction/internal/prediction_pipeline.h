// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The pipeline of delaunay_from_prediction() for a prediction given as index triples: import
// and certification, local repair, Lawson's flips seeded with the failing edges, insertion of the
// points no face uses, and the fallback to a build from scratch.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PREDICTION_PIPELINE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PREDICTION_PIPELINE_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/import/import_prediction.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/check/prediction_screens.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/build/prediction_regions_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/t_division_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The visitor given as a named parameter (visitor.h): the copy the chain holds, or the object
// of a std::reference_wrapper.
template <class Visitor>
Visitor& unwrap_visitor(Visitor& visitor)
{
  return visitor;
}
template <class Visitor>
Visitor& unwrap_visitor(std::reference_wrapper<Visitor> visitor)
{
  return visitor.get();
}

// The screens that reject the prediction `triples` before its import (Stage::screen):
// Outcome::ok when none does. Faces missing, told by counting (see missing_faces_exceed()):
// past n/8 the local repair (`carve`) would not pay; without it, past n/64 the faces cannot
// be a triangulation (any excess shows that, the margin keeps the count off the common case
// of about 2n faces).
template <class Gt, class PointIterator>
Outcome screen_outcome(const Gt& gt, PointIterator point_at, std::size_t n, const std::vector<std::uint32_t>& triples,
                       bool screen, bool default_flip_budget, std::size_t max_failing, bool carve)
{
  if(screen && fails_sampling_screen(gt, point_at, n, triples))
    return Outcome::screen_rejected;
  if(screen && default_flip_budget && failing_edges_exceed(point_at, n, triples, max_failing))
    return Outcome::too_many_failing_edges;
  if(missing_faces_exceed(gt, point_at, n, triples, carve ? n / 8 + 16 : n / 64 + 16))
    return carve ? Outcome::too_many_holes : Outcome::holes_or_not_a_triangulation;
  return Outcome::ok;
}

// make_delaunay() with Strategy::regions on `tr` (dimension 2): its faces are the prediction;
// the triangulation is built aside by regions (prediction_regions_build.h), then put on the same
// vertices. When the regions do not fit, `build_aside(aside, points, n)` (a build by blocks, or
// false), then the insertion, build it from scratch: a fallback. Throws as
// rebuild_keeping_vertices(), leaving `tr` as it is. `visitor` is told of Stage::regions, then
// of Stage::rebuild if the regions did not fit.
template <class Triangulation, class BuildAside, class Visitor>
void rebuild_by_prediction_regions(Triangulation& tr, std::size_t region_size, Statistics& stats, bool parallel,
                                   const BuildAside& build_aside, Visitor& visitor)
{
  std::vector<std::uint32_t> triples;
  visitor.stage_begin(Stage::regions);
  internal::finite_faces_as_index_triples(tr, triples);
  Outcome why = Outcome::ok;
  internal::rebuild_keeping_vertices(tr, stats, [&](auto& aside, auto points, std::size_t n) {
    Statistics built;
    why = internal::build_by_prediction_regions(aside, points, n, triples, region_size, built, parallel);
    stats.regions = built.regions;
    stats.boundary_vertices = built.boundary_vertices;
    std::vector<std::uint32_t>().swap(triples);
    if(why == Outcome::ok)
      return true;
    visitor.stage_end(Stage::regions);
    visitor.stage_begin(Stage::rebuild);
    return build_aside(aside, points, n);
  });
  visitor.stage_end(why == Outcome::ok ? Stage::regions : Stage::rebuild);
  if(why != Outcome::ok) {
    stats.fell_back = true;
    stats.outcome = why;
  }
}

// delaunay_from_prediction() for traits with exact predicates, on the points point_at[0..n)
// and the faces: check the points and the index triples (a non-finite point or a malformed face
// throws before `dt` changes), import and certify them, repair locally (carve, t-division),
// flip, insert the unused points; a build from scratch when a stage gives up (with `parallel`,
// by regions: block_parallel_build.h, as `tuning` says). `stats` comes with faces_in set.
// `visitor` is told of each stage as it begins and ends (visitor.h), on this thread.
// The failing edges past which Lawson's flips would exceed `max_flips`: each failing edge
// needs a flip, and the cascades they start more. Measured on the rho model's predictions with
// both completions and on random flips of DT(P) (bench_d_cross, 1e5 points), Lawson made 1.35
// to 2.6 flips per failing edge; the least ratio is used, so that a prediction is rebuilt at
// once only when its flips would almost surely run out. For the default budget only.
inline std::size_t max_failing_edges(std::size_t max_flips)
{
  return max_flips == std::size_t(-1) ? max_flips : std::size_t(double(max_flips) / 1.35);
}

template <class PointIterator, class FaceRange, class DT, class Visitor>
Statistics delaunay_from_index_triples(PointIterator point_at, std::size_t n, const FaceRange& faces,
                                       std::size_t number_of_faces, DT& dt, std::size_t max_flips,
                                       bool default_flip_budget, bool screen,
                                       Strategy strategy, std::size_t region_size, Statistics stats,
                                       bool parallel, const Tuning& tuning, Visitor& visitor)
{
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  const bool carve = strategy == Strategy::automatic || strategy == Strategy::carve ||
                     strategy == Strategy::t_division;
  // A budget the caller set is a hard limit: more failing edges than flips rebuild at once.
  // The default one is an estimate of what pays, and so is the rebuild at once when the
  // failing edges would exhaust it (max_failing_edges()), told from the first eighth of the
  // import on, or before it from samples of the faces (failing_edges_exceed()).
  const std::size_t max_failing = default_flip_budget ? max_failing_edges(max_flips) : max_flips;
  const auto& gt = dt.geom_traits();
  DT result(gt);
  internal::Imported_prediction<DT> imported;
  // Stage 1: the points checked finite, every face validated once, into 32-bit triples (a
  // malformed face throws here).
  visitor.stage_begin(Stage::check);
  internal::check_points_are_finite(point_at, n);
  std::vector<std::uint32_t> triples;
  const bool fits = internal::read_index_triples(faces, n, number_of_faces, triples, parallel);
  visitor.stage_end(Stage::check);
  // Stage 2: the screens, then the import.
  if(strategy == Strategy::rebuild || strategy == Strategy::spanning_tree)
    imported.failure = strategy == Strategy::rebuild ? Outcome::rebuild_requested : Outcome::spanning_tree_requested;
  else if(!fits)
    imported.failure = Outcome::too_many_indices;
  else if(number_of_faces == 0)
    imported.failure = Outcome::no_faces;
  else if(strategy == Strategy::regions) {
    // Theorem 5.4 in practical form (prediction_regions_build.h): a build, not a repair.
    visitor.stage_begin(Stage::regions);
    imported.failure = internal::build_by_prediction_regions(result, point_at, n, triples, region_size, stats, parallel);
    visitor.stage_end(Stage::regions);
    if(imported.failure == Outcome::ok) {
      dt.swap(result);
      return stats;
    }
  } else {
    visitor.stage_begin(Stage::screen);
    imported.failure = screen_outcome(gt, point_at, n, triples, screen, default_flip_budget, max_failing, carve);
    visitor.stage_end(Stage::screen);
    if(imported.failure == Outcome::ok)
      internal::Prediction_importer<DT>::run(result, point_at, n, triples, imported, carve, parallel, visitor,
                                             default_flip_budget ? max_failing : std::size_t(-1));
  }

  // The global fallback, a build from scratch: in spatial order, or, with
  // Strategy::spanning_tree, along a spanning tree of the faces' edges (Corollaries 3.4 and
  // 3.5). Measured at 1e6 points on predictions that fall back (points moved by 0.3 to 1
  // spacing, 1% of the points relabelled, random triples; bench_fallback.cpp), the spatial
  // order was as fast to 26% faster: the default.
  auto build_from_scratch = [&](Outcome why) {
    visitor.stage_begin(Stage::rebuild);
    stats.fell_back = true;
    stats.faces_certified = 0;
    stats.points_reinserted = 0;
    // The rebuild counts every duplicate again: those the local repair merged before it gave
    // up are not in the fresh triangulation's count yet.
    stats.duplicate_points = 0;
    result.tds().clear(); // release the partial import before building anew
    const std::vector<std::uint32_t> grid_order = std::move(imported.points_in_grid_order);
    imported = internal::Imported_prediction<DT>();
    DT fresh(gt);
    if(strategy != Strategy::spanning_tree || !fits || n >= std::size_t(internal::no_rank)) {
      std::vector<std::uint32_t>().swap(triples); // not needed: keep the peak memory down
      const std::size_t blocks = parallel ? internal::default_block_count(n, internal::available_threads(), tuning) : 1;
      if(blocks < 2 || !internal::build_in_blocks(fresh, point_at, n, stats, blocks))
        internal::build_from_scratch(fresh, point_at, n, stats, grid_order);
    } else {
      // Two edges of each face keep its three corners connected (`triples` is still as read:
      // the import, which reorders it, did not run).
      std::vector<std::uint32_t> ends;
      ends.reserve(4 * number_of_faces);
      for(std::size_t t = 0; t < triples.size(); t += 3)
        ends.insert(ends.end(), {triples[t], triples[t + 1], triples[t + 1], triples[t + 2]});
      std::vector<std::uint32_t>().swap(triples);
      internal::build_along_edges(fresh, point_at, n, ends, stats);
    }
    stats.outcome = why;
    dt.swap(fresh);
    visitor.stage_end(Stage::rebuild);
    return stats;
  };
  stats.input_reordered = imported.reordered;
  if(imported.failure != Outcome::ok)
    return build_from_scratch(imported.failure);
  stats.edges_tested = imported.edges_tested;
  stats.edges_not_locally_delaunay = imported.not_locally_delaunay.size();
  stats.faces_carved = imported.faces_dropped;
  // Small holes the import filled itself count as the first round of the local repair.
  stats.holes_refilled = imported.holes_filled;
  stats.carve_rounds = imported.holes_filled > 0 ? 1 : 0;
  auto filled_by_import = [&](const void* f) {
    return std::binary_search(imported.filled_faces.begin(), imported.filled_faces.end(), f);
  };

  // Repair. Each failing edge is not Delaunay and a flip removes one edge, so Lawson's
  // algorithm needs at least as many flips as there are failing edges, and in practice more
  // (max_failing_edges()): past the budget, the flips would be wasted.
  if(imported.not_locally_delaunay.size() > max_failing)
    return build_from_scratch(default_flip_budget ? Outcome::too_many_failing_edges : Outcome::flip_budget_exhausted);
  std::vector<std::pair<Face_handle, int>>& stack = imported.not_locally_delaunay;
  std::vector<const void*> modified; // predicted faces changed by the repair
  std::unique_ptr<internal::Carve_repair<DT>> repair;
  // Tracing and filling holes costs about 2 us per boundary half-edge at 1e6 points (measured:
  // 1% of a DT's faces deleted, 60,000 such half-edges, 0.12 s, before the import filled the
  // small holes itself; these are the half-edges it left), a rebuild about 0.75 us per
  // point: past n/4 of them the repair would cost more than the rebuild it avoids.
  if(imported.needs_repair && imported.open_halfedges.size() > n / 4 + 64)
    return build_from_scratch(Outcome::too_many_holes);
  if(imported.needs_repair) {
    // The faces kept are not a triangulation with a convex hull: fill the holes and close
    // the hull (carve_repair.h); vertices left without a face are reinserted.
    visitor.stage_begin(Stage::carve);
    repair.reset(new internal::Carve_repair<DT>(result, false));
    repair->expect_outer_cycle();
    // Faces that overlap without sharing an edge on one side (none left out) still meet at a
    // vertex in several fans: a vertex of a carved star may keep a closed fan elsewhere.
    repair->expect_several_fans();
    if(imported.faces_dropped > 0) // faces overlapped: some may still overlap unseen
      internal::carve_vertices_wound_twice(result, *repair);
    for(const auto& e : imported.open_halfedges)
      repair->add_open_halfedge(e.first, e.second);
    const Outcome why = repair->plan(internal::default_carve_limits(n));
    stats.carve_rounds = (std::max)(stats.carve_rounds, repair->rounds());
    if(why != Outcome::ok) {
      visitor.stage_end(Stage::carve);
      return build_from_scratch(why);
    }
    repair->commit(stack);
    if(!repair->finish_hull(stack, stats.flips)) {
      visitor.stage_end(Stage::carve);
      return build_from_scratch(Outcome::carve_not_a_triangulation);
    }
    std::size_t duplicates = 0;
    repair->reinsert(stack, modified, [&](Vertex_handle v, Vertex_handle same) {
      internal::merge_index_info_of(same, v);
      result.tds().delete_vertex(v);
      ++duplicates;
    });
    // Faces the import filled holes with are not predicted faces, carved or modified.
    modified.erase(std::remove_if(modified.begin(), modified.end(), filled_by_import), modified.end());
    std::size_t filled_removed = 0;
    for(const void* f : imported.filled_faces)
      filled_removed += repair->is_removed(f) ? 1 : 0;
    stats.faces_carved += repair->faces_removed() - filled_removed;
    stats.holes_refilled += repair->holes();
    stats.points_reinserted = repair->detached().size();
    stats.duplicate_points += duplicates;
    visitor.stage_end(Stage::carve);
  }
  std::unique_ptr<internal::T_division_repair<DT>> regions;
  if(strategy == Strategy::t_division) {
    visitor.stage_begin(Stage::t_division);
    std::size_t duplicates = 0;
    const Outcome why = internal::repair_by_t_division(
        result, regions, std::vector<Face_handle>(), true, stack, !repair, region_size,
        tuning.t_division_budget_factor, modified, stats, false,
        [&](Vertex_handle v, Vertex_handle same) {
          internal::merge_index_info_of(same, v);
          result.tds().delete_vertex(v);
          ++duplicates;
        },
        [&](const void* f) { return (repair && repair->is_created(f)) || filled_by_import(f); });
    // When the t-division does not pay (or cannot be planned), `result` is untouched: a
    // valid triangulation after the carve, which the flips finish as with Strategy::carve.
    if(why != Outcome::ok)
      regions.reset();
    stats.duplicate_points += duplicates;
    visitor.stage_end(Stage::t_division);
  }
  auto made_by_repair = [&](const void* f) {
    return (repair && repair->is_created(f)) || (regions && regions->is_created(f)) || filled_by_import(f);
  };
  std::vector<Face_handle> touched;
  // Points reinserted by the t-division make a few flips each, on top of the budget.
  const std::size_t flip_budget = max_flips + (regions ? 4 * regions->detached().size() : 0);
  visitor.stage_begin(Stage::flips);
  const bool flipped = internal::lawson_flip(result, stack, flip_budget, stats.flips, touched, parallel);
  visitor.stage_end(Stage::flips);
  if(!flipped)
    return build_from_scratch(Outcome::flip_budget_exhausted);

  // Points no face uses: duplicates of vertices, or points to insert.
  std::vector<std::size_t>& unused = imported.unused_points;
  stats.points_unused = unused.size();
  // Statistics::faces_certified: predicted faces never modified. Faces are told apart by
  // address, and a repair recycles the objects of the faces it destroys, so the faces the
  // stages made or changed are recorded as they go (filled_faces, is_created(), `modified`,
  // `touched`): a count at the end by vertex triples would need all 2n predicted triples
  // in a table (make_delaunay() would have to copy them first), a cost on every call.
  if(unused.empty() && !repair && !regions && imported.filled_faces.empty()) {
    stats.faces_certified = result.number_of_faces() - internal::count_distinct(touched);
  } else if(unused.empty() && !regions) {
    // The predicted faces kept, less those the repair modified (flipped, or split by a
    // reinserted vertex); the faces it made are not predicted faces.
    stats.faces_certified = number_of_faces - stats.faces_carved -
                            internal::count_distinct_addresses<typename DT::Face>(
                                modified, touched, 0, [&](const void* f) { return !made_by_repair(f); });
  } else {
    // A predicted face survives if it was never flipped, is not one a repair made (the
    // t-division may also remove faces the carve made: counted here, not subtracted), and has
    // no new vertex (insertion recycles the faces it destroys for faces around the new
    // vertex).
    for(const Face_handle f : touched)
      modified.push_back(&*f);
    internal::sort_unique_addresses(modified);
    std::vector<const void*> new_vertices;
    if(!unused.empty()) {
      visitor.stage_begin(Stage::insert);
      internal::insert_points(result, point_at, unused, stats, &new_vertices);
      visitor.stage_end(Stage::insert);
    }
    std::sort(new_vertices.begin(), new_vertices.end());
    auto is_new = [&](const Vertex_handle v) {
      return std::binary_search(new_vertices.begin(), new_vertices.end(), static_cast<const void*>(&*v));
    };
    stats.faces_certified = 0;
    for(auto f = result.finite_faces_begin(); f != result.finite_faces_end(); ++f)
      if(!std::binary_search(modified.begin(), modified.end(), static_cast<const void*>(&*f)) &&
         !made_by_repair(&*f) && !is_new(f->vertex(0)) && !is_new(f->vertex(1)) &&
         !is_new(f->vertex(2)))
        ++stats.faces_certified;
  }
  dt.swap(result);
  return stats;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PREDICTION_PIPELINE_H
