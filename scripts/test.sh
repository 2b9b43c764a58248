#!/usr/bin/env bash
# Builds everything (Release, in build/ at the repository root) and runs the tests and
# examples with ctest. Installs the build dependencies with apt-get if they are missing.
# Usage: scripts/test.sh   (from any directory)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/install_dependencies.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
cd build
ctest --output-on-failure -j2
