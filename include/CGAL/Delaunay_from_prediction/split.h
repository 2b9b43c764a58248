// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point: DT(S1) and DT(S2) from DT(S1 u S2) (B. Chazelle, O. Devillers, F. Hurtado,
// M. Mora, V. Sacristan, M. Teillaud, "Splitting a Delaunay triangulation in linear time"):
// the paper's randomized algorithm, and the faster default that inserts each part in the
// spatial order DT(S)'s vertices already have.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_SPLIT_H
#define CGAL_DELAUNAY_FROM_PREDICTION_SPLIT_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/randomized_split.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the Delaunay triangulations of the two parts of the vertices of a Delaunay
triangulation: `dt1` receives \f$DT(S_1)\f$, the vertices `v` for which `is_in_first(v)` is
`true`, and `dt2` receives \f$DT(S_2)\f$, the others (B. Chazelle, O. Devillers, F. Hurtado, M. Mora,
V. Sacristan, M. Teillaud, "Splitting a Delaunay triangulation in linear time").

By default (`Split_method::ordered`) each part is inserted in the order of `dt`'s vertices when
that order is spatially coherent, as it is after \cgal's range insertion (so no sort is
needed), and in the package's grid order otherwise (no bound is proven for either);
`Split_method::randomized` runs the paper's algorithm, expected linear time in the paper
(removal of the better of two random points, nearest neighbours by growing circles,
reinsertion by walks from them; here with \cgal's vertex removal and visibility walks, so
the paper's bound is not proven for it), which measured slower (see the user manual). Either way the results are exactly \cgal's triangulations of the two parts.

\tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`.
\tparam IsInFirst a function object taking a `DT::Vertex_handle` and returning a `bool`.
\tparam DT1, DT2 `CGAL::Delaunay_triangulation_2<Gt, Tds1>` and `<Gt, Tds2>`, with the points of
        `DT`. When the vertices of `DT` and of `DT1` (`DT2`) both have an `info()` and the first
        is assignable to the second, it is copied. Each of `DT`, `DT1`, `DT2` may be a
        `CGAL::Triangulation_hierarchy_2`; the outputs are kept as in `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters.

\param dt the input triangulation; not modified.
\param is_in_first tells the part of each finite vertex; called once per vertex, before anything
       is modified.
\param dt1 receives \f$DT(S_1)\f$; cleared first.
\param dt2 receives \f$DT(S_2)\f$; cleared first.
\param np optional named parameters among the following ones:
\cgalNamedParamsBegin
  \cgalParamNBegin{split_method}
    \cgalParamDescription{how the triangulations are computed}
    \cgalParamType{`Split_method`}
    \cgalParamDefault{`Split_method::automatic`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the random choices of `Split_method::randomized`}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{a fixed seed}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did: `points_reinserted` (every vertex of `dt`); with
         `Split_method::randomized` also `points_located`, `faces_visited` and `walk_fallbacks`
         of the reinsertion walks.
\throws Invalid_prediction if `dt1` or `dt2` is `dt`, if `dt1` is `dt2`, or if a vertex of `dt`
        has a non-finite coordinate (named by its rank in finite-vertex order). Then nothing is
        changed. An exception thrown by `is_in_first` leaves `dt1` and `dt2` unchanged too.

With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), each part is
built from scratch, decided by exact predicates on the coordinates rounded to double
(`Statistics::fell_back`): see \ref dfpInexactKernels.
*/
template <class DT, class IsInFirst, class DT1, class DT2,
          class NamedParameters = parameters::Default_named_parameters>
Statistics split_delaunay(const DT& dt, IsInFirst is_in_first, DT1& dt1, DT2& dt2,
                          const NamedParameters& np = parameters::default_values())
{
  static_assert(std::is_same<typename DT::Point, typename DT1::Point>::value &&
                    std::is_same<typename DT::Point, typename DT2::Point>::value,
                "split_delaunay: the three triangulations must have the same point type");
  if constexpr(internal::is_triangulation_hierarchy<DT1>::value || internal::is_triangulation_hierarchy<DT2>::value) {
    bool user_threw = false; // is_in_first runs before anything is modified
    internal::Noting_throws<IsInFirst> noting{is_in_first, &user_threw};
    auto untouched = [&] { return user_threw; };
    return internal::with_levels_rebuilt_if_hierarchy(dt1, [&](auto& t1) {
      return internal::with_levels_rebuilt_if_hierarchy(dt2, [&](auto& t2) { return split_delaunay(dt, noting, t1, t2, np); }, untouched);
    }, untouched);
  } else { // the body below, not instantiated for a hierarchy
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const void* const input = &dt;
  if(input == static_cast<const void*>(&dt1) || input == static_cast<const void*>(&dt2) ||
     static_cast<const void*>(&dt1) == static_cast<const void*>(&dt2))
    throw Invalid_prediction("Delaunay_from_prediction: split_delaunay needs dt1 and dt2 to be two triangulations "
                             "other than dt");
  internal::check_vertices_are_finite(dt);
  const Split_method method = choose_parameter(get_parameter(np, internal_np::split_method), Split_method::automatic);
  const std::uint64_t seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0x5eed5117u);
  using Vertex_handle = typename DT::Vertex_handle;
  // The vertices in container order, their points and their parts (is_in_first is called
  // here, before any change): in container order the vertices are read in memory order,
  // whatever the order of their points in the plane.
  std::vector<Vertex_handle> source;
  std::vector<typename DT::Point> point;
  std::vector<unsigned char> part;
  source.reserve(dt.number_of_vertices());
  point.reserve(dt.number_of_vertices());
  part.reserve(dt.number_of_vertices());
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    source.push_back(v);
    point.push_back(v->point());
    part.push_back(is_in_first(Vertex_handle(v)) ? 0 : 1);
  }
  const std::size_t n = source.size();
  Statistics stats;
  stats.points_reinserted = n;
  dt1.clear();
  dt2.clear();
  if constexpr(internal::decides_by_exact_predicates<typename DT::Geom_traits>::value) {
    // Inexact predicates (internal/toolbox/predicates.h): each part decided by exact predicates.
    (void)method;
    (void)seed;
    auto insert_part = [&](auto& target, int which) {
      std::vector<typename DT::Point> points;
      std::vector<Vertex_handle> from;
      for(std::size_t k = 0; k < n; ++k)
        if(part[k] == which) {
          points.push_back(point[k]);
          from.push_back(source[k]);
        }
      internal::insert_with_exact_predicates(target, points.begin(), points.size(),
                                 [&](std::size_t j, auto v, bool) { internal::copy_info(from[j], v); });
    };
    insert_part(dt1, 0);
    insert_part(dt2, 1);
    stats.fell_back = true;
    stats.outcome = Outcome::inexact_predicates;
    return stats;
  }
  std::vector<typename DT1::Vertex_handle> in_first(method == Split_method::randomized ? n : 0);
  std::vector<typename DT2::Vertex_handle> in_second(method == Split_method::randomized ? n : 0);
  if(method == Split_method::randomized && dt.dimension() == 2 && n < std::size_t(internal::no_rank)) {
    std::vector<std::uint32_t> removed, neighbour;
    internal::randomized_removal_order(dt, part, removed, neighbour, seed);
    // Step 6, for all the points in turn: reinsertion in reverse order of removal, each point
    // located by a walk from its neighbour's vertex (inserted before it).
    const std::size_t cap = internal::walk_cap(n);
    auto point_at = [&](std::size_t k) -> const typename DT::Point& { return point[k]; };
    internal::Vertex_grid<typename DT1::Vertex_handle> grid1(n, point_at);
    internal::Vertex_grid<typename DT2::Vertex_handle> grid2(n, point_at);
    std::vector<std::pair<typename DT1::Face_handle, int>> stack1;
    std::vector<std::pair<typename DT2::Face_handle, int>> stack2;
    auto reinsert = [&](std::uint32_t p, std::uint32_t q, auto& target, auto& vertex_of, auto& grid, auto& stack) {
      using Target_vertex = typename std::decay_t<decltype(target)>::Vertex_handle;
      const Target_vertex v = q == internal::no_rank
                                  ? target.insert(point[p])
                                  : internal::insert_walking_from(target, point[p], vertex_of[q], cap, grid, stack, stats);
      internal::copy_info(source[p], v);
      vertex_of[p] = v;
      grid.record(point[p], v);
    };
    for(std::size_t k = n; k-- > 0;) {
      if(part[removed[k]] == 0)
        reinsert(removed[k], neighbour[k], dt1, in_first, grid1, stack1);
      else
        reinsert(removed[k], neighbour[k], dt2, in_second, grid2, stack2);
    }
    return stats;
  }
  // Split_method::ordered (and the randomized method below dimension 2, or for 2^32 - 1
  // vertices or more, beyond its 32-bit indices).
  const bool in_order =
      internal::order_looks_spatial(n, [&](std::size_t k) -> const typename DT::Point& { return point[k]; });
  std::vector<std::size_t> first, second;
  for(std::size_t k = 0; k < n; ++k)
    (part[k] == 0 ? first : second).push_back(k);
  // Each part in its insertion order, its points and vertices gathered first: read in that
  // order from `dt`'s order they would be cache misses the insertion waits for.
  auto insert_part = [&](auto& target, std::vector<std::size_t>& indices) {
    if(!in_order)
      internal::sort_along_grid(indices, [&](std::size_t k) -> const typename DT::Point& { return point[k]; }, true);
    std::vector<typename DT::Point> gathered(indices.size());
    std::vector<Vertex_handle> from(indices.size());
    for(std::size_t j = 0; j < indices.size(); ++j) {
      gathered[j] = point[indices[j]];
      from[j] = source[indices[j]];
    }
    std::vector<std::size_t> local(indices.size());
    for(std::size_t j = 0; j < local.size(); ++j)
      local[j] = j;
    internal::insert_by_index(
        target, gathered.begin(), local,
        [&](std::size_t j, auto v, bool) {
#if defined(__GNUC__)
          if(j + 16 < from.size())
            __builtin_prefetch(&*from[j + 16]); // its info() is copied 16 insertions later
#endif
          internal::copy_info(from[j], v);
        },
        true);
  };
  insert_part(dt1, first);
  insert_part(dt2, second);
  return stats;
  } // not a hierarchy
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_SPLIT_H
