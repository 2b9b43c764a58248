// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Whether a list of points is already in a spatially coherent order: split_delaunay()'s ordered
// method then inserts each part in that order, with no sort.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SPATIAL_COHERENCE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SPATIAL_COHERENCE_H

#include <CGAL/Delaunay_from_prediction/internal/spatial_order.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether points listed in this order are spatially coherent: the median distance between
// 255 sampled consecutive points is at most 4 times the side of the area per point of their
// bounding box (CGAL's spatial sort, even in BRIO rounds, is; an order of insertion at random
// is not).
template <class PointAt>
bool order_looks_spatial(std::size_t n, PointAt point_at)
{
  if(n < 4096)
    return false; // small: sorting costs nothing
  const Box box = bounding_box(n, point_at);
  // Lengths and area on coordinates scaled by unit_scale(): neither overflows.
  const double scale = unit_scale(box);
  const double area_per_point =
      (box.xmax * scale - box.xmin * scale) * (box.ymax * scale - box.ymin * scale) / double(n);
  std::vector<double> squared;
  for(std::size_t s = 0; s < 255; ++s) {
    const std::size_t k = s * (n - 1) / 255;
    squared.push_back(squared_distance_in_double(point_at(k), point_at(k + 1), scale));
  }
  std::nth_element(squared.begin(), squared.begin() + 127, squared.end());
  return squared[127] <= 16 * area_per_point;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_SPATIAL_COHERENCE_H
