#!/usr/bin/env bash
# Builds (Release, in build/ at the repository root) and runs the main demo,
# examples/Delaunay_from_prediction/moving_points.cpp: particles in a vortex, the Delaunay
# triangulation kept up to date frame by frame with make_delaunay() and checked against
# CGAL's from-scratch build. Installs the build dependencies with apt-get if they are missing.
# Usage: scripts/demo.sh [N [frames [step]]]   (from any directory; arguments go to the demo)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/install_dependencies.sh

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target moving_points
exec build/examples/Delaunay_from_prediction/moving_points "$@"
