// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The differential fuzzer's checks with Epeck (run_kernel<Epeck>): the second translation unit
// of test_fuzz_differential, so that the two compile in parallel. Everything else, main()
// included, is in test_fuzz_differential.cpp.
#define DFP_FUZZ_EPECK_PART
#include "test_fuzz_differential.cpp"
