// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Shared helpers of the tests: an always-on check macro (tests are built in Release, where
// assert and CGAL_assertion vanish), point sets, predictions, and the oracle: CGAL's own
// Delaunay_triangulation_2 built from scratch on the same points with the same traits,
// compared face by face (by coordinates, and by point indices where vertices carry info).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_TEST_UTIL_H
#define CGAL_DELAUNAY_FROM_PREDICTION_TEST_UTIL_H

#include <CGAL/Delaunay_from_prediction_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#if defined(__unix__) || defined(__APPLE__)
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace dfp_test {

// ---------------------------------------------------------------------------------------------
// Checks
// ---------------------------------------------------------------------------------------------

inline int& failures()
{
  static int count = 0;
  return count;
}

inline std::vector<std::string>& scopes()
{
  static std::vector<std::string> stack;
  return stack;
}

inline std::string where()
{
  std::string s;
  for(const std::string& scope : scopes())
    s += (s.empty() ? "" : " / ") + scope;
  return s;
}

// Names the case being tested; failures print the stack of names.
struct Scope
{
  template <class... T>
  explicit Scope(const T&... parts)
  {
    std::ostringstream out;
    (out << ... << parts);
    scopes().push_back(out.str());
  }
  ~Scope() { scopes().pop_back(); }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;
};

inline bool report_failure(const char* file, int line, const char* expression, const std::string& note)
{
  ++failures();
  std::cerr << file << ":" << line << ": CHECK FAILED: " << expression;
  if(!note.empty())
    std::cerr << " (" << note << ")";
  std::cerr << "\n    in: " << where() << std::endl;
  return false;
}

// Returns 0 if no check failed; prints a summary.
inline int finish(const char* test_name)
{
  if(failures() == 0) {
    std::cout << test_name << ": all checks passed" << std::endl;
    return 0;
  }
  std::cerr << test_name << ": " << failures() << " check(s) FAILED" << std::endl;
  return 1;
}

// True if body() throws an E; false if it returns or throws anything else.
template <class E, class F>
bool throws_exception(const F& body)
{
  try {
    body();
  } catch(const E&) {
    return true;
  } catch(...) {
    return false;
  }
  return false;
}

// The message of the E that body() throws, or "(no exception)" if it returns; anything else
// thrown propagates.
template <class E, class F>
std::string exception_message(const F& body)
{
  try {
    body();
  } catch(const E& e) {
    return e.what();
  }
  return "(no exception)";
}

// Runs `body` in a child process, where a crash (a signal: a division by zero, a null
// dereference, a CGAL assertion) cannot take the whole test down; true if it returned or
// threw std::invalid_argument. Where fork() is not available, runs it here.
template <class F>
bool survives(const F& body)
{
#if defined(__unix__) || defined(__APPLE__)
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if(child == 0) {
    int code = 0;
    try {
      body();
    } catch(const std::invalid_argument&) { // Invalid_prediction included: a normal answer
    } catch(...) { // a CGAL assertion (in a debug build), or anything unexpected
      code = 2;
    }
    std::_Exit(code);
  }
  if(child < 0)
    return true; // could not fork: not a failure of the code under test
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
#else
  body();
  return true;
#endif
}

} // namespace dfp_test

// Always-on check (also in Release builds): prints file:line, the expression and the case.
#define DFP_CHECK(expr)                                                                          \
  ((expr) ? true : ::dfp_test::report_failure(__FILE__, __LINE__, #expr, std::string()))

#define DFP_CHECK_MSG(expr, msg)                                                                 \
  ((expr) ? true : ::dfp_test::report_failure(__FILE__, __LINE__, #expr, [&] {                 \
    std::ostringstream note_;                                                                    \
    note_ << msg;                                                                                \
    return note_.str();                                                                          \
  }()))

// Runs a test body, turning an unexpected exception into a failure.
#define DFP_RUN(body)                                                                            \
  do {                                                                                           \
    try {                                                                                        \
      body;                                                                                      \
    } catch(const std::exception& e) {                                                           \
      ::dfp_test::report_failure(__FILE__, __LINE__, #body, std::string("threw: ") + e.what());  \
    }                                                                                            \
  } while(false)

namespace dfp_test {

namespace DFP = CGAL::Delaunay_from_prediction;

// The ways the tests call delaunay_from_prediction(): each Strategy, and max_flips(0).
enum class Mode {
  defaults, automatic, carve, t_division, regions, flips, rebuild, spanning_tree, section_3, theorem_4_1, theorem_5_4, no_flips
};
// Every Strategy, and every Strategy and max_flips(0).
const Mode strategy_modes[] = {Mode::defaults,      Mode::automatic, Mode::carve,       Mode::t_division,
                               Mode::regions,       Mode::flips,     Mode::rebuild,     Mode::spanning_tree,
                               Mode::section_3,     Mode::theorem_4_1, Mode::theorem_5_4};
const Mode all_modes[] = {Mode::defaults,      Mode::automatic, Mode::carve,       Mode::t_division,
                          Mode::regions,       Mode::flips,     Mode::rebuild,     Mode::spanning_tree,
                          Mode::section_3,     Mode::theorem_4_1, Mode::theorem_5_4, Mode::no_flips};

inline const char* name_of(Mode m)
{
  switch(m) {
  case Mode::defaults: return "no parameter";
  case Mode::automatic: return "automatic";
  case Mode::carve: return "carve";
  case Mode::t_division: return "t_division";
  case Mode::regions: return "regions";
  case Mode::flips: return "flips";
  case Mode::spanning_tree: return "spanning_tree";
  case Mode::section_3: return "section_3";
  case Mode::theorem_4_1: return "theorem_4_1";
  case Mode::theorem_5_4: return "theorem_5_4";
  case Mode::no_flips: return "max_flips(0)";
  default: return "rebuild";
  }
}

// Calls body(np) with the named parameters of the mode (Mode::t_division with `tuning`).
template <class F>
DFP::Statistics with_mode(Mode m, const F& body, const DFP::Tuning& tuning = DFP::Tuning())
{
  namespace P = DFP::parameters;
  switch(m) {
  case Mode::defaults: return body(P::default_values());
  case Mode::automatic: return body(P::strategy(DFP::Strategy::automatic));
  case Mode::carve: return body(P::strategy(DFP::Strategy::carve));
  case Mode::t_division: return body(P::strategy(DFP::Strategy::t_division).tuning(tuning));
  case Mode::regions: return body(P::strategy(DFP::Strategy::regions));
  case Mode::flips: return body(P::strategy(DFP::Strategy::flips));
  case Mode::spanning_tree: return body(P::strategy(DFP::Strategy::spanning_tree));
  case Mode::section_3: return body(P::strategy(DFP::Strategy::section_3));
  case Mode::theorem_4_1: return body(P::strategy(DFP::Strategy::theorem_4_1));
  case Mode::theorem_5_4: return body(P::strategy(DFP::Strategy::theorem_5_4));
  case Mode::no_flips: return body(P::max_flips(std::size_t(0)));
  default: return body(P::strategy(DFP::Strategy::rebuild));
  }
}

// The concurrency the entry points run with: CGAL::Sequential_tag, or
// CGAL::Parallel_if_available_tag with TBB limited to one thread or to two (without TBB the
// tag is CGAL::Sequential_tag and the thread count means nothing).
enum class Concurrency { sequential, parallel_1_thread, parallel_2_threads };
const Concurrency all_concurrencies[] = {Concurrency::sequential, Concurrency::parallel_1_thread,
                                         Concurrency::parallel_2_threads};

inline Concurrency& current_concurrency()
{
  static Concurrency c = Concurrency::sequential;
  return c;
}

inline const char* name_of(Concurrency c)
{
  switch(c) {
  case Concurrency::sequential: return "Sequential_tag";
  case Concurrency::parallel_1_thread: return "Parallel_if_available_tag, 1 thread";
  default: return "Parallel_if_available_tag, 2 threads";
  }
}

// Runs body() with each concurrency in turn (current_concurrency() says which), under a case
// name that says it, with TBB's threads limited as it says.
template <class F>
void for_each_concurrency(const F& body)
{
  for(const Concurrency c : all_concurrencies) {
    Scope scope(name_of(c));
    current_concurrency() = c;
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                c == Concurrency::parallel_2_threads ? 2 : 1);
#endif
    body();
  }
  current_concurrency() = Concurrency::sequential;
}

// Calls call(tag) with the tag of current_concurrency(): a call site writes
// with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr); }).
template <class F>
auto with_concurrency(const F& call)
{
  if(current_concurrency() == Concurrency::sequential)
    return call(CGAL::Sequential_tag());
  return call(CGAL::Parallel_if_available_tag());
}

// How much slower this build runs than an optimized one, for time limits: unoptimized or
// sanitized code (scripts/sanitize.sh: -O0 with ASan and UBSan) runs up to about 20 times slower.
constexpr unsigned time_limit_scale =
#if !defined(__OPTIMIZE__) || defined(__SANITIZE_ADDRESS__)
    20;
#else
    1;
#endif

// Runs `body` in a forked child killed after `seconds` (times time_limit_scale: an endless
// loop is a failure too); its failures are counted here, a crash or a time-out reported as
// one. Where fork() is not available, runs it here.
template <class F>
void isolated(const std::string& what, const F& body, unsigned seconds = 120)
{
  seconds *= time_limit_scale;
#if defined(__unix__) || defined(__APPLE__)
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if(child == 0) {
    alarm(seconds); // an endless loop is killed by SIGALRM
    const int before = failures();
    {
      Scope scope(what);
      DFP_RUN(body());
    }
    std::cout.flush();
    std::cerr.flush();
    std::_Exit(std::min(failures() - before, 100));
  }
  if(child > 0) {
    int status = 0;
    waitpid(child, &status, 0);
    if(WIFEXITED(status)) {
      failures() += WEXITSTATUS(status); // the child printed them
    } else {
      Scope scope(what);
      report_failure(__FILE__, __LINE__, "the group ran to its end",
                     WIFSIGNALED(status) ? (WTERMSIG(status) == SIGALRM
                                                ? std::string("timed out after ") + std::to_string(seconds) + " s"
                                                : "crashed with signal " + std::to_string(WTERMSIG(status)))
                                         : std::string("stopped abnormally"));
    }
    return;
  }
#endif
  Scope scope(what);
  DFP_RUN(body());
}
using Face = std::array<std::size_t, 3>;
using Faces = std::vector<Face>;

// ---------------------------------------------------------------------------------------------
// Triangulation types
// ---------------------------------------------------------------------------------------------

template <class K, class Info>
using Tds_with_info =
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<Info, K>,
                                         CGAL::Triangulation_face_base_2<K>>;
template <class K, class Info = std::size_t>
using DT_with_info = CGAL::Delaunay_triangulation_2<K, Tds_with_info<K, Info>>;
template <class K>
using DT_plain = CGAL::Delaunay_triangulation_2<K>;
template <class K, class Info = std::size_t>
using T2_with_info = CGAL::Triangulation_2<K, Tds_with_info<K, Info>>;
template <class K>
using T2_plain = CGAL::Triangulation_2<K>;

// A user's own vertex base, derived from CGAL's, with a member that is not an index.
template <class Gt, class Vb = CGAL::Triangulation_vertex_base_2<Gt>>
struct Colored_vertex_base : Vb
{
  template <class Tds2>
  struct Rebind_TDS
  {
    using Vb2 = typename Vb::template Rebind_TDS<Tds2>::Other;
    using Other = Colored_vertex_base<Gt, Vb2>;
  };
  using Vb::Vb;
  int color = 7;
};

template <class K>
using DT_colored = CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<Colored_vertex_base<K>, CGAL::Triangulation_face_base_2<K>>>;
template <class K>
using T2_colored = CGAL::Triangulation_2<
    K, CGAL::Triangulation_data_structure_2<Colored_vertex_base<K>, CGAL::Triangulation_face_base_2<K>>>;

// Vertex info that is not assignable from an index: left alone.
struct Label
{
  int value = -3;
};
template <class K>
using DT_labeled = DT_with_info<K, Label>;

// Vertex info that holds a point index (an integer).
template <class V, class = void>
struct has_index_info : std::false_type {};
template <class V>
struct has_index_info<V, std::enable_if_t<std::is_integral<std::decay_t<decltype(std::declval<V&>().info())>>::value>>
    : std::true_type {};

template <class Tr>
constexpr bool has_vertex_info = has_index_info<typename Tr::Vertex>::value;

// ---------------------------------------------------------------------------------------------
// Point sets, generated in double (exactly representable in every kernel), then converted.
// ---------------------------------------------------------------------------------------------

struct XY
{
  double x, y;
};
using XYs = std::vector<XY>;

template <class K>
typename K::Point_2 make_point(double x, double y)
{
  return typename K::Point_2(typename K::FT(x), typename K::FT(y));
}

template <class K>
std::vector<typename K::Point_2> to_points(const XYs& xy)
{
  std::vector<typename K::Point_2> points;
  points.reserve(xy.size());
  for(const XY& p : xy)
    points.push_back(make_point<K>(p.x, p.y));
  return points;
}

template <class T>
void shuffle(std::vector<T>& v, CGAL::Random& rng)
{
  for(std::size_t i = v.size(); i > 1; --i)
    std::swap(v[i - 1], v[std::size_t(rng.get_int(0, int(i)))]);
}

// Labels 0..n-1 with the points of `chosen` permuted among themselves at random: faces or
// edges relabelled with it cross each other at those points (Corollary 3.5).
inline std::vector<std::size_t> permuted_among(std::size_t n, const std::vector<std::size_t>& chosen,
                                               CGAL::Random& rng)
{
  std::vector<std::size_t> label(n);
  for(std::size_t i = 0; i < n; ++i)
    label[i] = i;
  std::vector<std::size_t> moved = chosen;
  shuffle(moved, rng);
  for(std::size_t k = 0; k < chosen.size(); ++k)
    label[chosen[k]] = moved[k];
  return label;
}

// `faces` with about one point in `one_in + 1` of 0..n-1 permuted among the chosen ones: long
// wrong edges and faces that cross each other.
inline Faces with_points_relabelled(Faces faces, std::size_t n, int one_in, CGAL::Random& rng)
{
  std::vector<std::size_t> chosen;
  for(std::size_t i = 0; i < n; ++i)
    if(rng.get_int(0, one_in) == 0)
      chosen.push_back(i);
  const std::vector<std::size_t> label = permuted_among(n, chosen, rng);
  for(Face& f : faces)
    for(auto& v : f)
      v = label[v];
  return faces;
}

// A path through the points 0..n-1 in random order, as index pairs.
inline std::vector<std::pair<std::size_t, std::size_t>> random_path(std::size_t n, CGAL::Random& rng)
{
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  shuffle(order, rng);
  std::vector<std::pair<std::size_t, std::size_t>> path;
  for(std::size_t k = 1; k < n; ++k)
    path.emplace_back(order[k - 1], order[k]);
  return path;
}

inline XYs uniform_points(std::size_t n, CGAL::Random& rng, double lo = 0., double hi = 1.)
{
  XYs xy(n);
  for(XY& p : xy)
    p = {rng.get_double(lo, hi), rng.get_double(lo, hi)};
  return xy;
}

inline double gaussian(CGAL::Random& rng)
{
  double u = rng.get_double(1e-12, 1.);
  double v = rng.get_double(0., 1.);
  return std::sqrt(-2. * std::log(u)) * std::cos(6.283185307179586 * v);
}

// Gaussian blobs of very different spreads.
inline XYs clustered_points(std::size_t n, CGAL::Random& rng, int blobs = 8)
{
  std::vector<XY> centers(blobs);
  std::vector<double> sigma(blobs);
  for(int b = 0; b < blobs; ++b) {
    centers[b] = {rng.get_double(0., 1.), rng.get_double(0., 1.)};
    sigma[b] = std::pow(10., rng.get_double(-4., -1.));
  }
  XYs xy(n);
  for(std::size_t i = 0; i < n; ++i) {
    const int b = rng.get_int(0, blobs);
    xy[i] = {centers[b].x + sigma[b] * gaussian(rng), centers[b].y + sigma[b] * gaussian(rng)};
  }
  return xy;
}

// Integer grid w x h, shuffled: every unit square is a co-circular 4-tuple.
inline XYs grid_points(int w, int h, CGAL::Random& rng)
{
  XYs xy;
  for(int i = 0; i < w; ++i)
    for(int j = 0; j < h; ++j)
      xy.push_back({double(i), double(j)});
  shuffle(xy, rng);
  return xy;
}

// All integer points on the circle x^2 + y^2 = r^2 (exactly co-circular), plus the lattice
// points of a smaller concentric circle and the centre, shuffled.
inline XYs lattice_circle_points(long r, CGAL::Random& rng, long inner = 0)
{
  XYs xy;
  for(long radius : {r, inner}) {
    if(radius <= 0)
      continue;
    for(long x = -radius; x <= radius; ++x) {
      const long y2 = radius * radius - x * x;
      const long y = std::lround(std::sqrt(double(y2)));
      for(long t : {y - 1, y, y + 1})
        if(t >= 0 && t * t == y2) {
          xy.push_back({double(x), double(t)});
          if(t != 0)
            xy.push_back({double(x), double(-t)});
        }
    }
  }
  xy.push_back({0., 0.});
  shuffle(xy, rng);
  return xy;
}

// n points on the line y = 2x + 1 (exact integer coordinates), shuffled.
inline XYs collinear_points(std::size_t n, CGAL::Random& rng)
{
  XYs xy;
  for(std::size_t i = 0; i < n; ++i)
    xy.push_back({double(i) - double(n / 2), 2. * (double(i) - double(n / 2)) + 1.});
  shuffle(xy, rng);
  return xy;
}

// Appends `copies` exact copies of randomly chosen points, then shuffles everything.
inline XYs with_duplicates(XYs xy, std::size_t copies, CGAL::Random& rng)
{
  const std::size_t n = xy.size();
  for(std::size_t k = 0; k < copies; ++k)
    xy.push_back(xy[std::size_t(rng.get_int(0, int(n)))]);
  shuffle(xy, rng);
  return xy;
}

// Small degenerate sets for a strategy's own test: a grid, lattice points on circles (many
// co-circular), duplicates and collinear points (drawn in this order: braced lists evaluate
// left to right).
inline std::vector<std::pair<const char*, XYs>> small_degenerate_families(CGAL::Random& rng)
{
  return {{"grid", grid_points(40, 40, rng)},
          {"lattice circle", lattice_circle_points(30, rng, 10)},
          {"duplicates", with_duplicates(uniform_points(3000, rng), 300, rng)},
          {"collinear", collinear_points(200, rng)}};
}

inline XYs transformed(XYs xy, double scale, double offset)
{
  for(XY& p : xy)
    p = {p.x * scale + offset, p.y * scale + offset};
  return xy;
}

// Moves every point by up to `amplitude` in each coordinate.
inline XYs jittered(XYs xy, double amplitude, CGAL::Random& rng)
{
  if(!(amplitude > 0.))
    return xy; // CGAL::Random::get_double(a, a) never returns
  for(XY& p : xy)
    p = {p.x + rng.get_double(-amplitude, amplitude), p.y + rng.get_double(-amplitude, amplitude)};
  return xy;
}

// ---------------------------------------------------------------------------------------------
// Predictions (index triples)
// ---------------------------------------------------------------------------------------------

// Finite faces of a triangulation whose vertex info is a point index, ccw.
template <class Tr>
Faces faces_by_info(const Tr& tr)
{
  Faces faces;
  if(tr.dimension() < 2)
    return faces;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    faces.push_back({std::size_t(f->vertex(0)->info()), std::size_t(f->vertex(1)->info()),
                     std::size_t(f->vertex(2)->info())});
  return faces;
}

// CGAL's DT of the points, its vertex info a point index (for duplicates any one of them).
template <class K>
DT_with_info<K> indexed_delaunay(const std::vector<typename K::Point_2>& points)
{
  std::vector<std::pair<typename K::Point_2, std::size_t>> pairs;
  for(std::size_t i = 0; i < points.size(); ++i)
    pairs.emplace_back(points[i], i);
  DT_with_info<K> dt;
  dt.insert(pairs.begin(), pairs.end());
  return dt;
}

template <class K>
Faces delaunay_faces(const std::vector<typename K::Point_2>& points)
{
  return faces_by_info(indexed_delaunay<K>(points));
}

// A plain (non-Delaunay) CGAL::Triangulation_2 of the points, inserted in the given order.
template <class K>
T2_with_info<K> indexed_triangulation(const std::vector<typename K::Point_2>& points)
{
  T2_with_info<K> tr;
  typename T2_with_info<K>::Face_handle hint;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t before = tr.number_of_vertices();
    auto v = tr.insert(points[i], hint);
    if(tr.number_of_vertices() != before)
      v->info() = i;
    hint = v->face();
  }
  return tr;
}

// Flips up to k random interior edges whose quadrilateral is strictly convex (so the result is
// still a triangulation). Returns the number of flips made. An edge a flip created is never
// flipped: it stays, so the edge it replaced, which crosses it, cannot come back, and every flip
// removes an edge of the input for good (k flips of a Delaunay triangulation leave k of its
// edges missing, never the triangulation itself).
template <class Tr>
std::size_t flip_randomly(Tr& tr, std::size_t k, CGAL::Random& rng)
{
  if(tr.dimension() < 2 || k == 0)
    return 0;
  std::vector<typename Tr::Face_handle> faces;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    faces.push_back(f);
  auto orientation = tr.geom_traits().orientation_2_object();
  using Vertex_address = const typename Tr::Vertex*;
  auto edge = [](typename Tr::Vertex_handle u, typename Tr::Vertex_handle v) {
    const Vertex_address a = &*u, b = &*v;
    return std::pair<Vertex_address, Vertex_address>(std::min(a, b), std::max(a, b));
  };
  std::set<std::pair<Vertex_address, Vertex_address>> created;
  std::size_t done = 0;
  for(std::size_t attempt = 0; done < k && attempt < 100 * k + 100; ++attempt) {
    const auto f = faces[std::size_t(rng.get_int(0, int(faces.size())))];
    const int i = rng.get_int(0, 3);
    const auto g = f->neighbor(i);
    if(tr.is_infinite(g))
      continue;
    const auto& a = f->vertex(i)->point();
    const auto& b = f->vertex(tr.ccw(i))->point();
    const auto& c = f->vertex(tr.cw(i))->point();
    const auto opposite = g->vertex(tr.mirror_index(f, i));
    const auto& d = opposite->point();
    if(orientation(a, b, d) != CGAL::LEFT_TURN || orientation(a, d, c) != CGAL::LEFT_TURN)
      continue;
    if(created.count(edge(f->vertex(tr.ccw(i)), f->vertex(tr.cw(i)))) != 0)
      continue;
    created.insert(edge(f->vertex(i), opposite));
    tr.tds().flip(f, i);
    ++done;
  }
  return done;
}

template <class K>
Faces flipped_delaunay_faces(const std::vector<typename K::Point_2>& points, std::size_t k,
                             CGAL::Random& rng, std::size_t* flips_done = nullptr)
{
  auto dt = indexed_delaunay<K>(points);
  const std::size_t done = flip_randomly(dt, k, rng);
  if(flips_done != nullptr)
    *flips_done = done;
  return faces_by_info(dt);
}

inline Faces reversed(Faces faces)
{
  for(Face& f : faces)
    std::swap(f[1], f[2]);
  return faces;
}

inline Faces listed_twice(const Faces& faces)
{
  Faces twice = faces;
  twice.insert(twice.end(), faces.begin(), faces.end());
  return twice;
}

inline Faces shuffled(Faces faces, CGAL::Random& rng)
{
  shuffle(faces, rng);
  for(Face& f : faces) // rotate, keeping the orientation
    std::rotate(f.begin(), f.begin() + rng.get_int(0, 3), f.end());
  return faces;
}

inline Faces with_faces_deleted(Faces faces, std::size_t count, CGAL::Random& rng)
{
  shuffle(faces, rng);
  faces.resize(faces.size() > count ? faces.size() - count : 0);
  return faces;
}

inline Faces random_triples(std::size_t n, std::size_t m, CGAL::Random& rng)
{
  Faces faces;
  if(n < 3)
    return faces;
  while(faces.size() < m) {
    Face f;
    for(std::size_t& i : f)
      i = std::size_t(rng.get_int(0, int(n)));
    if(f[0] != f[1] && f[1] != f[2] && f[0] != f[2])
      faces.push_back(f);
  }
  return faces;
}

// True if the statistics show that a prediction was not used as it is: rebuilt from scratch,
// or repaired locally (faces carved, holes refilled, or at least one round of the repair).
// Whether the call fell back for this outcome, compared with the package's own list of
// reasons: rewording a reason cannot make a test pass or fail vacuously.
inline bool reason_is(const DFP::Statistics& s, DFP::Outcome outcome)
{
  return s.outcome == outcome;
}

inline bool repaired_or_rebuilt(const DFP::Statistics& s)
{
  return s.fell_back || s.faces_carved > 0 || s.holes_refilled > 0 || s.carve_rounds > 0;
}

// Number of distinct indices the faces use.
inline std::size_t used_indices(const Faces& faces)
{
  std::set<std::size_t> used;
  for(const Face& f : faces)
    used.insert(f.begin(), f.end());
  return used.size();
}

// ---------------------------------------------------------------------------------------------
// The oracle: comparison with CGAL's Delaunay_triangulation_2 built from scratch
// ---------------------------------------------------------------------------------------------

// Rotates a cyclic triple so that its smallest element comes first (orientation kept).
template <class T>
std::array<T, 3> canonical(std::array<T, 3> t)
{
  const auto smallest = std::min_element(t.begin(), t.end());
  std::rotate(t.begin(), smallest, t.end());
  return t;
}

template <class Point>
struct Geometry
{
  int dimension = -2;
  std::vector<Point> vertices;               // sorted
  std::vector<std::array<Point, 2>> edges;   // finite edges, endpoints sorted, sorted
  std::vector<std::array<Point, 3>> faces;   // finite faces, ccw, canonical rotation, sorted
};

// The geometry of `tr`, its points read through `to_point` (the identity by default; a
// conversion to another kernel's points compares triangulations across kernels).
template <class Tr, class ToPoint>
auto geometry_of(const Tr& tr, ToPoint to_point)
{
  using Point = std::decay_t<decltype(to_point(std::declval<const typename Tr::Point&>()))>;
  Geometry<Point> g;
  g.dimension = tr.dimension();
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    g.vertices.push_back(to_point(v->point()));
  std::sort(g.vertices.begin(), g.vertices.end());
  if(tr.dimension() >= 1)
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
      std::array<Point, 2> s = {to_point(e->first->vertex(tr.cw(e->second))->point()),
                                to_point(e->first->vertex(tr.ccw(e->second))->point())};
      if(s[1] < s[0])
        std::swap(s[0], s[1]);
      g.edges.push_back(s);
    }
  std::sort(g.edges.begin(), g.edges.end());
  if(tr.dimension() == 2)
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
      g.faces.push_back(canonical(std::array<Point, 3>{
          to_point(f->vertex(0)->point()), to_point(f->vertex(1)->point()), to_point(f->vertex(2)->point())}));
  std::sort(g.faces.begin(), g.faces.end());
  return g;
}

template <class Tr>
Geometry<typename Tr::Point> geometry_of(const Tr& tr)
{
  return geometry_of(tr, [](const typename Tr::Point& p) { return p; });
}

template <class T>
std::size_t count_missing(const std::vector<T>& sorted_a, const std::vector<T>& sorted_b)
{
  std::vector<T> diff;
  std::set_difference(sorted_a.begin(), sorted_a.end(), sorted_b.begin(), sorted_b.end(),
                      std::back_inserter(diff));
  return diff.size();
}

// The smallest index of every distinct point.
template <class Point>
std::map<Point, std::size_t> smallest_indices(const std::vector<Point>& points)
{
  std::map<Point, std::size_t> first;
  for(std::size_t i = 0; i < points.size(); ++i)
    first.emplace(points[i], i);
  return first;
}

// Checks that `tr` is exactly CGAL's Delaunay triangulation of `points` with the traits `Gt`
// (by default those of `tr`): valid, same dimension, vertices, edges and faces (by
// coordinates); and, where the vertices carry info, that each info is the smallest index of
// its point and that the faces agree as index triples. With other traits than those of `tr`
// (the reference for inexact kernels: `CGAL::Epick`, the exact decision on the same doubles)
// the points are compared rounded to double, and validity is that of the data structure, the
// faces' orientation being the reference's. Returns true if everything matched.
template <class Gt = void, class Tr, class Point>
bool check_is_cgal_delaunay(const Tr& tr, const std::vector<Point>& points)
{
  using Ref_gt = std::conditional_t<std::is_void<Gt>::value, typename Tr::Geom_traits, Gt>;
  using Ref_point = typename Ref_gt::Point_2;
  constexpr bool same_traits = std::is_same<Ref_gt, typename Tr::Geom_traits>::value;
  auto to_ref = [](const Point& p) {
    if constexpr(same_traits)
      return p;
    else
      return Ref_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  };
  const int before = failures();
  std::vector<Ref_point> ref_points;
  for(const Point& p : points)
    ref_points.push_back(to_ref(p));
  const CGAL::Delaunay_triangulation_2<Ref_gt> reference(ref_points.begin(), ref_points.end());
  if constexpr(same_traits)
    DFP_CHECK(tr.is_valid());
  else
    DFP_CHECK(tr.tds().is_valid());
  DFP_CHECK_MSG(tr.dimension() == reference.dimension(),
                tr.dimension() << " vs " << reference.dimension());
  DFP_CHECK_MSG(tr.number_of_vertices() == reference.number_of_vertices(),
                tr.number_of_vertices() << " vs " << reference.number_of_vertices());
  const Geometry<Ref_point> got = geometry_of(tr, to_ref), expected = geometry_of(reference);
  DFP_CHECK(got.vertices == expected.vertices);
  DFP_CHECK_MSG(got.edges == expected.edges,
                count_missing(got.edges, expected.edges) << " edges not in CGAL's DT, "
                    << count_missing(expected.edges, got.edges) << " of CGAL's missing");
  DFP_CHECK_MSG(got.faces == expected.faces,
                count_missing(got.faces, expected.faces) << " faces not in CGAL's DT, "
                    << count_missing(expected.faces, got.faces) << " of CGAL's missing (of "
                    << expected.faces.size() << ")");
  if constexpr(has_vertex_info<Tr>) {
    const auto first = smallest_indices(ref_points);
    bool info_ok = true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const auto it = first.find(to_ref(v->point()));
      info_ok = info_ok && it != first.end() && std::size_t(v->info()) == it->second;
    }
    DFP_CHECK_MSG(info_ok, "a vertex info is not the smallest index of its point");
    std::vector<Face> got_faces, expected_faces;
    if(tr.dimension() == 2)
      for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
        got_faces.push_back(canonical(Face{std::size_t(f->vertex(0)->info()),
                                           std::size_t(f->vertex(1)->info()),
                                           std::size_t(f->vertex(2)->info())}));
    if(reference.dimension() == 2)
      for(auto f = reference.finite_faces_begin(); f != reference.finite_faces_end(); ++f)
        expected_faces.push_back(canonical(Face{first.at(f->vertex(0)->point()),
                                                first.at(f->vertex(1)->point()),
                                                first.at(f->vertex(2)->point())}));
    std::sort(got_faces.begin(), got_faces.end());
    std::sort(expected_faces.begin(), expected_faces.end());
    DFP_CHECK(got_faces == expected_faces);
  }
  return failures() == before;
}

// Number of edges of the prediction that are not edges of CGAL's DT (by point indices; the
// points must be distinct). A lower bound on the flips Lawson's algorithm needs, and an upper
// bound on the edges that are not locally Delaunay.
template <class K>
std::size_t edges_not_in_delaunay(const Faces& faces, const std::vector<typename K::Point_2>& points)
{
  const auto dt = indexed_delaunay<K>(points);
  std::set<std::pair<std::size_t, std::size_t>> dt_edges, pred_edges;
  auto key = [](std::size_t a, std::size_t b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for(const Face& f : faces_by_info(dt))
    for(int j = 0; j < 3; ++j)
      dt_edges.insert(key(f[j], f[(j + 1) % 3]));
  for(const Face& f : faces)
    for(int j = 0; j < 3; ++j)
      pred_edges.insert(key(f[j], f[(j + 1) % 3]));
  std::size_t count = 0;
  for(const auto& e : pred_edges)
    count += dt_edges.count(e) == 0 ? 1 : 0;
  return count;
}

// Whether the call built by the prediction's regions (Strategy::regions, no fallback): at
// least two regions, every point inserted, and no edge tested (Strategy::t_division certifies
// first, and reinserts only some points).
inline bool built_by_prediction_regions(const DFP::Statistics& s, std::size_t n)
{
  return !s.fell_back && s.regions >= 2 && s.edges_tested == 0 && s.points_reinserted == n && n > 0;
}

// Whether delaunay_from_prediction() imported the faces Strategy::theorem_4_1 computed (its
// rounds ran and it did not fall back: the other strategies with rounds fall back).
inline bool built_by_theorem_4_1(const DFP::Statistics& s) { return !s.fell_back && s.insertion_rounds > 0; }

// Whether delaunay_from_prediction() imported the completion G' Strategy::theorem_5_4
// computed (it made a guess of d_cross and did not fall back).
inline bool built_by_theorem_5_4(const DFP::Statistics& s) { return !s.fell_back && s.d_cross_guesses > 0; }

// A certified face is a face of the result: at most the predicted faces (as point triples)
// that are faces of DT(points).
template <class DT>
void check_certified_faces_are_in_result(const DFP::Statistics& s, const Faces& faces,
                                         const std::vector<typename DT::Point>& points, const DT& dt)
{
  using Point = typename DT::Point;
  auto orientation = dt.geom_traits().orientation_2_object();
  const Geometry<Point> result = geometry_of(dt);
  std::vector<std::array<Point, 3>> predicted;
  for(const Face& f : faces) {
    std::array<Point, 3> t = {points[f[0]], points[f[1]], points[f[2]]};
    if(orientation(t[0], t[1], t[2]) == CGAL::RIGHT_TURN)
      std::swap(t[1], t[2]);
    predicted.push_back(canonical(t));
  }
  std::sort(predicted.begin(), predicted.end());
  predicted.erase(std::unique(predicted.begin(), predicted.end()), predicted.end());
  const std::size_t in_result = predicted.size() - count_missing(predicted, result.faces);
  DFP_CHECK_MSG(s.faces_certified <= in_result,
                s.faces_certified << " certified, " << in_result << " predicted faces in the result");
}

// Statistics that must hold for any call of delaunay_from_prediction.
//
// When the prediction is not a triangulation, the local repair may carve faces (the importer's
// left-out faces included: degenerate ones, and faces on the same side of an edge as an
// earlier face), refill holes and reinsert the vertices it detached, without falling back.
// Then the relations between flips, failing edges and certified faces of a plain repair by
// flips need not hold, and the points used by no kept face lie between those used by no face
// and those used by no non-degenerate face, plus three per face left out for overlapping.
template <class DT>
void check_statistics(const DFP::Statistics& s, const Faces& faces,
                      const std::vector<typename DT::Point>& points, const DT& dt)
{
  const std::size_t n = points.size();
  DFP_CHECK_MSG(s.faces_in == faces.size(), s.faces_in << " vs " << faces.size());
  DFP_CHECK(s.faces_certified <= s.faces_in);
  DFP_CHECK_MSG(s.duplicate_points + dt.number_of_vertices() == n,
                s.duplicate_points << " duplicates, " << dt.number_of_vertices() << " vertices, "
                                   << n << " points");
  DFP_CHECK_MSG((s.outcome == DFP::Outcome::ok) == !s.fell_back,
                "reason '" << to_string(s.outcome) << "'");
  if(built_by_theorem_4_1(s)) {
    // Strategy::theorem_4_1 imported the faces it computed: the import's counts are of those
    // faces, and the predicted faces kept are at most those that are faces of the result.
    DFP_CHECK(s.supercells > 0 || s.bad_supercells == 0);
    DFP_CHECK(s.bad_supercells <= s.supercells);
    DFP_CHECK(s.faces_certified <= s.faces_in);
  } else if(built_by_theorem_5_4(s)) {
    // Strategy::theorem_5_4 imported its completion G': the import's counts are of G', and
    // the predicted faces kept (those of G' that are G's, less those the repair changed) are
    // faces of the result.
    DFP_CHECK(s.regions_keeping_prediction == 0 || !s.regions_per_level.empty());
    check_certified_faces_are_in_result(s, faces, points, dt);
  } else if(s.fell_back || built_by_prediction_regions(s, n)) {
    DFP_CHECK_MSG(s.points_reinserted == n, s.points_reinserted << " vs " << n);
    DFP_CHECK(s.faces_certified == 0);
    if(!s.fell_back)
      DFP_CHECK_MSG(s.points_unused == n - used_indices(faces), s.points_unused << " unused");
  } else {
    const bool repaired = s.faces_carved > 0 || s.holes_refilled > 0 || s.carve_rounds > 0;
    DFP_CHECK(s.edges_not_locally_delaunay <= s.edges_tested);
    DFP_CHECK_MSG(s.faces_certified + s.faces_carved <= s.faces_in,
                  s.faces_certified << " certified, " << s.faces_carved << " carved, " << s.faces_in << " in");
    DFP_CHECK_MSG(s.carve_rounds > 0 || s.holes_refilled == 0, s.holes_refilled << " holes refilled in 0 rounds");
    // Degenerate faces are never kept.
    auto orientation = dt.geom_traits().orientation_2_object();
    Faces proper;
    for(const Face& f : faces)
      if(orientation(points[f[0]], points[f[1]], points[f[2]]) != CGAL::COLLINEAR)
        proper.push_back(f);
    const std::size_t degenerate = faces.size() - proper.size();
    DFP_CHECK_MSG(s.faces_carved >= degenerate, s.faces_carved << " carved, " << degenerate << " degenerate");
    const std::size_t unused_lo = n - used_indices(faces), unused_hi = n - used_indices(proper);
    const std::size_t overlapping = s.faces_carved >= degenerate ? s.faces_carved - degenerate : 0;
    DFP_CHECK_MSG(s.points_unused >= unused_lo && s.points_unused <= unused_hi + 3 * overlapping,
                  s.points_unused << " unused, expected " << unused_lo << " to " << unused_hi << " + 3 * "
                                  << overlapping);
    // The points used by no kept face, and the vertices left without a face by the carving
    // (each a vertex of a carved face).
    DFP_CHECK_MSG(s.points_reinserted >= s.points_unused &&
                      s.points_reinserted <= s.points_unused + 3 * s.faces_carved,
                  s.points_reinserted << " reinserted, " << s.points_unused << " unused, "
                                      << s.faces_carved << " carved");
    if(!repaired) {
      DFP_CHECK((s.flips == 0) == (s.edges_not_locally_delaunay == 0));
      DFP_CHECK_MSG(s.points_unused == unused_lo, s.points_unused << " vs " << unused_lo);
      DFP_CHECK_MSG(s.points_reinserted == s.points_unused,
                    s.points_reinserted << " reinserted, " << s.points_unused << " unused");
      if(s.points_unused == 0)
        DFP_CHECK(s.faces_certified + 2 * s.flips >= s.faces_in);
      if(s.points_unused == 0 && s.flips == 0)
        DFP_CHECK(s.faces_certified == s.faces_in);
    }
    check_certified_faces_are_in_result(s, faces, points, dt);
  }
}

// ---------------------------------------------------------------------------------------------
// Snapshots: "unchanged" means same vertex objects, info, points and connectivity.
// ---------------------------------------------------------------------------------------------

template <class Tr>
struct Snapshot
{
  using Point = typename Tr::Point;
  int dimension = -2;
  std::size_t number_of_vertices = 0;
  std::vector<const void*> vertices; // finite vertices, in iteration order
  std::vector<Point> points;
  std::vector<long long> infos;
  std::vector<std::array<const void*, 3>> faces; // every face (infinite ones too), sorted

  explicit Snapshot(const Tr& tr)
  {
    dimension = tr.dimension();
    number_of_vertices = tr.number_of_vertices();
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      vertices.push_back(&*v);
      points.push_back(v->point());
      if constexpr(has_vertex_info<Tr>)
        infos.push_back((long long)(v->info()));
    }
    // The face container itself: the face iterators skip the faces of dimension below 2.
    for(auto f = tr.tds().faces().begin(); f != tr.tds().faces().end(); ++f) {
      std::array<const void*, 3> t;
      for(int j = 0; j < 3; ++j)
        t[j] = f->vertex(j) == typename Tr::Vertex_handle() ? nullptr
                                                            : static_cast<const void*>(&*f->vertex(j));
      faces.push_back(tr.dimension() == 2 ? canonical(t) : t);
    }
    std::sort(faces.begin(), faces.end());
  }

  bool operator==(const Snapshot& o) const
  {
    return dimension == o.dimension && number_of_vertices == o.number_of_vertices &&
           vertices == o.vertices && points == o.points && infos == o.infos && faces == o.faces;
  }
};

template <class Tr>
void check_unchanged(const Tr& tr, const Snapshot<Tr>& before)
{
  const Snapshot<Tr> now(tr);
  DFP_CHECK(now.dimension == before.dimension);
  DFP_CHECK(now.number_of_vertices == before.number_of_vertices);
  DFP_CHECK(now.vertices == before.vertices);
  DFP_CHECK(now.points == before.points);
  DFP_CHECK(now.infos == before.infos);
  DFP_CHECK(now.faces == before.faces);
}

// ---------------------------------------------------------------------------------------------
// Vertex handles across make_delaunay
// ---------------------------------------------------------------------------------------------

template <class Tr>
using Handles = std::vector<typename Tr::Vertex_handle>;

// Inserts the points one by one; handle i holds point i (or the vertex of an equal earlier
// point) and, if the vertices have info, info i (the first index of a point). With traits
// whose predicates are not exact, whose insertion can crash or lose almost collinear points,
// the faces are those of CGAL's Epick Delaunay triangulation of the same doubles instead.
template <class Tr>
void insert_all(Tr& tr, const std::vector<typename Tr::Point>& points, Handles<Tr>& handles)
{
  using Vertex_handle = typename Tr::Vertex_handle;
  if constexpr(DFP::internal::decides_by_exact_predicates<typename Tr::Geom_traits>::value) {
    using Aside = DFP::internal::Deciding_dt;
    std::vector<std::pair<Aside::Point, std::size_t>> pairs;
    for(std::size_t i = 0; i < points.size(); ++i)
      pairs.emplace_back(Aside::Point(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y())), i);
    Aside aside;
    std::map<Aside::Point, std::size_t> first;
    for(const auto& [p, i] : pairs)
      first.emplace(p, i);
    aside.insert(pairs.begin(), pairs.end());
    tr.clear();
    std::vector<Vertex_handle> vertex(points.size());
    for(auto v = aside.finite_vertices_begin(); v != aside.finite_vertices_end(); ++v) {
      v->info() = first.at(v->point());
      vertex[v->info()] = tr.tds().create_vertex();
      vertex[v->info()]->set_point(points[v->info()]);
      if constexpr(has_vertex_info<Tr>)
        vertex[v->info()]->info() = v->info();
    }
    DFP::internal::transplant(aside, tr, [&](Aside::Vertex_handle v) {
      return v == aside.infinite_vertex() ? tr.infinite_vertex() : vertex[v->info()];
    });
    for(std::size_t i = 0; i < points.size(); ++i)
      handles.push_back(vertex[first.at(pairs[i].first)]);
    return;
  }
  typename Tr::Face_handle hint;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t before = tr.number_of_vertices();
    const Vertex_handle v = tr.insert(points[i], hint);
    handles.push_back(v);
    if constexpr(has_vertex_info<Tr>)
      if(tr.number_of_vertices() != before)
        v->info() = i;
    hint = v->face();
  }
}

// insert_all() of distinct points: handle i holds point i and, with info, info i.
template <class Tr>
void build(Tr& tr, const std::vector<typename Tr::Point>& points, Handles<Tr>& handles)
{
  insert_all(tr, points, handles);
  DFP_CHECK(tr.number_of_vertices() == points.size());
}

template <class Vertex_handle>
auto current_points(const std::vector<Vertex_handle>& handles)
{
  std::vector<std::decay_t<decltype(handles[0]->point())>> points;
  for(const auto& v : handles)
    points.push_back(v->point());
  return points;
}

// Every recorded handle is still a finite vertex of tr, with the expected point and its info
// unchanged (info i for handle i); there are no other vertices.
template <class Tr>
void check_handles(const Tr& tr, const Handles<Tr>& handles,
                   const std::vector<typename Tr::Point>& expected)
{
  DFP_CHECK_MSG(tr.number_of_vertices() == handles.size(),
                tr.number_of_vertices() << " vs " << handles.size());
  std::set<const void*> live;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    live.insert(&*v);
  bool all_live = true, points_ok = true, info_ok = true;
  for(std::size_t i = 0; i < handles.size(); ++i) {
    if(live.count(&*handles[i]) == 0) { // do not dereference a dead handle
      all_live = false;
      continue;
    }
    points_ok = points_ok && handles[i]->point() == expected[i];
    if constexpr(has_vertex_info<Tr>)
      info_ok = info_ok && std::size_t(handles[i]->info()) == i;
  }
  DFP_CHECK_MSG(all_live, "a vertex handle is no longer in the triangulation");
  DFP_CHECK(points_ok);
  DFP_CHECK(info_ok);
  DFP_CHECK(live.size() == handles.size());
}

template <class Tr>
std::size_t inverted_faces(const Tr& tr)
{
  std::size_t count = 0;
  auto orientation = tr.geom_traits().orientation_2_object();
  if(tr.dimension() == 2)
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
      count += orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) !=
               CGAL::LEFT_TURN;
  return count;
}

// Moves interior vertices by up to `amplitude`, one at a time, only where every incident
// face stays counterclockwise: the result is still a valid triangulation of the moved points.
template <class Tr>
std::size_t move_keeping_faces_ccw(Tr& tr, const Handles<Tr>& handles, double amplitude,
                                   CGAL::Random& rng)
{
  using K = typename Tr::Geom_traits;
  auto orientation = tr.geom_traits().orientation_2_object();
  std::size_t moved = 0;
  for(const auto& v : handles) {
    bool on_hull = false;
    auto fc = tr.incident_faces(v), done = fc;
    do
      on_hull = on_hull || tr.is_infinite(fc);
    while(++fc != done);
    if(on_hull)
      continue;
    const auto p = make_point<K>(CGAL::to_double(v->point().x()) + rng.get_double(-amplitude, amplitude),
                                 CGAL::to_double(v->point().y()) + rng.get_double(-amplitude, amplitude));
    bool ccw = true;
    do {
      const int i = fc->index(v);
      ccw = ccw && orientation(p, fc->vertex(tr.ccw(i))->point(), fc->vertex(tr.cw(i))->point()) ==
                       CGAL::LEFT_TURN;
    } while(++fc != done);
    if(ccw) {
      v->set_point(p);
      ++moved;
    }
  }
  return moved;
}

// True if `text` contains `number` as a whole decimal token (not part of a longer number).
template <class Integer>
bool mentions_number(const std::string& text, Integer number)
{
  const std::string token = std::to_string(number);
  for(std::size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + 1)) {
    const bool digit_before =
        at > 0 && (std::isdigit((unsigned char)text[at - 1]) || (token[0] != '-' && text[at - 1] == '-'));
    const std::size_t end = at + token.size();
    const bool digit_after = end < text.size() && std::isdigit((unsigned char)text[end]);
    if(!digit_before && !digit_after)
      return true;
  }
  return false;
}

} // namespace dfp_test

#endif // CGAL_DELAUNAY_FROM_PREDICTION_TEST_UTIL_H
