// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points for periodic domains: delaunay_from_prediction() and make_delaunay() for
// CGAL::Periodic_2_Delaunay_triangulation_2 (the flat torus), run by the pipeline of the
// Euclidean entry points with the torus's stages (internal/periodic/periodic_stages.h) on flat
// arrays (internal/periodic/torus_triangulation.h): check, a spatial order, import or read with
// the minimum-image convention, certify (the faces tile the torus once; in-circle tests),
// Lawson's flips, then the faces written into CGAL's data structure; CGAL's own build where the
// prediction is given up or the covering is in doubt.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H

#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/periodic/periodic_stages.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
computes the periodic Delaunay triangulation of `points` into `t`, using `faces` as a
prediction of it.

The result is exactly the triangulation CGAL's `Periodic_2_Delaunay_triangulation_2` builds from
the same points by range insertion (`t.insert(first, last)`): the same faces with the same
offsets, co-circular ties broken by CGAL's symbolic perturbation, and the same covering. When
`faces` is a triangulation of the torus at the points, it is certified in \f$O(n)\f$ time and
repaired by Lawson's flips that start at its non-locally-Delaunay edges; inverted faces (the
previous frame's faces after moves) are first untangled by flips and by taking vertices out
and putting them back. The result is written as a 1-sheeted covering. Each face's offsets follow the minimum-image convention: every edge is
taken as its shortest periodic image. Any other prediction is not an error, it is built from
scratch by CGAL (`Statistics::fell_back`, with `Statistics::outcome` saying why): faces whose
shortest images do not close, flat, repeated or overlapping faces, holes, points used by no face,
faces that do not cover the domain exactly once, tangles that neither a flip nor a reinsertion
undoes, more flips than the budget. Points too few or
too clustered for CGAL to keep a 1-sheeted covering (or so close to CGAL's criterion that its
outcome is in doubt: the diameter of every Delaunay face's circumcircle, the widest circle empty
of the points, must be below \f$\sqrt{0.166/8} \approx 0.144\f$ periods) are built by CGAL too
(`Outcome::not_1_sheeted`), which may give a 9-sheeted covering. The stages index points and
half-edges on 32 bits: from \f$2^{32} - 1\f$ points or \f$(2^{32} - 1)/3\f$ faces the faces are
validated, then ignored, and CGAL builds the triangulation (`Outcome::too_many_indices`).

\tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
        `CGAL::Parallel_if_available_tag`: with `CGAL::Parallel_tag` the in-circle tests of the
        certification, the scan for inverted faces and the spatial order run on TBB's threads;
        the rest runs on the calling thread. The result is the same triangulation whatever the
        tag and the number of threads.
\tparam PointRange a random-access range of `Gt::Point_2`.
\tparam FaceRange a range whose elements `f` give three integer indices `f[0]`, `f[1]`, `f[2]`
        into `points`.
\tparam Gt a `CGAL::Periodic_2_Delaunay_triangulation_traits_2` of a kernel with exact predicates
        (`Epick`, `Epeck`).
\tparam Tds its triangulation data structure. If its vertices have an `info()` assignable from
        `std::size_t`, every vertex's `info()` (every copy's, in a 9-sheeted covering) is set to
        the index of its point (for duplicate points, the smallest of their indices).
\tparam NamedParameters a sequence of named parameters.

\param points the points, each in `t.domain()` (half-open: \f$[x_{min}, x_{max}) \times [y_{min}, y_{max})\f$).
\param faces the predicted triangles, in any orientation.
\param t receives the result; cleared first. Its domain and traits are kept.
\param np optional named parameters among the ones listed below.

\cgalNamedParamsBegin
  \cgalParamNBegin{max_flips}
    \cgalParamDescription{the largest number of edge flips to make; past it CGAL builds the
      triangulation. With the default, a prediction with more failing edges than the default
      over 1.35 is built at once; with a given value, one with more failing edges than it.}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{three quarters of the number of points, plus 64}
  \cgalParamNEnd
  \cgalParamNBegin{strategy}
    \cgalParamDescription{`Strategy::rebuild` builds by CGAL's range insertion; every other value
      uses the prediction as above}
    \cgalParamType{`Strategy`}
    \cgalParamDefault{`Strategy::automatic`}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{as for the Euclidean `delaunay_from_prediction()`: each stage reported
      at most once, in this order: `Stage::check`, `Stage::order` (points and faces in no spatial
      order renumbered along a grid), `Stage::import` (the faces paired, their offsets by the
      minimum-image convention), `Stage::untangle`, `Stage::certify` (the in-circle test of every
      edge), `Stage::flips`, and `Stage::rebuild` when CGAL builds the triangulation}
    \cgalParamType{see `Default_visitor`}
    \cgalParamDefault{`Default_visitor()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a point has a non-finite coordinate or lies outside `t.domain()`,
        or a face has an index out of range or repeats an index, or, with a floating-point
        number type (`Epick`), the domain's period is outside \f$[2^{-500}, 2^{500}]\f$ (\cgal's
        covering test squares it in double). Then `t` is unchanged.
*/
template <class ConcurrencyTag = Sequential_tag, class PointRange, class FaceRange, class Gt, class Tds,
          class NamedParameters = parameters::Default_named_parameters>
Statistics delaunay_from_prediction(const PointRange& points, const FaceRange& faces,
                                    Periodic_2_Delaunay_triangulation_2<Gt, Tds>& t,
                                    const NamedParameters& np = parameters::default_values())
{
  using P2DT2 = Periodic_2_Delaunay_triangulation_2<Gt, Tds>;
  static_assert(internal::has_exact_predicates<Gt>::value,
                "Delaunay_from_prediction: the periodic overloads need traits with exact predicates (Epick, Epeck)");
  internal::check_point_range_type<PointRange, typename P2DT2::Point>();
  internal::check_face_range_type<FaceRange>();
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const internal::Pipeline_options options =
      internal::read_pipeline_options(np, n, internal::runs_in_parallel<ConcurrencyTag>());
  auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
  internal::Periodic_index_triples_stages<P2DT2, PointRange, FaceRange> stages(points, faces, t, options);
  return internal::run_prediction_pipeline(stages, options, internal::unwrap_visitor(visitor));
}

/*!
\ingroup PkgDelaunayFromPredictionRef
turns a periodic triangulation into the periodic Delaunay triangulation of its own vertices, in
place.

The points of `t`'s vertices may have been moved with `Vertex::set_point()` to new points of
`t.domain()` (the caller wraps them into it). The faces' offsets are recomputed by the
minimum-image convention (each edge taken as its shortest periodic image), so that a vertex
that crossed a side of the domain keeps its faces. When the faces, so translated, still tile the
torus once, inverted faces are untangled (by flips, and by taking vertices out and putting them
back), then the faces are certified in \f$O(n)\f$ time and repaired by Lawson's flips from the
non-locally-Delaunay edges; otherwise (faces no longer closing, tangles that neither undoes,
more flips than the budget) CGAL builds the triangulation of the points (`Statistics::fell_back`, with
`Statistics::outcome` saying why). The result equals CGAL's range insertion of the points, as
for `delaunay_from_prediction()`.

Vertex handles and their `info()` survive whenever `t` is a 1-sheeted covering before and after
the call (`t.is_1_cover()`); face handles do not. When it is not (few points, or points too
clustered: `Outcome::not_1_sheeted`), `t` becomes CGAL's build and its vertices are new objects,
each with the `info()` of the vertex that was at its point. From \f$(2^{32} - 1)/8\f$ vertices
(the stages index six half-edges a vertex on 32 bits) CGAL builds the triangulation
(`Outcome::too_many_indices`).

\tparam ConcurrencyTag as for `delaunay_from_prediction()`.
\tparam Gt, Tds as for `delaunay_from_prediction()`.
\tparam NamedParameters a sequence of named parameters: `max_flips`, `strategy` and `visitor`,
        as for `delaunay_from_prediction()`: the stages are `Stage::check`, `Stage::import` (the
        faces read from \cgal's data structure with their offsets by the minimum-image
        convention), `Stage::untangle`, `Stage::certify` (the in-circle test of every edge),
        `Stage::flips` and `Stage::rebuild`, each at most once; there is no `Stage::order`.

\param t the triangulation.
\param np optional named parameters.

\returns what the call did, see `Statistics`.
\throws Invalid_prediction if a vertex has a non-finite coordinate or lies outside `t.domain()`
        (naming it by its rank in `t.unique_vertices_begin()` order), or two vertices are at the
        same point, or the period is out of range as for `delaunay_from_prediction()`. Then `t`
        is unchanged.
*/
template <class ConcurrencyTag = Sequential_tag, class Gt, class Tds,
          class NamedParameters = parameters::Default_named_parameters>
Statistics make_delaunay(Periodic_2_Delaunay_triangulation_2<Gt, Tds>& t,
                         const NamedParameters& np = parameters::default_values())
{
  using P2DT2 = Periodic_2_Delaunay_triangulation_2<Gt, Tds>;
  static_assert(internal::has_exact_predicates<Gt>::value,
                "Delaunay_from_prediction: the periodic overloads need traits with exact predicates (Epick, Epeck)");
  const internal::Pipeline_options options =
      internal::read_pipeline_options(np, t.number_of_vertices(), internal::runs_in_parallel<ConcurrencyTag>());
  auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
  internal::Periodic_in_place_stages<P2DT2> stages(t, options);
  return internal::run_prediction_pipeline(stages, options, internal::unwrap_visitor(visitor));
}

/*!
\ingroup PkgDelaunayFromPredictionRef
A triangle of a periodic triangulation by point indices: its corners are the points of indices
`vertices[k]` translated by `offsets[k]` periods (`offsets[k][0]` times the domain's width in x,
`offsets[k][1]` times its height in y), counter-clockwise.
*/
struct Indexed_periodic_triangle
{
  std::array<std::size_t, 3> vertices; ///< the point indices of the corners.
  std::array<std::array<int, 2>, 3> offsets; ///< each corner's offset, in periods; least value 0 in x and in y.
};

/*!
\ingroup PkgDelaunayFromPredictionRef
the triangles of the periodic triangulation `t`, each once (a 9-sheeted covering's copies
counted once, as \cgal's `Periodic_2_triangulation_2::UNIQUE` iterator gives them), by the
`info()` of their vertices (for a copy, the `info()` of its original vertex): the point indices
when `t` was made by `delaunay_from_prediction()`. Linear in the size of `t`.

\tparam Gt, Tds as for `delaunay_from_prediction()`; the vertices have an `info()` convertible to
        `std::size_t`.
\param t the periodic triangulation.
\returns its triangles, each once, as point indices and offsets.
*/
template <class Gt, class Tds>
std::vector<Indexed_periodic_triangle> indexed_periodic_triangles(const Periodic_2_Delaunay_triangulation_2<Gt, Tds>& t)
{
  using P2DT2 = Periodic_2_Delaunay_triangulation_2<Gt, Tds>;
  std::vector<Indexed_periodic_triangle> triangles;
  triangles.reserve(t.number_of_faces());
  for(auto it = t.periodic_triangles_begin(P2DT2::UNIQUE); it != t.periodic_triangles_end(P2DT2::UNIQUE); ++it) {
    const auto f = it.get_face();
    Indexed_periodic_triangle triangle;
    int low_x = (*it)[0].second.x(), low_y = (*it)[0].second.y();
    for(int k = 1; k < 3; ++k) {
      low_x = (std::min)(low_x, (*it)[k].second.x());
      low_y = (std::min)(low_y, (*it)[k].second.y());
    }
    for(int k = 0; k < 3; ++k) {
      triangle.vertices[k] = static_cast<std::size_t>(t.get_original_vertex(f->vertex(k))->info());
      triangle.offsets[k] = {(*it)[k].second.x() - low_x, (*it)[k].second.y() - low_y};
    }
    triangles.push_back(triangle);
  }
  return triangles;
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

// Kinetic_Delaunay_triangulation_2 on the torus, which calls the two overloads above.
#include <CGAL/Delaunay_from_prediction/internal/periodic/kinetic_access.h>

#endif // CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H
