// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The stages of the periodic entry points (periodic_2.h), run by run_prediction_pipeline()
// as the Euclidean ones are (prediction_pipeline.h): check, then on the flat arrays of the
// torus (torus_triangulation.h) the spatial order and import of index triples
// (delaunay_from_prediction()) or the read of CGAL's data structure (make_delaunay()), the
// orientation that covers the torus once, the untangling, the in-circle tests (certify),
// Lawson's flips and the test of CGAL's covering; the faces written into CGAL's data structure,
// or CGAL's own build where the prediction is given up.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_PERIODIC_STAGES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_PERIODIC_STAGES_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/periodic/torus_triangulation.h>
#include <CGAL/Delaunay_from_prediction/internal/pipeline/prediction_pipeline.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/dense_index.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <numeric>
#include <sstream>
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

// What both periodic entry points do once the faces are on the torus's flat arrays `tt_`: the
// faces must cover the torus once (oriented so); the inverted ones are untangled; every edge
// is tested (Stage::certify); Lawson's flips repair the failing ones within the flip budget;
// the result must surely be what CGAL keeps as a 1-sheeted covering. The untangling comes
// before the in-circle tests: its flips would change edges already tested.
template <class Gt>
class Torus_stages
{
public:
  using Paths = Compiled_paths<strategy_bit(Strategy::automatic), false>; // the torus has one strategy
  static constexpr bool decides_exactly = true; // the periodic overloads require exact predicates
  static constexpr bool screens = false;        // no screen: the import is the first test

  Statistics& stats() { return stats_; }
  // The untangling ran within certify(), before the in-circle tests.
  template <class Run>
  Outcome repair(const Run&)
  {
    return Outcome::ok;
  }
  Outcome flip()
  {
    if(!lawson_flips(tt_, std::move(failing_), *geometry_, options_.max_flips, stats_.flips))
      return Outcome::flip_budget_exhausted;
    stats_.faces_certified = tt_.faces_never_flipped();
    return surely_one_sheeted(tt_, *geometry_) && offsets_fit_face_base(tt_) ? Outcome::ok : Outcome::not_1_sheeted;
  }
  bool has_unused_points() const { return false; } // the import requires every point used
  Outcome insert_unused_points() { return Outcome::ok; }

protected:
  explicit Torus_stages(const Pipeline_options& options) : options_(options) {}

  // After the faces are in `tt_` and `geometry_` is set: orientation, untangling, in-circle tests.
  template <class Run>
  Outcome orient_untangle_and_test(const Run& run)
  {
    Outcome why = orient_to_cover_once(tt_, *geometry_);
    if(why != Outcome::ok)
      return why;
    std::size_t inverted = 0;
    why = run(Stage::untangle, [&] {
      return untangle(tt_, *geometry_, options_.parallel, options_.max_inverted_faces(), options_.max_flips,
                      stats_.flips, inverted, stats_.points_reinserted);
    });
    if(why != Outcome::ok)
      return why;
    return run(Stage::certify, [&] {
      failing_ = failing_edges(tt_, *geometry_, options_.parallel, stats_.edges_tested);
      stats_.edges_not_locally_delaunay = failing_.size();
      return options_.failing_edges_outcome(failing_.size());
    });
  }

  // Frees the flat arrays before CGAL's build, which would otherwise be the peak on top of them.
  void release_torus()
  {
    tt_ = Torus_triangulation();
    geometry_.reset();
    std::vector<std::uint32_t>().swap(failing_);
  }

  const Pipeline_options& options_;
  Statistics stats_;
  Torus_triangulation tt_;
  std::unique_ptr<Torus_geometry<Gt>> geometry_;
  std::vector<std::uint32_t> failing_; // edges not locally Delaunay, for Lawson's flips
};

// delaunay_from_prediction() on the torus: `points` (copied, in the domain) and their faces
// `faces` (index triples) into `t`.
template <class P2DT2, class PointRange, class FaceRange>
class Periodic_index_triples_stages : public Torus_stages<typename P2DT2::Geom_traits>
{
  using Base = Torus_stages<typename P2DT2::Geom_traits>;
  using Gt = typename P2DT2::Geom_traits;
  using Point = typename P2DT2::Point;
  using Base::geometry_;
  using Base::options_;
  using Base::stats_;
  using Base::tt_;

public:
  Periodic_index_triples_stages(const PointRange& points, const FaceRange& faces, P2DT2& t,
                                const Pipeline_options& options)
      : Base(options), points_(points), faces_(faces), t_(t),
        n_(std::size_t(std::distance(std::begin(points), std::end(points)))),
        m_(std::size_t(std::distance(std::begin(faces), std::end(faces))))
  {
    stats_.faces_in = m_;
  }

  Outcome check()
  {
    check_domain_width<Gt>(t_.domain());
    copy_.assign(std::begin(points_), std::end(points_));
    for(std::size_t i = 0; i < n_; ++i)
      check_in_domain(copy_[i], t_.domain(), "point", i);
    fits_ = read_index_triples(faces_, n_, m_, triples_, options_.parallel);
    return Outcome::ok;
  }
  bool is_empty() const { return false; } // no points: CGAL's build clears t
  Outcome reason_not_to_use_prediction() const
  {
    if(!options_.uses_prediction())
      return Outcome::rebuild_requested;
    if(!fits_ || m_ >= std::size_t(std::uint32_t(-1) / 3)) // three 32-bit half-edges a face
      return Outcome::too_many_indices;
    return m_ == 0 ? Outcome::no_faces : Outcome::ok;
  }
  // Points and faces in no spatial order (shuffled, a model's output) renumbered along a grid,
  // so that the passes below read nearby memory; old_index() gives the caller's index back.
  template <class Run>
  Outcome certify(const Run& run)
  {
    run(Stage::order, [&] {
      order_.compute(t_.geom_traits(), copy_.begin(), n_, triples_, options_.parallel);
      return Outcome::ok;
    });
    std::vector<const Point*> pointers(n_);
    for(std::size_t i = 0; i < n_; ++i)
      pointers[i] = &copy_[order_.old_index(std::uint32_t(i))];
    geometry_.reset(new Torus_geometry<Gt>(t_.geom_traits(), std::move(pointers)));
    const Outcome why = run(Stage::import, [&] {
      const Outcome imported = import_index_triples(triples_, *geometry_, tt_);
      return imported != Outcome::ok ? imported : check_every_point_used(tt_, n_);
    });
    return why != Outcome::ok ? why : this->orient_untangle_and_test(run);
  }
  // The faces certified, then written into t with a vertex per point.
  void count_certified_faces()
  {
    t_.clear();
    std::vector<typename P2DT2::Vertex_handle> vertices(n_);
    for(std::size_t i = 0; i < n_; ++i) {
      vertices[i] = t_.tds().create_vertex();
      vertices[i]->set_point(geometry_->point(i));
      set_index_info(vertices[i], order_.old_index(std::uint32_t(i)));
    }
    write_periodic_triangulation(tt_, vertices, t_);
  }
  void rebuild()
  {
    this->release_torus();
    std::vector<std::uint32_t>().swap(triples_);
    build_as_cgal(copy_, t_, stats_);
  }

private:
  const PointRange& points_;
  const FaceRange& faces_;
  P2DT2& t_;
  std::size_t n_, m_;
  std::vector<Point> copy_;
  std::vector<std::uint32_t> triples_;
  bool fits_ = true;
  Spatial_order order_;
};

// make_delaunay() on the torus: the faces of `t`, whose vertices may have moved, repaired in
// place (same vertex objects).
template <class P2DT2>
class Periodic_in_place_stages : public Torus_stages<typename P2DT2::Geom_traits>
{
  using Base = Torus_stages<typename P2DT2::Geom_traits>;
  using Gt = typename P2DT2::Geom_traits;
  using Point = typename P2DT2::Point;
  using Vertex_handle = typename P2DT2::Vertex_handle;
  using Base::geometry_;
  using Base::options_;
  using Base::stats_;
  using Base::tt_;

public:
  Periodic_in_place_stages(P2DT2& t, const Pipeline_options& options) : Base(options), t_(t)
  {
    stats_.faces_in = t.number_of_vertices() == 0 ? 0 : t.number_of_faces();
  }

  Outcome check()
  {
    if(is_empty())
      return Outcome::ok;
    check_domain_width<Gt>(t_.domain());
    std::size_t rank = 0;
    for(auto v = t_.unique_vertices_begin(); v != t_.unique_vertices_end(); ++v, ++rank)
      check_in_domain(v->point(), t_.domain(), "vertex", rank);
    return Outcome::ok;
  }
  bool is_empty() const { return t_.number_of_vertices() == 0; }
  Outcome reason_not_to_use_prediction() const
  {
    if(!options_.uses_prediction())
      return Outcome::rebuild_requested;
    if(!t_.is_1_cover())
      return Outcome::not_1_sheeted;
    if(t_.dimension() != 2)
      return Outcome::dimension_below_2;
    if(t_.number_of_vertices() >= std::size_t(std::uint32_t(-1) / 8)) // six 32-bit half-edges a vertex
      return Outcome::too_many_indices;
    return Outcome::ok;
  }
  template <class Run>
  Outcome certify(const Run& run)
  {
    std::vector<const Point*> pointers;
    vertices_.reserve(t_.number_of_vertices());
    pointers.reserve(t_.number_of_vertices());
    for(auto v = t_.tds().vertices().begin(); v != t_.tds().vertices().end(); ++v) {
      vertices_.push_back(v);
      pointers.push_back(&v->point());
    }
    geometry_.reset(new Torus_geometry<Gt>(t_.geom_traits(), std::move(pointers)));
    const Outcome why = run(Stage::import, [&] {
      const Dense_index<typename P2DT2::Triangulation_data_structure::Vertex_range> vertex_index(t_.tds().vertices());
      read_periodic_triangulation(t_, [&](Vertex_handle v) { return vertex_index.of(v); }, tt_);
      return set_offsets_by_minimum_image(tt_, *geometry_);
    });
    return why != Outcome::ok ? why : this->orient_untangle_and_test(run);
  }
  // The faces certified, then written into t on its own vertex objects.
  void count_certified_faces() { write_periodic_triangulation(tt_, vertices_, t_); }
  void rebuild()
  {
    this->release_torus();
    std::vector<Vertex_handle>().swap(vertices_);
    rebuild_in_place(t_, stats_);
  }

private:
  P2DT2& t_;
  std::vector<Vertex_handle> vertices_;
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_PERIODIC_STAGES_H
