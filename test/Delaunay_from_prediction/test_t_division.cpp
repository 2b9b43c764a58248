// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Strategy::t_division (Theorem 2.1, internal/repair/t_division_repair.h) with 8 times its default budget
// (the default hands a damage of m marks in regions of t faces to the carve past m t = 0.15 n,
// where the division would cost more than a rebuild; at 20,000 points that is 4 marks with the
// default t = 625, 1 mark with t = 4096): on
// inputs of 20,000 points with local damage it must take its own path (no fallback, at least
// one bad region, few of them, the fill made of faces of DT(V_B), the vertices of the bad
// regions reinserted) and give exactly CGAL's triangulation, with vertex handles and info()
// kept in make_delaunay; the region size parameter must shape the division; heavy damage must
// make it give up before dividing and hand over to the carve. test_local_repair.cpp runs it, without budget, on every
// damaged and degenerate input of the local repair, and on many small random cases.

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

// The t-division's budget raised eightfold (Tuning::t_division_budget_factor): its repair is
// reached on small, damaged inputs. Every t-division call of this file passes it.
DFP::Tuning raised_budget()
{
  DFP::Tuning t;
  t.t_division_budget_factor = 8;
  return t;
}

std::string describe(const DFP::Statistics& s)
{
  std::ostringstream out;
  out << "fell_back=" << s.fell_back << " (" << to_string(s.outcome) << ") regions=" << s.regions
      << " bad_regions=" << s.bad_regions << " V_B=" << s.boundary_vertices << " carved=" << s.faces_carved
      << " holes=" << s.holes_refilled << " reinserted=" << s.points_reinserted << " flips=" << s.flips
      << " certified=" << s.faces_certified << " faces_in=" << s.faces_in;
  return out.str();
}

template <class K>
std::vector<typename K::Point_2> uniform(std::size_t n, std::uint64_t seed)
{
  Random random{seed};
  std::vector<typename K::Point_2> points;
  for(std::size_t i = 0; i < n; ++i)
    points.push_back(make_point<K>(random.uniform(), random.uniform()));
  return points;
}

// The t-division repair ran: local, and with the statistics it reports consistent.
void check_local(const DFP::Statistics& s, std::size_t n, std::size_t max_bad_regions)
{
  DFP_CHECK_MSG(!s.fell_back, describe(s));
  DFP_CHECK_MSG(s.bad_regions >= 1 && s.bad_regions <= max_bad_regions, describe(s));
  DFP_CHECK_MSG(s.regions > s.bad_regions, describe(s));
  DFP_CHECK_MSG(s.boundary_vertices > 0 && s.boundary_vertices < n / 2, describe(s));
  DFP_CHECK_MSG(s.faces_carved > 0 && s.holes_refilled > 0, describe(s));
  DFP_CHECK_MSG(s.points_reinserted < n / 4, describe(s));
  DFP_CHECK_MSG(s.faces_certified + s.faces_carved <= s.faces_in, describe(s));
}

// make_delaunay after moving a few vertices of a DT of n points far enough to invert faces.
template <class Tr>
void moved_few(const std::string& label, std::size_t n, std::size_t moved, std::uint64_t seed)
{
  using K = typename Tr::Geom_traits;
  Scope scope(label);
  const auto start = uniform<K>(n, seed);
  Tr tr;
  Handles<Tr> handles;
  build(tr, start, handles);
  DFP::make_delaunay(tr, DFP::parameters::max_flips(100 * n)); // a Triangulation_2 too
  Random random{seed + 1};
  const double spacing = 1.0 / std::sqrt(double(n));
  for(std::size_t k = 0; k < moved; ++k) {
    const auto v = handles[std::size_t(random.below(n))];
    v->set_point(make_point<K>(CGAL::to_double(v->point().x()) + 1.5 * spacing * (random.uniform() - 0.5),
                               CGAL::to_double(v->point().y()) + 1.5 * spacing * (random.uniform() - 0.5)));
  }
  const auto points = current_points(handles);
  DFP_CHECK_MSG(inverted_faces(tr) > 0, "the moves inverted no face");
  const DFP::Statistics s =
      DFP::make_delaunay(tr, DFP::parameters::strategy(DFP::Strategy::t_division).tuning(raised_budget()));
  check_local(s, n, moved * 3);
  check_handles(tr, handles, points);
  check_is_cgal_delaunay(tr, points);
}

// A hull vertex moved inwards: the hull is no longer convex, the regions at the reflex vertex
// are bad and refilled from DT(V_B), whose hull is convex.
void hull_dented(std::size_t n, std::uint64_t seed)
{
  using Tr = DT_with_info<Epick>;
  Scope scope("a hull vertex moved inwards");
  const auto start = uniform<Epick>(n, seed);
  Tr tr;
  Handles<Tr> handles;
  build(tr, start, handles);
  auto lowest = handles[0];
  for(const auto& v : handles)
    if(v->point().y() < lowest->point().y())
      lowest = v;
  lowest->set_point(Epick::Point_2(lowest->point().x(), lowest->point().y() + 3.0 / std::sqrt(double(n))));
  const auto points = current_points(handles);
  const DFP::Statistics s = DFP::make_delaunay(tr, DFP::parameters::strategy(DFP::Strategy::t_division).tuning(raised_budget()));
  check_local(s, n, 4);
  check_handles(tr, handles, points);
  check_is_cgal_delaunay(tr, points);
}

// delaunay_from_prediction: a few flipped edges (a triangulation), a few deleted faces (holes,
// closed by the carve's filler first), with the faces shuffled.
void from_prediction(std::size_t n, std::uint64_t seed)
{
  using DT = DT_with_info<Epick>;
  const auto points = uniform<Epick>(n, seed);
  const Faces dt_faces = DFP::delaunay_triangles(points);
  {
    Scope scope("delaunay_from_prediction, 6 random flips");
    const Faces faces = DFP::k_flip_prediction(points, 6, seed + 1);
    DT dt;
    const DFP::Statistics s =
        DFP::delaunay_from_prediction(points, faces, dt, DFP::parameters::strategy(DFP::Strategy::t_division).tuning(raised_budget()));
    check_local(s, n, 12);
    DFP_CHECK_MSG(s.points_reinserted > 0, describe(s)); // the vertices inside the bad regions
    check_is_cgal_delaunay(dt, points);
  }
  {
    Scope scope("delaunay_from_prediction, 0.05% of the faces deleted");
    const Faces faces = DFP::delete_faces(dt_faces, 0.0005, seed + 2);
    DFP_CHECK(faces.size() < dt_faces.size());
    DT dt;
    const DFP::Statistics s =
        DFP::delaunay_from_prediction(points, faces, dt, DFP::parameters::strategy(DFP::Strategy::t_division).tuning(raised_budget()));
    // The holes are filled by ear clipping; the regions are then bad where the fill is not
    // Delaunay (a quadrilateral hole with the wrong diagonal), or none is.
    DFP_CHECK_MSG(!s.fell_back && s.holes_refilled > 0, describe(s));
    DFP_CHECK_MSG(s.regions > 0 && s.bad_regions < s.regions, describe(s));
    check_is_cgal_delaunay(dt, points);
  }
}

// The region size shapes the division: about 2n/t regions (fragments under t/4 faces join a
// neighbour, so no more than twice that), and a larger t gives fewer boundary vertices.
void region_sizes(std::size_t n, std::uint64_t seed)
{
  using Tr = DT_with_info<Epick>;
  Scope scope("region_size");
  const auto start = uniform<Epick>(n, seed);
  std::size_t last_boundary = n + 1;
  for(std::size_t t : {256, 1024, 4096}) {
    Scope st("t = ", t);
    Tr tr;
    Handles<Tr> handles;
    build(tr, start, handles);
    handles[n / 2]->set_point(Epick::Point_2(handles[n / 2]->point().x() + 0.7 / std::sqrt(double(n)),
                                             handles[n / 2]->point().y()));
    const auto points = current_points(handles);
    const std::size_t faces = tr.number_of_faces();
    const DFP::Statistics s = DFP::make_delaunay(
        tr, DFP::parameters::strategy(DFP::Strategy::t_division, DFP::parameters::region_size(t)).tuning(raised_budget()));
    DFP_CHECK_MSG(!s.fell_back, describe(s));
    DFP_CHECK_MSG(s.regions >= faces / t && s.regions <= 2 * (faces / t) + 2, describe(s) << ", " << faces << " faces");
    DFP_CHECK_MSG(s.boundary_vertices < last_boundary, describe(s));
    last_boundary = s.boundary_vertices;
    // A bad region of at most t + t/4 faces (fragments joined) loses at most that many faces.
    DFP_CHECK_MSG(s.faces_carved <= 4 * (t + t / 4), describe(s));
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
  }
}

// Damage spread everywhere: more marks than regions can absorb; the call gives up on the
// t-division before dividing and hands over to the carve (which repairs or rebuilds), keeping
// the vertices.
void heavy_damage(std::size_t n, std::uint64_t seed)
{
  using Tr = DT_with_info<Epick>;
  Scope scope("every vertex moved by 0.05 x the spacing");
  const auto start = uniform<Epick>(n, seed);
  Tr tr, copy; // copy: the same triangulation for the carve (built apart: copying a
               // triangulation whose points moved fails CGAL's is_valid() postcondition in Debug)
  Handles<Tr> handles, copy_handles;
  build(tr, start, handles);
  build(copy, start, copy_handles);
  Random random{seed + 1};
  const double step = 0.05 / std::sqrt(double(n));
  for(std::size_t i = 0; i < handles.size(); ++i) {
    const auto& p = handles[i]->point();
    const Epick::Point_2 moved(p.x() + step * random.normal(), p.y() + step * random.normal());
    handles[i]->set_point(moved);
    copy_handles[i]->set_point(moved);
  }
  const auto points = current_points(handles);
  const DFP::Statistics s = DFP::make_delaunay(tr, DFP::parameters::strategy(DFP::Strategy::t_division).tuning(raised_budget()));
  const DFP::Statistics c = DFP::make_delaunay(copy, DFP::parameters::strategy(DFP::Strategy::carve));
  DFP_CHECK_MSG(s.regions == 0, describe(s)); // no division was made
  DFP_CHECK_MSG(s.bad_regions == 0 && s.boundary_vertices == 0, describe(s));
  // The carve took over: it repairs this damage locally, as the carve alone does.
  DFP_CHECK_MSG(!s.fell_back && !c.fell_back && s.faces_carved > 0, describe(s) + " vs carve " + describe(c));
  check_handles(tr, handles, points);
  check_is_cgal_delaunay(tr, points);
}

} // namespace

int main()
{
  const std::size_t n = 20000;
  using DT = DT_with_info<Epick>;
  using T2 = T2_with_info<Epick, int>;
  using DT_exact = DT_with_info<Epeck>;
  DFP_RUN(moved_few<DT>("make_delaunay, Delaunay_triangulation_2 with info, 5 vertices moved", n, 5, 11));
  DFP_RUN(moved_few<T2>("make_delaunay, Triangulation_2 with int info, 5 vertices moved", n, 5, 12));
  DFP_RUN(moved_few<DT_exact>("make_delaunay, Epeck, 3 vertices moved", n, 3, 13));
  DFP_RUN(hull_dented(n, 21));
  DFP_RUN(from_prediction(n, 31));
  DFP_RUN(region_sizes(n, 41));
  DFP_RUN(heavy_damage(n, 51));
  return finish("test_t_division");
}
