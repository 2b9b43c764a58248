// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The stages of the pipeline (prediction_pipeline.h) for delaunay_from_prediction(): a
// prediction given as index triples, checked, imported with its certificate into a fresh
// triangulation, repaired there, and swapped into the caller's only at the end.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_INDEX_TRIPLES_STAGES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_INDEX_TRIPLES_STAGES_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/prediction_regions_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/build/conflict_list_rounds.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/region_recursion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/supercells.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/check/prediction_screens.h>
#include <CGAL/Delaunay_from_prediction/internal/import/import_prediction.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/t_division_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <array>
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

template <class DT>
bool repair_region_completion(const typename DT::Geom_traits& gt, const std::vector<typename DT::Point>& points,
                              const std::vector<std::uint32_t>& triples, std::size_t budget,
                              std::vector<std::uint32_t>& out, std::size_t& work);

// The points point_at[0..n) and the faces `faces` (number_of_faces of them) into `dt`.
//
// Statistics::faces_certified counts the predicted faces never modified. Faces are told apart
// by address, and a repair recycles the objects of the faces it destroys, so the faces the
// stages make or change are recorded as they go (the import's filled faces, is_created(),
// `modified_`, `touched_`): a count at the end by vertex triples would need all 2n predicted
// triples in a table, a cost on every call. `CompiledPaths`: what the call compiles
// (Compiled_paths).
template <class DT, class PointIterator, class FaceRange, class CompiledPaths>
class Index_triples_stages
{
public:
  using Paths = CompiledPaths;
  // The `parallel` argument of the stages' functions: the call's, known at compile time.
  static constexpr Parallel_constant<Paths::parallel> parallel() { return {}; }
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  static constexpr bool decides_exactly = !decides_by_exact_predicates<typename DT::Geom_traits>::value;
  static constexpr bool screens = true; // screen() may give the prediction up

  Index_triples_stages(PointIterator point_at, std::size_t n, const FaceRange& faces, std::size_t number_of_faces,
                       DT& dt, const Pipeline_options& options)
      : point_at_(point_at), n_(n), faces_(faces), number_of_faces_(number_of_faces), dt_(dt), options_(options),
        result_(dt.geom_traits())
  {
    stats_.faces_in = number_of_faces;
  }

  Statistics& stats() { return stats_; }
  bool is_empty() const { return false; } // no points: the rebuild makes the empty triangulation

  // Every point finite, every face validated once into 32-bit triples (a malformed face
  // throws here, before `dt` changes).
  Outcome check()
  {
    check_points_are_finite(point_at_, n_);
    fits_ = read_index_triples(faces_, n_, number_of_faces_, triples_, parallel());
    return Outcome::ok;
  }

  Outcome reason_not_to_use_prediction() const
  {
    if(!options_.uses_prediction())
      return options_.strategy == Strategy::rebuild         ? Outcome::rebuild_requested
             : options_.strategy == Strategy::spanning_tree ? Outcome::spanning_tree_requested
                                                            : Outcome::section_3_requested;
    if(!fits_)
      return Outcome::too_many_indices;
    return number_of_faces_ == 0 ? Outcome::no_faces : Outcome::ok;
  }

  bool can_build_by_regions() const { return true; }

  Outcome build_by_regions()
  {
    const Outcome why = build_by_prediction_regions(result_, point_at_, n_, triples_, options_.region_size, stats_,
                                                    options_.parallel);
    if(why == Outcome::ok)
      dt_.swap(result_);
    return why;
  }

  // Theorem 4.1 (supercells.h): the prediction's faces replaced by the ones it computes, which
  // the import then certifies (the faces are kept when the points span no triangle).
  Outcome compute_by_supercells()
  {
    std::vector<std::uint32_t> computed;
    std::size_t kept = 0;
    if(n_ < std::size_t(no_rank) &&
       delaunay_faces_by_supercells(dt_.geom_traits(), point_at_, n_, triples_, computed, kept, stats_)) {
      triples_.swap(computed);
      number_of_faces_ = triples_.size() / 3;
      predicted_faces_kept_ = kept;
    }
    return Outcome::ok;
  }

  // Theorem 5.4 (region_recursion.h): the prediction's faces replaced by the completion G'
  // its recursion computes; the stages that follow are its step 6.
  Outcome compute_by_region_recursion()
  {
    if(n_ >= std::size_t(no_region))
      return Outcome::ok;
    auto point = [this](std::uint32_t g) -> decltype(point_at_[0]) { return point_at_[g]; };
    // Step 6 inside the recursion: the same stages on a region's points and its G'.
    auto repair = [&](const std::vector<std::uint32_t>& global, const std::vector<std::uint32_t>& triples,
                      std::size_t budget, std::vector<std::uint32_t>& out, std::size_t& work) {
      std::vector<typename DT::Point> points;
      points.reserve(global.size());
      for(const std::uint32_t g : global)
        points.push_back(point_at_[g]);
      return repair_region_completion<DT>(dt_.geom_traits(), points, triples, budget, out, work);
    };
    std::vector<std::uint32_t> completion;
    Region_recursion_report report;
    if(completion_by_region_recursion(dt_.geom_traits(), point, n_, triples_, repair,
                                      options_.tuning.d_cross_first_guess, completion, report)) {
      triples_.swap(completion);
      number_of_faces_ = triples_.size() / 3;
      predicted_faces_kept_ = report.counts.predicted_faces_kept;
    }
    stats_.regions_per_level = report.counts.regions_per_level;
    stats_.boundary_crossings = report.counts.crossings;
    stats_.regions_keeping_prediction = report.counts.regions_keeping_prediction;
    stats_.d_cross_guesses = report.guesses;
    return Outcome::ok;
  }

  // The screens that reject the prediction before its import: Outcome::ok when none does.
  Outcome screen() const
  {
    const auto& gt = dt_.geom_traits();
    if(options_.screen && fails_sampling_screen(gt, point_at_, n_, triples_))
      return Outcome::screen_rejected;
    if(options_.screen && options_.default_flip_budget &&
       failing_edges_exceed(point_at_, n_, triples_, options_.failing_edges_limit()))
      return Outcome::too_many_failing_edges;
    if(missing_faces_exceed(gt, point_at_, n_, triples_, options_.max_missing_faces()))
      return options_.repairs_locally() ? Outcome::too_many_holes : Outcome::holes_or_not_a_triangulation;
    return Outcome::ok;
  }

  // The import with its certificate (import_prediction.h), which reports Stage::order and
  // Stage::import itself. With the default budget it stops as soon as the failing edges it
  // has seen, extrapolated, pass the limit.
  template <class Run>
  Outcome certify(const Run& run)
  {
    Prediction_importer<DT>::run(result_, point_at_, n_, triples_, imported_, options_.repairs_locally(),
                                 parallel(), run.visitor,
                                 options_.default_flip_budget ? options_.failing_edges_limit() : std::size_t(-1),
                                 options_.max_open_halfedges());
    stats_.input_reordered = imported_.reordered;
    if(imported_.failure != Outcome::ok)
      return imported_.failure;
    stats_.edges_tested = imported_.edges_tested;
    stats_.edges_not_locally_delaunay = imported_.not_locally_delaunay.size();
    stats_.faces_carved = imported_.faces_dropped;
    // Small holes the import filled itself count as the first round of the local repair.
    stats_.holes_refilled = imported_.holes_filled;
    stats_.carve_rounds = imported_.holes_filled > 0 ? 1 : 0;
    return Outcome::ok;
  }

  // What the import could not make a triangulation of is carved and filled
  // (carve_repair.h); then, with Strategy::t_division, the t-division (Theorem 2.1).
  template <class Run>
  Outcome repair(const Run& run)
  {
    if(imported_.needs_repair) {
      if(imported_.open_halfedges.size() > options_.max_open_halfedges())
        return Outcome::too_many_holes;
      const Outcome why = run(Stage::carve, [&] { return carve(); });
      if(why != Outcome::ok)
        return why;
    }
    if constexpr(Paths::has(Strategy::t_division)) {
      if(options_.strategy == Strategy::t_division)
        run(Stage::t_division, [&] { return divide(); });
    }
    return Outcome::ok;
  }

  Outcome flip()
  {
    const std::size_t budget =
        options_.max_flips + (regions_ ? options_.flips_for_reinserted(regions_->detached().size()) : 0);
    return lawson_flip(result_, stack(), budget, stats_.flips, touched_, parallel())
               ? Outcome::ok
               : Outcome::flip_budget_exhausted;
  }

  // Points no face uses: duplicates of vertices, or points to insert.
  bool has_unused_points() const { return !imported_.unused_points.empty(); }

  Outcome insert_unused_points()
  {
    stats_.points_unused = imported_.unused_points.size();
    insert_points(result_, point_at_, imported_.unused_points, stats_, &new_vertices_);
    sort_by_address(new_vertices_);
    return Outcome::ok;
  }

  // Statistics::faces_certified, then the result handed over.
  void count_certified_faces()
  {
    if(!has_unused_points() && !carve_ && !regions_ && imported_.filled_faces.empty())
      stats_.faces_certified = result_.number_of_faces() - count_distinct(touched_);
    else if(!has_unused_points() && !regions_)
      // The predicted faces kept, less those the repair modified (flipped, or split by a
      // reinserted vertex); the faces it made are not predicted faces.
      stats_.faces_certified = number_of_faces_ - stats_.faces_carved -
                               count_distinct_addresses<typename DT::Face>(
                                   modified_, touched_, 0, [&](const void* f) { return !made_by_repair(f); });
    else
      stats_.faces_certified = count_faces_kept();
    if(predicted_faces_kept_ != none_kept) {
      // Theorem 4.1 or 5.4 imported its own faces: the predicted ones among them are those
      // its good supercells kept (Theorem 5.4: the faces of G'), less any face the
      // certificate's repair changed.
      const std::size_t changed = number_of_faces_ - (std::min)(number_of_faces_, stats_.faces_certified);
      // Never more than the faces read, should two supercells keep the same face.
      stats_.faces_certified =
          (std::min)(stats_.faces_in, predicted_faces_kept_ - (std::min)(predicted_faces_kept_, changed));
    }
    dt_.swap(result_);
  }

  // A build from scratch: in spatial order (in blocks on several threads), or, with
  // Strategy::spanning_tree or Strategy::section_3, along a spanning tree of the faces' edges
  // (Corollaries 3.4 and 3.5). Measured at 1e6 points on predictions that fall back (points moved by 0.3 to 1
  // spacing, 1% of the points relabelled, random triples; bench_fallback.cpp), the spatial
  // order was as fast to 26% faster: the default.
  void rebuild()
  {
    result_.tds().clear(); // release the partial import before building anew
    const std::vector<std::uint32_t> grid_order = std::move(imported_.points_in_grid_order);
    imported_ = Imported_prediction<DT>();
    DT fresh(dt_.geom_traits());
    if(!decides_exactly || !along_tree() || !fits_ || n_ >= std::size_t(no_rank)) {
      std::vector<std::uint32_t>().swap(triples_); // not needed: keep the peak memory down
      if(!build_in_blocks_if_parallel(fresh))
        build_from_scratch(fresh, point_at_, n_, stats_, grid_order);
    } else if constexpr(Paths::has(Strategy::spanning_tree) || Paths::has(Strategy::section_3)) {
      // Two edges of each face keep its three corners connected (`triples_` is still as read:
      // the import, which reorders it, did not run).
      std::vector<std::uint32_t> ends;
      ends.reserve(4 * number_of_faces_);
      for(std::size_t t = 0; t < triples_.size(); t += 3)
        ends.insert(ends.end(), {triples_[t], triples_[t + 1], triples_[t + 1], triples_[t + 2]});
      std::vector<std::uint32_t>().swap(triples_);
      if constexpr(Paths::has(Strategy::section_3)) {
        if(options_.strategy == Strategy::section_3) {
          build_by_conflict_list_rounds(fresh, point_at_, n_, ends, stats_);
          dt_.swap(fresh);
          return;
        }
      }
      build_along_edges(fresh, point_at_, n_, ends, stats_);
    }
    dt_.swap(fresh);
  }

private:
  // Whether the rebuild inserts along a spanning tree of the faces' edges.
  bool along_tree() const
  {
    return (Paths::has(Strategy::spanning_tree) && options_.strategy == Strategy::spanning_tree) ||
           (Paths::has(Strategy::section_3) && options_.strategy == Strategy::section_3);
  }

  // The rebuild in blocks on several threads (block_parallel_build.h), when the call runs on
  // several and the points are enough; false when it did not build.
  bool build_in_blocks_if_parallel(DT& fresh)
  {
    if constexpr(Paths::parallel && decides_exactly) {
      const std::size_t blocks = options_.rebuild_blocks();
      return blocks > 1 && build_in_blocks(fresh, point_at_, n_, stats_, blocks);
    } else {
      CGAL_USE(fresh);
      return false;
    }
  }

  std::vector<std::pair<Face_handle, int>>& stack() { return imported_.not_locally_delaunay; }

  bool filled_by_import(const void* f) const
  {
    return contains_address(imported_.filled_faces, f);
  }
  bool made_by_repair(const void* f) const
  {
    return (carve_ && carve_->is_created(f)) || (regions_ && regions_->is_created(f)) || filled_by_import(f);
  }
  // A vertex one face held twice (the faces overlap there) is at the same point as `same`.
  void merge_duplicate(Vertex_handle v, Vertex_handle same)
  {
    merge_index_info_of(same, v);
    result_.tds().delete_vertex(v);
    ++stats_.duplicate_points;
  }

  // The faces kept are not a triangulation with a convex hull: fill the holes and close the
  // hull (carve_repair.h); vertices left without a face are reinserted.
  Outcome carve()
  {
    carve_.reset(new Carve_repair<DT>(result_, false));
    carve_->expect_outer_cycle();
    // Faces that overlap without sharing an edge on one side (none left out) still meet at a
    // vertex in several fans: a vertex of a carved star may keep a closed fan elsewhere.
    carve_->expect_several_fans();
    if(imported_.faces_dropped > 0) // faces overlapped: some may still overlap unseen
      carve_vertices_wound_twice(result_, *carve_);
    for(const auto& e : imported_.open_halfedges)
      carve_->add_open_halfedge(e.first, e.second);
    const Outcome why = carve_->plan(default_carve_limits(n_));
    stats_.carve_rounds = (std::max)(stats_.carve_rounds, carve_->rounds());
    if(why != Outcome::ok)
      return why;
    carve_->commit(stack());
    if(!carve_->finish_hull(stack(), stats_.flips))
      return Outcome::carve_not_a_triangulation;
    carve_->reinsert(stack(), modified_, [&](Vertex_handle v, Vertex_handle same) { merge_duplicate(v, same); });
    // Faces the import filled holes with are not predicted faces, carved or modified.
    modified_.erase(std::remove_if(modified_.begin(), modified_.end(),
                                   [&](const void* f) { return filled_by_import(f); }),
                    modified_.end());
    std::size_t filled_removed = 0;
    for(const void* f : imported_.filled_faces)
      filled_removed += carve_->is_removed(f) ? 1 : 0;
    stats_.faces_carved += carve_->faces_removed() - filled_removed;
    stats_.holes_refilled += carve_->holes();
    stats_.points_reinserted = carve_->detached().size();
    return Outcome::ok;
  }

  // Theorem 2.1 (t_division_repair.h). When it does not pay (or cannot be planned), `result_`
  // is untouched: a valid triangulation after the carve, which the flips finish as with
  // Strategy::carve.
  Outcome divide()
  {
    const Outcome why = repair_by_t_division(
        result_, regions_, std::vector<Face_handle>(), true, stack(), !carve_, options_.region_size,
        options_.tuning.t_division_budget_factor, modified_, stats_, false,
        [&](Vertex_handle v, Vertex_handle same) { merge_duplicate(v, same); },
        [&](const void* f) { return (carve_ && carve_->is_created(f)) || filled_by_import(f); });
    if(why != Outcome::ok)
      regions_.reset();
    return why;
  }

  // A predicted face survives if it was never flipped, is not one a repair made (the
  // t-division may also remove faces the carve made: counted here, not subtracted), and has
  // no new vertex (insertion recycles the faces it destroys for faces around the new vertex).
  std::size_t count_faces_kept()
  {
    for(const Face_handle f : touched_)
      modified_.push_back(&*f);
    sort_unique_addresses(modified_);
    auto is_new = [&](const Vertex_handle v) {
      return contains_address(new_vertices_, static_cast<const void*>(&*v));
    };
    std::size_t kept = 0;
    for(auto f = result_.finite_faces_begin(); f != result_.finite_faces_end(); ++f)
      if(!contains_address(modified_, static_cast<const void*>(&*f)) &&
         !made_by_repair(&*f) && !is_new(f->vertex(0)) && !is_new(f->vertex(1)) && !is_new(f->vertex(2)))
        ++kept;
    return kept;
  }

  PointIterator point_at_;
  std::size_t n_;
  const FaceRange& faces_;
  std::size_t number_of_faces_;
  DT& dt_;
  const Pipeline_options& options_;
  Statistics stats_;
  DT result_; // the import, repaired; swapped into dt_ at the end
  std::vector<std::uint32_t> triples_;
  bool fits_ = true;
  Imported_prediction<DT> imported_;
  std::unique_ptr<Carve_repair<DT>> carve_;
  Pointer_if_compiled<T_division_repair<DT>, Paths::has(Strategy::t_division)> regions_;
  std::vector<const void*> modified_;   // predicted faces changed by a repair
  std::vector<Face_handle> touched_;    // faces flipped
  std::vector<const void*> new_vertices_; // the unused points inserted
  static constexpr std::size_t none_kept = std::size_t(-1);
  std::size_t predicted_faces_kept_ = none_kept; // Theorem 4.1's good faces or 5.4's G', when it ran
};

// The index of each point of `points`, found from the point: the smallest index of the
// points equal to it. Hashed on the nearest doubles, compared exactly.
template <class Point>
class Point_index
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  explicit Point_index(const std::vector<Point>& points)
      : points_(points), next_(points.size(), none), first_(2 * points.size() + 16)
  {
    for(std::size_t k = points.size(); k-- > 0;) { // each chain in increasing indices
      const auto inserted = first_.insert(key(points[k]), std::uint32_t(k));
      if(!inserted.second) {
        next_[k] = *inserted.first;
        *inserted.first = std::uint32_t(k);
      }
    }
  }

  std::uint32_t of(const Point& p) const
  {
    const std::uint32_t* k = first_.find(key(p));
    for(std::uint32_t i = k ? *k : none; i != none; i = next_[i])
      if(points_[i] == p)
        return i;
    return none;
  }

private:
  static std::uint64_t key(const Point& p)
  {
    // + 0.0 makes -0.0 the same key as 0.0, as the points are equal.
    const double x = CGAL::to_double(p.x()) + 0.0, y = CGAL::to_double(p.y()) + 0.0;
    std::uint64_t a, b;
    std::memcpy(&a, &x, sizeof a);
    std::memcpy(&b, &y, sizeof b);
    const std::uint64_t h = (a * 0x9E3779B97F4A7C15ull) ^ (b + 0x632BE59BD9B4E019ull + (a >> 29));
    return h == Hash_map<std::uint64_t, std::uint32_t>::free_key() ? 0 : h;
  }

  const std::vector<Point>& points_;
  std::vector<std::uint32_t> next_;
  Hash_map<std::uint64_t, std::uint32_t> first_;
};

// Step 6 of Theorem 5.4's recursion (region_recursion.h): DT(points) from their faces `triples`
// by the package's stages (import with its certificate, local repair of every hole, flips,
// insertion of the points in no face), sequentially, with at most `budget` flips, into `out`
// as index triples (of the smallest index among equal points). On the caller's triangulation
// type, with the point and face ranges of the common case (a std::vector of points, of
// std::array<std::size_t, 3>), so that a caller with those compiles the stages once.
// Adds the flips to `work`, and m log2 m for a region of m points built from scratch. False
// when the flips would pass the budget.
template <class DT>
bool repair_region_completion(const typename DT::Geom_traits& gt, const std::vector<typename DT::Point>& points,
                              const std::vector<std::uint32_t>& triples, std::size_t budget,
                              std::vector<std::uint32_t>& out, std::size_t& work)
{
  using Faces = std::vector<std::array<std::size_t, 3>>;
  Faces faces(triples.size() / 3);
  for(std::size_t t = 0; t < faces.size(); ++t)
    faces[t] = {triples[3 * t], triples[3 * t + 1], triples[3 * t + 2]};
  Pipeline_options options;
  options.n = points.size();
  options.max_flips = budget;
  options.default_flip_budget = false;
  options.screen = false;
  options.fills_every_hole = true;
  options.region_size = default_region_size(points.size());
  DT dt(gt);
  Index_triples_stages<DT, typename std::vector<typename DT::Point>::const_iterator, Faces,
                       Compiled_paths<strategy_bit(Strategy::automatic), false>>
      stages(points.begin(), points.size(), faces, faces.size(), dt, options);
  Default_visitor visitor;
  const Statistics s = run_prediction_pipeline(stages, options, visitor);
  work += s.flips;
  if(s.fell_back) {
    if(s.outcome == Outcome::flip_budget_exhausted)
      return false;
    work += points.size() * ceil_log2(points.size());
  }
  const Point_index<typename DT::Point> index(points);
  out.clear();
  out.reserve(6 * points.size());
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for(int i = 0; i < 3; ++i)
      out.push_back(index.of(f->vertex(i)->point()));
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_INDEX_TRIPLES_STAGES_H
