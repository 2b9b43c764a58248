// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Strategy::regions (Theorem 5.4 in practical form, internal/build/prediction_regions_build.h): the
// prediction divided into regions, each triangulated on its own, the faces the grid vouches
// for kept, the seams triangulated again. On predictions of every kind (right, a few flips,
// points moved by 0.1 to 1 spacing, the rho model with both completions, faces deleted) it
// must take its own path (no fallback, at least two regions, seams a minority of the points)
// and give exactly CGAL's triangulation, with vertex handles and info() kept by make_delaunay;
// random triples interleave the regions everywhere and must give up before triangulating;
// the region size must shape the division; degenerate inputs (co-circular grids, collinear
// points, duplicates, huge and tiny coordinates), the lower-bound configurations of the
// paper's Figures 1 and 2 and tiny region sizes must still give CGAL's triangulation, whatever
// the concurrency. test_local_repair.cpp and test_reliability.cpp
// run the strategy on their inputs too (Mode::regions).

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/prediction_models.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

using namespace dfp_test;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Random = DFP::internal::Splitmix64;

namespace {

std::string describe(const DFP::Statistics& s)
{
  std::ostringstream out;
  out << "fell_back=" << s.fell_back << " (" << to_string(s.outcome) << ") regions=" << s.regions
      << " seam points=" << s.boundary_vertices << " reinserted=" << s.points_reinserted
      << " certified=" << s.faces_certified << " faces_in=" << s.faces_in;
  return out.str();
}

template <class K>
std::vector<typename K::Point_2> uniform(std::size_t n, std::uint64_t seed, double scale = 1.0)
{
  Random random{seed};
  std::vector<typename K::Point_2> points;
  for(std::size_t i = 0; i < n; ++i)
    points.push_back(make_point<K>(scale * random.uniform(), scale * random.uniform()));
  return points;
}

template <class P>
std::vector<P> gaussian_moved(const std::vector<P>& points, double step, std::uint64_t seed)
{
  Random random{seed};
  std::vector<P> moved;
  for(const P& p : points)
    moved.emplace_back(CGAL::to_double(p.x()) + step * random.normal(), CGAL::to_double(p.y()) + step * random.normal());
  return moved;
}

// The strategy's own path: at least two regions, all points inserted, seams a minority (with
// regions of the default size).
void check_own_path(const DFP::Statistics& s, std::size_t n, std::size_t max_seam_points = 0)
{
  if(max_seam_points == 0)
    max_seam_points = n / 2;
  DFP_CHECK_MSG(!s.fell_back && (s.outcome == DFP::Outcome::ok), describe(s));
  DFP_CHECK_MSG(s.regions >= 2, describe(s));
  DFP_CHECK_MSG(s.points_reinserted == n, describe(s));
  DFP_CHECK_MSG(s.boundary_vertices > 0 && s.boundary_vertices < max_seam_points, describe(s));
  DFP_CHECK_MSG(s.faces_certified == 0, describe(s));
}

template <class Faces_, class P, class NP>
DFP::Statistics from_faces(const std::vector<P>& points, const Faces_& faces, const NP& np)
{
  DT_with_info<typename CGAL::Kernel_traits<P>::Kernel> dt;
  const DFP::Statistics s = with_concurrency([&](auto tag) {
    return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt, np);
  });
  check_is_cgal_delaunay(dt, points);
  return s;
}

// delaunay_from_prediction() on predictions of every kind, each concurrency.
void predictions(std::size_t n, std::uint64_t seed)
{
  const auto points = uniform<Epick>(n, seed);
  const auto np = DFP::parameters::strategy(DFP::Strategy::regions);
  const double spacing = 1.0 / std::sqrt(double(n));
  const Faces dt_faces = DFP::delaunay_triangles(points);
  for_each_concurrency([&] {
    {
      Scope scope("the Delaunay faces");
      check_own_path(from_faces(points, dt_faces, np), n);
    }
    {
      Scope scope("1% of the edges flipped");
      check_own_path(from_faces(points, DFP::k_flip_prediction(points, n / 100, seed + 1), np), n);
    }
    for(double sigma : {0.1, 0.5, 1.0}) {
      Scope scope("the Delaunay faces of the points before a move of sigma x spacing, sigma = ", sigma);
      const auto moved = gaussian_moved(points, sigma * spacing, seed + 2);
      check_own_path(from_faces(moved, dt_faces, np), n);
    }
    for(const auto completion : {DFP::Completion::random, DFP::Completion::adversarial})
      for(double rho : {0.1, 0.5}) {
        Scope scope("rho model, rho = ", rho, completion == DFP::Completion::random ? ", random" : ", adversarial");
        check_own_path(from_faces(points, DFP::rho_model_prediction(points, rho, seed + 3, completion), np), n);
      }
    {
      Scope scope("10% of the faces deleted");
      check_own_path(from_faces(points, DFP::delete_faces(dt_faces, 0.1, seed + 4), np), n);
    }
    {
      Scope scope("random triples: the regions interleave, no triangulation by regions");
      Random random{seed + 5};
      Faces triples;
      while(triples.size() < 2 * n) {
        const Face f{std::size_t(random.below(n)), std::size_t(random.below(n)), std::size_t(random.below(n))};
        if(f[0] != f[1] && f[1] != f[2] && f[0] != f[2])
          triples.push_back(f);
      }
      const DFP::Statistics s = from_faces(points, triples, np);
      DFP_CHECK_MSG(s.fell_back && reason_is(s, DFP::Outcome::regions_interleave), describe(s));
      DFP_CHECK_MSG(s.points_reinserted == n && s.boundary_vertices == 0, describe(s));
    }
  });
}

// make_delaunay() after every vertex moved, keeping vertex handles and info().
template <class Tr>
void moved_all(const std::string& label, std::size_t n, double sigma, std::uint64_t seed)
{
  using K = typename Tr::Geom_traits;
  Scope scope(label, ", sigma = ", sigma);
  const auto start = uniform<K>(n, seed);
  const auto moved = gaussian_moved(start, sigma / std::sqrt(double(n)), seed + 1);
  for_each_concurrency([&] {
    Tr tr;
    Handles<Tr> handles;
    build(tr, start, handles);
    DFP::make_delaunay(tr); // a Triangulation_2 too
    for(std::size_t i = 0; i < n; ++i)
      handles[i]->set_point(moved[i]);
    const DFP::Statistics s = with_concurrency([&](auto tag) {
      return DFP::make_delaunay<decltype(tag)>(tr, DFP::parameters::strategy(DFP::Strategy::regions));
    });
    check_own_path(s, n);
    check_handles(tr, handles, moved);
    check_is_cgal_delaunay(tr, moved);
  });
}

// The region size shapes the division: about n/(t/2) regions (fragments joined), and a
// smaller t puts more points in the seams; t of the whole prediction is one region, nothing
// to divide.
void region_sizes(std::size_t n, std::uint64_t seed)
{
  Scope scope("region_size");
  const auto points = gaussian_moved(uniform<Epick>(n, seed), 0.3 / std::sqrt(double(n)), seed + 1);
  const Faces faces = DFP::delaunay_triangles(uniform<Epick>(n, seed));
  std::size_t last_seams = 0;
  for(std::size_t t : {16384, 2048, 256}) {
    Scope st("t = ", t);
    const DFP::Statistics s =
        from_faces(points, faces, DFP::parameters::strategy(DFP::Strategy::regions, DFP::parameters::region_size(t)));
    check_own_path(s, n, n);
    const std::size_t share = t / 2;
    DFP_CHECK_MSG(s.regions >= n / share && s.regions <= 2 * (n / share) + 2, describe(s));
    DFP_CHECK_MSG(s.boundary_vertices > last_seams, describe(s));
    last_seams = s.boundary_vertices;
  }
  {
    Scope st("t = 4 n");
    const DFP::Statistics s =
        from_faces(points, faces, DFP::parameters::strategy(DFP::Strategy::regions, DFP::parameters::region_size(4 * n)));
    DFP_CHECK_MSG(s.fell_back && reason_is(s, DFP::Outcome::too_few_regions) && s.regions == 1, describe(s));
  }
}

// Strategy::regions with region size t (0: the default).
template <class P, class Faces_>
void with_region_size(std::size_t t, const std::vector<P>& points, const Faces_& faces)
{
  if(t == 0)
    from_faces(points, faces, DFP::parameters::strategy(DFP::Strategy::regions));
  else
    from_faces(points, faces, DFP::parameters::strategy(DFP::Strategy::regions, DFP::parameters::region_size(t)));
}

// Degenerate inputs, with tiny regions (every face near a seam) and the default ones.
void degenerate()
{
  for(std::size_t t : {std::size_t(8), std::size_t(64), std::size_t(0)}) {
    Scope st("t = ", t, " (0: the default)");
    for_each_concurrency([&] {
      {
        Scope scope("co-circular grid 40 x 40");
        std::vector<Epick::Point_2> points;
        for(int i = 0; i < 40; ++i)
          for(int j = 0; j < 40; ++j)
            points.emplace_back(i, j);
        with_region_size(t, points, DFP::delaunay_triangles(points));
        // Other diagonals of the grid's squares: still co-circular, all ties.
        with_region_size(t, points, DFP::k_flip_prediction(points, 400, 7));
      }
      {
        Scope scope("collinear points");
        std::vector<Epick::Point_2> points;
        for(int i = 0; i < 500; ++i)
          points.emplace_back(i, 2 * i);
        Faces faces;
        for(std::size_t i = 0; i + 2 < points.size(); ++i)
          faces.push_back({i, i + 1, i + 2});
        with_region_size(t, points, faces);
      }
      {
        Scope scope("duplicates");
        auto points = uniform<Epick>(2000, 17);
        Faces faces = DFP::delaunay_triangles(points);
        for(std::size_t i = 0; i < 200; ++i)
          points.push_back(points[7 * i]);
        faces.push_back({2000, 1, 2});
        with_region_size(t, points, faces);
      }
      {
        // Sides of the box in a ratio of 1e305: the grid's cells a side are clamped in double.
        Scope scope("subnormal spread, one point far off");
        std::vector<Epick::Point_2> points;
        for(int i = 0; i < 6; ++i)
          for(int j = 0; j < 6; ++j)
            points.emplace_back(i * 1.424e-306, j * 1.424e-306);
        const Faces faces = DFP::delaunay_triangles(points);
        points[3] = Epick::Point_2(points[3].x(), 1.0);
        with_region_size(t, points, faces);
      }
      for(double scale : {1e300, 1e-300}) {
        Scope scope("coordinates of order ", scale);
        const auto points = uniform<Epick>(3000, 19, scale);
        with_region_size(t, points, DFP::delaunay_triangles(points));
      }
    });
  }
}

// The lower-bound configurations of Figures 1 and 2 of the paper (lists merged by DT(P)):
// far from Delaunay, with regions of any size; the result must be CGAL's.
void lower_bound_configurations()
{
  for(std::size_t t : {std::size_t(16), std::size_t(0)}) {
    Scope st("t = ", t, " (0: the default)");
    for_each_concurrency([&] {
      {
        Scope scope("Figure 1: sorting, 3000 numbers");
        const auto instance = DFP::sorting_configuration<Epick>(3000, 5);
        with_region_size(t, instance.points, instance.faces);
      }
      {
        Scope scope("Figure 2: merging 8 lists of 300");
        const auto instance = DFP::merging_lists_configuration<Epick>(8, 300, 6);
        with_region_size(t, instance.points, instance.faces);
      }
    });
  }
}

// Epeck: the same path, exact constructions.
void exact_kernel(std::size_t n, std::uint64_t seed)
{
  Scope scope("Epeck");
  const auto start = uniform<Epeck>(n, seed);
  const auto moved = gaussian_moved(start, 0.5 / std::sqrt(double(n)), seed + 1);
  check_own_path(from_faces(moved, DFP::delaunay_triangles(start), DFP::parameters::strategy(DFP::Strategy::regions)), n);
}

} // namespace

int main()
{
  const std::size_t n = 20000;
  using DT = DT_with_info<Epick>;
  using T2 = T2_with_info<Epick, int>;
  DFP_RUN(predictions(n, 11));
  DFP_RUN(moved_all<DT>("make_delaunay, Delaunay_triangulation_2 with info", n, 0.5, 21));
  DFP_RUN(moved_all<T2>("make_delaunay, Triangulation_2 with int info", n, 1.0, 22));
  DFP_RUN(region_sizes(n, 31));
  DFP_RUN(degenerate());
  DFP_RUN(lower_bound_configurations());
  DFP_RUN(exact_kernel(5000, 41));
  return finish("test_prediction_regions");
}
