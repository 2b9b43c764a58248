// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Copies a vertex's info() into a vertex of another triangulation type when it can be assigned
// (split_delaunay() keeps each vertex's info in the part it goes to).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_VERTEX_INFO_COPY_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_VERTEX_INFO_COPY_H

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether the info() of a vertex of type To can be assigned that of a vertex of type From.
template <class From, class To, class = void>
struct can_copy_info : std::false_type {};
template <class From, class To>
struct can_copy_info<From, To, std::void_t<decltype(std::declval<To&>().info() = std::declval<const From&>().info())>>
    : std::true_type {};

template <class FromHandle, class ToHandle>
void copy_info(FromHandle from, ToHandle to)
{
  if constexpr(can_copy_info<std::decay_t<decltype(*from)>, std::decay_t<decltype(*to)>>::value)
    to->info() = from->info();
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_VERTEX_INFO_COPY_H
