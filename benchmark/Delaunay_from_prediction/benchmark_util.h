// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// What the two programs of this folder (bench_delaunay_from_prediction.cpp and
// experiment_prediction_quality.cpp) share: the triangulation types, seeds and random inputs
// (the package's own generator, so the inputs are the same with any standard library), faces
// exported from a triangulation with point indices, random flips, the timed calls and the
// signature that checks a result against CGAL's, the malloc policy, and small helpers of the
// options and of the run header. Memory counting (a replaced global operator new/delete) is not
// here: it belongs to bench_delaunay_from_prediction.cpp alone.

#ifndef DFP_BENCHMARK_UTIL_H
#define DFP_BENCHMARK_UTIL_H

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/prediction_measures.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/version.h>

#include <malloc.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace dfp_bench {

namespace DFP = CGAL::Delaunay_from_prediction;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using DT = CGAL::Delaunay_triangulation_2<K>; // timed, for CGAL and for us
// Set-up (exporting faces as point indices) and "CGAL with info": the same triangulation, with
// the point index in info.
using Info_vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using DTI = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Info_vb>>;
using Face = std::array<std::uint32_t, 3>; // what the timed calls read ("from a file")

// ---------------------------------------------------------------------------------------------
// Random numbers and seeds.
using Rng = DFP::internal::Splitmix64;

inline std::uint64_t mix(std::uint64_t x)
{
  x = (x ^ (x >> 33)) * 0xff51afd7ed558ccdull;
  x = (x ^ (x >> 33)) * 0xc4ceb9fe1a85ec53ull;
  return x ^ (x >> 33);
}
inline std::uint64_t bits(double d)
{
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}
// The seed of one input: a hash of the base seed (--seed), of what the input is for and of its
// size. Each program passes its own `salt`, the one its recorded inputs were drawn with.
inline std::uint64_t salted_seed(std::uint64_t salt, std::uint64_t base, const std::string& what,
                                 std::uint64_t n)
{
  std::uint64_t h = mix(base ^ salt) ^ mix(n + 17);
  for(char c : what)
    h = mix(h ^ std::uint64_t(static_cast<unsigned char>(c)));
  return h;
}

template <class T>
void shuffle(std::vector<T>& v, Rng& rng)
{
  for(std::size_t i = v.size(); i > 1; --i)
    std::swap(v[i - 1], v[rng.below(i)]);
}

// Random order of the list, random rotation of each triple (orientation kept).
inline void shuffle_faces(std::vector<Face>& faces, Rng& rng)
{
  shuffle(faces, rng);
  for(Face& f : faces) {
    const std::size_t r = rng.below(3);
    std::rotate(f.begin(), f.begin() + std::ptrdiff_t(r), f.end());
  }
}

// Labels 0..n-1 with the points of `chosen` permuted among themselves at random: faces or
// edges relabelled with it are drawn with crossings at those points (a combinatorial
// triangulation with self-crossings, the paper's Corollary 3.5).
inline std::vector<std::uint32_t> permuted_among(std::size_t n, const std::vector<std::uint32_t>& chosen, Rng& rng)
{
  std::vector<std::uint32_t> label(n);
  for(std::size_t i = 0; i < n; ++i)
    label[i] = std::uint32_t(i);
  std::vector<std::uint32_t> moved = chosen;
  shuffle(moved, rng);
  for(std::size_t k = 0; k < chosen.size(); ++k)
    label[chosen[k]] = moved[k];
  return label;
}

// ---------------------------------------------------------------------------------------------
// Inputs.
inline std::vector<Point> uniform_points(std::size_t n, std::uint64_t seed)
{
  Rng rng{seed};
  std::vector<Point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double x = rng.uniform();
    points.emplace_back(x, rng.uniform());
  }
  return points;
}

// Points of a named distribution: "uniform" in the unit square; "clustered" (1000 Gaussian
// clusters of standard deviation 0.002); "graded" (x = u^4, y = v^4: density varying over 8
// orders of magnitude).
inline std::vector<Point> distribution_points(const std::string& dist, std::size_t n, std::uint64_t seed)
{
  Rng rng{seed};
  std::vector<Point> points;
  points.reserve(n);
  if(dist == "uniform")
    return uniform_points(n, seed);
  if(dist == "clustered") {
    std::vector<Point> centres;
    for(int c = 0; c < 1000; ++c) {
      const double x = rng.uniform();
      centres.emplace_back(x, rng.uniform());
    }
    for(std::size_t i = 0; i < n; ++i) {
      const Point& c = centres[rng.below(centres.size())];
      const double dx = 0.002 * rng.normal();
      points.emplace_back(c.x() + dx, c.y() + 0.002 * rng.normal());
    }
    return points;
  }
  for(std::size_t i = 0; i < n; ++i) { // graded
    const double u = rng.uniform(), v = rng.uniform();
    points.emplace_back(u * u * u * u, v * v * v * v);
  }
  return points;
}

// (point, index) pairs: what a range insert into a DTI reads.
inline std::vector<std::pair<Point, std::uint32_t>> with_indices(const std::vector<Point>& points)
{
  std::vector<std::pair<Point, std::uint32_t>> with_index(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    with_index[i] = {points[i], std::uint32_t(i)};
  return with_index;
}

inline DTI build_indexed(const std::vector<Point>& points)
{
  const auto with_index = with_indices(points);
  return DTI(with_index.begin(), with_index.end());
}

// Mean spacing sqrt(A/n), A the area of the bounding box of the points (the unit of
// moved_points_prediction() in prediction_models.h).
inline double mean_spacing(const std::vector<Point>& points)
{
  if(points.empty())
    return 0.;
  double x0 = points[0].x(), x1 = x0, y0 = points[0].y(), y1 = y0;
  for(const Point& p : points) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  return std::sqrt((x1 - x0) * (y1 - y0) / double(points.size()));
}

// The points moved by independent noise of scale `step`, point i by the i-th draw of a
// generator seeded with `seed` (so the same seed gives the same field at every scale):
// gaussian, each coordinate plus N(0, step^2); disk, a point uniform in the disk of radius step;
// sparse, one point in 10,000 (the first, then every 10,000th) moved by Gaussian noise of
// scale 10 step, the others not moved (a few wrong points: the case Theorem 2.1 is made for).
inline std::vector<Point> noisy_points(const std::vector<Point>& points, const std::string& noise,
                                       double step, std::uint64_t seed)
{
  Rng rng{seed};
  std::vector<Point> out;
  out.reserve(points.size());
  std::size_t index = 0;
  for(const Point& p : points) {
    double dx, dy;
    if(noise == "sparse") { // one point in 10,000, ten times the step
      dx = 10 * step * rng.normal();
      dy = 10 * step * rng.normal();
      if(index++ % 10000 != 0)
        dx = dy = 0;
    } else if(noise == "gaussian") {
      dx = step * rng.normal();
      dy = step * rng.normal();
    } else {
      const double radius = step * std::sqrt(rng.uniform());
      const double angle = 2. * M_PI * rng.uniform();
      dx = radius * std::cos(angle);
      dy = radius * std::sin(angle);
    }
    out.emplace_back(p.x() + dx, p.y() + dy);
  }
  return out;
}

// Finite faces as point-index triples, in the order the triangulation iterates them.
template <class F = Face>
std::vector<F> export_faces(const DTI& t)
{
  std::vector<F> faces;
  faces.reserve(t.number_of_faces());
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f)
    faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return faces;
}

// The distinct edges of index triples, each as DFP::internal::edge_key (smaller index first), sorted.
template <class Faces>
std::vector<std::uint64_t> edges_of(const Faces& faces)
{
  std::vector<std::uint64_t> e;
  e.reserve(3 * faces.size());
  for(const auto& f : faces)
    for(int j = 0; j < 3; ++j)
      e.push_back(DFP::internal::edge_key(f[j], f[(j + 1) % 3]));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

// D: the number of predicted edges that are not Delaunay edges (both lists from edges_of()).
inline std::size_t wrong_edges(const std::vector<std::uint64_t>& predicted, const std::vector<std::uint64_t>& delaunay)
{
  std::size_t common = 0;
  auto a = predicted.begin(), b = delaunay.begin();
  while(a != predicted.end() && b != delaunay.end()) {
    if(*a < *b)
      ++a;
    else if(*b < *a)
      ++b;
    else {
      ++common;
      ++a;
      ++b;
    }
  }
  return predicted.size() - common;
}


inline std::vector<DTI::Face_handle> finite_face_handles(DTI& t)
{
  std::vector<DTI::Face_handle> faces;
  faces.reserve(t.number_of_faces());
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f)
    faces.push_back(f);
  return faces;
}

// One try of a random flip: draws a face of `faces` (finite faces of `t`, not empty; a flip
// keeps them valid) and one of its edges, and flips the edge if it is interior, its
// quadrilateral is strictly convex and accept(p, q, r, s) holds for the new faces (p, q, r) and
// (p, r, s). Returns whether it flipped.
template <class Accept>
bool try_random_flip(DTI& t, const std::vector<DTI::Face_handle>& faces, Rng& rng, const Accept& accept)
{
  const DTI::Face_handle f = faces[rng.below(faces.size())];
  const int i = int(rng.below(3));
  if(t.is_infinite(f->neighbor(i)))
    return false;
  // f = (p, q, s) counterclockwise, edge q-s is shared with the neighbour (s, q, r); the flip
  // makes p-r. Strictly convex p, q, r, s <=> both new faces (p, q, r) and (p, r, s) turn left.
  const Point& p = f->vertex(i)->point();
  const Point& q = f->vertex(DTI::ccw(i))->point();
  const Point& s = f->vertex(DTI::cw(i))->point();
  const Point& r = t.mirror_vertex(f, i)->point();
  const auto orientation = t.geom_traits().orientation_2_object();
  if(orientation(p, q, r) != CGAL::LEFT_TURN || orientation(p, r, s) != CGAL::LEFT_TURN ||
     !accept(p, q, r, s))
    return false;
  t.tds().flip(f, i);
  return true;
}

// Flips k random interior edges of `t` whose quadrilateral is strictly convex. Returns the
// number of flips made (k unless the triangulation has too few flippable edges).
inline std::size_t random_flips(DTI& t, std::size_t k, Rng& rng)
{
  const std::vector<DTI::Face_handle> faces = finite_face_handles(t);
  if(faces.empty())
    return 0;
  std::size_t done = 0, attempts = 0;
  const std::size_t max_attempts = 100 * k + 1000;
  const auto any = [](const Point&, const Point&, const Point&, const Point&) { return true; };
  while(done < k && attempts++ < max_attempts)
    if(try_random_flip(t, faces, rng, any))
      ++done;
  return done;
}

// ---------------------------------------------------------------------------------------------
// Checks: counts and an order-independent hash of the set of finite faces, each face the
// lexicographically sorted triple of its point coordinates.
struct Signature
{
  int dimension = -2;
  std::size_t vertices = 0, faces = 0;
  std::uint64_t sum = 0, xor_ = 0;
  bool operator==(const Signature& o) const
  {
    return dimension == o.dimension && vertices == o.vertices && faces == o.faces && sum == o.sum &&
           xor_ == o.xor_;
  }
  bool operator!=(const Signature& o) const { return !(*this == o); }
  std::string str() const
  {
    std::ostringstream s;
    s << "dim " << dimension << ", " << vertices << " vertices, " << faces << " faces, hash "
      << std::hex << sum << "/" << xor_;
    return s.str();
  }
};

template <class Tr>
Signature signature(const Tr& t)
{
  Signature sig;
  sig.dimension = t.dimension();
  sig.vertices = t.number_of_vertices();
  if(t.dimension() < 2)
    return sig;
  auto less = [](const Point* a, const Point* b) {
    return a->x() < b->x() || (a->x() == b->x() && a->y() < b->y());
  };
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    const Point* p[3] = {&f->vertex(0)->point(), &f->vertex(1)->point(), &f->vertex(2)->point()};
    std::sort(p, p + 3, less);
    std::uint64_t h = 0x243f6a8885a308d3ull;
    for(int j = 0; j < 3; ++j)
      h = mix(mix(h ^ bits(p[j]->x())) ^ bits(p[j]->y()));
    sig.sum += h;
    sig.xor_ ^= mix(h + 0x9e3779b97f4a7c15ull);
    ++sig.faces;
  }
  return sig;
}

// ---------------------------------------------------------------------------------------------
// Timed calls. The caller constructs the triangulation before the timer starts and destroys it
// after the timer stops; set-up (copies, moves) and the checks run outside the timers.

// Times call() alone; leaves the signature of `tr` afterwards.
template <class Tr, class Call>
double time_call(Tr& tr, const Call& call, Signature& sig)
{
  CGAL::Real_timer timer;
  timer.start();
  call();
  timer.stop();
  sig = signature(tr);
  return timer.time();
}

// CGAL's from-scratch build: range insert into an empty triangulation (DT of points, or DTI of
// (point, index) pairs: "CGAL with info").
template <class Tr = DT, class Input>
double time_cgal(const std::vector<Input>& input, Signature& sig)
{
  Tr tr;
  return time_call(tr, [&] { tr.insert(input.begin(), input.end()); }, sig);
}

// A visitor (named parameter `visitor`, passed as std::ref(timer)) that times the stages of
// delaunay_from_prediction() and make_delaunay(): wall-clock seconds per stage, summed over the
// calls it is given to, and the stages seen, in order.
struct Stage_timer
{
  std::vector<std::pair<DFP::Stage, double>> times; // each stage as it ended, with its seconds
  CGAL::Real_timer clock;
  double began = 0;

  Stage_timer() { clock.start(); }
  void stage_begin(DFP::Stage) { began = clock.time(); }
  void stage_end(DFP::Stage stage) { times.emplace_back(stage, clock.time() - began); }
  // The seconds spent in `stage` (0 if it did not run).
  double seconds(DFP::Stage stage) const
  {
    double sum = 0;
    for(const auto& t : times)
      sum += t.first == stage ? t.second : 0;
    return sum;
  }
  bool saw(DFP::Stage stage) const
  {
    return std::any_of(times.begin(), times.end(), [&](const auto& t) { return t.first == stage; });
  }
  void clear() { times.clear(); }
};

// Our delaunay_from_prediction().
template <class NamedParameters = DFP::parameters::Default_named_parameters>
double time_prediction(const std::vector<Point>& points, const std::vector<Face>& faces,
                       DFP::Statistics& stats, Signature& sig,
                       const NamedParameters& np = DFP::parameters::default_values())
{
  DT dt;
  return time_call(dt, [&] { stats = DFP::delaunay_from_prediction(points, faces, dt, np); }, sig);
}

inline double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// The rows of a stage-by-stage ablation (bench_import_stages, bench_repair_stages): the
// median seconds of each stage in the sequential and in the parallel mode, then their ratio.
// Where `staged` is false only the last stage (the whole call) has times. `check` ends the two
// rows of times.
inline void print_stage_rows(const std::string& label, const std::vector<double>* sequential,
                             const std::vector<double>* parallel, int stages, bool staged, const std::string& check)
{
  const std::vector<double>* seconds[2] = {sequential, parallel};
  const char* const modes[3] = {"sequential", "parallel", "seq/par"};
  for(int row = 0; row < 3; ++row) {
    std::printf("%-9s %-10s |", label.c_str(), modes[row]);
    for(int k = 0; k < stages; ++k) {
      const bool shown = staged || k == stages - 1;
      if(shown && row < 2)
        std::printf(" %9.4f", median(seconds[row][k]));
      else if(shown && median(parallel[k]) > 0)
        std::printf(" %9.2f", median(sequential[k]) / median(parallel[k]));
      else
        std::printf(" %9s", "-");
    }
    if(row < 2)
      std::printf(" | %s\n", check.c_str());
    else
      std::printf(" |\n");
  }
}

// ---------------------------------------------------------------------------------------------
// Allocator policy "keep", to be set before the first allocation of any input. glibc trimming
// the heap top and mmap/munmap of large blocks made timings erratic (the same call 2x slower in
// one phase than in another, depending on what the previous phase had freed): "keep" serves
// every block from the heap and never gives memory back, so after the first repetition neither
// CGAL nor we pay page faults for memory an earlier step already touched. False if mallopt
// failed (glibc's default policy is then in effect).
inline bool keep_freed_memory()
{
  return mallopt(M_MMAP_MAX, 0) == 1 && mallopt(M_TRIM_THRESHOLD, -1) == 1;
}

// ---------------------------------------------------------------------------------------------
// Options and output.

// Comma-separated list, empty items dropped.
inline std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while(std::getline(in, item, ','))
    if(!item.empty())
      out.push_back(item);
  return out;
}

// The value after option argv[i] (i moves to it); exits with status 2 if there is none.
inline std::string option_value(int argc, char** argv, int& i)
{
  if(i + 1 >= argc) {
    std::fprintf(stderr, "missing value after %s\n", argv[i]);
    std::exit(2);
  }
  return argv[++i];
}

// The last branch of the option loop: --help or -h prints the usage and exits with status 0;
// anything else is an unknown option: says so, prints the usage and exits with status 2.
[[noreturn]] inline void help_or_unknown(const std::string& option, const char* program,
                                         void (*usage)(const char*))
{
  if(option == "--help" || option == "-h") {
    usage(program);
    std::exit(0);
  }
  std::fprintf(stderr, "unknown option %s\n", option.c_str());
  usage(program);
  std::exit(2);
}

// What follows "key...:" on the first line of `file` that starts with `key`, or "unknown".
inline std::string read_first(const char* file, const char* key)
{
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, std::strlen(key), key) == 0) {
      const auto colon = line.find(':');
      std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
      v.erase(0, v.find_first_not_of(" \t"));
      return v;
    }
  return "unknown";
}

// Sizes listed with commas, each read as a double ("1e5,1e6").
inline std::vector<std::size_t> sizes_of(const std::string& list)
{
  std::vector<std::size_t> sizes;
  for(const std::string& v : split(list))
    sizes.push_back(std::size_t(std::atof(v.c_str())));
  return sizes;
}

inline std::string local_date_time()
{
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&now));
  return date;
}

// Compiler, CGAL version and build type, for the run header.
inline std::string build_description()
{
  return std::string("g++ ") + __VERSION__ + ", CGAL " + CGAL_VERSION_STR
#ifdef NDEBUG
         + ", NDEBUG (Release)";
#else
         + ", NOT A RELEASE BUILD (assertions on): timings are meaningless";
#endif
}

// A CSV field in double quotes (inner quotes doubled).
inline std::string csv_quote(const std::string& s)
{
  std::string out = "\"";
  for(char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

} // namespace dfp_bench

#endif // DFP_BENCHMARK_UTIL_H
