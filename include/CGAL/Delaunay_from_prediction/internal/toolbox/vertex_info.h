// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Vertex info as a point index: detected from the vertex type, so that every entry point
// works with or without info.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VERTEX_INFO_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VERTEX_INFO_H

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

template <class Vertex, class = void>
struct has_index_info : std::false_type {};

template <class Vertex>
struct has_index_info<Vertex, std::void_t<decltype(std::declval<Vertex&>().info() = std::size_t())>>
    : std::true_type {};

// Sets the info of `v` to `index` if it has one.
template <class Vertex_handle>
void set_index_info(Vertex_handle v, std::size_t index)
{
  if constexpr(has_index_info<std::decay_t<decltype(*v)>>::value)
    v->info() = index;
}

// `v` already holds a point of index `held`; the point of index `index` equals it. Keeps the
// smaller index, as the API promises for duplicates.
template <class Vertex_handle>
void merge_index_info(Vertex_handle v, std::size_t index)
{
  if constexpr(has_index_info<std::decay_t<decltype(*v)>>::value)
    if(index < static_cast<std::size_t>(v->info()))
      v->info() = index;
}

// The vertex `v` the insertion of the point of index `index` returned: a new vertex gets the
// index, an existing one (a duplicate point) keeps the smaller index, and `duplicates` counts it.
template <class Vertex_handle>
void record_index_info(Vertex_handle v, std::size_t index, bool is_new, std::size_t& duplicates)
{
  if(is_new) {
    set_index_info(v, index);
  } else {
    merge_index_info(v, index);
    ++duplicates;
  }
}

// A vertex at the same point as `v` goes: `v` keeps the smaller of their indices.
template <class Vertex_handle>
void merge_index_info_of(Vertex_handle v, Vertex_handle duplicate)
{
  if constexpr(has_index_info<std::decay_t<decltype(*v)>>::value)
    merge_index_info(v, static_cast<std::size_t>(duplicate->info()));
}

// Copies a vertex's info() into a vertex of another triangulation type when it can be
// assigned (split_delaunay() keeps each vertex's info in the part it goes to).
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

// The finite faces of `dt` as triples of the vertices' info() (point indices), counter-
// clockwise; none below dimension 2.
template <class DT>
std::vector<std::array<std::size_t, 3>> faces_of(const DT& dt)
{
  std::vector<std::array<std::size_t, 3>> faces;
  if(dt.dimension() == 2) {
    faces.reserve(dt.number_of_faces());
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  return faces;
}

// The finite edges of `dt` as pairs of the vertices' info(), each once (dimension 1 included).
template <class DT>
std::vector<std::array<std::size_t, 2>> edges_of(const DT& dt)
{
  std::vector<std::array<std::size_t, 2>> edges;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    edges.push_back({e->first->vertex(dt.cw(e->second))->info(), e->first->vertex(dt.ccw(e->second))->info()});
  return edges;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_VERTEX_INFO_H
