// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The closeness measures of Table 1 of "Delaunay Triangulations with Predictions" between a
// predicted triangulation G and DT(P), computed exactly:
//   D, D_local                      one pass over G's edges, O(n) after DT(P);
//   D_cross, d_cross                a straight walk in DT(P) along each wrong edge of G,
//                                   O(n + D_cross) plus one circulation per walked edge;
//   D_vio, d_vio                    a search in DT(P) from a vertex of each wrong triangle of G
//                                   that never leaves its circumcircle, O(n + D_vio);
//   D_flip                          bounded by D <= D_flip <= (flips of Lawson's algorithm).
// Everything uses the package's perturbed in-circle test, so every measure is 0 exactly when
// G is the triangulation CGAL's Delaunay_triangulation_2 builds.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_MEASURES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_MEASURES_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/prediction_measures.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
The closeness measures of Table 1 of the paper between a prediction \f$G\f$ (index triples) and
\f$DT(P)\f$, as computed by `prediction_measures()`.

Edges are counted once however many faces list them; points at the same position count as one
point (the one of smallest index). Every measure is defined for any list of triples, by the
paper's definitions read literally; the relations between them
(\f$D_{local} \le D \le D_{flip} \le D_{cross}\f$, \f$D\f$ = `D_missing`) are guaranteed only
when `is_triangulation` is `true`.
*/
struct Prediction_measures
{
  /// number of points.
  std::size_t points = 0;
  /// number of faces of the prediction, as given.
  std::size_t faces = 0;
  /// number of distinct edges of the prediction (an edge between two points at the same
  /// position is not counted).
  std::size_t edges = 0;
  /// number of edges of \f$DT(P)\f$.
  std::size_t delaunay_edges = 0;

  /// `true` if the faces form a triangulation of the points: all points distinct and used, no
  /// degenerate, inverted (against the others), repeated or crossing face, and a union that is
  /// the convex hull.
  bool is_triangulation = false;
  /// why `is_triangulation` is `false` (empty when it is `true`).
  std::string not_a_triangulation;

  /// \f$D\f$: number of edges of \f$G\f$ that are not edges of \f$DT(P)\f$.
  std::size_t D = 0;
  /// number of edges of \f$DT(P)\f$ that are not edges of \f$G\f$ (equal to \f$D\f$ for a
  /// triangulation).
  std::size_t D_missing = 0;
  /// \f$D_{local}\f$: number of edges of \f$G\f$ with exactly two faces whose fourth point lies
  /// strictly inside the (perturbed) circumcircle of the other face. (For two faces on opposite
  /// sides of the edge this does not depend on which face is taken; for two faces folded onto
  /// the same side, the edge counts if either fourth point is inside.)
  std::size_t D_local = 0;
  /// \f$D_{cross}\f$: number of pairs (edge of \f$G\f$, edge of \f$DT(P)\f$) whose relative
  /// interiors cross in a single point.
  std::size_t D_cross = 0;
  /// \f$d_{cross}\f$: the largest number of edges of \f$DT(P)\f$ crossed by one edge of \f$G\f$.
  std::size_t d_cross = 0;
  /// \f$D_{vio}\f$: number of pairs (point, face of \f$G\f$) with the point strictly inside the
  /// (perturbed) circumcircle of the face. (Table 1 of the paper says "triangle in
  /// \f$DT(P)\f$" here, which would make it always 0: faces of \f$G\f$ are meant.)
  std::size_t D_vio = 0;
  /// \f$d_{vio}\f$: the largest number of points strictly inside the (perturbed) circumcircle
  /// of one face of \f$G\f$.
  std::size_t d_vio = 0;
  /// lower bound on the flip distance \f$D_{flip}\f$ (computing it is NP-hard for point sets):
  /// \f$D\f$, since a flip replaces one edge. Meaningful when `is_triangulation`.
  std::size_t D_flip_lower = 0;
  /// upper bound on \f$D_{flip}\f$: the number of flips Lawson's algorithm makes from \f$G\f$
  /// to \f$DT(P)\f$. Empty when \f$G\f$ is not a triangulation or the flip budget ran out.
  std::optional<std::size_t> D_flip_upper;

  /// number of distinct faces whose three points are collinear or not distinct; they have no
  /// circumcircle and are left out of \f$D_{vio}\f$, \f$d_{vio}\f$ and \f$D_{local}\f$.
  std::size_t degenerate_faces = 0;
  /// number of edges of \f$G\f$ listed by more than two faces (left out of \f$D_{local}\f$).
  std::size_t edges_with_more_than_two_faces = 0;
};

namespace internal {

// prediction_measures() with the flip bound given; `violations` false leaves D_vio and d_vio 0
// (measure_prediction()), for benchmarks that need d_cross on inputs where D_vio is quadratic.
template <class PointRange, class FaceRange>
Prediction_measures measures_of(const PointRange& points, const FaceRange& faces, std::size_t max_flips,
                                bool violations)
{
  using Point = typename std::iterator_traits<decltype(std::begin(points))>::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  using DT = internal::Indexed_delaunay_2<K>;

  Prediction_measures m;
  const auto point_at = std::begin(points);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  m.points = n;
  if(n >= (std::size_t(1) << 32))
    throw Invalid_prediction("Delaunay_from_prediction: prediction_measures takes fewer than 2^32 points");
  // DT(P), and Lawson's flip count from G when G is a triangulation (Strategy::flips: a
  // prediction that is not a triangulation is rebuilt, not repaired, so that fell_back tells
  // which it is and the flips are Lawson's from G itself).
  DT dt;
  const Statistics stats = delaunay_from_prediction(
      points, faces, dt,
      parameters::max_flips(max_flips, parameters::screen_prediction(false, parameters::strategy(Strategy::flips))));
  m.faces = stats.faces_in;
  if(m.faces >= (std::size_t(1) << 32))
    throw Invalid_prediction("Delaunay_from_prediction: prediction_measures takes fewer than 2^32 faces");
  measure_prediction(m, point_at, n, faces, dt, stats, violations);
  return m;
}

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the closeness measures of Table 1 of the paper between the prediction `faces` and the
Delaunay triangulation of `points`, exactly (for a kernel with exact predicates).

All tests use CGAL's symbolic perturbation for co-circular points, so every measure is 0
exactly when `faces` is the triangulation `CGAL::Delaunay_triangulation_2` builds. The prediction
need not be a triangulation: the measures are then computed by their definitions read literally
(see `Prediction_measures`), and `is_triangulation` says why it is not one.

Cost: \f$DT(P)\f$ is computed with `delaunay_from_prediction()` from the prediction itself
(which also gives the Lawson flip count), then \f$O(n + D_{cross} + D_{vio})\f$ more, plus one
turn around an endpoint (the one of smaller degree in \f$DT(P)\f$) of each wrong edge, and one
around a vertex of each wrong face.

\tparam PointRange a random-access range of points of a CGAL kernel.
\tparam FaceRange a range of index triples, as for `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters.

\param points the points.
\param faces the prediction.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the most flips Lawson's algorithm may make for `D_flip_upper`; past it
      `D_flip_upper` is left empty. Lawson's algorithm makes at most \f$D_{cross}\f$ flips
      (Hanke, Ottmann and Schuierer), so the default costs no more than the crossing count.}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{\f$n(n-1)/2\f$, which exact predicates never reach (Lawson's algorithm
      flips each pair of points at most once); it only stops an inexact kernel from cycling}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the measures.
\throws Invalid_prediction for malformed input, as `delaunay_from_prediction()` does, and for
        \f$2^{32}\f$ or more points or faces.
*/
template <class PointRange, class FaceRange,
          class NamedParameters = parameters::Default_named_parameters>
Prediction_measures prediction_measures(const PointRange& points, const FaceRange& faces,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  // Lawson's algorithm flips a pair of points at most once (a flipped-away edge lies above
  // the lowered lifted surface for good), so with exact predicates it never needs more than
  // n(n-1)/2 flips; the bound only stops an inexact kernel from cycling.
  const std::size_t max_flips = choose_parameter(get_parameter(np, internal_np::max_flips),
                                                 n < 3 ? std::size_t(64) : n * (n - 1) / 2);
  return internal::measures_of(points, faces, max_flips, true);
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_MEASURES_H
