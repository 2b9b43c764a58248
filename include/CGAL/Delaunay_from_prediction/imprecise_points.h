// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Entry point: the Delaunay triangulation of imprecise points (O. Devillers, "Delaunay
// triangulation of imprecise points, a really fast algorithm"): disks are preprocessed once
// (an insertion order, the Delaunay triangulation of their centres built in that order, and
// for each disk the nearest centre among the disks before it: its hint); the triangulation of
// an instance, one point per disk, is then built by inserting the points in the same order,
// each located by a walk from the point of its hint's disk.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_IMPRECISE_POINTS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_IMPRECISE_POINTS_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/build/hierarchy.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

namespace internal {

template <class T, class = void>
struct is_range : std::false_type {};
template <class T>
struct is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>()))>> : std::true_type {};

} // namespace internal

/*!
\ingroup PkgDelaunayFromPredictionRef
A set of imprecise points: n disks, each the region where one point of a future point set
(an instance) will lie. Built once, it computes the Delaunay triangulation of any instance by
walks from nearest-neighbour hints (O. Devillers, "Delaunay triangulation of imprecise points,
a really fast algorithm"; see below for what of its Theorem 1 applies).

<b>Preprocessing</b> (the constructor; the paper's is \f$O(n \log n)\f$ expected with a
randomized incremental construction, the package locates each centre by a walk instead, with
no bound proven): the disks are put in an
order (`Disk_order`); the Delaunay triangulation of their centres is built incrementally in
that order, and after the insertion of the k-th centre its nearest neighbour among the
centres inserted before it is recorded (one of its Delaunay neighbours): the hint of the k-th
disk. The triangulation of the centres is then discarded; the object keeps the order, the
hints, the centres and the radii.

<b>An instance</b> (`triangulate()`): its points are inserted in the same order, each located
by a visibility walk in the current triangulation that starts at the vertex of its hint's
point. The paper's Theorem 1 (expected linear time) assumes disjoint disks of one radius (or
of one radius overlapping at most a constant number of times, its Section 6.1), a random
insertion order (`Disk_order::random`) and straight walks; for the default spatial order, for
disks of different radii (the paper's Section 6.2 shows a quadratic example) and for points
outside their disks no bound is proven. The walks here are visibility walks; one longer than
about \f$\log_2 n + 8\f$ faces starts again, uncapped, from a vertex inserted near the point.
The disks are not used by the computation itself: a point outside its disk only makes the walks
longer; the result is exact in every case.

The result is exactly the triangulation CGAL's `Delaunay_triangulation_2` builds from the
instance points (co-circular ties broken by CGAL's symbolic perturbation).

\tparam Gt a model of `DelaunayTriangulationTraits_2` (a CGAL kernel), whose `Point_2` is the
        point type of the triangulations `triangulate()` fills.
*/
template <class Gt>
class Imprecise_points_2
{
public:
  /// the point type.
  using Point = typename Gt::Point_2;
  /// the number type of the radii.
  using FT = typename Gt::FT;

  /*!
  preprocesses the disks of the given centres and radii (disk `i` is centred at the `i`-th
  centre, with the `i`-th radius).

  \tparam CentreRange a random-access range of `Point`.
  \tparam RadiusRange a range of values convertible to `FT`, as many as the centres.
  \tparam NamedParameters a sequence of named parameters.
  \param centres the centres of the disks.
  \param radii the radii of the disks (0 is allowed: a point known exactly).
  \param np optional named parameters among the following ones:
  \cgalNamedParamsBegin
    \cgalParamNBegin{disk_order}
      \cgalParamDescription{the insertion order of the disks}
      \cgalParamType{`Disk_order`}
      \cgalParamDefault{`Disk_order::spatial`}
    \cgalParamNEnd
    \cgalParamNBegin{random_seed}
      \cgalParamDescription{the seed of `Disk_order::random` (the rounds of the spatial order have
        the package's fixed seed)}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{a fixed seed: the same disks give the same order}
    \cgalParamNEnd
    \cgalParamNBegin{geom_traits}
      \cgalParamDescription{the traits used by the preprocessing}
      \cgalParamType{`Gt`}
      \cgalParamDefault{`Gt()`}
    \cgalParamNEnd
  \cgalNamedParamsEnd
  \throws Invalid_prediction if the numbers of centres and radii differ, a centre or a radius
          is not finite, a radius is negative, or there are \f$2^{32} - 1\f$ disks or more.
  */
  template <class CentreRange, class RadiusRange, class NamedParameters = parameters::Default_named_parameters,
            class = std::enable_if_t<internal::is_range<RadiusRange>::value>>
  Imprecise_points_2(const CentreRange& centres, const RadiusRange& radii,
                     const NamedParameters& np = parameters::default_values())
  {
    for(const auto& r : radii)
      radius_.push_back(FT(r));
    read_centres(centres);
    preprocess(np);
  }

  /*!
  preprocesses the disks of the given centres, all of the same radius (the paper's case: unit
  disks). Same named parameters and exceptions as above.
  \tparam CentreRange a random-access range of `Point`.
  \tparam NamedParameters a sequence of named parameters.
  \param centres the centres of the disks.
  \param radius the radius of every disk.
  \param np optional named parameters, as above.
  */
  template <class CentreRange, class NamedParameters = parameters::Default_named_parameters>
  Imprecise_points_2(const CentreRange& centres, const FT& radius,
                     const NamedParameters& np = parameters::default_values())
  {
    radius_.assign(std::size_t(std::distance(std::begin(centres), std::end(centres))), radius);
    read_centres(centres);
    preprocess(np);
  }

  /// \returns the number of disks.
  std::size_t size() const { return centre_.size(); }
  /// \returns the centre of disk `i`.
  /// \param i a disk index, below `size()`.
  const Point& centre(std::size_t i) const { return centre_[i]; }
  /// \returns the radius of disk `i`.
  /// \param i a disk index, below `size()`.
  const FT& radius(std::size_t i) const { return radius_[i]; }
  /// tests a point against a disk, exactly (where the number type is `double`, as with `Epick`,
  /// in rational arithmetic).
  /// \returns whether `p` lies in the closed disk `i`.
  /// \param i a disk index, below `size()`.
  /// \param p a point.
  bool contains(std::size_t i, const Point& p) const
  {
    if constexpr(std::is_floating_point<FT>::value) {
      // In floating point the squares would round, overflow at 1e160 (inf against inf: a far
      // point inside) and underflow at 1e-160 (0 against 0): compared exactly instead.
      using ET = CGAL::Exact_rational;
      const ET dx = ET(centre_[i].x()) - ET(p.x()), dy = ET(centre_[i].y()) - ET(p.y()), r = ET(radius_[i]);
      return CGAL::compare(dx * dx + dy * dy, r * r) != LARGER;
    } else {
      return CGAL::compare(traits_.compute_squared_distance_2_object()(centre_[i], p), radius_[i] * radius_[i]) !=
             LARGER;
    }
  }
  /// \returns the disks in insertion order: `insertion_order()[k]` is the index of the k-th
  /// disk inserted, in the preprocessing and in every instance.
  const std::vector<std::uint32_t>& insertion_order() const { return order_; }
  /// \returns the hint of disk `i`: the disk whose centre is nearest to disk `i`'s among the
  /// disks inserted before it (ties broken arbitrarily), or `size()` for the first disk inserted.
  /// \param i a disk index, below `size()`.
  std::size_t hint(std::size_t i) const
  {
    const std::uint32_t r = rank_[i];
    return r == 0 ? size() : std::size_t(order_[hint_rank_[r]]);
  }

  /*!
  computes the Delaunay triangulation of an instance: one point per disk, `instance[i]` for
  disk `i`. A point may lie outside its disk: the result is still exact, only slower.

  \tparam PointRange a random-access range of `Point`, `size()` of them.
  \tparam DT a `CGAL::Delaunay_triangulation_2<Gt, Tds>`. If its vertices have an `info()`
          assignable from `std::size_t`, every vertex's `info()` is set to the index of its disk
          (for points at equal positions, the smallest of their indices). A
          `CGAL::Triangulation_hierarchy_2` of one is kept as in `delaunay_from_prediction()`.
  \tparam NamedParameters a sequence of named parameters (none is used yet).
  \param instance the points.
  \param dt receives the result; cleared first.
  \param np optional named parameters, accepted for the interface to grow; none is used yet.
  \returns what the call did: `points_located`, `faces_visited` (divided by `points_located`:
           the mean length of a walk), `walk_fallbacks`, `points_reinserted` (every point),
           `duplicate_points`.
  \throws Invalid_prediction if `instance` does not have `size()` points or a point has a
          non-finite coordinate. Then `dt` is unchanged.

  With traits whose predicates are not exact (e.g. `Simple_cartesian<double>`), the triangulation
  is built from scratch, decided by exact predicates on the coordinates rounded to double
  (`Statistics::fell_back`): see \ref dfpInexactKernels.
  */
  template <class PointRange, class DT, class NamedParameters = parameters::Default_named_parameters>
  Statistics triangulate(const PointRange& instance, DT& dt,
                         const NamedParameters& np = parameters::default_values()) const
  {
    if constexpr(internal::is_triangulation_hierarchy<DT>::value) { // level 0, then the upper levels
      return internal::with_levels_rebuilt(dt, [&](auto& level0) { return triangulate(instance, level0, np); });
    } else { // the body below, not instantiated for a hierarchy
    static_assert(std::is_same<typename DT::Point, Point>::value,
                  "Imprecise_points_2::triangulate: the triangulation's points must be Gt::Point_2");
    (void)np;
    using Vertex_handle = typename DT::Vertex_handle;
    using Face_handle = typename DT::Face_handle;
    const auto points = std::begin(instance);
    const std::size_t n = std::size_t(std::distance(std::begin(instance), std::end(instance)));
    if(n != size()) {
      std::ostringstream msg;
      msg << "Delaunay_from_prediction: an instance of " << n << " points for " << size() << " disks";
      throw Invalid_prediction(msg.str());
    }
    internal::check_points_are_finite(points, n);
    Statistics stats;
    dt.clear();
    stats.points_reinserted = n;
    if(n == 0)
      return stats;
    if constexpr(internal::decides_by_exact_predicates<Gt>::value) {
      // Inexact predicates (internal/toolbox/predicates.h): faces decided by exact predicates
      // (rebuild.h), the walks and flips below relying on consistent predicates.
      internal::build_with_exact_predicates(dt, points, n, stats);
      return stats;
    }
    internal::Vertex_grid<Vertex_handle> grid(n, box_);
    const std::size_t cap = internal::walk_cap(n);
    std::vector<Vertex_handle> vertex(n);
    std::vector<std::pair<Face_handle, int>> flip_stack;
    // The points in insertion order first: the gather's cache misses overlap in a loop of their
    // own, where the insertion loop would wait for each.
    std::vector<Point> point(n);
    for(std::size_t r = 0; r < n; ++r)
      point[r] = points[order_[r]];
    for(std::size_t r = 0; r < n; ++r) {
      const std::uint32_t i = order_[r];
      const Point& q = point[r];
      const std::size_t count = dt.number_of_vertices();
      const Vertex_handle v = r == 0 ? dt.insert(q)
                                     : internal::insert_walking_from(dt, q, vertex[hint_rank_[r]], cap, grid,
                                                                     flip_stack, stats);
      internal::record_index_info(v, i, dt.number_of_vertices() != count, stats.duplicate_points);
      vertex[r] = v;
      grid.record(q, v);
    }
    return stats;
    } // not a hierarchy
  }

private:
  template <class CentreRange>
  void read_centres(const CentreRange& centres)
  {
    centre_.assign(std::begin(centres), std::end(centres));
    const std::size_t n = centre_.size();
    if(radius_.size() != n) {
      std::ostringstream msg;
      msg << "Delaunay_from_prediction: " << n << " disk centres but " << radius_.size() << " radii";
      throw Invalid_prediction(msg.str());
    }
    if(n >= std::size_t(internal::no_rank))
      throw Invalid_prediction("Delaunay_from_prediction: 2^32 - 1 disks or more are not supported");
    for(std::size_t i = 0; i < n; ++i) {
      if(!CGAL::is_finite(centre_[i].x()) || !CGAL::is_finite(centre_[i].y())) {
        std::ostringstream msg;
        msg << "Delaunay_from_prediction: the centre of disk " << i << " has a non-finite coordinate ("
            << CGAL::to_double(centre_[i].x()) << ", " << CGAL::to_double(centre_[i].y()) << ")";
        throw Invalid_prediction(msg.str());
      }
      if(!CGAL::is_finite(radius_[i]) || CGAL::is_negative(radius_[i])) {
        std::ostringstream msg;
        msg << "Delaunay_from_prediction: disk " << i << " has radius " << CGAL::to_double(radius_[i])
            << " (a radius must be finite and not negative)";
        throw Invalid_prediction(msg.str());
      }
    }
  }

  template <class NamedParameters>
  void preprocess(const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    traits_ = choose_parameter(get_parameter(np, CGAL::internal_np::geom_traits), Gt());
    const Disk_order disk_order = choose_parameter(get_parameter(np, internal_np::disk_order), Disk_order::spatial);
    const std::uint64_t seed =
        choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0x5eed1309u) + 0x1309ull;
    const std::size_t n = size();
    order_.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      order_[i] = std::uint32_t(i);
    internal::Splitmix64 random{seed};
    if(disk_order == Disk_order::random) {
      for(std::size_t k = n; k > 1; --k)
        std::swap(order_[k - 1], order_[random.below(k)]);
    } else {
      internal::sort_along_grid(order_, [&](std::uint32_t i) -> const Point& { return centre_[i]; }, true);
    }
    rank_.resize(n);
    for(std::size_t r = 0; r < n; ++r)
      rank_[order_[r]] = std::uint32_t(r);
    // The box of the disks, for the grid of fallback locations of the instances.
    if(n != 0) {
      double max_radius = 0;
      for(std::size_t i = 0; i < n; ++i)
        max_radius = (std::max)(max_radius, CGAL::to_double(radius_[i]));
      if(!(max_radius < std::numeric_limits<double>::infinity())) // a radius too large for double
        max_radius = 0;
      const internal::Box box = internal::bounding_box(n, [&](std::size_t i) -> const Point& { return centre_[i]; });
      // Widened by the radius, but finite: a box to infinity would give the grid no cells.
      const double huge = (std::numeric_limits<double>::max)();
      box_ = internal::Box();
      box_.add((std::max)(box.xmin - max_radius, -huge), (std::max)(box.ymin - max_radius, -huge));
      box_.add((std::min)(box.xmax + max_radius, huge), (std::min)(box.ymax + max_radius, huge));
      scale_ = internal::unit_scale(box);
    }
    compute_hints();
  }

  // The Delaunay triangulation of the centres, built in insertion order; the hint of the
  // k-th centre is its nearest Delaunay neighbour among the centres before it, found on the
  // fan of its new vertex (the nearest neighbour of a point is a Delaunay neighbour). Each
  // centre is located from the previous one (spatial order) or from the last centre inserted
  // in its grid cell (random order, where the previous centre is anywhere). The distances are
  // compared in double, on coordinates scaled to the box (squared_distance_in_double()): a
  // hint only chooses where a walk starts.
  void compute_hints()
  {
    // Inexact predicates (internal/toolbox/predicates.h): the centres' triangulation by exact
    // predicates on the coordinates rounded to double (Gt's could crash the insertion).
    constexpr bool exact = !internal::decides_by_exact_predicates<Gt>::value;
    using Cgt = std::conditional_t<exact, Gt, internal::Deciding_gt>;
    using Vb = Triangulation_vertex_base_with_info_2<std::uint32_t, Cgt>;
    using Tds = Triangulation_data_structure_2<Vb>;
    using Centre_triangulation = Delaunay_triangulation_2<Cgt, Tds>;
    using Vertex_handle = typename Centre_triangulation::Vertex_handle;
    using Face_handle = typename Centre_triangulation::Face_handle;
    const std::size_t n = size();
    hint_rank_.assign(n, 0);
    Centre_triangulation dt = [&] {
      if constexpr(exact)
        return Centre_triangulation(traits_);
      else
        return Centre_triangulation();
    }();
    internal::Vertex_grid<Vertex_handle> grid(n, box_);
    std::vector<std::pair<Face_handle, int>> flip_stack;
    Vertex_handle previous;
    for(std::size_t r = 0; r < n; ++r) {
      const typename Cgt::Point_2 c = [&] {
        if constexpr(exact)
          return centre_[order_[r]];
        else
          return typename Cgt::Point_2(CGAL::to_double(centre_[order_[r]].x()), CGAL::to_double(centre_[order_[r]].y()));
      }();
      Vertex_handle start = grid.near(c);
      if(start == Vertex_handle() ||
         (previous != Vertex_handle() && internal::squared_distance_in_double(previous->point(), c, scale_) <
                                             internal::squared_distance_in_double(start->point(), c, scale_)))
        start = previous;
      const std::size_t count = dt.number_of_vertices();
      const Vertex_handle v =
          internal::insert_near(dt, c, start == Vertex_handle() ? Face_handle() : start->face(), flip_stack);
      if(dt.number_of_vertices() == count) { // a centre already inserted
        hint_rank_[r] = v->info();
        previous = v;
        continue;
      }
      v->info() = std::uint32_t(r);
      if(r != 0) {
        // The nearest finite neighbour of v; in dimension 0 there is none but the first centre.
        std::uint32_t best = 0;
        double best_distance = std::numeric_limits<double>::infinity();
        if(dt.dimension() > 0) {
          auto w = dt.incident_vertices(v), end = w;
          do {
            if(dt.is_infinite(w))
              continue;
            const double d = internal::squared_distance_in_double(w->point(), c, scale_);
            if(d < best_distance) {
              best_distance = d;
              best = w->info();
            }
          } while(++w != end);
        }
        hint_rank_[r] = best;
      }
      grid.record(c, v);
      previous = v;
    }
  }


  Gt traits_;
  std::vector<Point> centre_;
  std::vector<FT> radius_;
  std::vector<std::uint32_t> order_;     // order_[r]: the disk inserted r-th
  std::vector<std::uint32_t> hint_rank_; // hint_rank_[r]: the rank of the hint of the disk of rank r (r > 0)
  std::vector<std::uint32_t> rank_;      // rank_[i]: the rank of disk i (inverse of order_)
  internal::Box box_; // of the disks, finite
  double scale_ = 1; // unit_scale() of the centres' box, for the distances of compute_hints()
};

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_IMPRECISE_POINTS_H
