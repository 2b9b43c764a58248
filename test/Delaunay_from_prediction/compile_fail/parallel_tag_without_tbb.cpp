// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Must NOT compile: CGAL::Parallel_tag in a build without TBB (CGAL_LINKED_WITH_TBB undefined).
// The ctest test parallel_tag_without_tbb_is_refused compiles it (syntax only) and expects
// the package's static_assert message; CGAL::Parallel_if_available_tag compiles and runs
// sequentially.

#include <CGAL/Delaunay_from_prediction_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace DFP = CGAL::Delaunay_from_prediction;
using DT = CGAL::Delaunay_triangulation_2<CGAL::Exact_predicates_inexact_constructions_kernel>;

int main()
{
  DT dt;
  DFP::make_delaunay<CGAL::Parallel_if_available_tag>(dt); // fine: sequential without TBB
  DFP::make_delaunay<CGAL::Parallel_tag>(dt);              // the static_assert
}
