// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// CGAL::Triangulation_hierarchy_2 as input or output of the entry points. The package fills
// and repairs level 0 through its TDS; the upper levels are then sampled anew, as CGAL samples
// them: every vertex of level 0 goes through the hierarchy's own
// insert(p, VERTEX, face, index), which draws its level with the hierarchy's random
// generator (geometric, ratio 30), leaves level 0 as it is, and for a level above 0 locates
// the point in the upper levels and inserts its copies there, linked by up() and down().

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_HIERARCHY_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_HIERARCHY_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <CGAL/Triangulation_hierarchy_2.h>

#include <stdexcept>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether T is a CGAL::Triangulation_hierarchy_2, or a class derived from one.
template <class T, class = void>
struct is_triangulation_hierarchy : std::false_type {};
template <class T>
struct is_triangulation_hierarchy<T, std::void_t<typename T::Tr_Base>>
    : std::is_base_of<CGAL::Triangulation_hierarchy_2<typename T::Tr_Base>, T> {};

// Level 0 of a hierarchy: the triangulation the package works on.
template <class Hierarchy>
typename Hierarchy::Tr_Base& level_zero(Hierarchy& h)
{
  return static_cast<typename Hierarchy::Tr_Base&>(h);
}

// CGAL's hierarchy class of `h` (its clear() and insert(), whatever a derived class declares).
template <class Hierarchy>
CGAL::Triangulation_hierarchy_2<typename Hierarchy::Tr_Base>& cgal_hierarchy(Hierarchy& h)
{
  return static_cast<CGAL::Triangulation_hierarchy_2<typename Hierarchy::Tr_Base>&>(h);
}

// Empties the upper levels of `h`, leaving level 0 (its vertex and face objects) as it is.
// With `unlink`, no vertex of level 0 has an up() copy afterwards; otherwise the caller resets
// them (they refer to destroyed copies).
template <class Hierarchy>
void clear_upper_levels(Hierarchy& h, bool unlink = true)
{
  using Tr_Base = typename Hierarchy::Tr_Base;
  using Vertex_handle = typename Tr_Base::Vertex_handle;
  // Level 0 moved out (a swap of the TDS's containers: every handle stays valid), all levels
  // cleared, level 0 swapped back.
  Tr_Base level0(h.geom_traits());
  level0.swap(level_zero(h));
  cgal_hierarchy(h).clear();
  level_zero(h).swap(level0);
  h.Tr_Base::infinite_vertex()->set_up(Vertex_handle());
  if(unlink)
    for(auto v = h.Tr_Base::finite_vertices_begin(); v != h.Tr_Base::finite_vertices_end(); ++v)
      v->set_up(Vertex_handle());
}

// Samples the upper levels of `h` anew from its level 0, which must be a valid triangulation.
// With traits whose predicates are not exact (predicates.h) the upper levels are left
// empty: filling them is CGAL's insertion with those predicates, which can crash or loop on
// almost collinear points; an empty upper level is valid, and locations start at level 0.
template <class Hierarchy>
void rebuild_upper_levels(Hierarchy& h)
{
  using Tr_Base = typename Hierarchy::Tr_Base;
  using Vertex_handle = typename Tr_Base::Vertex_handle;
  if constexpr(decides_by_exact_predicates<typename Hierarchy::Geom_traits>::value) {
    clear_upper_levels(h);
    return;
  }
  clear_upper_levels(h, false);
  // While level 0 reads as of dimension 0, the hierarchy's insert(p, VERTEX, f, i) costs a
  // level drawn and nothing else for the 29 vertices in 30 that stay at level 0: a
  // Delaunay_triangulation_2 (level 0's insert) restores the Delaunay property around the
  // vertex only from dimension 2 on (several in-circle tests that flip nothing here: 0.4 of
  // CGAL's whole hierarchy build, measured at 1e5 points), and the location at level 0 of a
  // vertex that goes up is, in dimension 0, a comparison with one point (its result is not
  // used: the copies are located in the upper levels, from the top).
  const int dimension = h.dimension();
  struct Restore_dimension
  {
    Tr_Base& level0;
    int dimension;
    ~Restore_dimension() { level0.tds().set_dimension(dimension); }
  } restore{level_zero(h), dimension};
  if(dimension > 0)
    level_zero(h).tds().set_dimension(0);
  // Container order: level 0 read in memory order; the points of the upper levels are
  // located from the top of the hierarchy, whatever the order.
  const auto end = h.Tr_Base::finite_vertices_end();
  for(auto v = h.Tr_Base::finite_vertices_begin(); v != end; ++v) {
    v->set_up(Vertex_handle());
    const auto f = v->face();
    cgal_hierarchy(h).insert(v->point(), Tr_Base::VERTEX, f, f->index(v));
  }
}

// Runs `run(level0)` on level 0 of the hierarchy `h`, then samples its upper levels anew.
// `run` is one of the entry points, on Tr_Base. When it throws std::invalid_argument
// (Invalid_prediction included: thrown before anything is changed) or `untouched()` says
// that level 0 was not modified, `h` is left as it was; after any other exception its upper
// levels are emptied (their down() copies would refer to vertices that may be gone), which
// leaves a valid hierarchy.
template <class Hierarchy, class Run, class Untouched>
auto with_levels_rebuilt(Hierarchy& h, Run run, Untouched untouched)
{
  try {
    auto result = run(level_zero(h));
    rebuild_upper_levels(h);
    return result;
  } catch(const std::invalid_argument&) {
    throw;
  } catch(...) {
    if(!untouched())
      clear_upper_levels(h);
    throw;
  }
}

template <class Hierarchy, class Run>
auto with_levels_rebuilt(Hierarchy& h, Run run)
{
  return with_levels_rebuilt(h, std::move(run), [] { return false; });
}

// Runs `run(t)` with `t` level 0 of `tr` when it is a hierarchy (then rebuilds its upper
// levels, see with_levels_rebuilt()), `tr` itself otherwise.
template <class Triangulation, class Run, class Untouched>
auto with_levels_rebuilt_if_hierarchy(Triangulation& tr, Run run, Untouched untouched)
{
  if constexpr(is_triangulation_hierarchy<Triangulation>::value)
    return with_levels_rebuilt(tr, std::move(run), std::move(untouched));
  else
    return run(tr);
}

template <class Triangulation, class Run>
auto with_levels_rebuilt_if_hierarchy(Triangulation& tr, Run run)
{
  return with_levels_rebuilt_if_hierarchy(tr, std::move(run), [] { return false; });
}

// A function object that calls `f` and notes in `*threw` whether it threw: an exception of a
// user's function object called before anything is modified leaves the hierarchies as they were.
template <class F>
struct Noting_throws
{
  F f;
  bool* threw;
  template <class... A>
  decltype(auto) operator()(A&&... a)
  {
    try {
      return f(std::forward<A>(a)...);
    } catch(...) {
      *threw = true;
      throw;
    }
  }
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_HIERARCHY_H
