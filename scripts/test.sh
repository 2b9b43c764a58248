#!/usr/bin/env bash
# The quick start's test command: builds and runs (ctest) the core tests (the suite `core`:
# results against CGAL's build on degenerate inputs with Epick and Epeck, on damaged
# predictions, and with an inexact kernel), the examples (each checks its results against
# CGAL's), the tool dfp on files and the Python module (pytest), in Release, in build/ at the
# repository root. Installs the build dependencies with apt-get if they are missing.
# With --all it builds and runs every test (the other suites, the differential fuzzer's fixed
# cases, each public header alone, the compile-time refusals; the suites other than core at -O1,
# see test/Delaunay_from_prediction/CMakeLists.txt) and type-checks the benchmarks
# (-fsyntax-only: no programs; build them with cmake -DDFP_BUILD_BENCHMARKS=ON
# -DDFP_BENCHMARKS_SYNTAX_ONLY=OFF), in the same build/: what CI runs. After a quick run it compiles only what is missing.
# Usage: scripts/test.sh [--all]   (from any directory)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$(date +%s)

case "${1:-}" in
  "") options=(-DDFP_QUICK_TESTS=ON -DDFP_BUILD_BENCHMARKS=OFF) ;;
  --all) options=(-DDFP_QUICK_TESTS=OFF -DDFP_BUILD_BENCHMARKS=ON -DDFP_BENCHMARKS_SYNTAX_ONLY=ON) ;;
  *) echo "usage: scripts/test.sh [--all]" >&2; exit 2 ;;
esac

scripts/install_dependencies.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${options[@]}"
cmake --build build -j2
cd build
# DFP_CTEST_EXCLUDE: a regular expression of tests not to run (.ci/run: those its first step ran).
ctest --output-on-failure -j2 ${DFP_CTEST_EXCLUDE:+-E "$DFP_CTEST_EXCLUDE"}
echo "scripts/test.sh ${1:-}: $(( ($(date +%s) - start) / 60 )) min $(( ($(date +%s) - start) % 60 )) s"
