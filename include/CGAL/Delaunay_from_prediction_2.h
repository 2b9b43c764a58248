// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points: the Delaunay triangulation of points from a predicted triangulation.
// Pipeline, one module per stage:
//   check   internal/input_check.h        malformed input -> Invalid_prediction, nothing touched
//   import, certify, export (fused)
//           internal/import_prediction.h  index triples -> CGAL TDS, twins by counting sort,
//                                         in-circle test of each edge as its twins pair up
//           internal/tds_certify.h        the same certificate read off a CGAL triangulation
//   local repair (a prediction that is not a triangulation)
//           internal/carve_repair.h       untangling flips, carving, holes, reinsertion
//           internal/ear_clipping.h       the hole filler
//           internal/region_repair.h      the t-division repair (Theorem 2.1)
//   repair  internal/lawson_flip.h        Lawson flips seeded with the failing edges
//           internal/rebuild.h            the package's insertion (point_insertion.h) for points
//                                         no face uses, from-scratch fallbacks, in-place
//                                         rebuilds keeping vertices

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_2_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/carve_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/import_prediction.h>
#include <CGAL/Delaunay_from_prediction/internal/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/region_repair.h>
#include <CGAL/Delaunay_from_prediction/internal/sort_addresses.h>
#include <CGAL/Delaunay_from_prediction/internal/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/tds_certify.h>

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

namespace internal {

// Default flip budget. Lawson's algorithm needs about as many flips as the prediction has
// wrong edges, and falls back at once when the failing edges alone exceed the budget. A flip
// with its re-tests costs about 0.4 of a point insertion of a rebuild (measured: 0.42 us per
// flip against about 1 us per point at 1e6 points), so 3n/4 wasted flips add at most about
// 0.3 of a rebuild; moves of 0.1 spacing need 0.44n (1e6 points) to 0.5n (5000 points), a
// plain Triangulation_2 of random points ~6n, which is cheaper to rebuild.
inline std::size_t default_max_flips(std::size_t n) { return 3 * n / 4 + 64; }

// Statistics::fallback_reason for Strategy::rebuild.
constexpr const char* rebuild_requested = "the rebuild strategy was chosen";
// Statistics::fallback_reason for Strategy::spanning_tree.
constexpr const char* spanning_tree_requested = "the spanning_tree strategy was chosen";

// Number of distinct faces in `faces`, not counting those whose address is in `except`.
template <class Face_handle>
std::size_t count_distinct(const std::vector<Face_handle>& faces,
                           std::vector<const void*> except = std::vector<const void*>())
{
  using Face = std::remove_cv_t<std::remove_reference_t<decltype(*faces.front())>>;
  std::sort(except.begin(), except.end());
  return count_distinct_addresses<Face>(std::vector<const void*>(), faces, 0, [&](const void* a) {
    return !std::binary_search(except.begin(), except.end(), a);
  });
}

// Limits of the local repair for `n` points. Measured at 1e6 points (moves of 0.1 spacing:
// 4.6% of the faces inverted, 0.19 n faces carved), the repair as a whole cost about a
// rebuild, the planning alone about 1.5 us per carved face; past n/8 carved faces a rebuild is
// cheaper.
inline Carve_limits default_carve_limits(std::size_t n)
{
  Carve_limits limits;
  limits.max_removed_faces = n / 8 + 64;
  limits.max_bad_faces = n / 16 + 16;
  return limits;
}

// Whether two of `tr`'s finite vertices, one of them in `candidates`, are at the same point.
// Coordinates that are doubles are compared bit for bit through a hash table of the
// candidates (one pass over the vertices, a few ns each); other number types by an exact
// binary search among the sorted candidates.
template <class Triangulation>
bool has_duplicate_of(const Triangulation& tr,
                      const std::vector<typename Triangulation::Vertex_handle>& candidates)
{
  using Point = typename Triangulation::Point;
  if(candidates.empty())
    return false;
  if constexpr(std::is_same<std::decay_t<decltype(CGAL::to_double(std::declval<Point>().x()))>, double>::value &&
               std::is_same<std::decay_t<decltype(std::declval<Point>().x())>, double>::value) {
    auto bits = [](double x) {
      x = (x == 0) ? 0.0 : x; // -0 == +0
      std::uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      return b;
    };
    std::size_t size = 64;
    int log_size = 6;
    while(size < 4 * candidates.size()) {
      size <<= 1;
      ++log_size;
    }
    struct Slot { std::uint64_t x, y; const void* v; };
    std::vector<Slot> table(size, Slot{0, 0, nullptr});
    auto hash = [](std::uint64_t x, std::uint64_t y) { return (x * 0x9E3779B97F4A7C15ull) ^ (y * 0xC2B2AE3D27D4EB4Full); };
    auto slot_of = [&](std::uint64_t x, std::uint64_t y, std::uint64_t h) {
      std::size_t i = std::size_t(h) & (size - 1);
      while(table[i].v != nullptr && (table[i].x != x || table[i].y != y))
        i = (i + 1) & (size - 1);
      return i;
    };
    // The table outgrows the caches (24 bytes a slot); a filter of 4 bits a slot, by other
    // bits of the hash, stays in them and turns away almost every vertex before the table.
    const int log_filter = log_size + 2;
    std::vector<std::uint64_t> filter((std::size_t(1) << log_filter) / 64 + 1, 0);
    auto filter_bit = [&](std::uint64_t h) { return std::size_t(h >> (64 - log_filter)); };
    for(const auto& v : candidates) {
      const std::uint64_t x = bits(v->point().x()), y = bits(v->point().y()), h = hash(x, y);
      Slot& s = table[slot_of(x, y, h)];
      if(s.v != nullptr)
        return true;
      s = Slot{x, y, &*v};
      filter[filter_bit(h) >> 6] |= std::uint64_t(1) << (filter_bit(h) & 63);
    }
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const std::uint64_t x = bits(v->point().x()), y = bits(v->point().y()), h = hash(x, y);
      if(((filter[filter_bit(h) >> 6] >> (filter_bit(h) & 63)) & 1) == 0)
        continue;
      const Slot& s = table[slot_of(x, y, h)];
      if(s.v != nullptr && s.v != &*v)
        return true;
    }
    return false;
  } else {
    auto less = [&](const Point& a, const Point& b) { return tr.geom_traits().compare_xy_2_object()(a, b) == SMALLER; };
    std::vector<std::pair<Point, const void*>> sorted;
    for(const auto& v : candidates)
      sorted.emplace_back(v->point(), &*v);
    std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) { return less(a.first, b.first); });
    for(std::size_t k = 1; k < sorted.size(); ++k)
      if(!less(sorted[k - 1].first, sorted[k].first))
        return true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const auto it = std::lower_bound(sorted.begin(), sorted.end(), v->point(),
                                       [&](const auto& a, const Point& p) { return less(a.first, p); });
      if(it != sorted.end() && !less(v->point(), it->first) && it->second != &*v)
        return true;
    }
    return false;
  }
}

// make_delaunay's local repair of a triangulation with faces that are not counterclockwise
// (`bad`): carves the stars of their vertices, fills the holes, reinserts those vertices
// (same objects), then flips. Returns null on success; otherwise why not, with `tr` either
// as it was (the carve did not fit the budget, or the result would not be a triangulation:
// rolled back) or a valid triangulation of the same vertices (the flip budget ran out).
// Never throws for duplicates: it returns first, and the caller's rebuild names them.
template <class Triangulation>
const char* carve_in_place(Triangulation& tr, const std::vector<typename Triangulation::Face_handle>& bad,
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
  const char* why = carve.plan(default_carve_limits(tr.number_of_vertices()));
  stats.carve_rounds = carve.rounds();
  if(why != nullptr)
    return why;
  if(has_duplicate_of(tr, carve.detached()))
    return "two vertices are at the same point";
  carve.commit(stack);
  if(!carve.finish_hull(stack, stats.flips)) {
    carve.rollback(flip_log); // the flips before the carve can still be undone
    return "the kept faces and the filled holes do not form a triangulation";
  }
  std::vector<const void*> modified;
  carve.reinsert(stack, modified, [](auto, auto) {
    CGAL_assertion_msg(false, "duplicates were ruled out before the carve");
  });
  stats.faces_carved = carve.faces_removed();
  stats.holes_refilled = carve.holes();
  stats.points_reinserted = carve.detached().size();
  if(!lawson_flip(tr, stack, max_flips, stats.flips, touched))
    return flip_budget_exhausted;
  // The predicted faces modified: those flipped (before the carve or after it) that were
  // neither carved nor made by the repair, and those insertion split.
  stats.faces_certified =
      stats.faces_in - stats.faces_carved -
      count_distinct_addresses<typename Triangulation::Face>(
          modified, touched, 0, [&](const void* f) { return !carve.is_removed(f) && !carve.is_created(f); });
  return nullptr;
}

// Budget of Strategy::t_division for n vertices, in point insertions (|V_B| plus four times
// the vertices to reinsert, see Region_repair::plan()): about a rebuild. Tests raise it to
// reach the repair on small, badly damaged inputs.
#ifndef CGAL_DELAUNAY_FROM_PREDICTION_T_DIVISION_BUDGET
#define CGAL_DELAUNAY_FROM_PREDICTION_T_DIVISION_BUDGET(n) (n)
#endif

// Strategy::t_division on the valid triangulation `tr` (region_repair.h): the faces in `bad`
// are not counterclockwise; the failing edges are those of `stack` (when `stack_fails`), or
// those of its edges that fail the in-circle test. Replaces the bad regions and reinserts
// their inner vertices, leaving the flips to the caller; returns null then, otherwise why not
// with `tr` untouched. With `check_duplicates`, returns first if a vertex to reinsert is at
// the point of another; otherwise `on_duplicate(v, w)` handles it as in reinsert_vertex_objects().
template <class Triangulation, class OnDuplicate, class MadeEarlier = bool (*)(const void*)>
const char* repair_by_regions(Triangulation& tr, std::unique_ptr<Region_repair<Triangulation>>& regions,
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
  const std::size_t budget = CGAL_DELAUNAY_FROM_PREDICTION_T_DIVISION_BUDGET(n);
  if(double(bad.size() + failing.size()) * double(region_size) > 0.15 * double(budget))
    return "the damage would make the t-division cost more than a rebuild";
  regions.reset(new Region_repair<Triangulation>(tr, region_size));
  for(const auto f : bad)
    regions->mark_bad_face(f);
  for(const auto& e : failing)
    regions->mark_failing_edge(e.first, e.second);
  if(!hull_is_convex)
    regions->mark_hull_if_not_convex();
  const char* why = regions->plan(budget);
  stats.regions = regions->regions();
  stats.bad_regions = regions->bad_regions();
  stats.boundary_vertices = regions->boundary_vertices();
  if(why != nullptr)
    return why;
  if(check_duplicates && has_duplicate_of(tr, regions->detached()))
    return "two vertices are at the same point";
  // Faces an earlier stage made (the carve's fill, the import's) are not predicted faces:
  // not counted as carved.
  stats.faces_carved += regions->faces_removed_if([&](const void* f) { return !made_earlier(f); });
  regions->commit(stack);
  regions->reinsert(stack, modified, on_duplicate);
  stats.holes_refilled += regions->holes();
  stats.points_reinserted += regions->detached().size();
  return nullptr;
}

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulation of `points` into `dt`, using `faces` as a prediction of it.

The result is exactly the triangulation CGAL's `Delaunay_triangulation_2` builds from the same
points: co-circular ties are broken by CGAL's symbolic perturbation. The time it takes depends
on how good the prediction is. When `faces` is a triangulation of the points, it is certified
in linear time and repaired by Lawson flips that start only at its non-locally-Delaunay edges;
points used by no face are then inserted. Any other prediction (degenerate, crossing, repeated
or overlapping faces, holes, faces missing at the hull) is not an error: the faces that cannot
be kept are left out or carved, the holes retriangulated and the vertices left without a face
reinserted, then the flips run (see the user manual, "Local Repair"). A prediction too damaged
for that to pay off is rebuilt from scratch (`Statistics::fell_back`).

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
      prediction or an inexact kernel that could make Lawson's algorithm cycle}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{three quarters of the number of points, plus 64}
  \cgalParamNEnd
  \cgalParamNBegin{screen_prediction}
    \cgalParamDescription{whether to draw 32 faces and 16 points at random first, and to build
      from scratch at once if more than half of the faces have a drawn point inside their
      circumcircle (a prediction that far from Delaunay would cost more to repair than to
      rebuild). Only used for at least 4096 points and faces with random access.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{strategy}
    \cgalParamDescription{how the prediction is used, see `Strategy`}
    \cgalParamType{`Strategy`}
    \cgalParamDefault{`Strategy::automatic`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a point has a non-finite coordinate, or a face has an index out
        of range or repeats an index. Then `dt` is unchanged.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
is built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class PointRange, class FaceRange, class DT,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_prediction(const PointRange& points, const FaceRange& faces, DT& dt,
                                    const NamedParameters& np = parameters::default_values())
{
  if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(dt, [&](auto& level0) { return delaunay_from_prediction(points, faces, level0, np); });
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;

  Statistics stats;
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t number_of_faces = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  stats.faces_in = number_of_faces;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(n));
  const bool screen = choose_parameter(get_parameter(np, internal_np::screen_prediction), true);
  const Strategy strategy = choose_parameter(get_parameter(np, internal_np::strategy), Strategy::automatic);
  const bool carve = strategy == Strategy::automatic || strategy == Strategy::carve ||
                     strategy == Strategy::t_division;
  const std::size_t region_size = choose_parameter(get_parameter(np, internal_np::region_size),
                                                   internal::default_region_size(n));
  const auto& gt = dt.geom_traits();

  // Check, then import and certify into a fresh triangulation (Invalid_prediction is thrown
  // before `dt` is touched).
  internal::check_points_are_finite(point_at, n);
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    // Inexact predicates (internal/exact_predicates.h): the faces are only checked (malformed
    // ones throw), the faces are decided by exact predicates (rebuild.h).
    std::size_t k = 0, idx[3];
    for(const auto& face : faces)
      internal::read_face(face, k++, n, idx);
    DT built(gt);
    internal::build_with_exact_predicates(built, point_at, n, stats);
    dt.swap(built);
    return stats;
  }
  DT result(gt);
  internal::Imported_prediction<DT> imported;
  auto read_all_faces = [&] {
    std::size_t k = 0, idx[3];
    for(const auto& face : faces)
      internal::read_face(face, k++, n, idx);
  };
  if(strategy == Strategy::rebuild || strategy == Strategy::spanning_tree) {
    read_all_faces();
    imported.failure = strategy == Strategy::rebuild ? internal::rebuild_requested : internal::spanning_tree_requested;
  } else if(screen && internal::fails_sampling_screen(gt, point_at, n, faces, number_of_faces)) {
    read_all_faces();
    imported.failure = "most sampled faces have sampled points inside their circumcircles";
  } else {
    internal::Prediction_importer<DT>::run(result, point_at, n, faces, number_of_faces, imported, carve);
  }

  // The global fallback, a build from scratch: in spatial order, or, with
  // Strategy::spanning_tree, along a spanning tree of the faces' edges (Corollaries 3.4 and
  // 3.5). Measured at 1e6 points on predictions that fall back (points moved by 0.3 to 1
  // spacing, 1% of the points relabelled, random triples; bench_fallback.cpp), the spatial
  // order was as fast to 26% faster: the default.
  auto build_from_scratch = [&](const char* why) {
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
    if(strategy != Strategy::spanning_tree || n >= std::size_t(internal::no_rank)) {
      internal::build_from_scratch(fresh, point_at, n, stats, grid_order);
    } else {
      // Two edges of each face keep its three corners connected.
      std::vector<std::uint32_t> ends;
      ends.reserve(4 * number_of_faces);
      std::size_t k = 0, idx[3];
      for(const auto& face : faces) {
        internal::read_face(face, k++, n, idx);
        ends.insert(ends.end(), {std::uint32_t(idx[0]), std::uint32_t(idx[1]), std::uint32_t(idx[1]),
                                 std::uint32_t(idx[2])});
      }
      internal::build_along_edges(fresh, point_at, n, ends, stats);
    }
    stats.fallback_reason = why;
    dt.swap(fresh);
    return stats;
  };
  stats.input_reordered = imported.reordered;
  if(imported.failure != nullptr)
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
  // algorithm needs at least as many flips as there are failing edges: past the budget, the
  // flips would be wasted.
  if(imported.not_locally_delaunay.size() > max_flips)
    return build_from_scratch(internal::flip_budget_exhausted);
  std::vector<std::pair<Face_handle, int>>& stack = imported.not_locally_delaunay;
  std::vector<const void*> modified; // predicted faces changed by the repair
  std::unique_ptr<internal::Carve_repair<DT>> repair;
  // Tracing and filling holes costs about 2 us per boundary half-edge at 1e6 points (measured:
  // 1% of a DT's faces deleted, 60,000 such half-edges, 0.12 s, before the import filled the
  // small holes itself; these are the half-edges it left), a rebuild about 0.75 us per
  // point: past n/4 of them the repair would cost more than the rebuild it avoids.
  if(imported.needs_repair && imported.open_halfedges.size() > n / 4 + 64)
    return build_from_scratch("too many holes for a local repair");
  if(imported.needs_repair) {
    // The faces kept are not a triangulation with a convex hull: fill the holes and close
    // the hull (carve_repair.h); vertices left without a face are reinserted.
    repair.reset(new internal::Carve_repair<DT>(result, false));
    repair->expect_outer_cycle();
    // Faces that overlap without sharing an edge on one side (none left out) still meet at a
    // vertex in several fans: a vertex of a carved star may keep a closed fan elsewhere.
    repair->expect_several_fans();
    if(imported.faces_dropped > 0) // faces overlapped: some may still overlap unseen
      internal::carve_vertices_wound_twice(result, *repair);
    for(const auto& e : imported.open_halfedges)
      repair->add_open_halfedge(e.first, e.second);
    const char* why = repair->plan(internal::default_carve_limits(n));
    stats.carve_rounds = (std::max)(stats.carve_rounds, repair->rounds());
    if(why != nullptr)
      return build_from_scratch(why);
    repair->commit(stack);
    if(!repair->finish_hull(stack, stats.flips))
      return build_from_scratch("the kept faces and the filled holes do not form a triangulation");
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
  }
  std::unique_ptr<internal::Region_repair<DT>> regions;
  if(strategy == Strategy::t_division) {
    std::size_t duplicates = 0;
    const char* why = internal::repair_by_regions(
        result, regions, std::vector<Face_handle>(), true, stack, !repair, region_size, modified, stats, false,
        [&](Vertex_handle v, Vertex_handle same) {
          internal::merge_index_info_of(same, v);
          result.tds().delete_vertex(v);
          ++duplicates;
        },
        [&](const void* f) { return (repair && repair->is_created(f)) || filled_by_import(f); });
    // When the t-division does not pay (or cannot be planned), `result` is untouched: a
    // valid triangulation after the carve, which the flips finish as with Strategy::carve.
    if(why != nullptr)
      regions.reset();
    stats.duplicate_points += duplicates;
  }
  auto made_by_repair = [&](const void* f) {
    return (repair && repair->is_created(f)) || (regions && regions->is_created(f)) || filled_by_import(f);
  };
  std::vector<Face_handle> touched;
  // Points reinserted by the t-division make a few flips each, on top of the budget.
  const std::size_t flip_budget = max_flips + (regions ? 4 * regions->detached().size() : 0);
  if(!internal::lawson_flip(result, stack, flip_budget, stats.flips, touched))
    return build_from_scratch(internal::flip_budget_exhausted);

  // Points no face uses: duplicates of vertices, or points to insert.
  std::vector<std::size_t>& unused = imported.unused_points;
  stats.points_unused = unused.size();
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
    if(!unused.empty())
      internal::insert_points(result, point_at, unused, stats, &new_vertices);
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
the same vertex objects (`Statistics::fell_back`).
With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the faces are
always rebuilt around the same vertex objects, decided by exact predicates on the coordinates
rounded to double (`Statistics::fell_back`): see \ref dfpInexactKernels.

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
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if two vertices are at the same point, naming both (by their rank
        in finite-vertex order). Then `tr` is unchanged.
*/
template <class Triangulation, class NamedParameters = parameters::Default_named_parameters>
Statistics make_delaunay(Triangulation& tr, const NamedParameters& np = parameters::default_values())
{
  if constexpr(internal::is_triangulation_hierarchy<Triangulation>::value) { // level 0, then the upper levels
    return internal::with_levels_rebuilt(tr, [&](auto& level0) { return make_delaunay(level0, np); });
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using Face_handle = typename Triangulation::Face_handle;

  Statistics stats;
  stats.faces_in = tr.dimension() == 2 ? tr.number_of_faces() : 0;
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 internal::default_max_flips(tr.number_of_vertices()));
  const Strategy strategy = choose_parameter(get_parameter(np, internal_np::strategy), Strategy::automatic);
  if(tr.number_of_vertices() == 0)
    return stats;
  // Inexact predicates (internal/exact_predicates.h): flips, walks and certificates could
  // cycle or corrupt; the faces are rebuilt around the same vertices, decided by exact predicates.
  if constexpr(internal::decides_by_exact_predicates<typename Triangulation::Geom_traits>::value) {
    stats.fell_back = true;
    stats.fallback_reason = internal::inexact_predicates;
    internal::rebuild_keeping_vertices(tr, stats); // leaves `tr` as it is when it throws
    return stats;
  }

  const bool carve = strategy == Strategy::automatic || strategy == Strategy::carve;
  const bool divide = strategy == Strategy::t_division;
  const std::size_t region_size = choose_parameter(get_parameter(np, internal_np::region_size),
                                                   internal::default_region_size(tr.number_of_vertices()));
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
  // regions from the edges that fail in the prediction as given.
  internal::Inline_flips<Triangulation> inline_flips{max_flips, stats.flips, touched, flips_before_carve};
  const char* why = strategy == Strategy::rebuild || strategy == Strategy::spanning_tree
                        ? internal::rebuild_requested
                        : internal::certify_triangulation(tr, stack, stats.edges_tested, hull_is_convex,
                                                          carve || divide ? &bad : nullptr, max_bad,
                                                          divide ? nullptr : &inline_flips);
  if(why == nullptr)
    stats.edges_not_locally_delaunay = divide ? stack.size() : inline_flips.edges_failing;
  // Lawson needs at least a flip per failing edge: past the budget, the flips are wasted.
  if(why == nullptr && stats.edges_not_locally_delaunay > max_flips)
    why = internal::flip_budget_exhausted;
  // Faces that are not ccw: first untangled by flips, then the rest carved (carve_repair.h).
  if(why == nullptr && divide) {
    // Theorem 2.1 (region_repair.h). If it does not pay or cannot be planned, `tr` is
    // untouched and the carve takes over; if the flip budget runs out, `tr` is a valid
    // triangulation of the same vertices, rebuilt below.
    std::unique_ptr<internal::Region_repair<Triangulation>> regions;
    std::vector<const void*> modified;
    why = internal::repair_by_regions(tr, regions, bad, hull_is_convex, stack, true, region_size, modified,
                                      stats, true, [](auto, auto) {
                                        CGAL_assertion_msg(false, "duplicates were ruled out before");
                                      });
    if(why == nullptr) {
      // Reinserted points make a few flips each, as in any incremental construction: they
      // count on top of the budget for the repair of the prediction.
      if(internal::lawson_flip(tr, stack, max_flips + 4 * regions->detached().size(), stats.flips, touched)) {
        stats.faces_certified = stats.faces_in - stats.faces_carved -
                                internal::count_distinct_addresses<typename Triangulation::Face>(
                                    modified, touched, 0, [&](const void* f) { return !regions->is_created(f); });
        return stats;
      }
      why = internal::flip_budget_exhausted;
    } else {
      // Not worth dividing, or no plan: `tr` is untouched, the carve below takes over.
      why = nullptr;
    }
  }
  if(why == nullptr && !bad.empty()) {
    const std::size_t inline_flipped = flips_before_carve.size();
    internal::untangle_by_flips(tr, bad, stack, flips_before_carve, touched);
    stats.flips += flips_before_carve.size() - inline_flipped;
    if(!bad.empty()) {
      why = internal::carve_in_place(tr, bad, stack, touched, flips_before_carve, max_flips, stats);
      if(why == nullptr)
        return stats;
      if(why == internal::flip_budget_exhausted)
        flips_before_carve.clear(); // the carve was committed: a triangulation again, nothing to undo
    }
  }
  std::vector<const void*> hull_faces; // finite faces made by convexify_hull
  if(why == nullptr && !hull_is_convex &&
     !internal::convexify_hull(tr, stack, hull_faces, stats.flips))
    why = "the hull is not a convex polygon wound once, and no flip of hull edges makes it one";
  if(why == nullptr) {
    if(internal::lawson_flip(tr, stack, max_flips, stats.flips, touched)) {
      stats.faces_certified = stats.faces_in - internal::count_distinct(touched, hull_faces);
      return stats;
    }
    why = internal::flip_budget_exhausted;
    flips_before_carve.clear(); // a triangulation again: no duplicates, nothing to undo
  }
  stats.fell_back = true;
  stats.fallback_reason = why;
  stats.faces_certified = 0;
  stats.points_reinserted = 0;
  try {
    internal::rebuild_keeping_vertices(tr, stats); // leaves `tr` as it is when it throws
  } catch(const Invalid_prediction&) {
    internal::undo_flips(tr, flips_before_carve);
    throw;
  }
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_2_H
