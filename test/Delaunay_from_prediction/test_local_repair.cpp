// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Local repair (named parameter `strategy`): predictions that are not triangulations of their
// points are repaired where they are damaged instead of being rebuilt from scratch. Bad faces
// are carved out (inverted or flat faces and the stars of their vertices in make_delaunay;
// degenerate, repeated or overlapping faces and whatever surrounds a non-simple hole in
// delaunay_from_prediction), the holes are retriangulated, the vertices left without a face
// are reinserted, then Lawson flips finish the job.
//
// Every call is made with each strategy (no parameter, automatic, carve, t_division, flips,
// rebuild) and its result must be exactly CGAL's Delaunay_triangulation_2 built from scratch,
// whatever path was taken. The budget of t_division is lifted in this file, so that its
// repair (t_division_repair.h) runs on small, badly damaged inputs too instead of falling back
// (test_t_division.cpp tests it with its budget). On top of that:
//  - a prediction that is a triangulation is handled as before: nothing carved or refilled;
//  - with small damage at moderate n, the carving strategies (default, automatic, carve) do
//    not fall back, carve where faces are inverted or repeated, and reinsert a number of points
//    proportional to the damage (at most 12 per damaged face, plus the unused points);
//  - strategy(flips) falls back on any prediction that is not a triangulation; strategy(rebuild)
//    always falls back and reinserts every point.
// Cases: make_delaunay after Gaussian moves (0.001 to 0.1 of the mean spacing) of every vertex
// of a DT / Triangulation_2, with and without info (handles and info kept); delaunay_from_prediction
// with interior holes, faces missing on the hull, unused points, repeated faces, self-crossing
// labelings, random triples added, and the DT of moved points; degenerate inputs (co-circular
// grids and lattice circles, collinear sets, duplicates, coordinates at 1e15 and 1e-15) where
// only exactness is asked; Simple_cartesian<double> (must terminate with a valid
// triangulation); Epeck. Every group runs in a child process with a time limit, so a crash or
// an endless loop is a failure of that group only.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/prediction_models.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <csignal>
#include <cstdint>
#include <limits>
#include <memory>
#include <functional>

using namespace dfp_test;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Inexact = CGAL::Simple_cartesian<double>;
using Random = DFP::internal::Splitmix64;

namespace {

// No budget for Strategy::t_division (Tuning::t_division_budget_factor infinite): its repair
// is reached whatever the damage.
DFP::Tuning unlimited_t_division()
{
  DFP::Tuning t;
  t.t_division_budget_factor = std::numeric_limits<double>::infinity();
  return t;
}

// ---------------------------------------------------------------------------------------------
// Strategies
// ---------------------------------------------------------------------------------------------

bool carves(Mode m) { return m == Mode::defaults || m == Mode::automatic || m == Mode::carve; }


std::string describe(const DFP::Statistics& s)
{
  std::ostringstream out;
  out << "faces_in=" << s.faces_in << " certified=" << s.faces_certified << " flips=" << s.flips
      << " reinserted=" << s.points_reinserted << " fell_back=" << s.fell_back << " tested="
      << s.edges_tested << " not_ld=" << s.edges_not_locally_delaunay << " unused=" << s.points_unused
      << " duplicates=" << s.duplicate_points << " reordered=" << s.input_reordered
      << " carved=" << s.faces_carved << " holes=" << s.holes_refilled << " rounds=" << s.carve_rounds
      << " regions=" << s.regions << " bad_regions=" << s.bad_regions << " V_B=" << s.boundary_vertices
      << " reason='" << to_string(s.outcome) << "'";
  return out.str();
}

// What a prediction is expected to make the call do.
struct Expect
{
  std::size_t damaged = 0;        // damaged faces: inverted, flat, deleted, repeated, crossing, overlapped
                                  // (with must_repair: points_reinserted <= 12 damaged + unused)
  bool valid = false;             // a triangulation of its vertices: nothing to carve or refill
  bool not_triangulation = false; // strategy(flips) must fall back
  bool carve_expected = false;    // the carving strategies must carve (faces_carved > 0)
  bool holes_expected = false;    // ... and refill holes (holes_refilled > 0)
  bool must_repair = false;       // ... and must not fall back (small damage)
};

// Checks shared by both functions and every strategy; `reinsert_bound` is what the
// proportionality asks of points_reinserted.
void check_strategy(Mode m, const DFP::Statistics& s, const Expect& e, std::size_t n,
                    std::size_t reinsert_bound)
{
  DFP_CHECK_MSG((s.outcome == DFP::Outcome::ok) == !s.fell_back, describe(s));
  DFP_CHECK_MSG(s.faces_certified <= s.faces_in, describe(s));
  DFP_CHECK_MSG(s.faces_carved <= s.faces_in, describe(s));
  if(s.fell_back) {
    DFP_CHECK_MSG(s.points_reinserted == n, describe(s) << ", n = " << n);
    DFP_CHECK_MSG(s.faces_certified == 0, describe(s));
  } else {
    DFP_CHECK_MSG(s.edges_not_locally_delaunay <= s.edges_tested, describe(s));
  }
  if(carves(m)) {
    if(e.must_repair)
      DFP_CHECK_MSG(!s.fell_back, describe(s));
    if(!s.fell_back) {
      if(e.valid)
        DFP_CHECK_MSG(s.faces_carved == 0 && s.holes_refilled == 0 && s.carve_rounds == 0, describe(s));
      if(e.carve_expected)
        DFP_CHECK_MSG(s.faces_carved > 0, describe(s));
      if(e.holes_expected)
        DFP_CHECK_MSG(s.holes_refilled > 0, describe(s));
      if(e.must_repair) // small damage: the repair stays local
        DFP_CHECK_MSG(s.points_reinserted <= reinsert_bound,
                      describe(s) << "; bound " << reinsert_bound << " (" << e.damaged << " damaged faces)");
    }
  } else if(m == Mode::t_division) {
    // Without its budget it falls back only past certification's limit on inverted faces, or
    // when every region is bad.
    if(!s.fell_back) {
      DFP_CHECK_MSG(s.regions > 0 || (s.faces_carved == 0 && s.points_reinserted <= reinsert_bound), describe(s));
      DFP_CHECK_MSG(s.bad_regions <= s.regions && s.boundary_vertices <= n, describe(s));
      DFP_CHECK_MSG(s.points_reinserted <= n, describe(s));
      if(e.valid)
        DFP_CHECK_MSG(s.carve_rounds == 0, describe(s));
      if(e.carve_expected) // an inverted face makes its region bad; a dropped face is carved
        DFP_CHECK_MSG(s.faces_carved > 0, describe(s));
    } else {
      // With exact predicates the fill always fits (t_division_repair.h): a fallback is for a
      // budget or a degenerate input, never for an inconsistency.
      DFP_CHECK_MSG(!reason_is(s, DFP::Outcome::kept_faces_do_not_fit) &&
                        !reason_is(s, DFP::Outcome::kept_faces_repeated),
                    describe(s));
    }
  } else if(m == Mode::regions) {
    // A build by the prediction's regions: every point inserted, no predicted face certified;
    // with exact predicates the pieces always fit, so a fallback is for interleaved regions or
    // a degenerate input.
    DFP_CHECK_MSG(s.points_reinserted == n, describe(s) << ", n = " << n);
    DFP_CHECK_MSG(s.faces_certified == 0 && s.faces_carved == 0, describe(s));
    DFP_CHECK_MSG(s.boundary_vertices <= n, describe(s));
    if(!s.fell_back)
      DFP_CHECK_MSG(s.regions >= 2, describe(s));
    else
      DFP_CHECK_MSG(reason_is(s, DFP::Outcome::too_few_regions) ||
                        reason_is(s, DFP::Outcome::regions_interleave) ||
                        reason_is(s, DFP::Outcome::regions_do_not_fit) ||
                        reason_is(s, DFP::Outcome::no_faces),
                    describe(s));
  } else if(m == Mode::flips) {
    if(e.not_triangulation)
      DFP_CHECK_MSG(s.fell_back, describe(s));
    if(e.valid && e.must_repair)
      DFP_CHECK_MSG(!s.fell_back, describe(s));
    DFP_CHECK_MSG(s.faces_carved == 0 && s.holes_refilled == 0, describe(s));
  } else if(m == Mode::theorem_4_1 && built_by_theorem_4_1(s)) {
    // delaunay_from_prediction: Theorem 4.1's own faces, imported with their certificate.
    DFP_CHECK_MSG(s.insertion_rounds <= 3, describe(s)); // 3, fewer for a handful of points
    DFP_CHECK_MSG(s.bad_supercells <= s.supercells, describe(s));
  } else if(m == Mode::theorem_5_4 && s.outcome != DFP::Outcome::rebuild_requested) {
    // delaunay_from_prediction: Theorem 5.4's completion G', repaired by the stages, which may
    // give it up as they give up any prediction (after carving part of it).
    DFP_CHECK_MSG(s.d_cross_guesses >= 1 || s.fell_back, describe(s));
    DFP_CHECK_MSG(!s.fell_back || s.faces_certified == 0, describe(s));
  } else { // rebuild, spanning_tree, section_3 (make_delaunay: rebuild, and theorems 4.1 and 5.4 there)
    DFP_CHECK_MSG(s.fell_back, describe(s));
    DFP_CHECK_MSG(s.points_reinserted == n, describe(s) << ", n = " << n);
    DFP_CHECK_MSG(s.outcome != DFP::Outcome::ok, describe(s));
    DFP_CHECK_MSG(s.faces_certified == 0 && s.faces_carved == 0, describe(s));
  }
}

bool verbose() { return std::getenv("DFP_TEST_VERBOSE") != nullptr; }

// ---------------------------------------------------------------------------------------------
// Isolation: each group runs in a child process with a time limit.
// ---------------------------------------------------------------------------------------------


// ---------------------------------------------------------------------------------------------
// Point sets and predictions, drawn with the package's random source
// ---------------------------------------------------------------------------------------------

XYs uniform_xy(std::size_t n, std::uint64_t seed, double lo = 0., double hi = 1.)
{
  Random random{seed};
  XYs xy(n);
  for(XY& p : xy) {
    const double x = lo + (hi - lo) * random.uniform();
    p = {x, lo + (hi - lo) * random.uniform()};
  }
  return xy;
}

template <class T>
void shuffle_with(std::vector<T>& v, Random& random)
{
  for(std::size_t i = v.size(); i > 1; --i)
    std::swap(v[i - 1], v[random.below(i)]);
}

XYs grid_xy(int w, int h, std::uint64_t seed)
{
  XYs xy;
  for(int i = 0; i < w; ++i)
    for(int j = 0; j < h; ++j)
      xy.push_back({double(i), double(j)});
  Random random{seed};
  shuffle_with(xy, random);
  return xy;
}

// Mean spacing sqrt(area of the bounding box / n).
double mean_spacing(const XYs& xy)
{
  double x0 = xy[0].x, x1 = x0, y0 = xy[0].y, y1 = y0;
  for(const XY& p : xy) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  return std::sqrt((x1 - x0) * (y1 - y0) / double(xy.size()));
}

XYs gaussian_moved(XYs xy, double sigma, std::uint64_t seed)
{
  Random random{seed};
  for(XY& p : xy) {
    const double dx = sigma * random.normal();
    p = {p.x + dx, p.y + sigma * random.normal()};
  }
  return xy;
}

template <class Point>
XYs to_xy(const std::vector<Point>& points)
{
  XYs xy;
  for(const Point& p : points)
    xy.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  return xy;
}

using Edge = std::pair<std::size_t, std::size_t>;
Edge edge_of(std::size_t a, std::size_t b) { return {std::min(a, b), std::max(a, b)}; }

// Edges used by exactly one face.
std::set<Edge> boundary_edges(const Faces& faces)
{
  std::map<Edge, int> uses;
  for(const Face& f : faces)
    for(int j = 0; j < 3; ++j)
      ++uses[edge_of(f[j], f[(j + 1) % 3])];
  std::set<Edge> boundary;
  for(const auto& [e, count] : uses)
    if(count == 1)
      boundary.insert(e);
  return boundary;
}

bool has_boundary_edge(const Face& f, const std::set<Edge>& boundary)
{
  for(int j = 0; j < 3; ++j)
    if(boundary.count(edge_of(f[j], f[(j + 1) % 3])))
      return true;
  return false;
}

// Splits `faces` into kept and deleted: each face that `eligible` accepts is deleted with
// probability `fraction`.
template <class Eligible>
Faces delete_some(const Faces& faces, double fraction, std::uint64_t seed, const Eligible& eligible,
                  std::size_t& deleted)
{
  Random random{seed};
  Faces kept;
  deleted = 0;
  for(const Face& f : faces)
    if(eligible(f) && random.uniform() < fraction)
      ++deleted;
    else
      kept.push_back(f);
  return kept;
}

std::array<std::size_t, 3> sorted_triple(Face f)
{
  std::sort(f.begin(), f.end());
  return f;
}

// Faces of `faces` that are not faces of `reference` (as sets of indices).
std::size_t faces_not_in(const Faces& faces, const Faces& reference)
{
  std::set<std::array<std::size_t, 3>> ref;
  for(const Face& f : reference)
    ref.insert(sorted_triple(f));
  std::size_t count = 0;
  for(const Face& f : faces)
    count += ref.count(sorted_triple(f)) ? 0 : 1;
  return count;
}

// Faces that are not counterclockwise on `points` (inverted or flat).
template <class Point>
std::size_t not_ccw(const Faces& faces, const std::vector<Point>& points)
{
  std::size_t count = 0;
  for(const Face& f : faces)
    count += CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::LEFT_TURN;
  return count;
}

// True if the interiors of two counterclockwise triangles meet (no edge of either separates them).
template <class Point>
bool interiors_meet(const std::array<Point, 3>& a, const std::array<Point, 3>& b)
{
  auto separates = [](const std::array<Point, 3>& s, const std::array<Point, 3>& o) {
    for(int i = 0; i < 3; ++i) {
      bool outside = true;
      for(const Point& p : o)
        outside = outside && CGAL::orientation(s[i], s[(i + 1) % 3], p) != CGAL::LEFT_TURN;
      if(outside)
        return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

template <class Point>
std::array<Point, 3> ccw_triangle(const Face& f, const std::vector<Point>& points)
{
  std::array<Point, 3> t = {points[f[0]], points[f[1]], points[f[2]]};
  if(CGAL::orientation(t[0], t[1], t[2]) == CGAL::RIGHT_TURN)
    std::swap(t[1], t[2]);
  return t;
}

// ---------------------------------------------------------------------------------------------
// delaunay_from_prediction
// ---------------------------------------------------------------------------------------------

// The statistics that must hold for any call (the new meaning of points_reinserted: unused
// points plus the vertices of carved faces).
template <class DT>
void check_dfp_statistics(const DFP::Statistics& s, const Faces& faces,
                          const std::vector<typename DT::Point>& points, const DT& dt)
{
  using Point = typename DT::Point;
  const std::size_t n = points.size();
  DFP_CHECK_MSG(s.faces_in == faces.size(), describe(s) << " vs " << faces.size());
  DFP_CHECK_MSG(s.duplicate_points + dt.number_of_vertices() == n,
                describe(s) << "; " << dt.number_of_vertices() << " vertices, " << n << " points");
  if(s.fell_back || built_by_prediction_regions(s, n))
    return;
  // Points used by no face are unused; a point used only by degenerate faces, or only by faces
  // the import left out because they overlap others (counted in faces_carved), may count too.
  Faces proper;
  for(const Face& f : faces)
    if(CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::COLLINEAR)
      proper.push_back(f);
  if(!built_by_theorem_4_1(s) && !built_by_theorem_5_4(s)) { // otherwise the import's counts are of the faces it computed
    DFP_CHECK_MSG(s.points_unused >= n - used_indices(faces) &&
                      s.points_unused <= n - used_indices(proper) + 3 * s.faces_carved,
                  describe(s) << "; " << n - used_indices(faces) << " points in no face, "
                              << n - used_indices(proper) << " in no proper face");
  }
  DFP_CHECK_MSG(s.points_reinserted >= s.points_unused, describe(s));
  if(s.faces_carved == 0)
    DFP_CHECK_MSG(s.points_reinserted == s.points_unused, describe(s));
  // A certified face is a face of the result.
  const Geometry<Point> result = geometry_of(dt);
  std::vector<std::array<Point, 3>> predicted;
  for(const Face& f : faces)
    if(CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::COLLINEAR)
      predicted.push_back(canonical(ccw_triangle(f, points)));
  std::sort(predicted.begin(), predicted.end());
  predicted.erase(std::unique(predicted.begin(), predicted.end()), predicted.end());
  const std::size_t in_result = predicted.size() - count_missing(predicted, result.faces);
  DFP_CHECK_MSG(s.faces_certified <= in_result, describe(s) << "; " << in_result << " predicted faces in the result");
}

// Runs every strategy on the prediction; the result must be CGAL's DT each time.
template <class DT>
void dfp_case(const std::string& label, const std::vector<typename DT::Point>& points,
              const Faces& faces, const Expect& e)
{
  using K = typename DT::Geom_traits;
  Scope scope(label);
  const std::size_t n = points.size();
  const std::size_t unused = n - used_indices(faces);
  for(Mode m : strategy_modes) {
    Scope sm("strategy ", name_of(m));
    DT dt;
    dt.insert(make_point<K>(1e3, 1e3)); // must be cleared
    dt.insert(make_point<K>(-1e3, 1e3));
    dt.insert(make_point<K>(0., -1e3));
    const DFP::Statistics s = with_mode(m, [&](const auto& np) {
      return DFP::delaunay_from_prediction(points, faces, dt, np);
    }, unlimited_t_division());
    if(verbose())
      std::cout << where() << ": " << describe(s) << std::endl;
    check_is_cgal_delaunay(dt, points);
    check_dfp_statistics(s, faces, points, dt);
    check_strategy(m, s, e, n, 12 * e.damaged + unused);
  }
}

// Uniform points and predictions with local damage.
template <class DT>
void damaged_predictions(const std::string& name, const std::vector<typename DT::Point>& points,
                         std::uint64_t seed, bool with_moves)
{
  using Point = typename DT::Point;
  const std::size_t n = points.size();
  const Faces dt_faces = DFP::delaunay_triangles(points);
  const std::set<Edge> hull = boundary_edges(dt_faces);
  std::set<std::size_t> hull_vertices;
  for(const Edge& e : hull) {
    hull_vertices.insert(e.first);
    hull_vertices.insert(e.second);
  }
  Scope scope(name, ", n = ", n);
  isolated("valid triangulations", [&] {
    {
      Expect e;
      e.valid = e.must_repair = true;
      Faces shuffled_faces = dt_faces;
      Random random{seed};
      shuffle_with(shuffled_faces, random);
      dfp_case<DT>("the DT, shuffled", points, shuffled_faces, e);
      const Faces flipped = DFP::k_flip_prediction(points, n / 50, seed + 1);
      dfp_case<DT>("the DT after n/50 flips", points, flipped, e);
    }
    {
      Expect e;
      e.valid = e.must_repair = true;
      Random random{seed + 2};
      std::vector<Point> subset;
      for(const Point& p : points)
        if(random.uniform() < 0.9)
          subset.push_back(p);
      // The DT of 90% of the points, re-indexed into `points` (the rest unused).
      std::map<Point, std::size_t> index;
      for(std::size_t i = 0; i < n; ++i)
        index.emplace(points[i], i);
      Faces faces = DFP::delaunay_triangles(subset);
      for(Face& f : faces)
        for(std::size_t& i : f)
          i = index.at(subset[i]);
      dfp_case<DT>("the DT of 90% of the points (unused points)", points, faces, e);
    }
  });
  isolated("holes", [&] {
    for(double fraction : {0.01, 0.1}) {
      std::ostringstream label;
      label << "delete_faces(" << fraction << ") (interior and hull)";
      const Faces kept = DFP::delete_faces(dt_faces, fraction, seed + 3);
      Expect e;
      e.damaged = dt_faces.size() - kept.size();
      e.not_triangulation = true;
      // 10% deleted leaves more hole boundary than n/4 half-edges: rebuilt by design (the
      // repair would cost more); exact either way.
      e.holes_expected = e.must_repair = fraction <= 0.01;
      dfp_case<DT>(label.str(), points, kept, e);
    }
    {
      std::size_t deleted = 0;
      const Faces kept = delete_some(dt_faces, 0.02, seed + 4,
                                     [&](const Face& f) { return !has_boundary_edge(f, hull); }, deleted);
      Expect e;
      e.damaged = deleted;
      e.not_triangulation = e.holes_expected = e.must_repair = true;
      dfp_case<DT>("2% of the interior faces deleted", points, kept, e);
    }
    {
      std::size_t deleted = 0;
      const Faces kept = delete_some(dt_faces, 0.5, seed + 5,
                                     [&](const Face& f) { return has_boundary_edge(f, hull); }, deleted);
      Expect e;
      e.damaged = deleted;
      e.must_repair = true;
      DFP_CHECK(deleted > 0);
      dfp_case<DT>("half of the faces on a hull edge deleted", points, kept, e);
    }
    {
      // Peel: every face with a hull vertex goes, the hull vertices are left unused.
      std::size_t deleted = 0;
      const Faces kept = delete_some(dt_faces, 1.1, seed, [&](const Face& f) {
        return hull_vertices.count(f[0]) || hull_vertices.count(f[1]) || hull_vertices.count(f[2]);
      }, deleted);
      Expect e;
      e.damaged = deleted;
      e.must_repair = true;
      DFP_CHECK(n - used_indices(kept) >= hull_vertices.size());
      dfp_case<DT>("every face at a hull vertex deleted (hull vertices unused)", points, kept, e);
    }
    {
      // Unused points and holes together.
      Random random{seed + 6};
      std::vector<bool> drop(n);
      for(std::size_t i = 0; i < n; ++i)
        drop[i] = random.uniform() < 0.02;
      std::size_t deleted = 0;
      const Faces kept = delete_some(dt_faces, 1.1, seed, [&](const Face& f) {
        return drop[f[0]] || drop[f[1]] || drop[f[2]];
      }, deleted);
      Expect e;
      e.damaged = deleted;
      e.not_triangulation = e.holes_expected = e.must_repair = true;
      dfp_case<DT>("the stars of 2% of the points deleted (their centres unused)", points, kept, e);
    }
  });
  isolated("repeated faces", [&] {
    {
      Random random{seed + 7};
      Faces faces = dt_faces;
      std::size_t copies = 0;
      for(const Face& f : dt_faces)
        if(random.uniform() < 0.01) {
          Face g = f;
          if(copies % 3 == 1)
            std::swap(g[1], g[2]); // reversed
          else if(copies % 3 == 2)
            std::rotate(g.begin(), g.begin() + 1, g.end());
          faces.push_back(g);
          ++copies;
        }
      shuffle_with(faces, random);
      DFP_CHECK(copies > 0);
      Expect e;
      e.damaged = 2 * copies;
      e.not_triangulation = e.carve_expected = e.must_repair = true;
      dfp_case<DT>("1% of the faces listed twice", points, faces, e);
    }
    {
      Expect e;
      e.damaged = dt_faces.size();
      e.not_triangulation = true; // no small damage: exactness only
      dfp_case<DT>("every face listed twice", points, listed_twice(dt_faces), e);
    }
  });
  isolated("crossing faces", [&] {
    for(std::size_t swaps : {std::size_t(5), std::size_t(20)}) {
      const Faces faces = DFP::self_crossing_prediction(points, swaps, seed + 8);
      Expect e;
      e.damaged = faces_not_in(faces, dt_faces);
      e.not_triangulation = e.carve_expected = true;
      // 20 swaps among 2000 clustered points fold about 1% of the faces, near the carving
      // budget (n/8 faces): only 5 swaps must stay local everywhere.
      e.must_repair = swaps == 5 || n >= 5000;
      DFP_CHECK(e.damaged > 0);
      dfp_case<DT>("self_crossing_prediction, " + std::to_string(swaps) + " swaps", points, faces, e);
    }
    {
      const Faces extra = DFP::random_triples(n, 3, seed + 9);
      Faces faces = dt_faces;
      Expect e;
      for(const Face& t : extra) {
        faces.push_back(t);
        e.damaged += 1;
        if(CGAL::orientation(points[t[0]], points[t[1]], points[t[2]]) == CGAL::COLLINEAR)
          continue;
        const auto a = ccw_triangle(t, points);
        for(const Face& f : dt_faces)
          e.damaged += interiors_meet(a, ccw_triangle(f, points)) ? 1 : 0;
      }
      e.not_triangulation = e.carve_expected = e.must_repair = true;
      dfp_case<DT>("the DT and 3 random triples", points, faces, e);
    }
  });
  if(with_moves)
    isolated("the DT of moved points", [&] {
      for(double noise : {0.001, 0.01, 0.05, 0.1}) {
        const Faces faces = DFP::moved_points_prediction(points, noise, seed + 10);
        Expect e;
        e.damaged = not_ccw(faces, points);
        e.not_triangulation = e.carve_expected = e.damaged > 0;
        // Index triples carry no orientation to untangle: inverted faces are left out and
        // their surroundings carved, which the budget allows up to about 2% of the faces
        // inverted (noise 0.05); at 0.1 (about 3%) the call may rebuild. Exact either way.
        e.must_repair = noise <= 0.05;
        if(noise >= 0.05)
          DFP_CHECK_MSG(e.damaged > 0, "no inverted face at noise " << noise);
        std::ostringstream label;
        label << "moved_points_prediction(" << noise << "), " << e.damaged << " faces inverted or flat";
        dfp_case<DT>(label.str(), points, faces, e);
      }
    });
}

// ---------------------------------------------------------------------------------------------
// make_delaunay
// ---------------------------------------------------------------------------------------------

// Builds Tr on `start` (made Delaunay), applies `move` to the handles, then calls make_delaunay
// with each strategy on a fresh copy. `expect_inverted`: the moves must invert faces.
template <class Tr>
void md_case(const std::string& label, const std::vector<typename Tr::Point>& start,
             const std::function<void(const Handles<Tr>&)>& move, bool must_repair,
             bool expect_inverted, bool exact = true)
{
  Scope scope(label);
  const std::size_t n = start.size();
  for(Mode m : strategy_modes) {
    Scope sm("strategy ", name_of(m));
    Tr tr;
    Handles<Tr> handles;
    build(tr, start, handles);
    DFP::make_delaunay(tr, DFP::parameters::max_flips(100 * n + 100)); // a Triangulation_2 too
    move(handles);
    const std::vector<typename Tr::Point> points = current_points(handles);
    const std::size_t inverted = inverted_faces(tr);
    const std::size_t faces_before = tr.dimension() == 2 ? tr.number_of_faces() : 0;
    if(m == Mode::defaults && expect_inverted)
      DFP_CHECK_MSG(inverted > 0, "the moves inverted no face");
    const DFP::Statistics s =
        with_mode(m, [&](const auto& np) { return DFP::make_delaunay(tr, np); }, unlimited_t_division());
    if(verbose())
      std::cout << where() << ": " << inverted << " inverted: " << describe(s) << std::endl;
    if(!exact) {
      DFP_CHECK(tr.is_valid());
      DFP_CHECK(tr.number_of_vertices() == n);
      check_handles(tr, handles, points);
      continue;
    }
    check_handles(tr, handles, points);
    check_is_cgal_delaunay(tr, points);
    DFP_CHECK_MSG(s.faces_in == faces_before, describe(s) << " vs " << faces_before);
    if(!s.fell_back) {
      DFP_CHECK_MSG(s.points_reinserted <= n, describe(s));
      if(s.faces_carved == 0 && !built_by_prediction_regions(s, n))
        DFP_CHECK_MSG(s.points_reinserted == 0, describe(s));
    }
    Expect e;
    e.damaged = inverted;
    e.valid = inverted == 0 && tr.dimension() == 2;
    e.not_triangulation = e.carve_expected = inverted > 0;
    e.must_repair = must_repair;
    check_strategy(m, s, e, n, 12 * inverted);
  }
}

template <class Tr>
std::function<void(const Handles<Tr>&)> gaussian_moves(double sigma, std::uint64_t seed)
{
  using K = typename Tr::Geom_traits;
  return [=](const Handles<Tr>& handles) {
    Random random{seed};
    for(const auto& v : handles) {
      const double dx = sigma * random.normal(), dy = sigma * random.normal();
      v->set_point(make_point<K>(CGAL::to_double(v->point().x()) + dx, CGAL::to_double(v->point().y()) + dy));
    }
  };
}

// Moves handle i to target[i].
template <class Tr>
std::function<void(const Handles<Tr>&)> moves_to(const std::vector<typename Tr::Point>& target)
{
  return [=](const Handles<Tr>& handles) {
    for(std::size_t i = 0; i < handles.size(); ++i)
      handles[i]->set_point(target[i]);
  };
}

template <class Tr>
void moved_triangulations(const std::string& name, const XYs& xy, std::uint64_t seed,
                          const std::vector<double>& sigmas)
{
  using K = typename Tr::Geom_traits;
  const auto points = to_points<K>(xy);
  const double spacing = mean_spacing(xy);
  isolated(name + ", n = " + std::to_string(xy.size()), [&] {
    for(double sigma : sigmas) {
      std::ostringstream label;
      label << "every vertex moved by " << sigma << " x the mean spacing";
      md_case<Tr>(label.str(), points, gaussian_moves<Tr>(sigma * spacing, seed), true, sigma >= 0.05);
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Degenerate inputs: exactness whatever the path
// ---------------------------------------------------------------------------------------------

template <class K>
void degenerate_dfp(const std::string& name, const XYs& xy, std::uint64_t seed)
{
  using DT = DT_with_info<K>;
  const auto points = to_points<K>(xy);
  isolated(name + " (" + std::to_string(xy.size()) + " points), delaunay_from_prediction", [&] {
    const Faces dt_faces = DFP::delaunay_triangles(points);
    Expect e; // exactness and consistency only
    dfp_case<DT>("the DT", points, dt_faces, e);
    for(double noise : {0.05, 0.3}) {
      std::ostringstream label;
      label << "moved_points_prediction(" << noise << ")";
      dfp_case<DT>(label.str(), points, DFP::moved_points_prediction(points, noise, seed), e);
    }
    if(!dt_faces.empty()) {
      dfp_case<DT>("delete_faces(0.05)", points, DFP::delete_faces(dt_faces, 0.05, seed + 1), e);
      Faces twice = dt_faces;
      for(std::size_t k = 0; k < dt_faces.size(); k += 17)
        twice.push_back(dt_faces[k]);
      dfp_case<DT>("some faces listed twice", points, twice, e);
      dfp_case<DT>("self_crossing_prediction(5)", points, DFP::self_crossing_prediction(points, 5, seed + 2), e);
    }
  });
}

// The prediction is the DT of other positions of the same points.
template <class K>
void degenerate_dfp_moved(const std::string& name, const XYs& xy, const XYs& predicted_from)
{
  using DT = DT_with_info<K>;
  const auto points = to_points<K>(xy);
  isolated(name + " (" + std::to_string(xy.size()) + " points), delaunay_from_prediction", [&] {
    Expect e;
    dfp_case<DT>("the DT of the other positions", points, DFP::delaunay_triangles(to_points<K>(predicted_from)), e);
  });
}

template <class K>
void degenerate_md(const std::string& name, const XYs& from, const XYs& to)
{
  using Tr = DT_with_info<K>;
  const auto start = to_points<K>(from);
  const auto target = to_points<K>(to);
  isolated(name + " (" + std::to_string(from.size()) + " points), make_delaunay", [&] {
    md_case<Tr>("DT with info", start, moves_to<Tr>(target), false, false);
    md_case<T2_plain<K>>("Triangulation_2 without info", start, moves_to<T2_plain<K>>(target), false, false);
  });
}

void degenerate_inputs()
{
  using K = Epick;
  const XYs grid = grid_xy(30, 30, 11);
  const XYs jittered_grid = gaussian_moved(grid, 0.2, 12);
  const XYs tiny_jitter = gaussian_moved(grid, 1e-9, 13);
  degenerate_dfp<K>("integer grid (co-circular)", grid, 14);
  degenerate_dfp_moved<K>("integer grid, predicted from the grid jittered by 0.2", grid, jittered_grid);
  degenerate_dfp_moved<K>("grid jittered by 1e-9, predicted from the exact grid", tiny_jitter, grid);
  degenerate_md<K>("jittered grid snapped onto the integer grid", jittered_grid, grid);
  degenerate_md<K>("integer grid moved by 0.6 (inverting faces)", grid, gaussian_moved(grid, 0.6, 15));
  degenerate_md<K>("grid jittered by 1e-9 moved onto the exact grid", tiny_jitter, grid);

  {
    CGAL::Random rng(17);
    const XYs circle = lattice_circle_points(1105, rng, 65);
    degenerate_dfp<K>("lattice points of two concentric circles (co-circular)", circle, 18);
    degenerate_md<K>("lattice circles, from jittered positions", gaussian_moved(circle, 20., 19), circle);
  }
  {
    // Collinear: points on y = 2x + 1; predictions from positions off the line (every face flat).
    XYs line;
    for(int i = 0; i < 200; ++i)
      line.push_back({double(i - 100), 2. * double(i - 100) + 1.});
    Random random{20};
    shuffle_with(line, random);
    const XYs off_line = gaussian_moved(line, 0.5, 21);
    degenerate_dfp<K>("collinear", line, 22);
    degenerate_dfp_moved<K>("collinear, predicted from positions off the line", line, off_line);
    degenerate_md<K>("points moved onto a line (dimension 2 -> 1)", off_line, line);
    // A line of points and a few points off it: 2D, many collinear vertices.
    XYs mixed = line;
    for(std::size_t k = 0; k < 10; ++k)
      mixed[k * 7] = {mixed[k * 7].x + 3., mixed[k * 7].y - 40. + double(k)};
    degenerate_dfp<K>("collinear, 10 points moved off the line", mixed, 23);
    degenerate_dfp_moved<K>("collinear with 10 off, predicted from all off the line", mixed,
                            gaussian_moved(mixed, 0.5, 24));
    degenerate_md<K>("nearly collinear moved onto the line with 10 off", off_line, mixed);
    degenerate_dfp<K>("nearly collinear (1e-12 off the line)", gaussian_moved(line, 1e-12, 25), 26);
  }
  {
    // Duplicates: moved predictions separate the copies, whose faces are degenerate.
    XYs xy = uniform_xy(1000, 27);
    for(std::size_t k = 0; k < 100; ++k)
      xy.push_back(xy[k * 9]);
    Random random{28};
    shuffle_with(xy, random);
    degenerate_dfp<K>("uniform with 100 duplicates", xy, 29);
    degenerate_dfp<K>("integer grid with duplicates", [&] {
      XYs g = grid_xy(20, 20, 30);
      for(std::size_t k = 0; k < 50; ++k)
        g.push_back(g[k * 5]);
      shuffle_with(g, random);
      return g;
    }(), 31);
  }
  {
    const XYs u = uniform_xy(1000, 32);
    degenerate_dfp<K>("uniform * 1e15", transformed(u, 1e15, 0.), 33);
    degenerate_dfp<K>("uniform * 1e-15", transformed(u, 1e-15, 0.), 34);
    degenerate_dfp<K>("uniform * 1e-15 + 1 (a few ulps apart: duplicates and collinear)",
                      transformed(u, 1e-15, 1.), 35);
    degenerate_dfp<K>("uniform in [0, 1000]^2 + 1e15", transformed(u, 1000., 1e15), 36);
    degenerate_dfp<K>("integer grid + 1e15", transformed(grid, 1., 1e15), 37);
    degenerate_dfp<K>("integer grid * 1e-15", transformed(grid, 1e-15, 0.), 38);
    degenerate_md<K>("uniform * 1e15, moved by 0.3 spacings", transformed(u, 1e15, 0.),
                     gaussian_moved(transformed(u, 1e15, 0.), 0.3 * 1e15 / std::sqrt(1000.), 39));
    degenerate_md<K>("uniform * 1e-15, moved by 0.3 spacings", transformed(u, 1e-15, 0.),
                     gaussian_moved(transformed(u, 1e-15, 0.), 0.3 * 1e-15 / std::sqrt(1000.), 40));
    degenerate_md<K>("jittered grid + 1e15 snapped onto the grid", transformed(jittered_grid, 1., 1e15),
                     transformed(grid, 1., 1e15));
  }
}

// The carve must not depend on where the faces sit in memory. It did: the outer loop was the
// counterclockwise loop with the lowest-leftmost vertex, and when an island hung at that very
// vertex the first in memory order won; the real outer loop, taken for an island, was then
// carved layer by layer past the budget (18 of 40 memory layouts of this very input fell back).
void carve_independent_of_memory_layout(const XYs& xy)
{
  using Tr = DT_with_info<Epick>;
  const auto points = to_points<Epick>(xy);
  std::vector<std::unique_ptr<char[]>> clutter;
  std::size_t carved = 0;
  for(int layout = 0; layout < 24; ++layout) {
    Scope scope("memory layout ", layout);
    for(int k = 0; k < 7 * layout; ++k) // shifts where the next blocks go
      clutter.emplace_back(new char[16 + (37 * k) % 200]);
    Tr tr;
    Handles<Tr> handles;
    build(tr, points, handles);
    gaussian_moves<Tr>(0.1 * mean_spacing(xy), 4001)(handles);
    const auto moved = current_points(handles);
    const DFP::Statistics s = DFP::make_delaunay(tr, DFP::parameters::strategy(DFP::Strategy::carve));
    DFP_CHECK_MSG(!s.fell_back, describe(s));
    if(layout == 0)
      carved = s.faces_carved;
    DFP_CHECK_MSG(s.faces_carved == carved, describe(s) << " vs " << carved << " carved with the first layout");
    check_handles(tr, handles, moved);
    check_is_cgal_delaunay(tr, moved);
  }
}

// The import's first check, by Euler's formula (excess = 2V - 2 - F - h, import_prediction.h):
// 15% of the faces deleted gives up before the spatial ordering (the statistics show no
// reordering), with CGAL's result; a complete triangulation of points in convex position, whose
// F = n - 2 faces are far below 2n, must not be taken for a prediction with holes (the hull
// bound counts every point), nor must 3% deleted (an excess of about 0.06 n, under n/8), which
// stops the import at once without local repair (Strategy::flips: past n/64).
void euler_early_exit()
{
  using DT = DT_with_info<Epick>;
  {
    Scope scope("15% of the faces deleted");
    const auto points = to_points<Epick>(uniform_xy(20000, 6001));
    const Faces kept = DFP::delete_faces(DFP::delaunay_triangles(points), 0.15, 6002);
    DT dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, kept, dt);
    DFP_CHECK_MSG(s.fell_back && reason_is(s, DFP::Outcome::too_many_holes), describe(s));
    DFP_CHECK_MSG(!s.input_reordered, describe(s)); // stopped before the spatial ordering
    check_is_cgal_delaunay(dt, points);
  }
  {
    Scope scope("3% of the faces deleted");
    const auto points = to_points<Epick>(uniform_xy(20000, 6003));
    const Faces kept = DFP::delete_faces(DFP::delaunay_triangles(points), 0.03, 6004);
    DT dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, kept, dt);
    DFP_CHECK_MSG(!s.fell_back && s.holes_refilled > 0, describe(s));
    check_is_cgal_delaunay(dt, points);
    // Without local repair (Strategy::flips) any excess above n/64 stops the import at once.
    DT flipped;
    const DFP::Statistics f =
        DFP::delaunay_from_prediction(points, kept, flipped, DFP::parameters::strategy(DFP::Strategy::flips));
    DFP_CHECK_MSG(f.fell_back && !f.input_reordered, describe(f));
    check_is_cgal_delaunay(flipped, points);
  }
  for(const std::size_t n : {std::size_t(50), std::size_t(3000), std::size_t(1200)}) {
    // On a parabola (no ties), or a grid of 3 rows: 800 of its 1200 points lie on the hull,
    // 796 of them inside hull edges, which the count must include.
    Scope scope(n == 1200 ? "grid of 400 x 3 points" : "points in convex position, n = ", n);
    XYs xy;
    for(std::size_t i = 0; i < n; ++i) {
      const double x = double(i) / double(n) - 0.5;
      xy.push_back(n == 1200 ? XY{double(i / 3), double(i % 3)} : XY{x, x * x});
    }
    const auto points = to_points<Epick>(xy);
    Faces faces = DFP::delaunay_triangles(points);
    Random random{6005};
    shuffle_with(faces, random);
    DT dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt);
    DFP_CHECK_MSG(!s.fell_back && s.faces_certified == faces.size(), describe(s));
    check_is_cgal_delaunay(dt, points);
    const DFP::Statistics f =
        DFP::delaunay_from_prediction(points, faces, dt, DFP::parameters::strategy(DFP::Strategy::flips));
    DFP_CHECK_MSG(!f.fell_back && f.faces_certified == faces.size(), describe(f));
    check_is_cgal_delaunay(dt, points);
  }
}

// The tolerant import fills small holes itself (import_prediction.h, fill_small_holes): holes
// that are single faces of a DT, with the hull intact, are all filled there (the importer's own
// output says so, and the hull is then closed without carve_repair.h), with the predicted faces
// certified and no flip; a vertex's star deleted leaves a hole around an unused point, filled
// and then the point inserted; two adjacent faces deleted leave a quadrilateral, whose diagonal
// the ear clipping may get wrong (a flip); a face on the hull deleted leaves the outer cycle to
// carve_repair.h, with the faces the import made not counted as predicted faces carved.
void import_fills_small_holes()
{
  using DT = DT_with_info<Epick>;
  const auto points = to_points<Epick>(uniform_xy(5000, 8001));
  const Faces faces = DFP::delaunay_triangles(points);
  DT reference;
  reference.insert(points.begin(), points.end());
  std::vector<char> on_hull(points.size(), 0);
  {
    std::map<std::pair<double, double>, std::size_t> index;
    for(std::size_t i = 0; i < points.size(); ++i)
      index[{points[i].x(), points[i].y()}] = i;
    for(auto v = reference.incident_vertices(reference.infinite_vertex()); ; ) {
      on_hull[index[{v->point().x(), v->point().y()}]] = 1;
      if(++v == reference.incident_vertices(reference.infinite_vertex()))
        break;
    }
  }
  auto touches_hull = [&](const Face& f) { return on_hull[f[0]] || on_hull[f[1]] || on_hull[f[2]]; };
  {
    Scope scope("interior faces with no common vertex deleted");
    std::vector<char> taken(points.size(), 0);
    Faces kept;
    std::size_t deleted = 0;
    for(std::size_t k = 0; k < faces.size(); ++k) {
      const Face& f = faces[k];
      if(k % 29 == 0 && !touches_hull(f) && !taken[f[0]] && !taken[f[1]] && !taken[f[2]]) {
        taken[f[0]] = taken[f[1]] = taken[f[2]] = 1;
        ++deleted;
      } else {
        kept.push_back(f);
      }
    }
    DFP_CHECK(deleted > 100);
    DT imported;
    DFP::internal::Imported_prediction<DT> out;
    std::vector<std::uint32_t> triples;
    DFP_CHECK(DFP::internal::read_index_triples(kept, points.size(), kept.size(), triples));
    DFP::internal::Prediction_importer<DT>::run(imported, points.begin(), points.size(), triples, out, true);
    DFP_CHECK_MSG(out.failure == DFP::Outcome::ok && !out.needs_repair && out.holes_filled == deleted &&
                      out.filled_faces.size() == deleted && out.not_locally_delaunay.empty(),
                  DFP::to_string(out.failure) << " needs_repair " << out.needs_repair << ", " << out.holes_filled
                                                   << " holes filled, " << deleted << " deleted");
    DFP_CHECK(imported.is_valid());
    DT dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, kept, dt);
    DFP_CHECK_MSG(!s.fell_back && s.holes_refilled == deleted && s.carve_rounds == 1 && s.flips == 0 &&
                      s.faces_carved == 0 && s.faces_certified == kept.size(),
                  describe(s) << "; " << deleted << " deleted");
    check_is_cgal_delaunay(dt, points);
    check_dfp_statistics(s, kept, points, dt);
  }
  // The faces around vertex `center`, or the two faces on an interior edge (a quadrilateral).
  auto without = [&](auto drop) {
    Faces kept;
    for(const Face& f : faces)
      if(!drop(f))
        kept.push_back(f);
    return kept;
  };
  std::size_t center = 0;
  while(on_hull[center])
    ++center;
  const Face first = [&] {
    for(const Face& f : faces)
      if(!touches_hull(f))
        return f;
    return faces[0];
  }();
  auto has = [](const Face& f, std::size_t v) { return f[0] == v || f[1] == v || f[2] == v; };
  for(int c = 0; c < 4; ++c) {
    const char* what[] = {"the star of a vertex deleted (its point unused)", "two adjacent faces deleted",
                          "two adjacent faces deleted, other edge", "a face on the hull and interior faces deleted"};
    Scope scope(what[c]);
    Faces kept;
    if(c == 0) {
      kept = without([&](const Face& f) { return has(f, center); });
    } else if(c < 3) {
      // `first` and its neighbour across the edge opposite its vertex c.
      const std::size_t a = first[c % 3], b = first[(c + 1) % 3];
      kept = without([&](const Face& f) { return has(f, a) && has(f, b); });
    } else {
      std::size_t hull_face = 0;
      while(!touches_hull(faces[hull_face]))
        ++hull_face;
      kept = without([&](const Face& f) { return &f == &faces[hull_face] || (&f - &faces[0]) % 97 == 5; });
    }
    DT dt;
    const DFP::Statistics s = DFP::delaunay_from_prediction(points, kept, dt);
    DFP_CHECK_MSG(!s.fell_back && s.holes_refilled >= 1 && s.carve_rounds >= 1, describe(s));
    if(c == 0)
      DFP_CHECK_MSG(s.points_unused == 1 && s.points_reinserted == 1 && s.faces_carved == 0, describe(s));
    if(c == 1 || c == 2)
      DFP_CHECK_MSG(s.faces_in == faces.size() - 2 && s.flips <= 1 && s.faces_carved == 0, describe(s));
    check_is_cgal_delaunay(dt, points);
    check_dfp_statistics(s, kept, points, dt);
  }
}

// Statistics::faces_certified counts the distinct faces a repair touched with a bitmap of face
// slots (sort_addresses.h), or by sorting when the addresses are too spread out for one. Both
// paths against a count by std::set, with repeats, a `listed` part and a `keep` filter; the
// spread case takes objects from a large heap block and from a static array, so its test
// checks that the bitmap was indeed ruled out.
void distinct_face_count()
{
  struct Object { std::uint64_t words[7]; }; // the size of a CGAL face
  static Object far_away[64];
  std::vector<Object> block(200000);        // 11 MB: its own mapping, far from far_away
  Random random{7001};
  for(const bool spread : {false, true}) {
    std::vector<const Object*> handles;
    std::vector<const void*> listed;
    for(int k = 0; k < 30000; ++k) {
      const Object* o = spread && k % 3 == 0 ? &far_away[random() % 64] : &block[random() % 5000];
      (k % 5 == 0 ? listed.push_back(o) : handles.push_back(o));
    }
    const std::size_t first = 1000;
    auto keep = [&](const void* p) { return (reinterpret_cast<std::uintptr_t>(p) / sizeof(Object)) % 3 != 0; };
    std::set<const void*> expected(listed.begin(), listed.end());
    for(std::size_t k = first; k < handles.size(); ++k)
      if(keep(handles[k]))
        expected.insert(handles[k]);
    std::uint64_t low = ~std::uint64_t(0), high = 0;
    for(const void* p : listed) {
      low = (std::min)(low, std::uint64_t(reinterpret_cast<std::uintptr_t>(p)));
      high = (std::max)(high, std::uint64_t(reinterpret_cast<std::uintptr_t>(p)));
    }
    for(std::size_t k = first; k < handles.size(); ++k) {
      low = (std::min)(low, std::uint64_t(reinterpret_cast<std::uintptr_t>(handles[k])));
      high = (std::max)(high, std::uint64_t(reinterpret_cast<std::uintptr_t>(handles[k])));
    }
    const bool bitmap = DFP::internal::Slot_bitmap<Object>::fits(low, high, listed.size() + handles.size() - first);
    DFP_CHECK_MSG(bitmap == !spread, (spread ? "spread" : "one block") << ": bitmap " << bitmap);
    const std::size_t counted = DFP::internal::count_distinct_addresses<Object>(listed, handles, first, keep);
    DFP_CHECK_MSG(counted == expected.size(), (spread ? "spread" : "one block") << ": " << counted << " counted, "
                                                                                 << expected.size() << " expected");
  }
}

// Strategy::t_division with tiny regions (4 to 64 faces) on many small random inputs, so that
// most regions touch bad ones and the fills meet each other, the hull and the grid's
// co-circular ties: make_delaunay after random moves (vertex handles and info kept), and
// delaunay_from_prediction from the DT of other points (crossing and inverted faces).
void t_division_small_random_cases()
{
  using Tr = DT_with_info<Epick>;
  std::size_t repaired = 0;
  for(std::uint64_t seed = 0; seed < 160; ++seed) {
    Random random{seed * 7919 + 5};
    const std::size_t n = 20 + std::size_t(random.below(500));
    const int kind = int(random.below(3));
    XYs xy = kind == 0 ? uniform_xy(n, seed + 100)
             : kind == 1 ? grid_xy(int(std::sqrt(double(n))) + 1, int(std::sqrt(double(n))) + 1, seed + 200)
                         : uniform_xy(n, seed + 300, -1e6, 1e6);
    const double sigmas[] = {0.01, 0.1, 0.4, 1.0};
    const double sigma = sigmas[random.below(4)];
    XYs moved = gaussian_moved(xy, sigma * mean_spacing(xy), seed + 400);
    if(kind == 1) // a quarter stays on the grid: co-circular ties
      for(std::size_t i = 0; i < xy.size(); i += 4)
        moved[i] = xy[i];
    const std::size_t sizes[] = {4, 8, 16, 64};
    const std::size_t t = sizes[random.below(4)];
    std::ostringstream label;
    label << "seed " << seed << ", n = " << xy.size() << ", sigma = " << sigma << ", t = " << t;
    Scope scope(label.str());
    const auto target = to_points<Epick>(moved);
    if(std::set<std::pair<double, double>>([&] {
         std::set<std::pair<double, double>> distinct;
         for(const XY& p : moved)
           distinct.insert({p.x, p.y});
         return distinct;
       }()).size() != moved.size())
      continue; // make_delaunay rejects duplicates (test_bad_input.cpp)
    const auto np =
        DFP::parameters::strategy(DFP::Strategy::t_division, DFP::parameters::region_size(t)).tuning(unlimited_t_division());
    {
      Tr tr;
      Handles<Tr> handles;
      build(tr, to_points<Epick>(xy), handles);
      moves_to<Tr>(target)(handles);
      const DFP::Statistics s = DFP::make_delaunay(tr, np);
      repaired += !s.fell_back && s.bad_regions > 0 ? 1 : 0;
      check_handles(tr, handles, target);
      check_is_cgal_delaunay(tr, target);
    }
    {
      const Faces faces = delaunay_faces<Epick>(to_points<Epick>(xy)); // predicted from the unmoved points
      Tr dt;
      const DFP::Statistics s = DFP::delaunay_from_prediction(target, faces, dt, np);
      repaired += !s.fell_back && s.bad_regions > 0 ? 1 : 0;
      check_is_cgal_delaunay(dt, target);
    }
  }
  DFP_CHECK_MSG(repaired >= 100, repaired << " of 320 calls took the t-division repair");
}

} // namespace

int main()
{
  const XYs uniform_5000 = uniform_xy(5000, 1001);
  {
    Scope scope("Epick");
    damaged_predictions<DT_with_info<Epick>>("uniform, DT with size_t info", to_points<Epick>(uniform_5000), 2001, true);
    {
      // Clustered points: combinatorial damage only (moves by the mean spacing would wreck the blobs).
      CGAL::Random rng(3001);
      damaged_predictions<DT_plain<Epick>>("clustered, DT without info", to_points<Epick>(clustered_points(2000, rng)),
                                          2002, false);
    }
    isolated("n = 20000", [&] {
      const auto points = to_points<Epick>(uniform_xy(20000, 1002));
      const Faces dt_faces = DFP::delaunay_triangles(points);
      using DT = DT_with_info<Epick>;
      {
        const Faces faces = DFP::moved_points_prediction(points, 0.05, 2003);
        Expect e;
        e.damaged = not_ccw(faces, points);
        e.not_triangulation = e.carve_expected = e.damaged > 0;
        e.must_repair = true;
        DFP_CHECK(e.damaged > 0);
        dfp_case<DT>("moved_points_prediction(0.05)", points, faces, e);
      }
      {
        const Faces kept = DFP::delete_faces(dt_faces, 0.01, 2004);
        Expect e;
        e.damaged = dt_faces.size() - kept.size();
        e.not_triangulation = e.holes_expected = e.must_repair = true;
        dfp_case<DT>("delete_faces(0.01)", points, kept, e);
      }
      md_case<DT>("make_delaunay, every vertex moved by 0.05 x the mean spacing", points,
                  gaussian_moves<DT>(0.05 / std::sqrt(20000.), 2005), true, true);
    });
    const std::vector<double> sigmas = {0.001, 0.01, 0.05, 0.1};
    moved_triangulations<DT_with_info<Epick>>("make_delaunay, Delaunay_triangulation_2 with size_t info",
                                              uniform_5000, 4001, sigmas);
    moved_triangulations<T2_with_info<Epick, int>>("make_delaunay, Triangulation_2 with int info",
                                                   uniform_5000, 4002, sigmas);
    moved_triangulations<DT_plain<Epick>>("make_delaunay, Delaunay_triangulation_2 without info",
                                          uniform_xy(2000, 1003), 4003, {0.1});
    degenerate_inputs();
    isolated("t_division, tiny regions, small random inputs", [] { t_division_small_random_cases(); });
    isolated("carve, the same input in 24 memory layouts", [&] { carve_independent_of_memory_layout(uniform_5000); });
    isolated("early exit of the import by Euler's formula", [] { euler_early_exit(); });
    isolated("distinct face count of the statistics", [] { distinct_face_count(); });
    isolated("small holes filled by the import", [] { import_fills_small_holes(); });
  }
  {
    Scope scope("Simple_cartesian<double> (inexact): terminates with a valid triangulation");
    const XYs xy = uniform_xy(2000, 1004);
    const auto points = to_points<Inexact>(xy);
    const double spacing = mean_spacing(xy);
    for(const char* sigma_text : {"0.1", "0.5", "2"}) {
      const double sigma = std::atof(sigma_text);
      isolated(std::string("moved by ") + sigma_text + " x the mean spacing", [&] {
        md_case<DT_with_info<Inexact>>("DT with info", points, gaussian_moves<DT_with_info<Inexact>>(sigma * spacing, 5001),
                                       false, false, false);
        md_case<T2_plain<Inexact>>("Triangulation_2", points, gaussian_moves<T2_plain<Inexact>>(sigma * spacing, 5002),
                                   false, false, false);
      });
    }
    isolated("jittered grid snapped onto the integer grid", [&] {
      md_case<DT_with_info<Inexact>>("DT with info", to_points<Inexact>(gaussian_moved(grid_xy(20, 20, 5003), 0.2, 5004)),
                                     moves_to<DT_with_info<Inexact>>(to_points<Inexact>(grid_xy(20, 20, 5003))),
                                     false, false, false);
    });
  }
  {
    Scope scope("Epeck");
    const XYs xy = uniform_xy(300, 1005);
    const auto points = to_points<Epeck>(xy);
    isolated("make_delaunay, moved", [&] {
      md_case<DT_with_info<Epeck>>("moved by 0.1 x the mean spacing", points,
                                   gaussian_moves<DT_with_info<Epeck>>(0.1 * mean_spacing(xy), 6001), false, false);
      md_case<DT_with_info<Epeck>>("moved by 0.5 x the mean spacing", points,
                                   gaussian_moves<DT_with_info<Epeck>>(0.5 * mean_spacing(xy), 6002), false, true);
    });
    isolated("delaunay_from_prediction, moved points", [&] {
      const Faces faces = DFP::moved_points_prediction(points, 0.3, 6003);
      Expect e;
      e.damaged = not_ccw(faces, points);
      DFP_CHECK(e.damaged > 0);
      e.not_triangulation = e.carve_expected = e.damaged > 0; // n = 300: exactness, no budget asked
      dfp_case<DT_with_info<Epeck>>("moved_points_prediction(0.3)", points, faces, e);
    });
  }
  return finish("test_local_repair");
}
