// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Malformed input to delaunay_from_prediction(): an index out of range (== n, > n, negative,
// huge unsigned), a face repeating an index, a NaN or infinite coordinate in any point (used
// or not). Each throws Invalid_prediction (a std::invalid_argument) whose what() names the face
// number and the offending index (or the point), and leaves the caller's triangulation (pre-filled
// with another triangulation) and containers exactly as they were. Malformed faces are found
// wherever they are: after a face that already makes the prediction unusable, last in the list,
// and when the sampling screen rejects the prediction first (n >= 4096).
// make_delaunay() and split_delaunay() on a triangulation one of whose vertices was moved to a
// NaN or infinite point: Invalid_prediction naming the vertex, the triangulation unchanged
// (Epick, Simple_cartesian<double>, and Epeck, whose exact value of a NaN would raise SIGFPE).

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_prediction/split.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <cstring>
#include <limits>

using namespace dfp_test;

// Same coordinates, bit for bit (NaN equal to the same NaN).
template <class Point>
bool same_points(const std::vector<Point>& a, const std::vector<Point>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i) {
    const double c[2] = {CGAL::to_double(a[i].x()), CGAL::to_double(a[i].y())};
    const double d[2] = {CGAL::to_double(b[i].x()), CGAL::to_double(b[i].y())};
    if(std::memcmp(c, d, sizeof c) != 0)
      return false;
    if(c[0] == c[0] && c[1] == c[1] && std::isfinite(c[0]) && std::isfinite(c[1]) && !(a[i] == b[i]))
      return false;
  }
  return true;
}

// Expects delaunay_from_prediction(points, faces, dt) to throw Invalid_prediction whose
// message mentions every number in `mentioned`, and to change nothing.
template <class DT, class Point, class FaceRange>
void expect_invalid(const std::vector<Point>& points, const FaceRange& faces,
                    const std::vector<long long>& mentioned, const std::string& mentioned_text = "")
{
  // dt holds an unrelated triangulation, with info where it has one.
  DT dt;
  {
    CGAL::Random rng(7);
    for(int i = 0; i < 20; ++i) {
      const auto v = dt.insert(make_point<typename DT::Geom_traits>(rng.get_double(5., 6.), rng.get_double(5., 6.)));
      if constexpr(has_vertex_info<DT>)
        v->info() = 1000 + i;
    }
  }
  const Snapshot<DT> before(dt);
  const std::vector<Point> points_copy = points;
  const FaceRange faces_copy = faces;
  bool thrown = false;
  try {
    DFP::delaunay_from_prediction(points, faces, dt);
  } catch(const DFP::Invalid_prediction& e) {
    thrown = true;
    const std::string what = e.what();
    for(long long number : mentioned)
      DFP_CHECK_MSG(mentions_number(what, number), number << " not in: " << what);
    if(!mentioned_text.empty())
      DFP_CHECK_MSG(what.find(mentioned_text) != std::string::npos, mentioned_text << " not in: " << what);
    const std::invalid_argument* base = &e; // the documented base class
    DFP_CHECK(base != nullptr);
  } catch(const std::exception& e) {
    DFP_CHECK_MSG(false, "threw something other than Invalid_prediction: " << e.what());
  }
  DFP_CHECK(thrown);
  check_unchanged(dt, before);
  DFP_CHECK(dt.is_valid());
  DFP_CHECK(same_points(points, points_copy));
  DFP_CHECK(faces == faces_copy);
}

template <class DT, class Point, class FaceRange>
void expect_invalid_unsigned(const std::vector<Point>& points, const FaceRange& faces,
                             std::size_t face, unsigned long long index)
{
  // what() must contain the face number and the (unsigned) index.
  DT dt;
  dt.insert(make_point<typename DT::Geom_traits>(7., 7.));
  dt.insert(make_point<typename DT::Geom_traits>(8., 7.));
  dt.insert(make_point<typename DT::Geom_traits>(7., 9.));
  const Snapshot<DT> before(dt);
  const FaceRange faces_copy = faces;
  bool thrown = false;
  try {
    DFP::delaunay_from_prediction(points, faces, dt);
  } catch(const std::invalid_argument& e) {
    thrown = dynamic_cast<const DFP::Invalid_prediction*>(&e) != nullptr;
    const std::string what = e.what();
    DFP_CHECK_MSG(mentions_number(what, face) && mentions_number(what, index), what);
  }
  DFP_CHECK(thrown);
  check_unchanged(dt, before);
  DFP_CHECK(faces == faces_copy);
}

template <class K, class I>
std::vector<std::array<I, 3>> as_type(const Faces& faces)
{
  std::vector<std::array<I, 3>> out;
  for(const Face& f : faces)
    out.push_back({I(f[0]), I(f[1]), I(f[2])});
  return out;
}

template <class K, class DT>
void test_indices(CGAL::Random& rng)
{
  using Point = typename K::Point_2;
  const std::size_t n = 50;
  const std::vector<Point> points = to_points<K>(uniform_points(n, rng));
  const Faces good = delaunay_faces<K>(points);
  const long long N = (long long)n;
  using F = std::vector<std::array<int, 3>>;
  auto with_face = [&](std::size_t at, std::array<int, 3> bad) {
    F faces = as_type<K, int>(good);
    faces[at] = bad;
    return faces;
  };
  {
    Scope s("index == n");
    expect_invalid<DT>(points, with_face(7, {3, int(n), 5}), {7, N});
  }
  {
    Scope s("index > n, in position 2");
    expect_invalid<DT>(points, with_face(11, {3, 4, int(n) + 13}), {11, N + 13});
  }
  {
    Scope s("negative index");
    expect_invalid<DT>(points, with_face(9, {-1, 3, 4}), {9, -1});
  }
  {
    Scope s("most negative int");
    expect_invalid<DT>(points, with_face(12, {2, (std::numeric_limits<int>::min)(), 4}),
                       {12, (long long)(std::numeric_limits<int>::min)()});
  }
  {
    Scope s("face repeating an index");
    expect_invalid<DT>(points, with_face(14, {6, 21, 6}), {14, 6});
  }
  {
    Scope s("face with one index three times");
    expect_invalid<DT>(points, with_face(3, {17, 17, 17}), {3, 17});
  }
  {
    Scope s("bad face last, after faces that already make the prediction unusable");
    F faces = as_type<K, int>(random_triples(n, 40, rng));
    faces.push_back({1, 2, int(n) + 100});
    expect_invalid<DT>(points, faces, {40, N + 100});
  }
  {
    Scope s("bad face last in a good prediction");
    F faces = as_type<K, int>(good);
    faces.push_back({8, 8, 9});
    expect_invalid<DT>(points, faces, {(long long)good.size(), 8});
  }
  {
    Scope s("huge unsigned index (size_t)");
    auto faces = as_type<K, std::size_t>(good);
    faces[5][1] = std::size_t(-1);
    expect_invalid_unsigned<DT>(points, faces, 5, (unsigned long long)std::size_t(-1));
  }
  {
    Scope s("unsigned index 2^32 - 1 (the 32-bit sentinel)");
    auto faces = as_type<K, std::uint32_t>(good);
    faces[6][0] = 0xFFFFFFFFu;
    expect_invalid_unsigned<DT>(points, faces, 6, 0xFFFFFFFFull);
  }
  {
    Scope s("size_t index 2^32 + 3 (aliases point 3 in 32 bits)");
    auto faces = as_type<K, std::size_t>(good);
    faces[8][2] = (std::size_t(1) << 32) + 3;
    expect_invalid_unsigned<DT>(points, faces, 8, (1ull << 32) + 3);
  }
  {
    Scope s("valid call after the failures works");
    DT dt;
    DFP::delaunay_from_prediction(points, good, dt);
    check_is_cgal_delaunay(dt, points);
  }
}

template <class K, class DT>
void test_non_finite(CGAL::Random& rng)
{
  using Point = typename K::Point_2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = 60;
  std::vector<Point> points = to_points<K>(uniform_points(n, rng));
  const Faces good = delaunay_faces<K>(points);
  {
    Scope s("NaN x in a point no face uses");
    std::vector<Point> p = points;
    p.push_back(make_point<K>(nan, 0.5));
    expect_invalid<DT>(p, good, {(long long)n});
  }
  {
    Scope s("NaN y in a used point");
    std::vector<Point> p = points;
    p[23] = make_point<K>(0.5, nan);
    expect_invalid<DT>(p, good, {23});
  }
  {
    Scope s("+infinity in a used point");
    std::vector<Point> p = points;
    p[31] = make_point<K>(inf, 0.25);
    expect_invalid<DT>(p, good, {31}, "inf");
  }
  {
    Scope s("-infinity in a point no face uses, empty face list");
    std::vector<Point> p = points;
    p[44] = make_point<K>(0.25, -inf);
    expect_invalid<DT>(p, Faces(), {44}, "inf");
  }
  {
    Scope s("NaN and a bad face together");
    std::vector<Point> p = points;
    p[2] = make_point<K>(nan, nan);
    Faces faces = good;
    faces[0] = {0, 0, 1};
    DT dt;
    bool thrown = false;
    try {
      DFP::delaunay_from_prediction(p, faces, dt);
    } catch(const DFP::Invalid_prediction&) {
      thrown = true;
    }
    DFP_CHECK(thrown);
    DFP_CHECK(dt.number_of_vertices() == 0);
  }
}

// A vertex of `tr` moved to (x, y) with a non-finite coordinate: make_delaunay() and
// split_delaunay() throw naming its rank in finite-vertex order, before anything changes.
// Compared with a snapshot taken with the vertex at its old point, then put back (a NaN point
// equals no point, not even itself).
template <class Tr>
void expect_non_finite_vertex(Tr& tr, std::size_t rank, double x, double y, bool parallel)
{
  using Point = typename Tr::Point;
  auto v = tr.finite_vertices_begin();
  std::advance(v, std::ptrdiff_t(rank));
  const Point old = v->point();
  const Snapshot<Tr> before(tr);
  v->set_point(make_point<typename Tr::Geom_traits>(x, y));
  auto expect_throw = [&](const char* call, auto&& f) {
    bool thrown = false;
    try {
      f();
    } catch(const DFP::Invalid_prediction& e) {
      thrown = true;
      DFP_CHECK_MSG(mentions_number(std::string(e.what()), rank) && std::strstr(e.what(), "non-finite") != nullptr,
                    call << ": " << e.what());
    }
    DFP_CHECK_MSG(thrown, call << " did not throw for vertex " << rank);
  };
  expect_throw("make_delaunay", [&] {
    if(parallel)
      DFP::make_delaunay<CGAL::Parallel_if_available_tag>(tr);
    else
      DFP::make_delaunay(tr);
  });
  if constexpr(std::is_same<Tr, CGAL::Delaunay_triangulation_2<typename Tr::Geom_traits>>::value) {
    Tr first, second;
    first.insert(Point(5, 5)); // must stay as it is
    expect_throw("split_delaunay", [&] { DFP::split_delaunay(tr, [](auto) { return true; }, first, second); });
    DFP_CHECK(first.number_of_vertices() == 1 && second.number_of_vertices() == 0);
  }
  DFP_CHECK(!DFP::internal::is_finite_point(v->point())); // still where the caller put it
  v->set_point(old);
  check_unchanged(tr, before);
}

template <class Tr>
void test_non_finite_vertices(const char* name, CGAL::Random& rng)
{
  Scope scope(name, ": a vertex moved to a non-finite point");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  using K = typename Tr::Geom_traits;
  const auto points = to_points<K>(uniform_points(400, rng));
  for(const bool parallel : {false, true}) {
    Tr tr;
    tr.insert(points.begin(), points.end());
    expect_non_finite_vertex(tr, 0, nan, 0.5, parallel);
    expect_non_finite_vertex(tr, 123, 0.5, nan, parallel);
    expect_non_finite_vertex(tr, 399, inf, 0.25, parallel);
    expect_non_finite_vertex(tr, 200, 0.25, -inf, parallel);
    // Moved points elsewhere too (the repair would have work to do): still checked first.
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      v->set_point(make_point<K>(CGAL::to_double(v->point().x()) + rng.get_double(-0.05, 0.05),
                                 CGAL::to_double(v->point().y())));
    expect_non_finite_vertex(tr, 7, nan, nan, parallel);
  }
}

// n >= 4096: the sampling screen may reject the prediction before the full check; the
// malformed face must still be reported.
template <class K, class DT>
void test_screened(CGAL::Random& rng)
{
  using Point = typename K::Point_2;
  const std::size_t n = 5000;
  const std::vector<Point> points = to_points<K>(uniform_points(n, rng));
  {
    Scope s("random triples (screen rejects), bad index in the last face");
    std::vector<std::array<int, 3>> faces = as_type<K, int>(random_triples(n, 2 * n, rng));
    faces.back() = {4, int(n) + 7, 9};
    expect_invalid<DT>(points, faces, {(long long)(2 * n - 1), (long long)n + 7});
  }
  {
    Scope s("random triples (screen rejects), repeated index in face 1234");
    std::vector<std::array<int, 3>> faces = as_type<K, int>(random_triples(n, 2 * n, rng));
    faces[1234] = {77, 3, 77};
    expect_invalid<DT>(points, faces, {1234, 77});
  }
  {
    Scope s("DT, every other face out of range");
    std::vector<std::array<int, 3>> faces = as_type<K, int>(delaunay_faces<K>(points));
    for(std::size_t k = 1; k < faces.size(); k += 2)
      faces[k][0] = -5;
    expect_invalid<DT>(points, faces, {1, -5});
  }
}

template <class K>
void test_kernel(const char* name, bool finite_checks)
{
  Scope scope(name);
  CGAL::Random rng(99);
  DFP_RUN((test_indices<K, DT_with_info<K>>(rng)));
  if(finite_checks) { // the double kernels: also without info, and non-finite coordinates
    DFP_RUN((test_indices<K, DT_plain<K>>(rng)));
    DFP_RUN((test_non_finite<K, DT_with_info<K>>(rng)));
    DFP_RUN((test_non_finite<K, DT_plain<K>>(rng)));
  }
}

int main()
{
  // Non-finite coordinates in the point ranges: kernels with double coordinates (Epeck
  // below, in a build without CGAL's assertions; Gmpq cannot represent them).
  test_kernel<CGAL::Exact_predicates_inexact_constructions_kernel>("Epick", true);
  test_kernel<CGAL::Simple_cartesian<double>>("Simple_cartesian<double>", true);
  test_kernel<CGAL::Exact_predicates_exact_constructions_kernel>("Epeck", false);
  test_kernel<CGAL::Simple_cartesian<CGAL::Gmpq>>("Simple_cartesian<Gmpq>", false);
  {
    CGAL::Random rng(17);
    using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
    DFP_RUN(test_non_finite_vertices<DT_with_info<Epick>>("Epick, Delaunay_triangulation_2 with info", rng));
    DFP_RUN(test_non_finite_vertices<CGAL::Delaunay_triangulation_2<Epick>>("Epick, Delaunay_triangulation_2", rng));
    DFP_RUN(test_non_finite_vertices<T2_plain<Epick>>("Epick, Triangulation_2", rng));
    DFP_RUN(test_non_finite_vertices<CGAL::Delaunay_triangulation_2<CGAL::Simple_cartesian<double>>>(
        "Simple_cartesian<double>", rng));
#if defined(NDEBUG) || defined(CGAL_NDEBUG)
    // Epeck holds a NaN or an infinity made from a double as its interval (with CGAL's
    // assertions on, the interval itself refuses it): the package must never ask for its
    // exact value, which would raise SIGFPE in GMP.
    using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
    DFP_RUN(test_non_finite_vertices<CGAL::Delaunay_triangulation_2<Epeck>>("Epeck", rng));
    {
      Scope s("Epeck, delaunay_from_prediction, NaN in point 9"); // the points compared by hand:
      std::vector<Epeck::Point_2> p = to_points<Epeck>(uniform_points(40, rng)); // an exact
      const Faces good = delaunay_faces<Epeck>(p);                  // comparison would raise SIGFPE
      p[9] = make_point<Epeck>(std::numeric_limits<double>::quiet_NaN(), 0.5);
      DT_with_info<Epeck> dt;
      dt.insert(Epeck::Point_2(1, 2));
      bool thrown = false;
      try {
        DFP::delaunay_from_prediction(p, good, dt);
      } catch(const DFP::Invalid_prediction& e) {
        thrown = mentions_number(std::string(e.what()), 9);
      }
      DFP_CHECK(thrown && dt.number_of_vertices() == 1);
    }
#endif
  }
  {
    Scope scope("Epick, n = 5000");
    CGAL::Random rng(5);
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    DFP_RUN((test_screened<K, DT_with_info<K>>(rng)));
  }
  return finish("test_bad_input");
}
