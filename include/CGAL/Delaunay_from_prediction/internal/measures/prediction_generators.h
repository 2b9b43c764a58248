// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Support of the prediction generators of prediction_models.h: DT(P) with point indices as
// info, its faces as index triples, edges drawn uniformly at random, and flips made only where
// the two faces form a strictly convex quadrilateral.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_GENERATORS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_GENERATORS_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/prediction_measures.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Kernel_traits.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The finite faces of a triangulation, for drawing edges uniformly at random. CGAL's flip
// reuses the two faces it changes, so the list stays valid while flipping.
template <class DT>
class Random_edges
{
public:
  using Face_handle = typename DT::Face_handle;

  explicit Random_edges(const DT& dt)
  {
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      faces_.push_back(f);
    // Euler: 2E = 3F + h, with h hull edges and F = 2V - 2 - h finite faces.
    const std::size_t v = dt.number_of_vertices();
    hull_edges_ = faces_.empty() ? 0 : 2 * v - 2 - faces_.size();
  }
  std::size_t number_of_edges() const { return (3 * faces_.size() + hull_edges_) / 2; }
  // Draws an edge uniformly: each interior edge is two of the 3F + h half-edges, each hull
  // edge one finite half-edge and one infinite one. Returns false for a hull edge (which no
  // flip can change).
  bool draw(Splitmix64& random, Face_handle& f, int& i) const
  {
    if(faces_.empty())
      return false; // no triangle: nothing to flip
    const std::size_t r = random.below(3 * faces_.size() + hull_edges_);
    if(r >= 3 * faces_.size())
      return false;
    f = faces_[r / 3];
    i = int(r % 3);
    return true;
  }

private:
  std::vector<Face_handle> faces_;
  std::size_t hull_edges_ = 0;
};

// Flips the edge (f, i) if both its faces are finite and form a strictly convex quadrilateral.
template <class DT>
bool flip_if_convex(DT& dt, typename DT::Face_handle f, int i)
{
  const auto g = f->neighbor(i);
  if(dt.is_infinite(f) || dt.is_infinite(g))
    return false;
  const auto& d = g->vertex(dt.tds().mirror_index(f, i))->point();
  if(!flip_makes_ccw_faces(dt.geom_traits(), f->vertex(i)->point(), f->vertex(ccw(i))->point(),
                           f->vertex(cw(i))->point(), d))
    return false;
  dt.tds().flip(f, i);
  return true;
}

template <class DT>
std::uint64_t edge_key_of(typename DT::Face_handle f, int i)
{
  return edge_key(f->vertex(ccw(i))->info(), f->vertex(cw(i))->info());
}

// DT(P), each vertex's info the smallest index of its point.
template <class PointRange>
auto indexed_delaunay(const PointRange& points)
{
  using Point = typename std::iterator_traits<decltype(std::begin(points))>::value_type;
  using K = typename CGAL::Kernel_traits<Point>::Kernel;
  Indexed_delaunay_2<K> dt;
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  check_points_are_finite(std::begin(points), n);
  Statistics ignored;
  build_from_scratch(dt, std::begin(points), n, ignored);
  return dt;
}

inline void check_probability(double rho, const char* what)
{
  if(!(rho >= 0.0 && rho <= 1.0))
    throw std::invalid_argument(std::string("Delaunay_from_prediction: ") + what +
                                " must be in [0, 1]");
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_GENERATORS_H
