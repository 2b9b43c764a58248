#!/usr/bin/env bash
# Builds the tests, the examples, the tool dfp and the Python module (Release, in build/ at the
# repository root) and runs them with ctest. The benchmarks are left out (CI builds them after;
# `cmake -S . -B build -DDFP_BUILD_BENCHMARKS=ON` adds them). Installs the build dependencies
# with apt-get if they are missing.
# Usage: scripts/test.sh   (from any directory)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
start=$(date +%s)

scripts/install_dependencies.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDFP_BUILD_BENCHMARKS=OFF
cmake --build build -j2
cd build
ctest --output-on-failure -j2
echo "scripts/test.sh: $(( ($(date +%s) - start) / 60 )) min $(( ($(date +%s) - start) % 60 )) s"
