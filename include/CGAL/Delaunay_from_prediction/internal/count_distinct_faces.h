// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The number of distinct faces in a list of face handles, for Statistics::faces_certified of
// delaunay_from_prediction() and make_delaunay().

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_COUNT_DISTINCT_FACES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_COUNT_DISTINCT_FACES_H

#include <CGAL/Delaunay_from_prediction/internal/sort_addresses.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

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

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_COUNT_DISTINCT_FACES_H
