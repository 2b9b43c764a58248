// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The stages of the pipeline (prediction_pipeline.h) for make_delaunay(): a CGAL triangulation
// whose points may have moved, certified and repaired in place, or rebuilt around the same
// vertex objects.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_IN_PLACE_STAGES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_IN_PLACE_STAGES_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/prediction_regions_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/import/tds_certify.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/t_division_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// `tr`'s faces are the prediction of the Delaunay triangulation of its own vertices.
//
// Every flip until the triangulation is certified again (during certification, untangling)
// is logged: if the rebuild finds two vertices at the same point, they are undone before it
// throws, so that `tr` is left as it was (a carve rolled back updates the log).
// `CompiledPaths`: what the call compiles (Compiled_paths).
template <class Triangulation, class CompiledPaths>
class In_place_stages
{
public:
  using Paths = CompiledPaths;
  // The `parallel` argument of the stages' functions: the call's, known at compile time.
  static constexpr Parallel_constant<Paths::parallel> parallel() { return {}; }
  using Face_handle = typename Triangulation::Face_handle;
  static constexpr bool decides_exactly = !decides_by_exact_predicates<typename Triangulation::Geom_traits>::value;
  static constexpr bool screens = true; // screen() may give the prediction up

  In_place_stages(Triangulation& tr, const Pipeline_options& options)
      : tr_(tr), options_(options),
        // Lawson's flips start during certification, except for the t-division, which plans
        // its regions from the edges that fail in the prediction as given, and in parallel,
        // where the faces are only read while they are certified, block by block.
        flip_inline_(options.strategy != Strategy::t_division && !options.parallel),
        inline_flips_{options.max_flips, stats_.flips, touched_, flips_before_repair_}
  {
    stats_.faces_in = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  }

  Statistics& stats() { return stats_; }
  bool is_empty() const { return tr_.number_of_vertices() == 0; }

  // Every vertex's point finite (throws before `tr` is touched).
  Outcome check()
  {
    check_vertices_are_finite(tr_);
    return Outcome::ok;
  }

  Outcome reason_not_to_use_prediction() const
  {
    // Theorems 4.1 and 5.4 run on index triples only: make_delaunay() rebuilds.
    return options_.uses_prediction() && options_.strategy != Strategy::theorem_4_1 &&
                   options_.strategy != Strategy::theorem_5_4
               ? Outcome::ok
               : Outcome::rebuild_requested;
  }

  // Theorems 4.1 and 5.4 run on index triples only (reason_not_to_use_prediction() rules them
  // out here).
  Outcome compute_by_supercells() { return Outcome::rebuild_requested; }
  Outcome compute_by_region_recursion() { return Outcome::rebuild_requested; }

  bool can_build_by_regions() const
  {
    return tr_.dimension() == 2 && tr_.number_of_vertices() < std::size_t(no_region);
  }

  // The faces of `tr` are the prediction; the triangulation is built aside by regions, then
  // put on the same vertices. When the regions do not fit, `tr` is as it was.
  Outcome build_by_regions()
  {
    std::vector<std::uint32_t> triples;
    finite_faces_as_index_triples(tr_, triples);
    Outcome why = Outcome::ok;
    rebuild_keeping_vertices(
        tr_, stats_,
        [&](auto& aside, auto points, std::size_t n) {
          Statistics built;
          why = build_by_prediction_regions(aside, points, n, triples, options_.region_size, built, options_.parallel);
          stats_.regions = built.regions;
          stats_.boundary_vertices = built.boundary_vertices;
          std::vector<std::uint32_t>().swap(triples);
          return why == Outcome::ok;
        },
        false);
    return why;
  }

  // Too many inverted faces, foreseen from a sample before any test or flip (tds_certify.h).
  Outcome screen() const
  {
    return options_.repairs_locally() && inverted_faces_exceed_early(tr_, options_.max_inverted_faces())
               ? Outcome::too_many_inverted_faces
               : Outcome::ok;
  }

  // The certificate read off `tr` (tds_certify.h); faces not counterclockwise are listed for
  // the local repair.
  template <class Run>
  Outcome certify(const Run& run)
  {
    const Outcome why = run(Stage::certify, [&] {
      return certify_faces(tr_, stack_, stats_.edges_tested, hull_is_convex_,
                           options_.repairs_locally() ? &inverted_ : nullptr, options_.max_inverted_faces(),
                           flip_inline_ ? &inline_flips_ : nullptr, parallel());
    });
    if(why == Outcome::ok)
      stats_.edges_not_locally_delaunay = flip_inline_ ? inline_flips_.edges_failing : stack_.size();
    return why;
  }

  // Faces that are not counterclockwise: with Strategy::t_division, the bad regions of a
  // t-division (Theorem 2.1) replaced; otherwise, or when that does not pay, untangled by
  // flips, then the stars of what remains carved (carve_repair.h).
  template <class Run>
  Outcome repair(const Run& run)
  {
    if constexpr(Paths::has(Strategy::t_division)) {
      if(options_.strategy == Strategy::t_division && run(Stage::t_division, [&] { return divide(); }) == Outcome::ok)
        return Outcome::ok;
    }
    if(inverted_.empty())
      return Outcome::ok;
    run(Stage::untangle, [&] { return untangle(); });
    if(inverted_.empty())
      return Outcome::ok;
    return run(Stage::carve, [&] { return carve(); });
  }

  // A hull no longer convex is repaired by flips of hull edges, then Lawson's flips.
  Outcome flip()
  {
    if(!hull_is_convex_ && !convexify_hull(tr_, stack_, hull_faces_, stats_.flips))
      return Outcome::hull_not_convex;
    const std::size_t budget =
        options_.max_flips + (regions_ ? options_.flips_for_reinserted(regions_->detached().size()) : 0);
    if(lawson_flip(tr_, stack_, budget, stats_.flips, touched_, parallel()))
      return Outcome::ok;
    flips_before_repair_.clear(); // a triangulation again, without duplicates: nothing to undo
    return Outcome::flip_budget_exhausted;
  }

  bool has_unused_points() const { return false; } // every point is a vertex
  Outcome insert_unused_points() { return Outcome::ok; }

  // Statistics::faces_certified: the predicted faces neither carved, nor modified (flipped, or
  // split by a reinserted vertex), nor made by a repair.
  void count_certified_faces()
  {
    using Face = typename Triangulation::Face;
    if(regions_)
      stats_.faces_certified = stats_.faces_in - stats_.faces_carved -
                               count_distinct_addresses<Face>(modified_, touched_, 0, [&](const void* f) {
                                 return !regions_->is_created(f);
                               });
    else if(carve_)
      stats_.faces_certified = stats_.faces_in - stats_.faces_carved -
                               count_distinct_addresses<Face>(modified_, touched_, 0, [&](const void* f) {
                                 return !carve_->is_removed(f) && !carve_->is_created(f);
                               });
    else
      stats_.faces_certified = stats_.faces_in - count_distinct(touched_, hull_faces_);
  }

  // The faces rebuilt around the same vertex objects (rebuild.h), in blocks on several
  // threads; on two vertices at the same point, the logged flips are undone and `tr` is as
  // it was when the exception leaves.
  void rebuild()
  {
    try {
      if constexpr(Paths::parallel && decides_exactly) {
        rebuild_keeping_vertices(tr_, stats_, [&](auto& aside, auto points, std::size_t n) {
          const std::size_t blocks = options_.rebuild_blocks();
          Statistics ignored;
          return blocks > 1 && build_in_blocks(aside, points, n, ignored, blocks);
        });
      } else {
        rebuild_keeping_vertices(tr_, stats_);
      }
    } catch(const Invalid_prediction&) {
      undo_flips(tr_, flips_before_repair_);
      throw;
    }
  }

private:
  // Theorem 2.1 (t_division_repair.h). If it does not pay or cannot be planned, `tr` is
  // untouched and the carve takes over; otherwise the flips finish it.
  Outcome divide()
  {
    const Outcome why = repair_by_t_division(tr_, regions_, inverted_, hull_is_convex_, stack_, true,
                                             options_.region_size, options_.tuning.t_division_budget_factor,
                                             modified_, stats_, true, [](auto, auto) {
                                               CGAL_assertion_msg(false, "duplicates were ruled out before");
                                             });
    if(why != Outcome::ok) {
      regions_.reset();
      return why;
    }
    hull_is_convex_ = true; // the t-division closed the hull
    inverted_.clear();
    return Outcome::ok;
  }

  // Flips that make inverted faces counterclockwise where one flip does (flips.h).
  Outcome untangle()
  {
    const std::size_t logged = flips_before_repair_.size();
    untangle_by_flips(tr_, inverted_, stack_, flips_before_repair_, touched_, parallel());
    stats_.flips += flips_before_repair_.size() - logged;
    return Outcome::ok;
  }

  // The stars of the vertices of the faces still inverted carved, the holes filled, those
  // vertices reinserted (carve_repair.h); rolled back when it fails.
  Outcome carve()
  {
    carve_.reset(new Carve_repair<Triangulation>(tr_, true));
    const Outcome why = carve_and_reinsert(*carve_, tr_, inverted_, stack_, flips_before_repair_, modified_, stats_);
    if(why != Outcome::ok) {
      carve_.reset();
      return why;
    }
    hull_is_convex_ = true; // the carve closed the hull
    return Outcome::ok;
  }

  Triangulation& tr_;
  const Pipeline_options& options_;
  Statistics stats_;
  std::vector<std::pair<Face_handle, int>> stack_; // edges that may fail, for Lawson's flips
  std::vector<Face_handle> inverted_;              // faces not counterclockwise
  bool hull_is_convex_ = false;
  Flip_log<Triangulation> flips_before_repair_;
  std::vector<Face_handle> touched_;               // faces flipped
  std::vector<const void*> modified_;              // predicted faces changed by a repair
  std::vector<const void*> hull_faces_;            // finite faces made by convexify_hull()
  bool flip_inline_;
  Inline_flips<Triangulation> inline_flips_;
  Pointer_if_compiled<T_division_repair<Triangulation>, Paths::has(Strategy::t_division)> regions_;
  std::unique_ptr<Carve_repair<Triangulation>> carve_;
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_IN_PLACE_STAGES_H
