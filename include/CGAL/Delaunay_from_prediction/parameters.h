// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Named parameters of the package. CGAL 5.5 pastes a fixed list of tags into
// Named_function_parameters, so an outside package cannot add `.max_flips()` to CGAL's own
// chain. Ours return a Named_parameters, a CGAL chain (derived from it, so that CGAL's lookup
// reads it) with the package's parameters as members: `max_flips(10).strategy(s)`. They also
// take an optional CGAL chain as a second argument: `max_flips(10, CGAL::parameters::verbose(true))`.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_PARAMETERS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_PARAMETERS_H

#include <CGAL/Delaunay_from_prediction/visitor.h>
#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Delaunay_from_prediction {

namespace internal_np {
enum max_flips_t { max_flips };
enum screen_prediction_t { screen_prediction };
enum strategy_t { strategy };
enum region_size_t { region_size };
enum disk_order_t { disk_order };
enum split_method_t { split_method };
enum sample_probability_t { sample_probability };
enum visitor_t { visitor };
enum tuning_t { tuning };
} // namespace internal_np

/*!
\ingroup PkgDelaunayFromPredictionRef
How `delaunay_from_prediction()` and `make_delaunay()` use a prediction (named parameter
`strategy`). Whatever the strategy, the result is the same exact Delaunay triangulation; only
the time differs.
*/
enum class Strategy {
  /// the default: `carve`, whose cheap measurements decide between the local repair and a
  /// rebuild (sampled faces against sampled points, missing faces counted, inverted faces and
  /// failing edges counted during certification, each against a budget); `regions`,
  /// `t_division` and `spanning_tree` are never chosen, being measured slower than the
  /// rebuild or the repair on every input (see the user manual, section "How the Default
  /// Strategy Chooses").
  automatic,
  /// certify, then Lawson flips; a prediction that is not a triangulation of its points is
  /// rebuilt from scratch at once (for comparison).
  flips,
  /// certify; carve out inverted, flat, repeated and overlapping faces with the stars of
  /// their vertices; retriangulate the holes and reinsert the carved vertices; then Lawson
  /// flips. Falls back to a rebuild when the damage exceeds the budget.
  carve,
  /// Theorem 2.1 of the paper: certify; divide the faces into regions of about t faces
  /// (named parameter `region_size`); build the Delaunay triangulation of the vertices on
  /// region boundaries; keep the regions with no failing test whose boundary faces are faces
  /// of it; replace the others by its faces and reinsert their inner vertices; then Lawson
  /// flips. A prediction with holes or overlaps first gets them filled as by `carve`. When
  /// the damage would spoil most regions, or the division cannot be planned, the repair is
  /// left to `carve` (the flips, after a fill). Never faster than `carve` beyond run-to-run
  /// noise, much slower where it divides (see the user manual): selectable for comparison.
  t_division,
  /// Theorem 5.4 of the paper (the \f$d_{cross}\f$-sensitive algorithm) in practical form:
  /// divide the prediction's faces into connected regions of about t faces (named parameter
  /// `region_size`; by default two regions per thread and at least four), triangulate each
  /// region's points on its own (on TBB's threads with `CGAL::Parallel_tag`), keep the faces
  /// whose circumdisks a grid shows to hold no point of another region, triangulate the seams
  /// between them again, join the pieces and certify the result by exact predicates. The
  /// prediction need not be a triangulation: inverted, crossing, missing faces only widen the
  /// seams. Falls back to a rebuild when the regions interleave too much. Not the paper's
  /// recursion: each region is built by the package's insertion, so the work is that of a
  /// build from scratch plus the seams, whatever \f$d_{cross}\f$ (see the user manual).
  regions,
  /// ignore the prediction and rebuild (for comparisons).
  rebuild,
  /// `delaunay_from_prediction()` only (`make_delaunay()` treats it as `rebuild`): no
  /// certification or repair; the triangulation is built from scratch along a spanning tree
  /// of the faces' edges, as `delaunay_from_spanning_graph()` does (Corollaries 3.4 and 3.5
  /// of the paper: the faces need not be planar; the paper's \f$O((n + D \log n) \log^* n)\f$
  /// bound is not proven for this insertion, which has no conflict lists, see
  /// `delaunay_from_spanning_graph()`). Reported as a fallback, as `rebuild` is. Slower than
  /// the default on every prediction measured (see the user manual): selectable for comparison.
  spanning_tree,
  /// Section 3 of the paper as written (Lemma 3.2, Theorem 3.3), in
  /// `delaunay_from_spanning_graph()` and the functions built on it, and in
  /// `delaunay_from_prediction()` along a spanning tree of the faces' edges (Corollaries 3.4
  /// and 3.5; `make_delaunay()` treats it as `rebuild`): nested random samples of the points
  /// weighted by their degree in the tree, with \f$s_1 = n\f$, \f$s_{i+1} = \lfloor \log_2
  /// s_i \rfloor\f$, ..., \f$s_\ell = 1\f$; each round locates every point in the sample's
  /// triangulation by walks along the tree capped at \f$\log_2 n\f$ faces, computes the
  /// conflict lists by graph search, and builds the next sample's triangulation by randomized
  /// incremental construction with those conflict lists. No heuristic fallback: a useless
  /// graph costs what the analysis says. Two substitutions, named in the manual: a grid and
  /// a walk for the \f$O(\log n)\f$ point location, and the incremental construction for
  /// the per-cell lower envelopes. Reported as a fallback, as `spanning_tree` is. For
  /// comparing the theory with the practical strategies; slower than the default.
  section_3,
  /// Theorem 4.1 of the paper, with Corollary 4.2 (`delaunay_from_prediction()` only;
  /// `make_delaunay()` treats it as `rebuild`): Section 3's rounds along a spanning tree of
  /// the faces' edges, stopped after three rounds (\f$s_1 = n\f$, \f$s_2 = \lfloor \log_2 n
  /// \rfloor\f$, \f$s_3 = \lfloor \log_2 s_2 \rfloor\f$); the exceptional cells computed at
  /// once; the cells grouped into supercells of about \f$t = s_3^4\f$ cells; along the walls
  /// between supercells, chains of Delaunay edges; a supercell whose regions the prediction
  /// triangulates with locally Delaunay faces keeps them, the others are computed cell by
  /// cell. The faces are then imported with the package's certificate, which repairs what a
  /// degenerate input (points on a Voronoi edge of the sample) left wrong. Substitutions,
  /// named in the manual: the cells are the sample's Voronoi cells, the supercells grown
  /// breadth-first, the chains traced crossing by crossing. For comparing the theory with the
  /// practical strategies; slower than the default.
  theorem_4_1,
  /// Theorem 5.4 of the paper (`delaunay_from_prediction()` only; `make_delaunay()` treats it
  /// as `rebuild`): the recursion over the prediction's regions. Each level divides its faces
  /// into regions of at most about \f$t = \max(\lceil \log_2 \mu \rceil^2, b^2)\f$ faces,
  /// computes each region's Delaunay triangulation recursively (from scratch at most
  /// \f$b^2\f$ faces), keeps its triangles that lie inside the region, uncut by the region's
  /// boundary (found by walking each boundary segment through it), and repairs their union
  /// \f$G'\f$ with the package's D-sensitive repair (import with its certificate, local
  /// repair of the seams, Lawson's flips); the top level's \f$G'\f$ is repaired by the
  /// call's own stages. \f$d_{cross}\f$ is guessed as in the proof: \f$b = 2^{2^j}\f$ from
  /// \f$j = \lceil \log_2 \log^* \mu \rceil\f$, each run capped at \f$\mu 2^j\f$ units of
  /// work. Substitutions, named in the manual: the package's region growing for the
  /// t-division, walks instead of ray shooting, the seams filled by the import's hole tracer.
  /// For comparing the theory with the practical strategies; slower than the default.
  theorem_5_4
};

/*!
\ingroup PkgDelaunayFromPredictionRef
A strategy known at compile time, given by `parameters::strategy<S>()`: a call with it
compiles the code of `S` only. A call without the named parameter `strategy` compiles the code
of `Strategy::automatic` only (and its fallback, the rebuild); a call given a `Strategy`
value, known at run time, compiles every strategy. It converts to `Strategy`.
*/
template <Strategy S>
using Strategy_constant = std::integral_constant<Strategy, S>;

/*!
\ingroup PkgDelaunayFromPredictionRef
The order in which `Imprecise_points_2` inserts the disks, in its preprocessing and in every
instance (named parameter `disk_order`).
*/
enum class Disk_order {
  /// the default: the package's biased randomized grid order of the centres (random rounds,
  /// each sorted along a grid), the order of the paper's fastest experiment, where
  /// consecutive insertions are near each other in memory.
  spatial,
  /// a uniformly random order: the order of the paper's analysis (Theorem 1); slower, its
  /// accesses being cache misses.
  random
};

/*!
\ingroup PkgDelaunayFromPredictionRef
How `split_delaunay()` computes the two triangulations (named parameter `split_method`). Both
give exactly \cgal's triangulations of the two parts.
*/
enum class Split_method {
  /// the default: `ordered`, the faster on every input measured (see the user manual).
  automatic,
  /// each part inserted, point by point, in the order of the input triangulation's vertices
  /// when that order is spatially coherent (a triangulation built by \cgal's range insertion
  /// keeps its points in spatial-sort order), otherwise in the package's grid order; each point
  /// located from the previous point of its part. No sort when the order is coherent.
  ordered,
  /// the paper's randomized algorithm (Theorem 3): remove from a copy of the input, one by one,
  /// the better of two random points (the one whose nearest neighbour in its own part a search
  /// by growing circles over the current triangulation finds first), then reinsert the points
  /// in reverse order into the triangulation of their part, each located by a walk from that
  /// nearest neighbour. The paper proves expected \f$O(n)\f$ time with a removal linear in the
  /// degree; with \cgal's removal and visibility walks the bound is not proven here, and the
  /// removals cost more than the insertions they spare: selectable for comparison.
  randomized
};

/*!
\ingroup PkgDelaunayFromPredictionRef
Thresholds of `delaunay_from_prediction()` and `make_delaunay()` (named parameter `tuning`),
for experiments and tests; the defaults are measured. Whatever the values, the result is the
same triangulation: only the time differs.
*/
struct Tuning
{
  /// `Strategy::t_division` gives up when its work (in point insertions) would exceed this
  /// factor times n, about a rebuild: past it the division costs more than the rebuild
  /// (bench_delaunay_from_prediction's t-division cases, 1e5 and 1e6 points); tests raise it to reach the division on small inputs.
  double t_division_budget_factor = 1;
  /// with `CGAL::Parallel_tag`, a build from scratch is made in blocks only from this many
  /// threads: on 2 threads at 1e6 points the build in blocks measured 1.22-1.66 times as fast
  /// as CGAL's build on the rebuilt rows and the sequential build on flat arrays 1.52-1.66
  /// (results/rebuild_flat_arrays_vs_faces_1e6.txt), and on one thread the build in 4 blocks
  /// took 0.6877 s where CGAL's build took 0.6514 s (results/region_build_stages_1thread_1e6.txt).
  /// 4 is a choice, not a measurement: no machine with more than 2 cores was available.
  std::size_t min_threads_for_blocks = 4;
  /// ... and only in blocks of at least this many points (two or more blocks): smaller blocks
  /// make the seams' share grow; at 1e6 points on 2 threads 4 blocks gave 1.58x the sequential
  /// build, 2 blocks 1.23x, 8 blocks 1.51x (results/region_build_blocks_1e6.txt). Tests lower it to build in
  /// blocks at small sizes.
  std::size_t min_points_per_block = std::size_t(1) << 15;
  /// `Strategy::theorem_5_4`: the first \f$j\f$ of the guesses \f$b = 2^{2^j}\f$ of
  /// \f$d_{cross}\f$; -1 (the default) starts where the proof does, at \f$\lceil \log_2
  /// \log^* \mu \rceil\f$ for \f$\mu\f$ faces: 2 up to 65,536 faces (a base case of
  /// \f$b^2 = 256\f$ faces), 3 beyond (65,536 faces). Tests and benchmarks set 0 or 1 to make the
  /// recursion deep on small inputs.
  int d_cross_first_guess = -1;
};

/// \ingroup PkgDelaunayFromPredictionRef
/// Named parameters of the package; CGAL's own (`CGAL::parameters::...`) are visible here too.
namespace parameters {
using namespace CGAL::parameters;

/*!
\ingroup PkgDelaunayFromPredictionRef
A chain of named parameters that starts with one of the package's: a
`CGAL::Named_function_parameters` (every function of \cgal and of the package reads it as one)
whose members add the package's parameters, so that they chain as \cgal's do:
`DFP::parameters::max_flips(1000).strategy(DFP::Strategy::flips).screen_prediction(false)`.
\cgal's own members (such as `.geom_traits()`) chain too, but return a plain
`CGAL::Named_function_parameters`, after which the package's parameters are added with their
two-argument form: `max_flips(1000, CGAL::parameters::geom_traits(gt))`.
*/
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// the \cgal chain this is.
  using Chain = CGAL::Named_function_parameters<T, Tag, Base>;
  /// constructs the chain of one parameter.
  /// \param v the value of the parameter.
  explicit Named_parameters(const T& v) : Chain(v) {}
  /// constructs the chain of a parameter followed by a chain.
  /// \param v the value of the parameter.
  /// \param next the chain that follows it.
  Named_parameters(const T& v, const Base& next) : Chain(v, next) {}

#define CGAL_DFP_CHAINED_PARAMETER(NAME)                                                         \
  template <class V>                                                                           \
  Named_parameters<V, internal_np::NAME##_t, Chain> NAME(const V& v) const                     \
  {                                                                                            \
    return Named_parameters<V, internal_np::NAME##_t, Chain>(v, *this);                        \
  }
  /// \name Chained package parameters
  /// Each adds the named parameter of the same name (see the free functions) to the chain.
  /// @{
  CGAL_DFP_CHAINED_PARAMETER(max_flips)
  CGAL_DFP_CHAINED_PARAMETER(screen_prediction)
  CGAL_DFP_CHAINED_PARAMETER(strategy)
  CGAL_DFP_CHAINED_PARAMETER(region_size)
  /// adds the named parameter `strategy` with the strategy `S` known at compile time: the
  /// call compiles the code of `S` only (see `Strategy_constant`).
  /// \returns the chain with the parameter added.
  template <Strategy S>
  Named_parameters<Strategy_constant<S>, internal_np::strategy_t, Chain> strategy() const
  {
    return Named_parameters<Strategy_constant<S>, internal_np::strategy_t, Chain>(Strategy_constant<S>(), *this);
  }
  CGAL_DFP_CHAINED_PARAMETER(disk_order)
  CGAL_DFP_CHAINED_PARAMETER(split_method)
  CGAL_DFP_CHAINED_PARAMETER(sample_probability)
  CGAL_DFP_CHAINED_PARAMETER(visitor)
  CGAL_DFP_CHAINED_PARAMETER(tuning)
  /// @}
#undef CGAL_DFP_CHAINED_PARAMETER
};

/// limits the number of edge flips; past it the call finishes with a from-scratch build.
/// \param v the largest number of flips (a `std::size_t`).
/// \returns the named parameter `max_flips` with value `v`.
template <class T>
Named_parameters<T, internal_np::max_flips_t> max_flips(const T& v)
{
  return Named_parameters<T, internal_np::max_flips_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::max_flips_t, CGAL::Named_function_parameters<A, B, C>>
max_flips(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::max_flips_t,
                                         CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// enables (default) or disables the sampling screen that rejects a prediction at once when
/// sampled faces have sampled points inside their circumcircles.
/// \param v `true` to screen the prediction (a `bool`).
/// \returns the named parameter `screen_prediction` with value `v`.
template <class T>
Named_parameters<T, internal_np::screen_prediction_t> screen_prediction(const T& v)
{
  return Named_parameters<T, internal_np::screen_prediction_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::screen_prediction_t, CGAL::Named_function_parameters<A, B, C>>
screen_prediction(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::screen_prediction_t,
                                         CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// chooses how the prediction is used, see `Strategy`.
/// \param v a `Strategy`.
/// \returns the named parameter `strategy` with value `v`.
template <class T>
Named_parameters<T, internal_np::strategy_t> strategy(const T& v)
{
  return Named_parameters<T, internal_np::strategy_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::strategy_t, CGAL::Named_function_parameters<A, B, C>>
strategy(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::strategy_t,
                                         CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// chooses the strategy `S` at compile time: the call compiles the code of `S` only, where
/// `strategy(S)` compiles every strategy (see `Strategy_constant`).
/// \tparam S a `Strategy`.
/// \returns the named parameter `strategy` with value `Strategy_constant<S>`.
template <Strategy S>
Named_parameters<Strategy_constant<S>, internal_np::strategy_t> strategy()
{
  return Named_parameters<Strategy_constant<S>, internal_np::strategy_t>(Strategy_constant<S>());
}
/// same, chained in front of other named parameters.
/// \tparam S a `Strategy`.
/// \param np the named parameters to chain after it.
/// \returns the chain `Strategy_constant<S>`, then `np`.
template <Strategy S, class A, class B, class C>
Named_parameters<Strategy_constant<S>, internal_np::strategy_t, CGAL::Named_function_parameters<A, B, C>>
strategy(const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<Strategy_constant<S>, internal_np::strategy_t, CGAL::Named_function_parameters<A, B, C>>(
      Strategy_constant<S>(), np);
}

/// sets the number of faces t of a region of `Strategy::t_division` (default: n/32 for n
/// points, at least 64 and at most 4096; the paper's proof takes log2(n)^2, which was measured
/// twice as slow at 1e6 points, see the user manual) and of `Strategy::regions` (default: two
/// regions per thread and at least four, that is 2n / (2 max(2, threads)) faces, at least 64).
/// \param v the region size (a `std::size_t`).
/// \returns the named parameter `region_size` with value `v`.
template <class T>
Named_parameters<T, internal_np::region_size_t> region_size(const T& v)
{
  return Named_parameters<T, internal_np::region_size_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::region_size_t, CGAL::Named_function_parameters<A, B, C>>
region_size(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::region_size_t,
                                         CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// chooses the insertion order of `Imprecise_points_2`, see `Disk_order`.
/// \param v a `Disk_order`.
/// \returns the named parameter `disk_order` with value `v`.
template <class T>
Named_parameters<T, internal_np::disk_order_t> disk_order(const T& v)
{
  return Named_parameters<T, internal_np::disk_order_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::disk_order_t, CGAL::Named_function_parameters<A, B, C>>
disk_order(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::disk_order_t, CGAL::Named_function_parameters<A, B, C>>(v,
                                                                                                                 np);
}
/// chooses how `split_delaunay()` works, see `Split_method`.
/// \param v a `Split_method`.
/// \returns the named parameter `split_method` with value `v`.
template <class T>
Named_parameters<T, internal_np::split_method_t> split_method(const T& v)
{
  return Named_parameters<T, internal_np::split_method_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::split_method_t, CGAL::Named_function_parameters<A, B, C>>
split_method(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::split_method_t, CGAL::Named_function_parameters<A, B, C>>(
      v, np);
}
/// sets the probability with which `brio_dc_delaunay()` puts in the next sample a point that is
/// not matched on its component's cycle (the paper's value is 1/2; the default 1/8).
/// \param v a probability in \f$(0, 1]\f$ (a `double`).
/// \returns the named parameter `sample_probability` with value `v`.
template <class T>
Named_parameters<T, internal_np::sample_probability_t> sample_probability(const T& v)
{
  return Named_parameters<T, internal_np::sample_probability_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::sample_probability_t, CGAL::Named_function_parameters<A, B, C>>
sample_probability(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::sample_probability_t,
                                         CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// sets the visitor told of each stage of `delaunay_from_prediction()` and `make_delaunay()`
/// as it begins and ends, see `Default_visitor` (the default, which does nothing) and `Stage`.
/// The chain holds a copy: pass `std::ref(v)` to have `v` itself called.
/// \param v a visitor (a class with `stage_begin(Stage)` and `stage_end(Stage)`), or a
///        `std::reference_wrapper` of one.
/// \returns the named parameter `visitor` with value `v`.
template <class T>
Named_parameters<T, internal_np::visitor_t> visitor(const T& v)
{
  return Named_parameters<T, internal_np::visitor_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::visitor_t, CGAL::Named_function_parameters<A, B, C>>
visitor(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::visitor_t, CGAL::Named_function_parameters<A, B, C>>(v, np);
}

/// sets the thresholds of `delaunay_from_prediction()` and `make_delaunay()`, see `Tuning`:
/// for experiments and tests; the defaults are measured.
/// \param v a `Tuning`.
/// \returns the named parameter `tuning` with value `v`.
template <class T>
Named_parameters<T, internal_np::tuning_t> tuning(const T& v)
{
  return Named_parameters<T, internal_np::tuning_t>(v);
}
/// same, chained in front of other named parameters.
/// \param v the value of the parameter.
/// \param np the named parameters to chain after it.
/// \returns the chain `v`, then `np`.
template <class T, class A, class B, class C>
Named_parameters<T, internal_np::tuning_t, CGAL::Named_function_parameters<A, B, C>>
tuning(const T& v, const CGAL::Named_function_parameters<A, B, C>& np)
{
  return Named_parameters<T, internal_np::tuning_t, CGAL::Named_function_parameters<A, B, C>>(v, np);
}
} // namespace parameters
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_PARAMETERS_H
