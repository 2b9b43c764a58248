// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The one pipeline of delaunay_from_prediction() and make_delaunay(): the options both read
// from their named parameters, the limits that decide between a repair and a rebuild, and the
// driver that runs the stages in order and reports each to the visitor. The stages themselves
// are written twice only where their input differs: index triples imported into a fresh
// triangulation (index_triples_stages.h), a CGAL triangulation repaired in place
// (in_place_stages.h).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_PREDICTION_PIPELINE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_PREDICTION_PIPELINE_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>
#include <CGAL/Delaunay_from_prediction/internal/build/block_parallel_build.h>
#include <CGAL/Delaunay_from_prediction/internal/build/prediction_regions_build.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/t_division_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
#include <utility>

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

// The failing edges past which Lawson's flips would exceed `max_flips`: each failing edge
// needs a flip, and the cascades they start more. Measured on the rho model's predictions with
// both completions and on random flips of DT(P) (bench_d_cross, 1e5 points), Lawson made 1.35
// to 2.6 flips per failing edge; the least ratio is used, so that a prediction is rebuilt at
// once only when its flips would almost surely run out. For the default budget only.
inline std::size_t max_failing_edges(std::size_t max_flips)
{
  return max_flips == std::size_t(-1) ? max_flips : std::size_t(double(max_flips) / 1.35);
}

// What one call compiles: the strategies it may run (bit `1 << s` of `StrategyMask` for
// Strategy `s`) and whether it may run on several threads. Both are known at compile time
// from the call's ConcurrencyTag and the type of its named parameter `strategy`, so that a
// program compiles only the code its calls can reach: without the parameter only
// Strategy::automatic (with its fallback, the rebuild), with parameters::strategy<S>() only S,
// with a run-time value every strategy. Each branch to a strategy's code stands behind
// `if constexpr(Paths::has(s))`; Paths::parallel keeps the code that only runs on several
// threads out of sequential calls.
template <std::uint32_t StrategyMask, bool Parallel>
struct Compiled_paths
{
  static constexpr bool parallel = Parallel;
  static constexpr bool has(Strategy s) { return ((StrategyMask >> unsigned(s)) & 1u) != 0; }
};

constexpr std::uint32_t strategy_bit(Strategy s) { return std::uint32_t(1) << unsigned(s); }

template <class T>
struct is_strategy_constant : std::false_type
{
};
template <Strategy S>
struct is_strategy_constant<Strategy_constant<S>> : std::true_type
{
};

// The strategies a call with named parameters `NamedParameters` may run (Compiled_paths).
template <class NamedParameters>
constexpr std::uint32_t strategies_compiled()
{
  using Given = typename CGAL::internal_np::Get_param<typename NamedParameters::base, internal_np::strategy_t>::type;
  if constexpr(std::is_same<Given, CGAL::internal_np::Param_not_found>::value)
    return strategy_bit(Strategy::automatic);
  else if constexpr(is_strategy_constant<Given>::value)
    return strategy_bit(Given::value);
  else
    return ~std::uint32_t(0);
}

// A stage's helper object that only strategy `s` makes (the t-division's): a std::unique_ptr
// where the call compiles `s`, elsewhere a pointer that is always null, so that neither the
// helper's destructor nor what it owns (the t-division's own triangulation type) is compiled.
template <class T>
struct Null_pointer
{
  explicit operator bool() const { return false; }
  T* operator->() const { return nullptr; }
  void reset() {}
};
template <class T, bool compiled>
using Pointer_if_compiled = std::conditional_t<compiled, std::unique_ptr<T>, Null_pointer<T>>;

template <class NamedParameters, bool Parallel>
using Compiled_paths_of = Compiled_paths<strategies_compiled<NamedParameters>(), Parallel>;

// What both entry points read from their named parameters, and the limits that choose between
// a repair and a rebuild, each with the measurement behind it. `n`: the points (vertices).
struct Pipeline_options
{
  std::size_t n = 0;
  std::size_t max_flips = 0;
  bool default_flip_budget = true; // max_flips not given: an estimate of what pays, not a limit
  bool screen = true;
  Strategy strategy = Strategy::automatic;
  std::size_t region_size = 0;
  Tuning tuning;
  bool parallel = false;
  // Theorem 5.4's step 6 inside its recursion (region_recursion.h): the faces are a region's
  // completion G', whose seams and pockets up to the convex hull are the proof's steps 4 and 5,
  // filled whatever their number.
  bool fills_every_hole = false;

  // Whether the prediction is used at all (Strategy::rebuild and Strategy::spanning_tree
  // build from scratch).
  bool uses_prediction() const
  {
    return strategy != Strategy::rebuild && strategy != Strategy::spanning_tree && strategy != Strategy::section_3;
  }
  // Whether faces that are not a triangulation (inverted, overlapping, holes) are repaired
  // locally instead of rebuilt.
  bool repairs_locally() const
  {
    return strategy == Strategy::automatic || strategy == Strategy::carve || strategy == Strategy::t_division ||
           strategy == Strategy::theorem_4_1 || strategy == Strategy::theorem_5_4;
  }
  // A budget the caller set is a hard limit: more failing edges than flips rebuild at once.
  // The default one is an estimate, and so is the limit (max_failing_edges()).
  std::size_t failing_edges_limit() const
  {
    return default_flip_budget ? max_failing_edges(max_flips) : max_flips;
  }
  // Lawson's algorithm needs a flip per failing edge at least, in practice more: past the
  // limit the flips would be wasted.
  Outcome failing_edges_outcome(std::size_t failing) const
  {
    if(failing <= failing_edges_limit())
      return Outcome::ok;
    return default_flip_budget ? Outcome::too_many_failing_edges : Outcome::flip_budget_exhausted;
  }
  // Faces missing from index triples, told by counting (missing_faces_exceed()): past n/8
  // the local repair would not pay; without it, past n/64 the faces cannot be a triangulation
  // (any excess shows that, the margin keeps the count off the common case of about 2n faces).
  std::size_t max_missing_faces() const
  {
    return fills_every_hole ? 2 * n + 16 : repairs_locally() ? n / 8 + 16 : n / 64 + 16; // 2n: no limit
  }
  // Half-edges left open by the import (hole boundaries): tracing and filling costs about
  // 2 us per such half-edge at 1e6 points (1% of a DT's faces deleted: 60,000 of them,
  // 0.12 s), a rebuild about 0.75 us per point, so past n/4 the repair costs more.
  std::size_t max_open_halfedges() const { return fills_every_hole ? 6 * n + 64 : n / 4 + 64; } // 6n: no limit
  // Faces not counterclockwise that the local repair takes on (default_carve_limits()).
  std::size_t max_inverted_faces() const { return default_carve_limits(n).max_bad_faces; }
  // Points reinserted by the t-division make a few flips each, as in any incremental
  // construction: on top of the budget for the repair of the prediction.
  std::size_t flips_for_reinserted(std::size_t reinserted) const { return 4 * reinserted; }
  // Blocks of a rebuild on several threads (block_parallel_build.h); 1: sequential.
  std::size_t rebuild_blocks() const
  {
    return parallel ? default_block_count(n, available_threads(), tuning) : 1;
  }
};

// The options of delaunay_from_prediction() or make_delaunay() on n points, from `np`.
template <class NamedParameters>
Pipeline_options read_pipeline_options(const NamedParameters& np, std::size_t n, bool parallel)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Pipeline_options o;
  o.n = n;
  o.parallel = parallel;
  o.max_flips = choose_parameter(get_parameter(np, internal_np::max_flips), default_max_flips(n));
  o.default_flip_budget = parameters::is_default_parameter<NamedParameters, internal_np::max_flips_t>::value;
  o.screen = choose_parameter(get_parameter(np, internal_np::screen_prediction), true);
  o.strategy = choose_parameter(get_parameter(np, internal_np::strategy), Strategy::automatic);
  o.region_size = choose_parameter(get_parameter(np, internal_np::region_size),
                                   o.strategy == Strategy::regions
                                       ? default_prediction_region_size(n, parallel ? available_threads() : 1)
                                       : default_region_size(n));
  o.tuning = choose_parameter(get_parameter(np, internal_np::tuning), Tuning());
  return o;
}

// Runs a stage's body between the visitor's stage_begin() and stage_end(); the stages that
// report stages of their own (the import) reach the visitor through it.
template <class Visitor>
struct Stage_runner
{
  Visitor& visitor;

  template <class Body>
  Outcome operator()(Stage stage, Body&& body) const
  {
    visitor.stage_begin(stage);
    const Outcome why = body();
    visitor.stage_end(stage);
    return why;
  }
};

// The stages that use the prediction, in order, up to the first that gives it up: Outcome::ok
// when they made the Delaunay triangulation, otherwise why not. `run(stage, body)` reports
// `stage` to the visitor around `body`.
template <class Stages, class Visitor>
Outcome use_prediction(Stages& stages, const Pipeline_options& options, const Stage_runner<Visitor>& run)
{
  using Paths = typename Stages::Paths;
  Outcome why = stages.reason_not_to_use_prediction();
  if constexpr(Paths::has(Strategy::regions)) {
    if(why == Outcome::ok && options.strategy == Strategy::regions && stages.can_build_by_regions()) {
      // Theorem 5.4 in practical form (prediction_regions_build.h): a build, not a repair.
      return run(Stage::regions, [&] { return stages.build_by_regions(); });
    }
  }
  if constexpr(Paths::has(Strategy::theorem_4_1)) {
    if(why == Outcome::ok && options.strategy == Strategy::theorem_4_1) {
      // Theorem 4.1 (supercells.h) computes the faces, which the stages below certify.
      why = run(Stage::supercells, [&] { return stages.compute_by_supercells(); });
    }
  }
  if constexpr(Paths::has(Strategy::theorem_5_4)) {
    if(why == Outcome::ok && options.strategy == Strategy::theorem_5_4) {
      // Theorem 5.4 (region_recursion.h) computes the completion G'; the stages below are its
      // step 6.
      why = run(Stage::region_recursion, [&] { return stages.compute_by_region_recursion(); });
    }
  }
  if constexpr(Stages::screens) {
    if(why == Outcome::ok)
      why = run(Stage::screen, [&] { return stages.screen(); });
  }
  if(why == Outcome::ok)
    why = stages.certify(run); // Stage::order and Stage::import, or Stage::certify
  if(why == Outcome::ok)
    why = options.failing_edges_outcome(stages.stats().edges_not_locally_delaunay);
  if(why == Outcome::ok)
    why = stages.repair(run); // Stage::carve, Stage::t_division, Stage::untangle, as needed
  if(why == Outcome::ok)
    why = run(Stage::flips, [&] { return stages.flip(); });
  if(why == Outcome::ok && stages.has_unused_points())
    why = run(Stage::insert, [&] { return stages.insert_unused_points(); });
  if(why == Outcome::ok)
    stages.count_certified_faces();
  return why;
}

// The pipeline. `stages` (index_triples_stages.h or in_place_stages.h) holds the state and
// the Statistics; each stage returns Outcome::ok to go on, or why the prediction is given up,
// and then the points are triangulated from scratch (the rebuild), with the reason recorded.
// Every stage is reported to `visitor` as it begins and ends, on this thread (visitor.h).
// Throws Invalid_prediction from the check, or from the rebuild for two points at the same
// place, with the caller's data as it was.
// `stages` are spent: their Statistics are moved out.
template <class Stages, class Visitor>
Statistics run_prediction_pipeline(Stages& stages, const Pipeline_options& options, Visitor& visitor)
{
  Statistics& stats = stages.stats();
  const Stage_runner<Visitor> run{visitor};
  run(Stage::check, [&] { return stages.check(); });
  if(stages.is_empty())
    return std::move(stats);
  // Inexact predicates (toolbox/predicates.h): flips, walks and certificates could cycle or
  // corrupt; the triangulation is built from scratch, decided by exact predicates.
  Outcome why = Outcome::inexact_predicates;
  if constexpr(Stages::decides_exactly)
    why = use_prediction(stages, options, run);
  if(why == Outcome::ok)
    return std::move(stats);
  run(Stage::rebuild, [&] {
    stats.fell_back = true;
    stats.outcome = why;
    stats.faces_certified = 0;
    stats.points_reinserted = 0;
    // The rebuild counts every duplicate again: those a repair merged before it gave up are
    // not in the fresh triangulation's count yet.
    stats.duplicate_points = 0;
    stages.rebuild();
    return why;
  });
  return std::move(stats);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PIPELINE_PREDICTION_PIPELINE_H
