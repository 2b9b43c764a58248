// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Imprecise_points_2: the Delaunay triangulation of an instance of preprocessed disks. Every
// result is compared with CGAL's triangulation of the instance built from scratch with the
// same kernel (by coordinates and by disk indices), in both insertion orders: the paper's
// disjoint disks with points inside, at the centres and on the boundaries, points outside
// their disks, overlapping disks of any radii, and degenerate sets (grids, co-circular,
// collinear, duplicate points and duplicate centres, huge and tiny coordinates, n < 3). Also
// the preprocessing itself (the order is a permutation, each hint is the nearest earlier
// centre), the walks being short, one object serving many instances, and bad input.

#include <CGAL/Delaunay_from_prediction/imprecise_points.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>

using namespace dfp_test;

// Disks given in double (exactly representable in every kernel): centres and radii.
struct Disks
{
  XYs centres;
  std::vector<double> radii;
  bool dyadic = false; // centres and radii multiples of 2^-10: c + (r, 0) is exactly on the circle
};

inline Disks disks_at(const XYs& centres, double radius)
{
  Disks d;
  d.centres = centres;
  d.radii.assign(centres.size(), radius);
  return d;
}

// The paper's point set (Section 5): centres drawn uniformly in a 2 sqrt(n) x 2 sqrt(n)
// square, each kept if farther than 1 from those kept before (disjoint disks of radius 1/2);
// here rounded to multiples of 2^-10.
inline Disks paper_disks(std::size_t n, CGAL::Random& rng)
{
  Disks d;
  d.dyadic = true;
  const double side = 2 * std::sqrt(double(n));
  while(d.centres.size() < n) {
    const XY c{std::round(rng.get_double(0, side) * 1024) / 1024, std::round(rng.get_double(0, side) * 1024) / 1024};
    bool far = true;
    for(const XY& e : d.centres)
      far = far && (e.x - c.x) * (e.x - c.x) + (e.y - c.y) * (e.y - c.y) > 1;
    if(far)
      d.centres.push_back(c);
  }
  d.radii.assign(n, 0.5);
  return d;
}

// One point uniform in each disk.
inline XYs points_in(const Disks& d, CGAL::Random& rng)
{
  XYs xy;
  for(std::size_t i = 0; i < d.centres.size(); ++i) {
    double u, v;
    do {
      u = rng.get_double(-1, 1);
      v = rng.get_double(-1, 1);
    } while(u * u + v * v > 1);
    xy.push_back({d.centres[i].x + d.radii[i] * u, d.centres[i].y + d.radii[i] * v});
  }
  return xy;
}

// One point on the boundary of each disk, exactly (an axis direction: c + (r, 0) and so on).
inline XYs points_on_boundaries(const Disks& d, CGAL::Random& rng)
{
  XYs xy;
  for(std::size_t i = 0; i < d.centres.size(); ++i) {
    const double r = d.radii[i];
    switch(rng.get_int(0, 4)) {
    case 0: xy.push_back({d.centres[i].x + r, d.centres[i].y}); break;
    case 1: xy.push_back({d.centres[i].x - r, d.centres[i].y}); break;
    case 2: xy.push_back({d.centres[i].x, d.centres[i].y + r}); break;
    default: xy.push_back({d.centres[i].x, d.centres[i].y - r}); break;
    }
  }
  return xy;
}

template <class K>
struct Imprecise_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  using FT = typename K::FT;
  using Imprecise = DFP::Imprecise_points_2<K>;
  CGAL::Random rng{2718};

  static std::vector<FT> radii_of(const Disks& d)
  {
    std::vector<FT> r;
    for(double x : d.radii)
      r.push_back(FT(x));
    return r;
  }

  // Triangulates the instance into a triangulation holding other points first, compares
  // with CGAL.
  template <class DT = DT_with_info<K>>
  DFP::Statistics run(const Imprecise& disks, const XYs& xy, bool exact = true)
  {
    const Points points = to_points<K>(xy);
    DT dt;
    dt.insert(make_point<K>(-50., 7.));
    dt.insert(make_point<K>(-51., 7.));
    const DFP::Statistics s = disks.triangulate(points, dt);
    if(exact) {
      check_is_cgal_delaunay(dt, points);
    } else {
      // Inexact predicates: only a valid structure holding every point is promised.
      DFP_CHECK(dt.tds().is_valid());
      DFP_CHECK(dt.number_of_vertices() == smallest_indices(points).size());
    }
    DFP_CHECK(s.points_reinserted == points.size());
    DFP_CHECK_MSG(s.duplicate_points == points.size() - smallest_indices(points).size(), s.duplicate_points);
    DFP_CHECK(s.points_located < (std::max)(std::size_t(1), points.size()));
    // Inexact predicates: built by CGAL's insertion instead, a fallback (predicates.h).
    DFP_CHECK(s.fell_back == DFP::internal::decides_by_exact_predicates<K>::value);
    return s;
  }

  // The preprocessing: the order is a permutation and each hint is a disk inserted earlier
  // whose centre is nearest to the disk's centre among those (brute force, in double).
  void check_hints(const Imprecise& disks, const Disks& d)
  {
    const std::size_t n = d.centres.size();
    DFP_CHECK(disks.size() == n);
    const auto& order = disks.insertion_order();
    std::vector<std::size_t> rank(n, n);
    for(std::size_t r = 0; r < order.size(); ++r)
      if(order[r] < n)
        rank[order[r]] = r;
    DFP_CHECK(order.size() == n && std::count(rank.begin(), rank.end(), n) == 0);
    bool hints_ok = true;
    for(std::size_t r = 0; r < n && rank[order[r]] == r; ++r) {
      const std::size_t i = order[r], h = disks.hint(i);
      if(r == 0) {
        hints_ok = hints_ok && h == n;
        continue;
      }
      auto dist = [&](std::size_t j) {
        const double dx = d.centres[i].x - d.centres[j].x, dy = d.centres[i].y - d.centres[j].y;
        return dx * dx + dy * dy;
      };
      double best = dist(order[0]);
      for(std::size_t s = 1; s < r; ++s)
        best = (std::min)(best, dist(order[s]));
      hints_ok = hints_ok && h < n && rank[h] < r && dist(h) == best;
    }
    DFP_CHECK_MSG(hints_ok, "a hint is not the nearest centre inserted before");
  }

  // Every instance of the disks, in both orders.
  void instances_of(const Disks& d, bool exact = true, bool hints = false)
  {
    for(DFP::Disk_order order : {DFP::Disk_order::spatial, DFP::Disk_order::random}) {
      Scope s(order == DFP::Disk_order::spatial ? "spatial order" : "random order");
      const Imprecise disks(to_points<K>(d.centres), radii_of(d), DFP::parameters::disk_order(order));
      if(hints)
        check_hints(disks, d);
      {
        Scope c("points inside");
        run(disks, points_in(d, rng), exact);
      }
      {
        Scope c("points at the centres");
        run(disks, d.centres, exact);
      }
      {
        Scope c("points on the boundaries");
        const XYs xy = points_on_boundaries(d, rng);
        const Points points = to_points<K>(xy);
        bool all_contained = true;
        for(std::size_t i = 0; i < points.size(); ++i)
          all_contained = all_contained && disks.contains(i, points[i]);
        DFP_CHECK(!exact || !d.dyadic || all_contained);
        run(disks, xy, exact);
      }
      {
        // Each point given to another disk: the hints are wrong, the result is still exact.
        Scope c("points outside their disks");
        XYs xy = points_in(d, rng);
        shuffle(xy, rng);
        run(disks, xy, exact);
      }
    }
  }

  void random_disks()
  {
    for(std::size_t n : {0u, 1u, 2u, 3u, 4u, 10u, 200u, 2000u}) {
      Scope s("paper's disks, n = ", n);
      instances_of(paper_disks(n, rng), true, n <= 200);
    }
    {
      // Section 6: overlapping disks of any radius, some of radius 0.
      Scope s("overlapping disks of radii 0 to 40 spacings");
      Disks d;
      d.centres = uniform_points(1500, rng, 0, 40);
      for(std::size_t i = 0; i < d.centres.size(); ++i)
        d.radii.push_back(i % 10 == 0 ? 0. : rng.get_double(0, 40));
      instances_of(d);
    }
    {
      Scope s("clustered centres, unit radius");
      Disks d;
      d.centres = clustered_points(1500, rng);
      d.radii.assign(d.centres.size(), 1.);
      instances_of(d);
    }
  }

  void degenerate_disks()
  {
    {
      Scope s("grid 30 x 30 (co-circular quadruples), radius 0.25");
      instances_of(disks_at(grid_points(30, 30, rng), 0.25), true, true);
    }
    {
      Scope s("lattice points on two circles and the centre, radius 0");
      instances_of(disks_at(lattice_circle_points(65, rng, 25), 0.));
    }
    {
      Scope s("collinear centres, radius 0 (collinear instances)");
      instances_of(disks_at(collinear_points(200, rng), 0.), true, true);
    }
    {
      Scope s("duplicate centres");
      instances_of(disks_at(with_duplicates(uniform_points(500, rng), 200, rng), 0.01));
    }
    {
      Scope s("grid with duplicate centres, radius 0 (duplicate points)");
      instances_of(disks_at(with_duplicates(grid_points(12, 12, rng), 60, rng), 0.));
    }
    {
      Scope s("huge coordinates");
      instances_of(disks_at(transformed(uniform_points(500, rng), 1e150, 3e150), 1e147));
    }
    {
      Scope s("tiny coordinates");
      instances_of(disks_at(transformed(uniform_points(500, rng), 1e-150, -2e-150), 1e-153));
    }
    {
      Scope s("all disks equal");
      instances_of(disks_at(XYs(20, XY{0.5, 0.25}), 0.5));
    }
    {
      // Every point at one position, the disks apart: all duplicates of one point.
      Scope s("all points equal, disks apart");
      const Disks d = paper_disks(50, rng);
      const Imprecise disks(to_points<K>(d.centres), FT(100));
      run(disks, XYs(50, XY{3., 4.}));
    }
  }

  // Other triangulation types, the one-radius constructor, one object for many instances.
  void interface()
  {
    const Disks d = paper_disks(400, rng);
    const Imprecise disks(to_points<K>(d.centres), FT(0.5));
    Scope s("interface");
    for(int k = 0; k < 3; ++k)
      run(disks, points_in(d, rng));
    run<DT_plain<K>>(disks, points_in(d, rng));
    run<DT_colored<K>>(disks, points_in(d, rng));
    run<DT_labeled<K>>(disks, points_in(d, rng));
    DFP_CHECK(disks.radius(7) == FT(0.5));
    DFP_CHECK(disks.centre(7) == make_point<K>(d.centres[7].x, d.centres[7].y));
    DFP_CHECK(!disks.contains(7, make_point<K>(d.centres[7].x + 0.5, d.centres[7].y + 1e-3)));
  }
};

// The paper's claim on its own input: locations are short walks from the hints, in both
// orders, and the seed changes the random order only.
void walks_are_short()
{
  CGAL::Random rng(31);
  using K = CGAL::Epick;
  Imprecise_test<K> t;
  const Disks d = paper_disks(20000, rng);
  const auto centres = to_points<K>(d.centres);
  for(DFP::Disk_order order : {DFP::Disk_order::spatial, DFP::Disk_order::random}) {
    Scope s(order == DFP::Disk_order::spatial ? "spatial order" : "random order", ", 20000 disks");
    const DFP::Imprecise_points_2<K> disks(centres, K::FT(0.5), DFP::parameters::disk_order(order));
    const DFP::Statistics st = t.run(disks, points_in(d, rng));
    DFP_CHECK_MSG(st.points_located + 8 > centres.size(), st.points_located);
    // The paper measures about 2.8 triangles per point (its walk counts the first triangle).
    DFP_CHECK_MSG(st.faces_visited < 3 * st.points_located, st.faces_visited << " faces for " << st.points_located);
    DFP_CHECK_MSG(st.walk_fallbacks < centres.size() / 100, st.walk_fallbacks);
  }
  const auto seeded = [&](unsigned seed) {
    return DFP::Imprecise_points_2<K>(centres, K::FT(0.5),
                                      DFP::parameters::disk_order(DFP::Disk_order::random,
                                                                  CGAL::parameters::random_seed(seed)))
        .insertion_order();
  };
  DFP_CHECK(seeded(1) == seeded(1));
  DFP_CHECK(seeded(1) != seeded(2));
  const DFP::Imprecise_points_2<K> spatial(centres, K::FT(0.5));
  const DFP::Imprecise_points_2<K> spatial_seeded(centres, K::FT(0.5), CGAL::parameters::random_seed(9));
  DFP_CHECK(spatial.insertion_order() == spatial_seeded.insertion_order());
}

// Bad input throws Invalid_prediction naming what is wrong; a triangulation passed to a
// failing call is unchanged.
void bad_input()
{
  using K = CGAL::Epick;
  using Imprecise = DFP::Imprecise_points_2<K>;
  CGAL::Random rng(8);
  const Disks d = paper_disks(60, rng);
  const auto centres = to_points<K>(d.centres);
  std::vector<double> radii = d.radii;
  auto throws_naming = [&](const auto& body, const std::string& words) {
    const std::string message = exception_message<DFP::Invalid_prediction>(body);
    return DFP_CHECK_MSG(message.find(words) != std::string::npos, message);
  };
  {
    Scope s("negative radius");
    auto bad = radii;
    bad[12] = -0.5;
    throws_naming([&] { (void)Imprecise(centres, bad); }, "disk 12 has radius -0.5");
    throws_naming([&] { (void)Imprecise(centres, K::FT(-1)); }, "disk 0 has radius -1");
  }
  {
    Scope s("non-finite radius");
    auto bad = radii;
    bad[5] = std::nan("");
    throws_naming([&] { (void)Imprecise(centres, bad); }, "disk 5 has radius nan");
    bad[5] = HUGE_VAL;
    throws_naming([&] { (void)Imprecise(centres, bad); }, "disk 5 has radius inf");
  }
  {
    Scope s("non-finite centre");
    auto bad = centres;
    bad[33] = make_point<K>(1., HUGE_VAL);
    throws_naming([&] { (void)Imprecise(bad, radii); }, "centre of disk 33");
  }
  {
    Scope s("as many radii as centres");
    auto bad = radii;
    bad.pop_back();
    throws_naming([&] { (void)Imprecise(centres, bad); }, "60 disk centres but 59 radii");
  }
  const Imprecise disks(centres, radii);
  DT_with_info<K> dt;
  for(int k = 0; k < 5; ++k)
    dt.insert(make_point<K>(k, k * k))->info() = 100 + std::size_t(k);
  const Snapshot<DT_with_info<K>> before(dt);
  auto instance = to_points<K>(points_in(d, rng));
  {
    Scope s("instance of another size");
    auto bad = instance;
    bad.push_back(bad[0]);
    throws_naming([&] { disks.triangulate(bad, dt); }, "an instance of 61 points for 60 disks");
    bad.resize(3);
    throws_naming([&] { disks.triangulate(bad, dt); }, "an instance of 3 points for 60 disks");
    check_unchanged(dt, before);
  }
  {
    Scope s("non-finite instance point");
    auto bad = instance;
    bad[41] = make_point<K>(std::nan(""), 2.);
    throws_naming([&] { disks.triangulate(bad, dt); }, "point 41");
    check_unchanged(dt, before);
  }
}

int main()
{
  {
    Scope s("Epick");
    Imprecise_test<CGAL::Epick> t;
    DFP_RUN(t.random_disks());
    DFP_RUN(t.degenerate_disks());
    DFP_RUN(t.interface());
  }
  {
    Scope s("Epeck");
    Imprecise_test<CGAL::Epeck> t;
    DFP_RUN(t.instances_of(paper_disks(300, t.rng), true, true));
    DFP_RUN(t.instances_of(disks_at(lattice_circle_points(25, t.rng, 5), 0.)));
    DFP_RUN(t.interface());
  }
  {
    // Inexact: must terminate with a valid triangulation (exactness is not promised).
    Scope s("Simple_cartesian<double>");
    Imprecise_test<CGAL::Simple_cartesian<double>> t;
    DFP_RUN(t.instances_of(paper_disks(1000, t.rng), false));
    DFP_RUN(t.instances_of(disks_at(jittered(grid_points(20, 20, t.rng), 1e-13, t.rng), 0.5), false));
  }
  DFP_RUN(walks_are_short());
  DFP_RUN(bad_input());
  return finish("test_imprecise_points");
}
