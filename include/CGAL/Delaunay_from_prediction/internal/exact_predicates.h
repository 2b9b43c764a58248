// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// has_exact_predicates<Gt>: whether the orientation and in-circle predicates of the traits
// `Gt` are exact, so that the package's own algorithms (Lawson flips, walks, certificates,
// carving) may rely on them being consistent. True when the traits declare filtered
// predicates (`Gt::Has_filtered_predicates`: Epick, Epeck, any Filtered_kernel) or when
// their number type is exact (`Algebraic_structure_traits<Gt::FT>::Is_exact`, e.g.
// Simple_cartesian<Gmpq>). decides_by_exact_predicates<Gt>: traits that are not, on 2D
// kernel points (Simple_cartesian<double>); the entry points then decide the faces by
// Epick's exact predicates on the coordinates rounded to double (rebuild.h: build_deciding()),
// since CGAL's own insertion with such traits was seen to lose points, leave invalid
// triangulations and crash on almost collinear points.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EXACT_PREDICATES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EXACT_PREDICATES_H

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/tags.h>

#include <type_traits>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

template <class Gt, class = void>
struct declares_filtered_predicates : std::false_type {};

template <class Gt>
struct declares_filtered_predicates<Gt, std::void_t<decltype(Gt::Has_filtered_predicates)>>
    : std::integral_constant<bool, bool(Gt::Has_filtered_predicates)> {};

template <class Gt, class = void>
struct has_exact_number_type : std::false_type {};

template <class Gt>
struct has_exact_number_type<Gt, std::void_t<typename Algebraic_structure_traits<typename Gt::FT>::Is_exact>>
    : std::is_same<typename Algebraic_structure_traits<typename Gt::FT>::Is_exact, Tag_true> {};

template <class Gt>
struct has_exact_predicates
    : std::integral_constant<bool, declares_filtered_predicates<Gt>::value || has_exact_number_type<Gt>::value> {};

// Whether the entry points decide the faces by Epick's predicates on the coordinates rounded to
// double (rebuild.h) instead of the traits' own: their predicates are not exact, and their
// points are 2D points of a kernel, whose x() and y() are what the predicates read. (Points of
// other traits, e.g. 3D points under Projection_traits_xz_3, have no such coordinates: those
// traits are used as they are.)
template <class Gt>
struct decides_by_exact_predicates
    : std::integral_constant<bool, !has_exact_predicates<Gt>::value &&
                                       std::is_same<typename Gt::Point_2,
                                                    typename Kernel_traits<typename Gt::Point_2>::Kernel::Point_2>::value> {};


} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_EXACT_PREDICATES_H
