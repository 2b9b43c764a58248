// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// delaunay_from_prediction() with every kind of prediction, good and bad, on uniform and
// clustered points (Epick): the result is always CGAL's DT built from scratch, and the
// statistics say what happened (certified, flipped, fell back, points unused, duplicates).
// Also: the accepted face and point containers, vertex bases with and without info, and
// Statistics written to a stream.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <deque>
#include <list>
#include <sstream>
#include <string>

using namespace dfp_test;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Points = std::vector<Point>;

// Runs delaunay_from_prediction into a DT pre-filled with unrelated points (it must be
// cleared), checks the result against CGAL and the statistics for consistency.
template <class DT, class PointRange, class FaceRange,
          class NP = DFP::parameters::Default_named_parameters>
DFP::Statistics run(const PointRange& points, const FaceRange& faces, const Faces& as_indices,
                    const NP& np = DFP::parameters::default_values())
{
  DT dt;
  dt.insert(make_point<K>(1e3, 1e3));
  dt.insert(make_point<K>(-1e3, 1e3));
  dt.insert(make_point<K>(0., -1e3));
  const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt, np);
  const Points copy(std::begin(points), std::end(points));
  check_is_cgal_delaunay(dt, copy);
  check_statistics(s, as_indices, copy, dt);
  return s;
}

template <class DT, class NP = DFP::parameters::Default_named_parameters>
DFP::Statistics run(const Points& points, const Faces& faces,
                    const NP& np = DFP::parameters::default_values())
{
  return run<DT>(points, faces, faces, np);
}

// Interior edges of a triangulation with F faces of n points (all used, all distinct).
std::size_t interior_edges(std::size_t faces, std::size_t n) { return 2 * faces + 1 - n; }

template <class DT>
void test_good_predictions(const Points& points, CGAL::Random& rng)
{
  const std::size_t n = points.size();
  const Faces dt_faces = delaunay_faces<K>(points);
  {
    Scope scope("the DT itself, shuffled");
    const DFP::Statistics s = run<DT>(points, shuffled(dt_faces, rng));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.faces_in == dt_faces.size());
    DFP_CHECK(s.faces_certified == s.faces_in);
    DFP_CHECK(s.flips == 0);
    DFP_CHECK(s.edges_not_locally_delaunay == 0);
    DFP_CHECK_MSG(s.edges_tested == interior_edges(dt_faces.size(), n), s.edges_tested);
    DFP_CHECK(s.points_unused == 0);
    DFP_CHECK(s.points_reinserted == 0);
    DFP_CHECK(s.duplicate_points == 0);
  }
  {
    Scope scope("the DT, faces reversed");
    const DFP::Statistics s = run<DT>(points, reversed(dt_faces));
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.faces_certified == s.faces_in);
    DFP_CHECK(s.flips == 0);
  }
  for(std::size_t k : {std::size_t(1), std::size_t(10), n / 20}) {
    Scope scope("the DT after ", k, " random flips");
    std::size_t done = 0;
    const Faces faces = shuffled(flipped_delaunay_faces<K>(points, k, rng, &done), rng);
    DFP_CHECK(done == k);
    const std::size_t wrong = edges_not_in_delaunay<K>(faces, points);
    DFP_CHECK(wrong >= 1);
    const DFP::Statistics s = run<DT>(points, faces);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.flips > 0);
    DFP_CHECK_MSG(s.flips >= wrong, s.flips << " flips, " << wrong << " wrong edges");
    DFP_CHECK_MSG(s.edges_not_locally_delaunay >= 1 && s.edges_not_locally_delaunay <= wrong,
                  s.edges_not_locally_delaunay << " vs " << wrong);
    DFP_CHECK(s.edges_tested == interior_edges(faces.size(), n));
    DFP_CHECK(s.faces_certified < s.faces_in);
    DFP_CHECK(s.faces_certified + 2 * s.flips >= s.faces_in);
    DFP_CHECK(s.points_unused == 0);
  }
  {
    Scope scope("a plain Triangulation_2 of the points (random insertion order)");
    const Faces faces = shuffled(faces_by_info(indexed_triangulation<K>(points)), rng);
    const std::size_t wrong = edges_not_in_delaunay<K>(faces, points);
    DFP_CHECK(wrong > 0);
    {
      Scope defaults("default parameters"); // exact; whether it falls back: test_triangulation_prediction
      run<DT>(points, faces);
    }
    {
      Scope budget("max_flips(100 n)");
      const DFP::Statistics s = run<DT>(points, faces, DFP::parameters::max_flips(100 * n));
      DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
      DFP_CHECK_MSG(s.flips >= wrong, s.flips << " flips, " << wrong << " wrong edges");
      DFP_CHECK(s.edges_not_locally_delaunay >= 1 && s.edges_not_locally_delaunay <= wrong);
      DFP_CHECK(s.edges_tested == interior_edges(faces.size(), n));
      DFP_CHECK(s.points_unused == 0);
    }
  }
}

template <class DT>
void test_bad_predictions(const Points& points, const XYs& xy, CGAL::Random& rng)
{
  const std::size_t n = points.size();
  const Faces dt_faces = delaunay_faces<K>(points);
  const double spacing = 1. / std::sqrt(double(n));
  for(double relative : {0.01, 0.3, 3.}) {
    Scope scope("the DT of the points jittered by ", relative, " of the spacing");
    const Points moved = to_points<K>(jittered(xy, relative * spacing, rng));
    run<DT>(points, delaunay_faces<K>(moved)); // exact; falling back allowed
  }
  for(std::size_t count : {std::size_t(1), std::size_t(25)}) {
    Scope scope(count, " faces deleted");
    run<DT>(points, with_faces_deleted(dt_faces, count, rng));
  }
  {
    Scope scope("a face deleted from the interior only");
    // An interior face: all three of its edges shared. Deleting it leaves a hole.
    Faces faces = dt_faces;
    const auto dt = indexed_delaunay<K>(points);
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      if(!dt.is_infinite(f->neighbor(0)) && !dt.is_infinite(f->neighbor(1)) &&
         !dt.is_infinite(f->neighbor(2))) {
        const Face hole = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
        faces.erase(std::find(faces.begin(), faces.end(), hole));
        break;
      }
    DFP_CHECK(faces.size() + 1 == dt_faces.size());
    run<DT>(points, faces);
  }
  {
    // Deleting a face with a hull edge whose third vertex is interior leaves a single boundary
    // cycle, not convex: not a triangulation of the convex hull. Deleting an ear (a hull vertex
    // in one face only) leaves that point unused and a convex boundary: still a triangulation.
    const auto dt = indexed_delaunay<K>(points);
    bool notch_done = false, ear_done = false;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      int hull_edges = 0, apex = -1;
      for(int i = 0; i < 3; ++i)
        if(dt.is_infinite(f->neighbor(i))) {
          ++hull_edges;
          apex = i;
        }
      if(hull_edges != 1)
        continue;
      const auto v = f->vertex(apex);
      bool apex_on_hull = false;
      auto c = dt.incident_vertices(v), done = c;
      do
        apex_on_hull = apex_on_hull || dt.is_infinite(c);
      while(++c != done);
      if(apex_on_hull || notch_done)
        continue;
      Scope scope("a hull face deleted, leaving a notch in the boundary");
      const Face gone = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
      Faces faces = dt_faces;
      faces.erase(std::find(faces.begin(), faces.end(), gone));
      const DFP::Statistics s = run<DT>(points, faces);
      DFP_CHECK(s.points_unused == 0);
      notch_done = true;
    }
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end() && !ear_done; ++v) {
      if(dt.degree(v) != 3)
        continue;
      auto f = dt.incident_faces(v), done = f;
      int finite = 0;
      Face ear;
      do
        if(!dt.is_infinite(f)) {
          ++finite;
          ear = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
        }
      while(++f != done);
      if(finite != 1)
        continue;
      Scope scope("an ear deleted (its hull vertex unused)");
      Faces faces = dt_faces;
      faces.erase(std::find(faces.begin(), faces.end(), ear));
      const DFP::Statistics s = run<DT>(points, faces);
      DFP_CHECK(!s.fell_back);
      DFP_CHECK(s.points_unused == 1);
      ear_done = true;
    }
    DFP_CHECK(notch_done);
    (void)ear_done; // an ear exists only if some hull vertex has degree 2 in the faces
  }
  {
    Scope scope("random triples");
    const Faces triples = random_triples(n, 2 * n, rng);
    {
      Scope flips("strategy(flips): falls back");
      const DFP::Statistics s = run<DT>(points, triples, DFP::parameters::strategy(DFP::Strategy::flips));
      DFP_CHECK(s.fell_back);
    }
    {
      Scope automatic("default strategy: rebuilt, or repaired locally when the damage is small");
      const DFP::Statistics s = run<DT>(points, triples);
      DFP_CHECK(repaired_or_rebuilt(s));
    }
  }
  {
    Scope scope("no faces");
    {
      Scope flips("strategy(flips)");
      const DFP::Statistics s = run<DT>(points, Faces(), DFP::parameters::strategy(DFP::Strategy::flips));
      DFP_CHECK(s.fell_back);
      DFP_CHECK(s.faces_in == 0);
    }
    {
      Scope automatic("default strategy");
      const DFP::Statistics s = run<DT>(points, Faces());
      DFP_CHECK(s.faces_in == 0);
      DFP_CHECK(s.faces_certified == 0);
    }
  }
  {
    Scope scope("the DT listed twice");
    const DFP::Statistics s = run<DT>(points, listed_twice(dt_faces));
    DFP_CHECK(s.faces_in == 2 * dt_faces.size());
  }
  {
    Scope scope("the DT listed twice, the second copy reversed");
    Faces faces = dt_faces;
    const Faces back = reversed(dt_faces);
    faces.insert(faces.end(), back.begin(), back.end());
    run<DT>(points, faces);
  }
  {
    Scope scope("the DT plus one face listed twice");
    Faces faces = dt_faces;
    faces.push_back(dt_faces[dt_faces.size() / 2]);
    run<DT>(points, faces);
  }
  {
    Scope scope("the DT plus a crossing face");
    Faces faces = dt_faces;
    faces.push_back({0, n / 3, 2 * n / 3});
    run<DT>(points, faces);
  }
  {
    Scope scope("the DT of other points, one face made (nearly) collinear");
    // Move the third point of a face to the midpoint of the other two: that face becomes flat
    // (up to the rounding of the midpoint) and its neighbours are inverted.
    Points moved = points;
    const Face f = dt_faces[0];
    moved[f[2]] = CGAL::midpoint(moved[f[0]], moved[f[1]]);
    run<DT>(moved, dt_faces);
  }
}

// Faces that wind twice around their centre: five ccw faces (c, p_j, p_{j+2}) of a convex
// pentagon p_0..p_4 and its centre c. Every interior edge has one face on each side, the
// boundary (a pentagram) turns left at every vertex and has as many edges as Euler's formula
// asks; only its total turn (4 pi) tells that the faces cover the pentagon twice.
template <class DT>
void test_double_cover()
{
  Scope scope("faces covering a pentagon twice (pentagram boundary)");
  const Points points = {Point(0, 0),    Point(1000, 0),   Point(309, 951),
                         Point(-809, 588), Point(-809, -588), Point(309, -951)};
  Faces faces;
  for(std::size_t j = 0; j < 5; ++j)
    faces.push_back({0, 1 + j, 1 + (j + 2) % 5});
  for(const Face& f : faces)
    DFP_CHECK(CGAL::orientation(points[f[0]], points[f[1]], points[f[2]]) == CGAL::LEFT_TURN);
  {
    Scope flips("strategy(flips): falls back");
    const DFP::Statistics s = run<DT>(points, faces, DFP::parameters::strategy(DFP::Strategy::flips));
    DFP_CHECK(s.fell_back);
  }
  {
    Scope automatic("default strategy");
    const DFP::Statistics s = run<DT>(points, faces);
    DFP_CHECK(repaired_or_rebuilt(s));
  }
}

// Many small predictions, each the DT with a few random local corruptions: a vertex of a
// face replaced (often by a neighbour, so that faces overlap or leave a gap), a face removed,
// duplicated or added, a vertex index moved to a duplicate point. Small inputs make it likely
// that the corrupted faces still pass some of the structural checks.
template <class DT>
void test_random_corruptions(CGAL::Random& rng)
{
  for(int trial = 0; trial < 400; ++trial) {
    const std::size_t n = std::size_t(rng.get_int(5, 30));
    XYs xy = trial % 3 == 0 ? grid_points(rng.get_int(2, 6), rng.get_int(2, 6), rng) : uniform_points(n, rng);
    if(trial % 5 == 0)
      xy = with_duplicates(xy, 2, rng);
    const Points points = to_points<K>(xy);
    Faces faces = delaunay_faces<K>(points);
    if(faces.empty())
      continue;
    const int corruptions = rng.get_int(1, 4);
    std::ostringstream what;
    for(int c = 0; c < corruptions && !faces.empty(); ++c) {
      const std::size_t f = std::size_t(rng.get_int(0, int(faces.size())));
      switch(rng.get_int(0, 5)) {
      case 0: { // a vertex replaced by a vertex of another face
        const Face& g = faces[std::size_t(rng.get_int(0, int(faces.size())))];
        const std::size_t i = std::size_t(rng.get_int(0, 3)), v = g[std::size_t(rng.get_int(0, 3))];
        if(v != faces[f][(i + 1) % 3] && v != faces[f][(i + 2) % 3]) {
          what << " replace " << f << "[" << i << "]=" << v;
          faces[f][i] = v;
        }
        break;
      }
      case 1:
        what << " delete " << f;
        faces.erase(faces.begin() + std::ptrdiff_t(f));
        break;
      case 2:
        what << " duplicate " << f;
        faces.push_back(reversed(Faces{faces[f]})[0]);
        break;
      case 3: { // a face made of a face's edge and a vertex of the neighbouring face
        const Face g = faces[std::size_t(rng.get_int(0, int(faces.size())))];
        const Face h = {faces[f][0], faces[f][1], g[std::size_t(rng.get_int(0, 3))]};
        if(h[2] != h[0] && h[2] != h[1]) {
          what << " add " << h[0] << "," << h[1] << "," << h[2];
          faces.push_back(h);
        }
        break;
      }
      default: { // two faces swap a vertex
        const std::size_t g = std::size_t(rng.get_int(0, int(faces.size())));
        const std::size_t i = std::size_t(rng.get_int(0, 3)), j = std::size_t(rng.get_int(0, 3));
        Face a = faces[f], b = faces[g];
        std::swap(a[i], b[j]);
        if(a[0] != a[1] && a[1] != a[2] && a[0] != a[2] && b[0] != b[1] && b[1] != b[2] && b[0] != b[2]) {
          what << " swap " << f << "[" << i << "]," << g << "[" << j << "]";
          faces[f] = a;
          faces[g] = b;
        }
      }
      }
    }
    Scope scope("corrupted prediction, trial ", trial, ":", what.str());
    run<DT>(points, faces);
  }
}

template <class DT>
void test_subsets_and_duplicates(const Points& points, CGAL::Random& rng)
{
  const std::size_t n = points.size();
  {
    Scope scope("a DT of the first half of the points");
    const Points half(points.begin(), points.begin() + std::ptrdiff_t(n / 2));
    const Faces faces = delaunay_faces<K>(half);
    const DFP::Statistics s = run<DT>(points, faces);
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.points_unused == n - n / 2);
    DFP_CHECK(s.points_reinserted == n - n / 2);
    DFP_CHECK(s.faces_certified < s.faces_in);
  }
  {
    Scope scope("a DT of the last tenth of the points (prediction far from covering)");
    Faces faces = delaunay_faces<K>(Points(points.end() - std::ptrdiff_t(n / 10), points.end()));
    for(Face& f : faces)
      for(std::size_t& i : f)
        i += n - n / 10;
    const DFP::Statistics s = run<DT>(points, faces);
    DFP_CHECK_MSG(!s.fell_back, to_string(s.outcome));
    DFP_CHECK(s.points_unused == n - n / 10);
  }
  {
    Scope scope("a single face");
    const DFP::Statistics s = run<DT>(points, Faces{{0, 1, 2}});
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.points_unused == n - 3);
  }

  // Points with duplicates: the last m points are copies of the first m.
  const std::size_t m = 30;
  Points with_copies = points;
  for(std::size_t i = 0; i < m; ++i)
    with_copies.push_back(points[i]);
  const Faces dt_faces = delaunay_faces<K>(points);
  {
    Scope scope("the DT of the distinct points, copies unused");
    const DFP::Statistics s = run<DT>(with_copies, dt_faces);
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.points_unused == m);
    DFP_CHECK(s.duplicate_points == m);
    DFP_CHECK(s.faces_certified == s.faces_in);
  }
  {
    Scope scope("the DT using the copies (larger indices) instead of the originals");
    Faces faces = dt_faces;
    for(Face& f : faces)
      for(std::size_t& i : f)
        if(i < m)
          i += n;
    const DFP::Statistics s = run<DT>(with_copies, faces); // info must be the smaller index
    DFP_CHECK(!s.fell_back);
    DFP_CHECK(s.points_unused == m);
    DFP_CHECK(s.duplicate_points == m);
    DFP_CHECK(s.faces_certified == s.faces_in);
  }
  {
    Scope scope("the DT using originals in some faces and copies in others");
    Faces faces = dt_faces;
    for(std::size_t k = 0; k < faces.size(); k += 2)
      for(std::size_t& i : faces[k])
        if(i < m)
          i += n;
    run<DT>(with_copies, faces);
  }
  {
    Scope scope("a face whose distinct indices are equal points");
    Faces faces = dt_faces;
    faces.push_back({0, n, 5}); // points 0 and n are equal
    run<DT>(with_copies, faces);
  }
  {
    Scope scope("copies interleaved, random order, DT prediction with any copy");
    const Points shuffled_copies = [&] {
      Points p = with_copies;
      shuffle(p, rng);
      return p;
    }();
    run<DT>(shuffled_copies, delaunay_faces<K>(shuffled_copies));
  }
}

// Face containers: any range of triples with operator[], signed or unsigned indices.
void test_containers(const Points& points)
{
  const Faces faces = delaunay_faces<K>(points);
  using DT = DT_with_info<K>;
  {
    Scope scope("std::vector<std::array<int, 3>>");
    std::vector<std::array<int, 3>> f;
    for(const Face& t : faces)
      f.push_back({int(t[0]), int(t[1]), int(t[2])});
    const DFP::Statistics s = run<DT>(points, f, faces);
    DFP_CHECK(!s.fell_back && s.faces_certified == faces.size());
  }
  {
    Scope scope("std::vector<std::vector<unsigned>>");
    std::vector<std::vector<unsigned>> f;
    for(const Face& t : faces)
      f.push_back({unsigned(t[2]), unsigned(t[1]), unsigned(t[0])});
    const DFP::Statistics s = run<DT>(points, f, faces);
    DFP_CHECK(!s.fell_back && s.faces_certified == faces.size());
  }
  {
    Scope scope("std::list<std::array<long long, 3>>, std::deque of points");
    std::list<std::array<long long, 3>> f;
    for(const Face& t : faces)
      f.push_back({(long long)t[0], (long long)t[1], (long long)t[2]});
    const std::deque<Point> p(points.begin(), points.end());
    const DFP::Statistics s = run<DT>(p, f, faces);
    DFP_CHECK(!s.fell_back && s.faces_certified == faces.size());
  }
  {
    Scope scope("std::vector<std::array<std::uint16_t, 3>> (small indices)");
    const Points few(points.begin(), points.begin() + 200);
    const Faces few_faces = delaunay_faces<K>(few);
    std::vector<std::array<std::uint16_t, 3>> f;
    for(const Face& t : few_faces)
      f.push_back({std::uint16_t(t[0]), std::uint16_t(t[1]), std::uint16_t(t[2])});
    const DFP::Statistics s = run<DT>(few, f, few_faces);
    DFP_CHECK(!s.fell_back && s.faces_certified == few_faces.size());
  }
}

// Vertex bases that are not an index holder: a user's vertex base derived from CGAL's, and
// info() of a type not assignable from an index. The result is exact, the members untouched.
void test_other_vertex_bases(const Points& points, CGAL::Random& rng)
{
  const Faces faces = flipped_delaunay_faces<K>(points, 20, rng);
  {
    Scope scope("vertex base derived from CGAL's, with a color");
    const DFP::Statistics s = run<DT_colored<K>>(points, faces);
    DFP_CHECK(!s.fell_back);
    DT_colored<K> dt;
    DFP::delaunay_from_prediction(points, faces, dt);
    bool colors = true;
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      colors = colors && v->color == 7;
    DFP_CHECK(colors);
    DFP::delaunay_from_prediction(points, Faces(), dt); // fallback path
    check_is_cgal_delaunay(dt, points);
  }
  {
    Scope scope("info() of a type not assignable from an index");
    run<DT_labeled<K>>(points, faces);
    DT_labeled<K> dt;
    for(const Faces& f : {faces, Faces(), delaunay_faces<K>(Points(points.begin(), points.begin() + 100))}) {
      DFP::delaunay_from_prediction(points, f, dt);
      check_is_cgal_delaunay(dt, points);
      bool labels = true;
      for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
        labels = labels && v->info().value == -3;
      DFP_CHECK(labels);
    }
  }
}

template <class DT>
void test_all(const char* dt_name, const XYs& xy, CGAL::Random& rng)
{
  Scope scope(dt_name);
  const Points points = to_points<K>(xy);
  DFP_RUN(test_good_predictions<DT>(points, rng));
  DFP_RUN(test_bad_predictions<DT>(points, xy, rng));
  DFP_RUN(test_subsets_and_duplicates<DT>(points, rng));
  DFP_RUN(test_double_cover<DT>());
  DFP_RUN(test_random_corruptions<DT>(rng));
}

// operator<< of Statistics: the five main members always, other counts only when not 0, the
// reason when the call fell back; every value as the member holds it.
void test_statistics_stream(const Points& points)
{
  CGAL::Random rng(25); // its own: the tests after it keep their random draws
  auto text_of = [](const DFP::Statistics& s) {
    std::ostringstream out;
    out << s;
    return out.str();
  };
  auto has_line = [](const std::string& text, const std::string& line) {
    return text.find(line + "\n") != std::string::npos &&
           (text.compare(0, line.size() + 1, line + "\n") == 0 || text.find("\n" + line + "\n") != std::string::npos);
  };
  const Faces dt_faces = faces_by_info(indexed_delaunay<K>(points));
  const DFP::Statistics good = run<DT_with_info<K>>(points, shuffled(dt_faces, rng));
  const std::string text = text_of(good);
  DFP_CHECK_MSG(has_line(text, "faces_in: " + std::to_string(dt_faces.size())), text);
  DFP_CHECK_MSG(has_line(text, "faces_certified: " + std::to_string(good.faces_certified)), text);
  DFP_CHECK_MSG(has_line(text, "flips: 0"), text);
  DFP_CHECK_MSG(has_line(text, "fell_back: false"), text);
  DFP_CHECK_MSG(has_line(text, "edges_tested: " + std::to_string(good.edges_tested)), text);
  DFP_CHECK_MSG(text.find("regions:") == std::string::npos && text.find("outcome") == std::string::npos, text);
  DFP::Statistics bad;
  bad.fell_back = true;
  bad.regions = 7;
  bad.outcome = DFP::Outcome::degenerate_face;
  const std::string bad_text = text_of(bad);
  DFP_CHECK_MSG(has_line(bad_text, "fell_back: true") && has_line(bad_text, "regions: 7") &&
                    has_line(bad_text, "outcome: a face is degenerate (its points are collinear or equal)"),
                bad_text);
  DFP_CHECK_MSG(bad_text.find("edges_tested") == std::string::npos, bad_text);
}

int main()
{
  CGAL::Random rng(20260101);
  {
    Scope scope("uniform, n = 3000");
    const XYs xy = uniform_points(3000, rng);
    test_all<DT_with_info<K>>("DT with size_t info", xy, rng);
    test_all<DT_plain<K>>("DT without info", xy, rng);
    DFP_RUN(test_containers(to_points<K>(xy)));
    DFP_RUN(test_other_vertex_bases(to_points<K>(xy), rng));
    DFP_RUN(test_statistics_stream(to_points<K>(xy)));
  }
  {
    Scope scope("clustered, n = 3000");
    const XYs xy = clustered_points(3000, rng);
    test_all<DT_with_info<K, int>>("DT with int info", xy, rng);
  }
  {
    Scope scope("uniform, n = 40");
    test_all<DT_with_info<K>>("DT with size_t info", uniform_points(40, rng), rng);
  }
  return finish("test_predictions");
}
