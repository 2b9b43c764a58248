// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry points for periodic domains: delaunay_from_prediction() and make_delaunay() for
// CGAL::Periodic_2_Delaunay_triangulation_2 (the flat torus). Their stages work on flat arrays
// (internal/periodic/torus_triangulation.h): check, a spatial order, import or read with the
// minimum-image convention, certify (the faces tile the torus once; in-circle tests), Lawson's flips, then
// the faces written into CGAL's data structure; CGAL's own build where the prediction is given
// up or the covering is in doubt.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H
#define CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H

#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/visitor.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/periodic/torus_triangulation.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/dense_index.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <sstream>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Throws Invalid_prediction naming `item` `i` when point p is not finite or lies outside the
// half-open domain [xmin, xmax) x [ymin, ymax) (exact comparisons of the kernel's numbers).
template <class Point, class Rectangle>
void check_in_domain(const Point& p, const Rectangle& domain, const char* item, std::size_t i)
{
  const bool finite = is_finite_point(p);
  if(finite && !(p.x() < domain.xmin()) && p.x() < domain.xmax() && !(p.y() < domain.ymin()) &&
     p.y() < domain.ymax())
    return;
  std::ostringstream msg;
  msg << "Delaunay_from_prediction: " << item << " " << i << " ";
  write_coordinates(msg, p);
  if(finite)
    msg << " lies outside the periodic domain [" << CGAL::to_double(domain.xmin()) << ", "
        << CGAL::to_double(domain.xmax()) << ") x [" << CGAL::to_double(domain.ymin()) << ", "
        << CGAL::to_double(domain.ymax()) << ")";
  else
    msg << " has a non-finite coordinate";
  throw Invalid_prediction(msg.str());
}

// Throws Invalid_prediction when the domain's period is outside [2^-500, 2^500] and the traits'
// number type is a floating-point one (Epick's double). CGAL's periodic triangulation decides
// its covering by comparing squared edge lengths with 0.166 period^2 in that number type: below
// that range the square underflows (to 0 or to subnormals: CGAL then takes a triangulation of a
// few points for a 1-sheeted covering and crashes), above it the squares of a few periods
// overflow. An exact number type (Epeck) has no such limit.
template <class Gt, class Rectangle>
void check_domain_width(const Rectangle& domain)
{
  if constexpr(std::is_floating_point<typename Gt::FT>::value) {
    const double width = CGAL::to_double(domain.xmax()) - CGAL::to_double(domain.xmin());
    if(width >= std::ldexp(1.0, -500) && width <= std::ldexp(1.0, 500))
      return;
    std::ostringstream msg;
    msg << "Delaunay_from_prediction: the periodic domain's period " << width
        << " is outside [2^-500, 2^500] (about 3e-151 to 3e150): CGAL's Periodic_2_triangulation_2 compares "
           "squared edge lengths with 0.166 period^2 in double, which underflows or overflows there; scale the "
           "coordinates, or use exact constructions (Epeck)";
    throw Invalid_prediction(msg.str());
  }
}

// The index of a point among `points`, by exact lexicographic comparisons: the smallest index
// among equal points. Used where CGAL built the triangulation, to give its vertices their
// indices, and to find equal points.
template <class Gt>
class Point_index_lookup
{
public:
  using Point = typename Gt::Point_2;

  Point_index_lookup(const std::vector<const Point*>& points, const Gt& gt) : points_(points), gt_(gt)
  {
    order_.resize(points.size());
    std::iota(order_.begin(), order_.end(), std::uint32_t(0));
    auto compare = gt.compare_xy_2_object();
    std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Comparison_result c = compare(*points_[a], *points_[b]);
      return c == SMALLER || (c == EQUAL && a < b);
    });
  }
  std::size_t operator()(const Point& p) const
  {
    auto compare = gt_.compare_xy_2_object();
    const auto it = std::lower_bound(order_.begin(), order_.end(), p, [&](std::uint32_t a, const Point& q) {
      return compare(*points_[a], q) == SMALLER;
    });
    CGAL_assertion(it != order_.end() && compare(*points_[*it], p) == EQUAL);
    return *it;
  }
  // Two indices of equal points, the first pair in lexicographic order; false if none.
  bool find_equal_pair(std::size_t& first, std::size_t& second) const
  {
    auto compare = gt_.compare_xy_2_object();
    for(std::size_t k = 1; k < order_.size(); ++k)
      if(compare(*points_[order_[k - 1]], *points_[order_[k]]) == EQUAL) {
        first = order_[k - 1];
        second = order_[k];
        return true;
      }
    return false;
  }

private:
  const std::vector<const Point*>& points_;
  const Gt& gt_;
  std::vector<std::uint32_t> order_;
};

// The stages of both entry points after the faces are in `tt`: the faces must cover the torus
// once (oriented so); the inverted ones are untangled by flips; every edge is tested; Lawson's
// flips repair the failing ones within the flip budget; the result must surely be what CGAL
// keeps as a 1-sheeted covering. Outcome::ok when `tt` is then the Delaunay triangulation CGAL
// builds; otherwise why the prediction is given up. `certify` is the stage the in-circle tests
// are reported as (Stage::certify).
template <class Gt, class Runner>
Outcome certify_and_flip(Torus_triangulation& tt, const Torus_geometry<Gt>& geometry, const Pipeline_options& options,
                         Stage certify, Statistics& stats, const Runner& run)
{
  Outcome why = orient_to_cover_once(tt, geometry);
  if(why != Outcome::ok)
    return why;
  std::size_t inverted = 0;
  why = run(Stage::untangle, [&] {
    return untangle(tt, geometry, options.parallel, options.max_inverted_faces(), options.max_flips, stats.flips, inverted,
                    stats.points_reinserted);
  });
  if(why != Outcome::ok)
    return why;
  std::vector<std::uint32_t> failing;
  why = run(certify, [&] {
    failing = failing_edges(tt, geometry, options.parallel, stats.edges_tested);
    stats.edges_not_locally_delaunay = failing.size();
    return options.failing_edges_outcome(failing.size());
  });
  if(why != Outcome::ok)
    return why;
  why = run(Stage::flips, [&] {
    return lawson_flips(tt, std::move(failing), geometry, options.max_flips, stats.flips) ? Outcome::ok
                                                                                         : Outcome::flip_budget_exhausted;
  });
  if(why != Outcome::ok)
    return why;
  stats.faces_certified = tt.faces_never_flipped();
  return surely_one_sheeted(tt, geometry) && offsets_fit_face_base(tt) ? Outcome::ok : Outcome::not_1_sheeted;
}

// CGAL's build of `points` into `t` (range insertion, as CGAL does it), each vertex's info()
// the index of its point (the smallest for equal points), the copies of a 9-sheeted covering
// included.
template <class P2DT2>
void build_as_cgal(const std::vector<typename P2DT2::Point>& points, P2DT2& t, Statistics& stats)
{
  t.clear();
  t.insert(points.begin(), points.end());
  clear_vertex_offsets(t);
  stats.points_reinserted = points.size();
  stats.duplicate_points = points.size() - t.number_of_vertices();
  if constexpr(has_index_info<typename P2DT2::Vertex>::value) {
    std::vector<const typename P2DT2::Point*> pointers(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      pointers[i] = &points[i];
    const Point_index_lookup<typename P2DT2::Geom_traits> lookup(pointers, t.geom_traits());
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
      v->info() = lookup(v->point());
  }
}

// make_delaunay()'s build when the faces are given up: CGAL's build of the vertices' points.
// When t and the build are 1-sheeted, its faces are written on t's own vertex objects (handles
// and info() survive); otherwise t becomes the build, whose vertices get the info() of the
// vertex at their point. Throws Invalid_prediction, t unchanged, if two vertices are at the same
// point.
template <class P2DT2>
void rebuild_in_place(P2DT2& t, Statistics& stats)
{
  using Vertex_handle = typename P2DT2::Vertex_handle;
  std::vector<Vertex_handle> vertices;
  std::vector<const typename P2DT2::Point*> pointers;
  for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v) {
    vertices.push_back(v);
    pointers.push_back(&v->point());
  }
  const Point_index_lookup<typename P2DT2::Geom_traits> lookup(pointers, t.geom_traits());
  std::size_t first = 0, second = 0;
  if(lookup.find_equal_pair(first, second)) {
    std::ostringstream msg;
    msg << "Delaunay_from_prediction: vertices " << (std::min)(first, second) << " and " << (std::max)(first, second)
        << " (in vertex order) are at the same point ";
    write_coordinates(msg, *pointers[first]);
    throw Invalid_prediction(msg.str());
  }
  P2DT2 build(t.domain(), t.geom_traits());
  std::vector<typename P2DT2::Point> points;
  points.reserve(pointers.size());
  for(const auto* p : pointers)
    points.push_back(*p);
  build.insert(points.begin(), points.end());
  stats.points_reinserted = points.size();
  if(t.is_1_cover() && build.is_1_cover() && build.dimension() == 2) {
    Torus_triangulation tt;
    read_periodic_triangulation(build, [&](Vertex_handle v) { return lookup(v->point()); }, tt);
    write_periodic_triangulation(tt, vertices, t);
    return;
  }
  for(auto v = build.tds().vertices().begin(); v != build.tds().vertices().end(); ++v)
    copy_info(vertices[lookup(v->point())], v);
  t.swap(build);
  clear_vertex_offsets(t);
  stats.outcome = Outcome::not_1_sheeted;
}

} // namespace internal

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
  using Point = typename P2DT2::Point;
  static_assert(internal::has_exact_predicates<Gt>::value,
                "Delaunay_from_prediction: the periodic overloads need traits with exact predicates (Epick, Epeck)");
  internal::check_point_range_type<PointRange, Point>();
  internal::check_face_range_type<FaceRange>();
  constexpr bool parallel = internal::runs_in_parallel<ConcurrencyTag>();
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t m = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  const internal::Pipeline_options options = internal::read_pipeline_options(np, n, parallel);
  auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
  const internal::Stage_runner<std::remove_reference_t<decltype(internal::unwrap_visitor(visitor))>> run{
      internal::unwrap_visitor(visitor)};
  Statistics stats;
  stats.faces_in = m;

  std::vector<Point> copy;
  std::vector<std::uint32_t> triples;
  bool fits = true;
  run(Stage::check, [&] {
    internal::check_domain_width<Gt>(t.domain());
    copy.assign(std::begin(points), std::end(points));
    for(std::size_t i = 0; i < n; ++i)
      internal::check_in_domain(copy[i], t.domain(), "point", i);
    fits = internal::read_index_triples(faces, n, m, triples, parallel);
    return Outcome::ok;
  });

  Outcome why = Outcome::ok;
  if(!options.uses_prediction())
    why = Outcome::rebuild_requested;
  else if(!fits || m >= std::size_t(std::uint32_t(-1) / 3)) // three 32-bit half-edges a face
    why = Outcome::too_many_indices;
  else if(m == 0)
    why = Outcome::no_faces;
  // Points and faces in no spatial order (shuffled, a model's output) renumbered along a grid,
  // so that the passes below read nearby memory; old_index() gives the caller's index back.
  internal::Spatial_order order;
  if(why == Outcome::ok)
    run(Stage::order, [&] {
      order.compute(t.geom_traits(), copy.begin(), n, triples, parallel);
      return Outcome::ok;
    });
  internal::Torus_triangulation tt;
  std::vector<const Point*> pointers(n);
  for(std::size_t i = 0; i < n; ++i)
    pointers[i] = &copy[order.old_index(std::uint32_t(i))];
  const internal::Torus_geometry<Gt> geometry(t.geom_traits(), pointers);
  if(why == Outcome::ok)
    why = run(Stage::import, [&] {
      const Outcome imported = internal::import_index_triples(triples, geometry, tt);
      return imported != Outcome::ok ? imported : internal::check_every_point_used(tt, n);
    });
  if(why == Outcome::ok)
    why = internal::certify_and_flip(tt, geometry, options, Stage::certify, stats, run);
  if(why == Outcome::ok) {
    t.clear();
    std::vector<typename P2DT2::Vertex_handle> vertices(n);
    for(std::size_t i = 0; i < n; ++i) {
      vertices[i] = t.tds().create_vertex();
      vertices[i]->set_point(*pointers[i]);
      internal::set_index_info(vertices[i], order.old_index(std::uint32_t(i)));
    }
    internal::write_periodic_triangulation(tt, vertices, t);
    return stats;
  }
  stats.fell_back = true;
  stats.outcome = why;
  run(Stage::rebuild, [&] {
    internal::build_as_cgal(copy, t, stats);
    return Outcome::ok;
  });
  return stats;
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
  using Point = typename P2DT2::Point;
  static_assert(internal::has_exact_predicates<Gt>::value,
                "Delaunay_from_prediction: the periodic overloads need traits with exact predicates (Epick, Epeck)");
  constexpr bool parallel = internal::runs_in_parallel<ConcurrencyTag>();
  const std::size_t n = t.number_of_vertices();
  const internal::Pipeline_options options = internal::read_pipeline_options(np, n, parallel);
  auto visitor = parameters::choose_parameter<Default_visitor>(parameters::get_parameter(np, internal_np::visitor));
  const internal::Stage_runner<std::remove_reference_t<decltype(internal::unwrap_visitor(visitor))>> run{
      internal::unwrap_visitor(visitor)};
  Statistics stats;
  if(n == 0)
    return stats;
  stats.faces_in = t.number_of_faces();

  run(Stage::check, [&] {
    internal::check_domain_width<Gt>(t.domain());
    std::size_t rank = 0;
    for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v, ++rank)
      internal::check_in_domain(v->point(), t.domain(), "vertex", rank);
    return Outcome::ok;
  });

  Outcome why = Outcome::ok;
  if(!options.uses_prediction())
    why = Outcome::rebuild_requested;
  else if(!t.is_1_cover())
    why = Outcome::not_1_sheeted;
  else if(t.dimension() != 2)
    why = Outcome::dimension_below_2;
  else if(n >= std::size_t(std::uint32_t(-1) / 8)) // six 32-bit half-edges a vertex
    why = Outcome::too_many_indices;
  if(why == Outcome::ok) {
    const auto& tds = t.tds();
    const internal::Dense_index<typename P2DT2::Triangulation_data_structure::Vertex_range> vertex_index(tds.vertices());
    std::vector<typename P2DT2::Vertex_handle> vertices;
    std::vector<const Point*> pointers;
    vertices.reserve(n);
    pointers.reserve(n);
    for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v) {
      vertices.push_back(v);
      pointers.push_back(&v->point());
    }
    const internal::Torus_geometry<Gt> geometry(t.geom_traits(), pointers);
    internal::Torus_triangulation tt;
    why = run(Stage::import, [&] {
      internal::read_periodic_triangulation(t, [&](typename P2DT2::Vertex_handle v) { return vertex_index.of(v); }, tt);
      return internal::set_offsets_by_minimum_image(tt, geometry);
    });
    if(why == Outcome::ok)
      why = internal::certify_and_flip(tt, geometry, options, Stage::certify, stats, run);
    if(why == Outcome::ok) {
      internal::write_periodic_triangulation(tt, vertices, t);
      return stats;
    }
  }
  stats.fell_back = true;
  stats.outcome = why;
  run(Stage::rebuild, [&] {
    internal::rebuild_in_place(t, stats);
    return Outcome::ok;
  });
  return stats;
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

namespace internal {

// Kinetic_Delaunay_triangulation_2 on the torus: set_point() moves every copy of a vertex, the
// points must lie in the domain, and make_delaunay() keeps the vertex objects only when the
// triangulation is 1-sheeted before and after.
template <class Gt, class Tds>
struct Kinetic_access<Periodic_2_Delaunay_triangulation_2<Gt, Tds>>
{
  using DT = Periodic_2_Delaunay_triangulation_2<Gt, Tds>;

  static DT empty_like(const DT& dt) { return DT(dt.domain(), dt.geom_traits()); }
  template <class F>
  static void for_each_vertex(DT& dt, F f)
  {
    for(auto v = dt.tds().vertices().begin(); v != dt.tds().vertices().end(); ++v)
      f(typename DT::Vertex_handle(v));
  }
  template <class F>
  static void for_each_point_vertex(const DT& dt, F f)
  {
    for(auto v = dt.unique_vertices_begin(); v != dt.unique_vertices_end(); ++v)
      f(typename DT::Vertex_handle(v));
  }
  template <class PointRange>
  static void check_points(const DT& dt, const PointRange& points)
  {
    check_domain_width<Gt>(dt.domain());
    std::size_t i = 0;
    for(const auto& p : points)
      check_in_domain(p, dt.domain(), "point", i++);
  }
  template <class ConcurrencyTag, class NamedParameters>
  static std::pair<Statistics, bool> repair(DT& dt, const NamedParameters& np)
  {
    const bool was_1_sheeted = dt.is_1_cover();
    const Statistics stats = make_delaunay<ConcurrencyTag>(dt, np);
    return {stats, was_1_sheeted && dt.is_1_cover()};
  }
  template <class ConcurrencyTag, class PointRange, class FaceRange, class NamedParameters>
  static Statistics build(const PointRange& points, const FaceRange& faces, DT& dt, const NamedParameters& np)
  {
    return delaunay_from_prediction<ConcurrencyTag>(points, faces, dt, np);
  }
  // The triangles as index triples, but for those that repeat a point (only a 9-sheeted
  // covering has them; an index triple cannot say them).
  static std::vector<std::array<std::size_t, 3>> faces(const DT& dt)
  {
    std::vector<std::array<std::size_t, 3>> faces;
    for(const Indexed_periodic_triangle& t : indexed_periodic_triangles(dt))
      if(t.vertices[0] != t.vertices[1] && t.vertices[1] != t.vertices[2] && t.vertices[2] != t.vertices[0])
        faces.push_back(t.vertices);
    return faces;
  }
};

} // namespace internal

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_PERIODIC_2_H
