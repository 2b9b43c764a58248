// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Inputs large enough (n >= 2^16; reordering starts at 2^12) for the import to reorder them spatially (renumbered points,
// sorted faces) and for its frontier of open half-edges to wrap around: the result must still
// be CGAL's DT, with each vertex's info the smallest index of its point, whatever the order
// of the points and faces, and whether the reordering ran or was skipped.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/hilbert_sort.h>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Points = std::vector<K::Point_2>;

template <class NP = DFP::parameters::Default_named_parameters>
DFP::Statistics run(const Points& points, const Faces& faces, const NP& np = NP())
{
  DT_with_info<K> dt;
  const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt, np);
  check_is_cgal_delaunay(dt, points);
  check_statistics(s, faces, points, dt);
  return s;
}

void test_orders(Points points, CGAL::Random& rng)
{
  const std::size_t n = points.size();
  {
    Scope scope("points and faces in random order");
    const DFP::Statistics s = run(points, shuffled(delaunay_faces<K>(points), rng));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.input_reordered);
    DFP_CHECK(s.faces_certified == s.faces_in);
  }
  {
    Scope scope("the DT after ", n / 100, " random flips, random order");
    const DFP::Statistics s = run(points, shuffled(flipped_delaunay_faces<K>(points, n / 100, rng), rng));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.flips > 0);
  }
  {
    Scope scope("a prediction covering about half of the points");
    Points half(points.begin(), points.begin() + std::ptrdiff_t(n / 2));
    Faces faces = shuffled(delaunay_faces<K>(half), rng);
    const DFP::Statistics s = run(points, faces);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.points_unused == n - n / 2);
  }
  {
    Scope scope("points in Hilbert order, faces sorted by smallest index (no reordering)");
    CGAL::hilbert_sort(points.begin(), points.end());
    Faces faces = delaunay_faces<K>(points);
    for(Face& f : faces)
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    std::sort(faces.begin(), faces.end());
    const DFP::Statistics s = run(points, faces);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(!s.input_reordered);
  }
  {
    Scope scope("points in Hilbert order, faces in random order (faces sorted only)");
    const DFP::Statistics s = run(points, shuffled(delaunay_faces<K>(points), rng));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.input_reordered);
  }
  {
    Scope scope("duplicates of every 7th point appended, prediction on the originals");
    Points with_copies = points;
    for(std::size_t i = 0; i < n; i += 7)
      with_copies.push_back(points[i]);
    const DFP::Statistics s = run(with_copies, shuffled(delaunay_faces<K>(points), rng));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.duplicate_points == with_copies.size() - n);
  }
}

int main()
{
  CGAL::Random rng(2026);
  const std::size_t n = 70000;
  {
    Scope scope("uniform, n = ", n);
    DFP_RUN(test_orders(to_points<K>(uniform_points(n, rng)), rng));
  }
  {
    Scope scope("clustered, n = ", n);
    DFP_RUN(test_orders(to_points<K>(clustered_points(n, rng)), rng));
  }
  {
    Scope scope("integer grid 300 x 300 (co-circular everywhere), n = 90000");
    DFP_RUN(test_orders(to_points<K>(grid_points(300, 300, rng)), rng));
  }
  return finish("test_large_input");
}
