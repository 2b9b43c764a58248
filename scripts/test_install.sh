#!/usr/bin/env bash
# Uses the package the way an outside project does, in a throw-away folder:
#  1. configure with -DBUILD_TESTING=OFF and install into a prefix (`cmake --install`);
#  2. an outside CMake project: find_package(Delaunay_from_prediction CONFIG REQUIRED
#     COMPONENTS TBB) and target_link_libraries(... CGAL::Delaunay_from_prediction), building
#     the example from_indexed_faces.cpp (it returns 0 only if its results equal CGAL's) and a
#     CGAL::Parallel_tag call;
#  3. the same example through add_subdirectory() of the repository;
#  4. the repository's examples folder configured on its own against the installed package;
#  5. when scripts/test.sh has built build/: that build installed, dfp and the Python module
#     run from the prefix.
# Each program is run. Installs the build dependencies with apt-get if they are missing.
# Usage: scripts/test_install.sh   (from any directory; about 3 minutes on 2 cores)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo=$(pwd)
scripts/install_dependencies.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "== install into $work/prefix"
cmake -S . -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DDFP_BUILD_EXAMPLES=OFF \
  -DDFP_BUILD_BENCHMARKS=OFF > "$work/configure.log"
cmake --install "$work/build" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/include/CGAL/Delaunay_from_prediction_2.h"
test -f "$work/prefix/share/cmake/Delaunay_from_prediction/Delaunay_from_predictionConfig.cmake"

mkdir -p "$work/app"
cp examples/Delaunay_from_prediction/from_indexed_faces.cpp "$work/app/"
cat > "$work/app/parallel.cpp" <<'CPP'
// CGAL::Parallel_tag through the installed package's TBB component: the result, from a
// prediction with every seventh face given clockwise, must be the triangulation CGAL builds.
#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <algorithm>
#include <array>
#include <iostream>
#include <utility>
#include <vector>
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
using Triple = std::array<std::size_t, 3>;
std::vector<Triple> face_set(const DT& dt)
{
  std::vector<Triple> faces;
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    Triple t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}
int main()
{
  CGAL::Random random(7);
  std::vector<K::Point_2> points;
  std::vector<std::pair<K::Point_2, std::size_t>> indexed;
  for(std::size_t i = 0; i < 20000; ++i) {
    points.emplace_back(random.get_double(), random.get_double());
    indexed.emplace_back(points.back(), i);
  }
  const DT reference(indexed.begin(), indexed.end());
  std::vector<Triple> faces = face_set(reference);
  for(std::size_t k = 0; k < faces.size(); k += 7)
    std::swap(faces[k][1], faces[k][2]);
  DT dt;
  CGAL::Delaunay_from_prediction::delaunay_from_prediction<CGAL::Parallel_tag>(points, faces, dt);
  const bool ok = face_set(dt) == face_set(reference);
  std::cout << "Parallel_tag: " << dt.number_of_faces() << " faces, " << (ok ? "equal to CGAL's" : "NOT CGAL's")
            << "\n";
  return ok ? 0 : 1;
}
CPP
cat > "$work/app/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.14)
project(outside_app CXX)
find_package(Delaunay_from_prediction 1.0 CONFIG REQUIRED COMPONENTS TBB)
add_executable(from_indexed_faces from_indexed_faces.cpp)
target_link_libraries(from_indexed_faces PRIVATE CGAL::Delaunay_from_prediction)
add_executable(parallel parallel.cpp)
target_link_libraries(parallel PRIVATE CGAL::Delaunay_from_prediction)
CMAKE
echo "== outside project, find_package"
cmake -S "$work/app" -B "$work/app/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/app.log"
cmake --build "$work/app/build" -j2 > "$work/app_build.log" || { cat "$work/app_build.log"; exit 1; }
"$work/app/build/from_indexed_faces" | tail -n 2
"$work/app/build/parallel"

mkdir -p "$work/sub"
cp examples/Delaunay_from_prediction/from_indexed_faces.cpp "$work/sub/"
cat > "$work/sub/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.14)
project(outside_subdirectory CXX)
add_subdirectory("$repo" dfp)
add_executable(from_indexed_faces from_indexed_faces.cpp)
target_link_libraries(from_indexed_faces PRIVATE CGAL::Delaunay_from_prediction)
CMAKE
echo "== outside project, add_subdirectory"
cmake -S "$work/sub" -B "$work/sub/build" -DCMAKE_BUILD_TYPE=Release > "$work/sub.log"
cmake --build "$work/sub/build" -j2 > "$work/sub_build.log" || { cat "$work/sub_build.log"; exit 1; }
"$work/sub/build/from_indexed_faces" | tail -n 2

echo "== the examples folder on its own, against the installed package"
cmake -S examples/Delaunay_from_prediction -B "$work/examples" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/examples.log"
cmake --build "$work/examples" -j2 --target moving_points > "$work/examples_build.log" ||
  { cat "$work/examples_build.log"; exit 1; }
"$work/examples/moving_points" 20000 3 | tail -n 2
# 5. The project's own build (build/, when scripts/test.sh has made it) installed: the tool dfp
#    and the Python module run from the prefix, outside the build tree.
if compgen -G "build/python/delaunay_from_prediction*.so" > /dev/null &&
   [ -x build/examples/Delaunay_from_prediction/dfp/dfp ]; then
  echo "== build/ installed: dfp and the Python module from the prefix"
  cmake --install build --prefix "$work/full" > "$work/full_install.log"
  "$work/full/bin/dfp" --help > /dev/null
  site=$(echo "$work"/full/lib/python3.*/dist-packages)
  # The pytest suite's helpers compare the faces (test_python_module.py imports the module too).
  (cd "$work" && PYTHONDONTWRITEBYTECODE=1 PYTHONPATH="$site:$repo/test/Delaunay_from_prediction/python" /usr/bin/python3 -c '
import numpy as np, delaunay_from_prediction as dfp
from test_python_module import assert_same
points = np.random.default_rng(3).random((2000, 2))
reference = dfp.delaunay_triangulation(points)
triangles, stats = dfp.delaunay_from_prediction(points, reference[::-1])
assert dfp.__file__.startswith("'"$site"'"), dfp.__file__
assert_same(triangles, reference)
print("installed module:", dfp.__file__)')
else
  echo "== build/ installed: skipped (no build/ with dfp and the Python module: run scripts/test.sh first)"
fi
echo "test_install: all passed"
