// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// What keeps a program that calls the package quick to compile (compile_time.sh): the
// compiler's time goes mostly to optimizing the code it emits, so code that only rare inputs
// reach is marked CGAL_DFP_RARELY_RUN (a hole boundary that is not a simple polygon, islands
// of faces, a rollback, two points at one place, collinear points). GCC and Clang then
// optimize it for size and inline less into it, and its callers treat the call as unlikely;
// the hot paths are compiled as before. CGAL_DFP_OUT_OF_LINE keeps one copy of a helper that
// many places call off the hot loops (an insertion into a hash table, a sort of addresses),
// where a call costs nothing measurable and each inlined copy is code to compile.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CODE_SIZE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CODE_SIZE_H

#if defined(__GNUC__) || defined(__clang__)
#define CGAL_DFP_RARELY_RUN __attribute__((cold))
#define CGAL_DFP_OUT_OF_LINE __attribute__((noinline))
#else
#define CGAL_DFP_RARELY_RUN
#define CGAL_DFP_OUT_OF_LINE
#endif

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_TOOLBOX_CODE_SIZE_H
