// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Benchmark of delaunay_from_prediction() and make_delaunay() against CGAL's own
// Delaunay_triangulation_2 built from scratch (range insert, which spatial-sorts first), timed
// in the same run, on the same points, with the same triangulation type
// (plain CGAL::Delaunay_triangulation_2<Epick>), one thread, CGAL::Real_timer (wall clock),
// median of --reps repetitions, fixed seeds.
//
// Cases (--cases, by name):
//   shuffled  D = 0: the Delaunay faces, list shuffled, each triple rotated at random; points in
//             random order.
//   hilbert   D = 0, coherent input: points Hilbert-sorted, faces in the order CGAL's own DT of
//             the sorted points iterates them. CGAL's reference is built from the sorted points.
//   flips     k random flips (0.1%, 1%, 10% of n) of strictly convex interior quadrilaterals in a
//             copy of the DT, faces exported in random order.
//   move      make_delaunay() on a CGAL DT whose every point was moved by sigma x (mean
//             nearest-neighbour distance, sigma = 0.0001 ... 0.5) in a random direction; only
//             the call is timed.
//             CGAL's reference is a from-scratch build of the moved points.
//   random    2n-5 random index triples (distinct indices) as a prediction.
//   memory    peak heap bytes of the `shuffled` and `random` calls vs CGAL's from-scratch build.
//   kinetic   make_delaunay() on a CGAL DT with point indices in info() whose every vertex was
//             moved by noise (--noise: gaussian, each coordinate N(0, s^2), or disk, uniform in
//             the disk of radius s, or sparse, one vertex in 10,000 moved by gaussian noise of
//             scale 10 s) of scale s = sigma x mean spacing sqrt(A/n) (A: area of the
//             bounding box), sigma = 0.001 ... 1, with strategy carve (local repair),
//             t_division (Theorem 2.1, --region-size) and flips (the behaviour before local
//             repair: a triangulation with an inverted face is rebuilt in place), and on
//             request regions (Theorem 5.4 in practical form) and rebuild. Every repetition copies the moved DT
//             (untimed) and times the call alone. Also reported: inverted and flat faces
//             before the call, faces carved, holes refilled, points reinserted, time per
//             reinserted point. CGAL's reference is a from-scratch build of the moved points.
//   deleted   delaunay_from_prediction() from the Delaunay faces with 1% and 10% of them
//             deleted (each independently), list shuffled, strategies carve, t_division, flips.
//
// Every result of ours is compared with CGAL's (vertex and face counts and an order-independent
// hash of the face set as sorted coordinate triples), outside the timers; a mismatch prints
// "CHECK FAILED" and makes the program exit with status 1.
//
// Usage: bench_delaunay_from_prediction [--n 100000,1000000] [--reps 3]
//          [--cases shuffled,hilbert,flips,move,random,memory,kinetic,deleted]
//          [--dist uniform,clustered] [--noise gaussian,disk] [--csv FILE]
//          [--malloc keep|default] [--seed S] [--threads T]
//
// With --threads T (a build with TBB), every case but memory and deleted also times our call
// with CGAL::Parallel_tag in a TBB arena of T threads, in the same repetitions, and prints its
// speed-up over the sequential call.

#include "benchmark_util.h"

#include <CGAL/hilbert_sort.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <malloc.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// ---------------------------------------------------------------------------------------------
// Memory measurement: a counting global operator new/delete.
//
// Every C++ allocation of the process (CGAL's Compact_container blocks, std::vector buffers of
// CGAL's spatial sort and of our import, ...) goes through these operators. They allocate with
// malloc and keep the number of bytes currently held (malloc_usable_size of each block) and its
// high-water mark. The peak of a call is (high-water mark during the call) - (bytes held when it
// started): the largest amount of heap the call itself held at once, its result included, the
// caller's inputs excluded. Unlike ru_maxrss this does not depend on which pages glibc has
// already faulted in or kept (the "keep" allocator policy below never returns memory, so a
// forked child reusing the parent's free heap would show no RSS growth at all), and it is exact
// and repeatable. It does not see malloc's own bookkeeping or memory obtained with plain malloc
// (CGAL and this package use none on these paths; GMP is never reached with Epick on these
// inputs). Single thread, so plain counters.
namespace counting {
// Atomic: the parallel calls allocate from TBB's threads too.
std::atomic<std::size_t> current_bytes{0};
std::atomic<std::size_t> peak_bytes{0};

inline void account(void* p)
{
  const std::size_t now = current_bytes.fetch_add(malloc_usable_size(p)) + malloc_usable_size(p);
  std::size_t peak = peak_bytes.load();
  while(now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
}
inline void* allocate(std::size_t size)
{
  void* p = std::malloc(size == 0 ? 1 : size);
  if(p == nullptr)
    throw std::bad_alloc();
  account(p);
  return p;
}
inline void* allocate_aligned(std::size_t size, std::size_t alignment)
{
  if(alignment < sizeof(void*))
    alignment = sizeof(void*);
  void* p = nullptr;
  if(posix_memalign(&p, alignment, size == 0 ? 1 : size) != 0)
    throw std::bad_alloc();
  account(p);
  return p;
}
inline void release(void* p) noexcept
{
  if(p == nullptr)
    return;
  current_bytes -= malloc_usable_size(p);
  std::free(p);
}

// Measures the heap peak of one scope, relative to what is held when it starts.
struct Peak_scope
{
  std::size_t base;
  Peak_scope() : base(current_bytes.load()) { peak_bytes = base; }
  std::size_t bytes() const { return peak_bytes - base; }
};
} // namespace counting

void* operator new(std::size_t size) { return counting::allocate(size); }
void* operator new[](std::size_t size) { return counting::allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  try { return counting::allocate(size); } catch(...) { return nullptr; }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept
{
  try { return counting::allocate(size); } catch(...) { return nullptr; }
}
void* operator new(std::size_t size, std::align_val_t a) { return counting::allocate_aligned(size, std::size_t(a)); }
void* operator new[](std::size_t size, std::align_val_t a) { return counting::allocate_aligned(size, std::size_t(a)); }
void operator delete(void* p) noexcept { counting::release(p); }
void operator delete[](void* p) noexcept { counting::release(p); }
void operator delete(void* p, std::size_t) noexcept { counting::release(p); }
void operator delete[](void* p, std::size_t) noexcept { counting::release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { counting::release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { counting::release(p); }
void operator delete(void* p, std::align_val_t) noexcept { counting::release(p); }
void operator delete[](void* p, std::align_val_t) noexcept { counting::release(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { counting::release(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { counting::release(p); }

namespace {

using namespace dfp_bench;

// The seed of one input of this program. Its own salt, as before benchmark_util.h: the uniform
// inputs are still those of the recorded tables (the clustered ones changed when this program
// took the package's generator, whose normal draws differ from its former own).
std::uint64_t seed_for(std::uint64_t base, const std::string& what, std::size_t n)
{
  return salted_seed(0x1234567ull, base, what, n);
}

// ---------------------------------------------------------------------------------------------
// Inputs.
std::vector<Point> make_points(const std::string& dist, std::size_t n, std::uint64_t seed)
{
  const std::uint64_t points_seed = seed_for(seed, "points/" + dist, n);
  if(dist == "uniform")
    return uniform_points(n, points_seed);
  // clustered: 64 gaussian blobs, centres in [0.1, 0.9]^2, std dev in [0.005, 0.035]
  Rng rng{points_seed};
  std::vector<Point> points;
  points.reserve(n);
  constexpr int blobs = 64;
  double cx[blobs], cy[blobs], sd[blobs];
  for(int b = 0; b < blobs; ++b) {
    cx[b] = 0.1 + 0.8 * rng.uniform();
    cy[b] = 0.1 + 0.8 * rng.uniform();
    sd[b] = 0.005 + 0.03 * rng.uniform();
  }
  for(std::size_t i = 0; i < n; ++i) {
    const int b = int(rng.below(blobs));
    const double x = cx[b] + sd[b] * rng.normal();
    points.emplace_back(x, cy[b] + sd[b] * rng.normal());
  }
  return points;
}

// Number of points equal to an earlier one (the checks assume none; reported if any).
std::size_t count_duplicates(const std::vector<Point>& points)
{
  std::vector<std::pair<double, double>> xy(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    xy[i] = {points[i].x(), points[i].y()};
  std::sort(xy.begin(), xy.end());
  return std::size_t(xy.end() - std::unique(xy.begin(), xy.end()));
}

std::vector<Face> random_triples(std::size_t n, std::size_t count, Rng& rng)
{
  std::vector<Face> faces(count);
  for(Face& f : faces) {
    f[0] = std::uint32_t(rng.below(n));
    do f[1] = std::uint32_t(rng.below(n)); while(f[1] == f[0]);
    do f[2] = std::uint32_t(rng.below(n)); while(f[2] == f[0] || f[2] == f[1]);
  }
  return faces;
}

// Mean nearest-neighbour distance: the nearest neighbour of a point is a Delaunay neighbour, so
// it is the mean over vertices of their shortest incident edge.
double mean_nearest_neighbour_distance(const DTI& t)
{
  std::vector<double> shortest(t.number_of_vertices(), std::numeric_limits<double>::infinity());
  for(auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) {
    const auto a = e->first->vertex(DTI::ccw(e->second));
    const auto b = e->first->vertex(DTI::cw(e->second));
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
    shortest[a->info()] = std::min(shortest[a->info()], d);
    shortest[b->info()] = std::min(shortest[b->info()], d);
  }
  double sum = 0;
  std::size_t count = 0;
  for(double d : shortest)
    if(std::isfinite(d)) {
      sum += d;
      ++count;
    }
  return count == 0 ? 0. : sum / double(count);
}

// The move of a point: distance `step`, direction drawn from a hash of its coordinates, so that
// the moved set does not depend on the order in which the vertices are visited.
Point moved(const Point& p, double step, std::uint64_t salt)
{
  const std::uint64_t h = mix(mix(bits(p.x()) ^ salt) ^ bits(p.y()));
  const double angle = 2. * M_PI * (double(h >> 11) * 0x1.0p-53);
  return Point(p.x() + step * std::cos(angle), p.y() + step * std::sin(angle));
}

// Finite faces of `t` that are clockwise (inverted) and flat, e.g. after its points moved.
std::pair<std::size_t, std::size_t> inverted_and_flat_faces(const DTI& t)
{
  std::size_t inverted = 0, flat = 0;
  const auto orientation = t.geom_traits().orientation_2_object();
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    const CGAL::Orientation o =
        orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    inverted += o == CGAL::RIGHT_TURN ? 1 : 0;
    flat += o == CGAL::COLLINEAR ? 1 : 0;
  }
  return {inverted, flat};
}

// The strategies compared by the kinetic and deleted cases.
struct Named_strategy
{
  const char* name;
  DFP::Strategy strategy;
};
const Named_strategy repair_strategies[] = {{"carve", DFP::Strategy::carve},
                                            {"t_division", DFP::Strategy::t_division},
                                            {"flips", DFP::Strategy::flips},
                                            {"regions", DFP::Strategy::regions},
                                            {"rebuild", DFP::Strategy::rebuild}};

// ---------------------------------------------------------------------------------------------
// Options and output.
struct Options
{
  std::vector<std::size_t> sizes{100000, 1000000};
  int reps = 3;
  std::vector<std::string> cases{"shuffled", "hilbert", "flips", "move", "random", "memory"};
  std::vector<std::string> dists{"uniform", "clustered"};
  std::vector<std::string> noises{"gaussian"};
  std::string csv;
  std::string malloc_policy = "keep";
  std::uint64_t seed = 20260101;
  std::vector<std::string> strategies{"carve", "t_division", "flips"};
  std::size_t region_size = 0; // 0: the default of each strategy
  int threads = 0;             // > 0: every call of ours also with CGAL::Parallel_tag on that many threads
  bool runs(const std::string& s) const
  {
    return std::find(strategies.begin(), strategies.end(), s) != strategies.end();
  }
  bool wants(const std::string& c) const { return std::find(cases.begin(), cases.end(), c) != cases.end(); }
};

void usage(const char* program)
{
  std::printf(
      "usage: %s [options]\n"
      "  --n LIST        numbers of points, comma separated, 1e6 notation allowed (default 100000,1000000)\n"
      "  --reps R        repetitions per measurement, the median is reported (default 3)\n"
      "  --cases LIST    subset of shuffled,hilbert,flips,move,random,memory,kinetic,deleted\n"
      "                  (default shuffled,hilbert,flips,move,random,memory)\n"
      "  --dist LIST     subset of uniform,clustered (default both)\n"
      "  --noise LIST    noise of the kinetic case, subset of gaussian,disk,sparse (default gaussian)\n"
      "  --csv FILE      also write one CSV row per measurement to FILE\n"
      "  --malloc P      keep (default): mallopt(M_MMAP_MAX=0, M_TRIM_THRESHOLD=-1), freed memory is\n"
      "                  kept by the process and reused; default: glibc's own policy\n"
      "  --seed S        base seed of every input (default 20260101)\n"
      "  --strategies L  strategies of kinetic and deleted, subset of carve,t_division,flips,regions,\n"
      "                  rebuild (default carve,t_division,flips)\n"
      "  --region-size T region size t of strategy t_division (default: max(64, log2(n)^2))\n"
      "  --threads T     also time every call of ours with CGAL::Parallel_tag in a TBB arena of T\n"
      "                  threads, in the same repetitions, and print its speed-up over the\n"
      "                  sequential call (default 0: sequential only; needs TBB)\n",
      program);
}

Options parse(int argc, char** argv)
{
  Options o;
  auto value = [&](int& i) { return option_value(argc, argv, i); };
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n") {
      o.sizes.clear();
      for(const std::string& s : split(value(i))) {
        const double d = std::stod(s);
        if(!(d >= 3) || d > 4e9) {
          std::fprintf(stderr, "bad --n value %s\n", s.c_str());
          std::exit(2);
        }
        o.sizes.push_back(std::size_t(std::llround(d)));
      }
    } else if(a == "--reps") {
      o.reps = std::max(1, std::atoi(value(i).c_str()));
    } else if(a == "--cases") {
      o.cases = split(value(i));
      for(const std::string& c : o.cases)
        if(c != "shuffled" && c != "hilbert" && c != "flips" && c != "move" && c != "random" &&
           c != "memory" && c != "kinetic" && c != "deleted") {
          std::fprintf(stderr, "unknown case %s\n", c.c_str());
          std::exit(2);
        }
    } else if(a == "--dist") {
      o.dists = split(value(i));
      for(const std::string& d : o.dists)
        if(d != "uniform" && d != "clustered") {
          std::fprintf(stderr, "unknown distribution %s\n", d.c_str());
          std::exit(2);
        }
    } else if(a == "--noise") {
      o.noises = split(value(i));
      for(const std::string& d : o.noises)
        if(d != "gaussian" && d != "disk" && d != "sparse") {
          std::fprintf(stderr, "unknown noise %s\n", d.c_str());
          std::exit(2);
        }
    } else if(a == "--csv") {
      o.csv = value(i);
    } else if(a == "--malloc") {
      o.malloc_policy = value(i);
      if(o.malloc_policy != "keep" && o.malloc_policy != "default") {
        std::fprintf(stderr, "--malloc takes keep or default\n");
        std::exit(2);
      }
    } else if(a == "--strategies") {
      o.strategies = split(value(i));
      for(const std::string& st : o.strategies)
        if(st != "carve" && st != "t_division" && st != "flips" && st != "regions" && st != "rebuild") {
          std::fprintf(stderr, "unknown strategy %s\n", st.c_str());
          std::exit(2);
        }
    } else if(a == "--threads") {
      o.threads = std::max(0, std::atoi(value(i).c_str()));
#ifndef CGAL_LINKED_WITH_TBB
      if(o.threads > 0) {
        std::fprintf(stderr, "--threads needs a build with TBB (CGAL_LINKED_WITH_TBB)\n");
        std::exit(2);
      }
#endif
    } else if(a == "--region-size") {
      o.region_size = std::size_t(std::max(1LL, std::atoll(value(i).c_str())));
    } else if(a == "--seed") {
      o.seed = std::strtoull(value(i).c_str(), nullptr, 10);
    } else {
      help_or_unknown(a, argv[0], usage);
    }
  }
  return o;
}

std::string read_line(const char* file)
{
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string join(const std::vector<double>& v)
{
  std::ostringstream s;
  s.precision(6);
  for(std::size_t i = 0; i < v.size(); ++i)
    s << (i ? ";" : "") << v[i];
  return s.str();
}

struct Row
{
  std::string dist, kase, param;
  std::size_t n = 0;
  std::vector<double> cgal_times, our_times;
  DFP::Statistics stats;
  bool has_stats = false;
  bool memory = false;
  std::size_t cgal_bytes = 0, our_bytes = 0;
  bool ok = true;
  std::string failure;
  // The value of our call's `strategy` named parameter ("automatic": not passed).
  std::string strategy = "automatic";
  // kinetic and deleted: a second line with the local repair's statistics, and the damage of
  // the prediction before the call (-1: not applicable): finite faces inverted (clockwise) and
  // flat, faces deleted.
  bool repair_details = false;
  long long inverted = -1, flat = -1, deleted = -1;
};

// Median time of our call per point it (re)inserted, in microseconds (NaN if none): an upper
// bound of the cost of one reinsertion, certification and flips included.
double us_per_reinserted_point(const Row& r)
{
  if(!r.has_stats || r.stats.points_reinserted == 0)
    return std::numeric_limits<double>::quiet_NaN();
  return 1e6 * median(r.our_times) / double(r.stats.points_reinserted);
}

std::string csv_count(long long v) { return v < 0 ? std::string() : std::to_string(v); }

class Report
{
public:
  explicit Report(const std::string& csv_file)
  {
    if(!csv_file.empty()) {
      csv_.open(csv_file);
      if(!csv_) {
        std::fprintf(stderr, "cannot write %s\n", csv_file.c_str());
        std::exit(2);
      }
    }
  }
  std::ofstream& csv() { return csv_; }

  void table_header() const
  {
    std::printf("%-9s %8s %-8s %-24s %9s %9s %7s  %-8s %8s %8s  %s\n", "dist", "n", "case",
                "param", "CGAL[s]", "ours[s]", "ratio", "path", "flips", "D_local", "check");
    std::printf("%s\n", std::string(118, '-').c_str());
    std::fflush(stdout);
  }

  void add(const Row& r)
  {
    if(!r.ok) {
      ++failures_;
      const std::string msg = "!!!!!!!! CHECK FAILED: " + r.dist + " n=" + std::to_string(r.n) +
                              " " + r.kase + " " + r.param + ": " + r.failure + " !!!!!!!!";
      std::printf("%s\n", msg.c_str());
      std::fprintf(stderr, "%s\n", msg.c_str());
    }
    const double tc = median(r.cgal_times), to = median(r.our_times);
    if(r.memory) {
      const double mc = double(r.cgal_bytes) / 1048576., mo = double(r.our_bytes) / 1048576.;
      std::printf("%-9s %8zu %-8s %-24s CGAL %8.1f MiB (%5.1f B/pt)  ours %8.1f MiB (%5.1f B/pt)  ours/CGAL %5.2f  %s\n",
                  r.dist.c_str(), r.n, r.kase.c_str(), r.param.c_str(), mc,
                  double(r.cgal_bytes) / double(r.n), mo, double(r.our_bytes) / double(r.n),
                  r.cgal_bytes ? double(r.our_bytes) / double(r.cgal_bytes) : 0., r.ok ? "ok" : "FAILED");
    } else {
      std::string path = "-";
      if(r.has_stats)
        path = r.stats.fell_back ? "FALLBACK"
               : r.stats.faces_carved > 0 || r.stats.holes_refilled > 0 ? "repair"
                                                                        : "predict";
      std::string check = r.ok ? "ok" : "FAILED";
      if(r.has_stats && r.stats.fell_back && r.stats.outcome != DFP::Outcome::ok)
        check += std::string(" (") + to_string(r.stats.outcome) + ")";
      std::printf("%-9s %8zu %-8s %-24s %9.4f %9.4f %7.2f  %-8s %8zu %8zu  %s\n", r.dist.c_str(),
                  r.n, r.kase.c_str(), r.param.c_str(), tc, to, tc / to, path.c_str(),
                  r.has_stats ? r.stats.flips : 0, r.has_stats ? r.stats.edges_not_locally_delaunay : 0,
                  check.c_str());
      if(r.repair_details) {
        std::ostringstream line;
        line << std::string(19, ' ') << "before: ";
        if(r.deleted >= 0)
          line << "deleted " << r.deleted << " faces";
        else
          line << "inverted " << r.inverted << ", flat " << r.flat;
        line << " | after (" << r.strategy << "): ";
        if(r.has_stats) {
          line << "fell_back " << (r.stats.fell_back ? "yes" : "no") << ", carved "
               << r.stats.faces_carved << ", holes " << r.stats.holes_refilled << ", rounds "
               << r.stats.carve_rounds << ", reinserted " << r.stats.points_reinserted
               << ", flips " << r.stats.flips;
          const double us = us_per_reinserted_point(r);
          if(std::isfinite(us))
            line << std::fixed << std::setprecision(3) << ", " << us << " us/reinserted pt";
        } else {
          line << "no statistics";
        }
        std::printf("%s\n", line.str().c_str());
      }
    }
    std::fflush(stdout);
    if(csv_) {
      csv_ << r.dist << ',' << r.n << ',' << r.kase << ',' << csv_quote(r.param) << ','
           << (r.memory ? std::size_t(1) : std::max(r.cgal_times.size(), r.our_times.size())) << ',';
      if(r.memory)
        csv_ << ",,,,,";
      else
        csv_ << tc << ',' << to << ',' << tc / to << ',' << join(r.cgal_times) << ','
             << join(r.our_times) << ',';
      if(r.has_stats)
        csv_ << int(r.stats.fell_back) << ',' << csv_quote(to_string(r.stats.outcome))
             << ',' << r.stats.flips << ',' << r.stats.faces_in << ',' << r.stats.faces_certified << ','
             << r.stats.points_reinserted << ',' << r.stats.edges_tested << ','
             << r.stats.edges_not_locally_delaunay << ',' << r.stats.points_unused << ',';
      else
        csv_ << ",,,,,,,,,";
      if(r.memory)
        csv_ << r.cgal_bytes << ',' << r.our_bytes << ','
             << (r.cgal_bytes ? double(r.our_bytes) / double(r.cgal_bytes) : 0.) << ',';
      else
        csv_ << ",,,";
      csv_ << (r.ok ? "ok" : "FAILED");
      // Columns added with local repair, after `check` so that older readers are unaffected.
      csv_ << ',' << r.strategy << ',' << csv_count(r.inverted) << ',' << csv_count(r.flat) << ','
           << csv_count(r.deleted) << ',';
      if(r.has_stats) {
        csv_ << r.stats.faces_carved << ',' << r.stats.holes_refilled << ',' << r.stats.carve_rounds << ',';
        const double us = us_per_reinserted_point(r);
        if(std::isfinite(us))
          csv_ << us;
      } else {
        csv_ << ",,,";
      }
      csv_ << '\n';
      csv_.flush();
    }
  }
  int failures() const { return failures_; }

private:
  std::ofstream csv_;
  int failures_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Measurements (the timed calls are time_cgal(), time_prediction() and time_call() of
// benchmark_util.h).

// One timed call of ours: fills the statistics and the signature, returns the time.
using Our_call = std::function<double(DFP::Statistics&, Signature&)>;

// Runs `reps` repetitions of CGAL's build (`cgal`) and of each call ours[j] (its results go to
// *rows[j], and so do CGAL's times, shared by all rows), in an order that rotates with the
// repetition (repetition r starts with the (r mod (m + 1))-th of CGAL, ours[0], ...,
// ours[m - 1]; with one call of ours: CGAL first in even repetitions, ours first in odd ones)
// so that all see the same machine load, and checks every result of ours against CGAL's. A
// call that throws fails its row and is not repeated.
template <class Cgal>
void measure_all(int reps, const std::vector<Row*>& rows, Cgal cgal, const std::vector<Our_call>& ours)
{
  const std::size_t m = ours.size();
  Signature reference;
  std::vector<double> cgal_times;
  bool cgal_agrees = true;
  std::vector<std::vector<Signature>> results(m);
  std::vector<bool> alive(m, true);
  std::size_t alive_count = m;
  for(int r = 0; r < reps && alive_count > 0; ++r) {
    for(std::size_t turn = 0; turn <= m && alive_count > 0; ++turn) {
      const std::size_t slot = (turn + std::size_t(r)) % (m + 1); // 0: CGAL, j + 1: ours[j]
      if(slot == 0) {
        Signature s;
        cgal_times.push_back(cgal(s));
        if(cgal_times.size() == 1)
          reference = s;
        else if(s != reference)
          cgal_agrees = false;
        continue;
      }
      const std::size_t j = slot - 1;
      if(!alive[j])
        continue;
      Row& row = *rows[j];
      Signature s;
      try {
        row.our_times.push_back(ours[j](row.stats, s));
      } catch(const std::exception& e) {
        row.ok = false;
        row.failure = std::string("exception: ") + e.what();
        alive[j] = false;
        --alive_count;
        continue;
      }
      row.has_stats = true;
      results[j].push_back(s);
    }
  }
  for(std::size_t j = 0; j < m; ++j) {
    Row& row = *rows[j];
    row.cgal_times = cgal_times;
    if(!cgal_agrees && row.ok) {
      row.ok = false;
      row.failure = "CGAL's own repetitions disagree";
    }
    for(const Signature& s : results[j])
      if(s != reference && row.ok) {
        row.ok = false;
        row.failure = "ours: " + s.str() + "; CGAL: " + reference.str();
      }
  }
}

// The same with one call of ours.
template <class Cgal, class Ours>
void measure(int reps, Row& row, Cgal cgal, Ours ours)
{
  measure_all(reps, {&row}, cgal, {Our_call(ours)});
}

// --threads: the number of threads of the parallel calls (0: none).
int parallel_threads = 0;

// Runs call() in a TBB arena of parallel_threads threads.
template <class Call>
double in_arena(const Call& call)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena arena(parallel_threads);
  return arena.execute(call);
#else
  return call();
#endif
}

// The row of the parallel twin of `row`.
Row parallel_row(Row row)
{
  row.param += " | par " + std::to_string(parallel_threads);
  return row;
}

// Reports `rows`, and, for each pair (sequential, parallel) in `pairs`, the speed-up of the
// parallel call over the sequential one (ratio of their medians in the same repetitions).
void report_with_speedups(Report& report, const std::vector<Row>& rows,
                          const std::vector<std::pair<std::size_t, std::size_t>>& pairs)
{
  for(const Row& row : rows)
    report.add(row);
  for(const auto& p : pairs)
    std::printf("%19s%s: Parallel_tag on %d threads %.2f times as fast as sequential\n", "",
                rows[p.first].param.c_str(), parallel_threads,
                median(rows[p.first].our_times) / median(rows[p.second].our_times));
  std::fflush(stdout);
}

// Measures `ours` (a call taking the concurrency tag: ours(tag, stats, signature)) against
// CGAL's build `cgal` and reports it; with --threads, also the call with CGAL::Parallel_tag in
// an arena of that many threads, in the same repetitions.
template <class Cgal, class Ours>
void measure_and_report(int reps, Report& report, const Row& row, Cgal cgal, Ours ours)
{
  std::vector<Row> rows{row};
  std::vector<Our_call> calls{[&](DFP::Statistics& st, Signature& s) { return ours(CGAL::Sequential_tag(), st, s); }};
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel_threads > 0) {
    rows.push_back(parallel_row(row));
    calls.push_back([&](DFP::Statistics& st, Signature& s) {
      return in_arena([&] { return ours(CGAL::Parallel_tag(), st, s); });
    });
  }
#endif
  std::vector<Row*> pointers;
  for(Row& r : rows)
    pointers.push_back(&r);
  measure_all(reps, pointers, cgal, calls);
  report_with_speedups(report, rows, rows.size() > 1 ? std::vector<std::pair<std::size_t, std::size_t>>{{0, 1}}
                                                     : std::vector<std::pair<std::size_t, std::size_t>>{});
}

// A delaunay_from_prediction() case: CGAL builds `points` from scratch, we build them from
// `faces`.
void measure_prediction(int reps, Report& report, const Row& row, const std::vector<Point>& points,
                        const std::vector<Face>& faces)
{
  measure_and_report(reps, report, row, [&](Signature& s) { return time_cgal(points, s); },
                     [&](auto tag, DFP::Statistics& st, Signature& s) {
                       DT dt;
                       return time_call(dt, [&] { st = DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt); }, s);
                     });
}

std::string percent(double f)
{
  std::ostringstream s;
  s << f * 100 << "%";
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// One (distribution, n): all requested cases.
void run(const Options& o, const std::string& dist, std::size_t n, Report& report)
{
  const int reps = o.reps;
  const std::vector<Point> points = make_points(dist, n, o.seed);
  if(const std::size_t d = count_duplicates(points))
    std::printf("# note: %s n=%zu has %zu duplicate points\n", dist.c_str(), n, d);

  // The Delaunay triangulation of `points`, with point indices (set-up, untimed).
  DTI indexed;
  if(o.wants("shuffled") || o.wants("flips") || o.wants("move") || o.wants("memory") ||
     o.wants("kinetic") || o.wants("deleted"))
    indexed = build_indexed(points);

  auto new_row = [&](const std::string& kase, const std::string& param) {
    Row row;
    row.dist = dist;
    row.n = n;
    row.kase = kase;
    row.param = param;
    return row;
  };

  // 1. D = 0, shuffled faces, points in random order.
  std::vector<Face> shuffled_faces;
  if(o.wants("shuffled") || o.wants("memory")) {
    Rng rng{seed_for(o.seed, "shuffled/" + dist, n)};
    shuffled_faces = export_faces(indexed);
    shuffle_faces(shuffled_faces, rng);
  }
  if(o.wants("shuffled")) {
    measure_prediction(reps, report, new_row("shuffled", "D=0, random order"), points, shuffled_faces);
  }

  // 2. D = 0, coherent: Hilbert-sorted points, faces in the order CGAL's DT of the sorted points
  //    iterates them (indices into the sorted points). CGAL builds from the sorted points.
  if(o.wants("hilbert")) {
    std::vector<Point> sorted = points;
    CGAL::hilbert_sort(sorted.begin(), sorted.end());
    std::vector<Face> mesh_faces;
    {
      const DTI t = build_indexed(sorted);
      mesh_faces = export_faces(t);
    }
    measure_prediction(reps, report, new_row("hilbert", "D=0, Hilbert + mesh order"), sorted, mesh_faces);
  }

  // 3. k random flips of the DT, faces in random order.
  if(o.wants("flips")) {
    for(double fraction : {0.001, 0.01, 0.1}) {
      const std::size_t k = std::max<std::size_t>(1, std::size_t(std::llround(fraction * double(n))));
      Rng rng{seed_for(o.seed, "flips/" + dist + "/" + std::to_string(k), n)};
      std::vector<Face> faces;
      std::size_t made = 0;
      {
        DTI flipped = indexed;
        made = random_flips(flipped, k, rng);
        faces = export_faces(flipped);
      }
      shuffle_faces(faces, rng);
      measure_prediction(reps, report, new_row("flips", "k=" + percent(fraction) + " n (" + std::to_string(made) + ")"),
                         points, faces);
    }
  }

  // 4. make_delaunay() after moving every point by sigma x mean nearest-neighbour distance, in
  //    a direction drawn from the point's coordinates. Every repetition copies CGAL's DT of the
  //    points and moves its vertices (untimed), then times make_delaunay() alone. CGAL builds
  //    the moved points from scratch.
  if(o.wants("move")) {
    const double nn = mean_nearest_neighbour_distance(indexed);
    const DT base(points.begin(), points.end());
    const std::uint64_t salt = seed_for(o.seed, "move/" + dist, n);
    // 0.0001 turns no face over; at 1e5 points and more, 0.001 already turns over a few of the
    // skinniest faces, which the local repair (carve_repair.h) takes care of.
    for(double sigma : {0.0001, 0.001, 0.01, 0.1, 0.5}) {
      const double step = sigma * nn;
      std::vector<Point> moved_points(points.size());
      for(std::size_t i = 0; i < points.size(); ++i)
        moved_points[i] = moved(points[i], step, salt);
      std::ostringstream param;
      param << "sigma=" << sigma << " (" << std::setprecision(2) << step << ")";
      measure_and_report(reps, report, new_row("move", param.str()),
                         [&](Signature& s) { return time_cgal(moved_points, s); },
                         [&](auto tag, DFP::Statistics& st, Signature& s) {
                           DT tr = base;
                           for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
                             v->set_point(moved(v->point(), step, salt));
                           return time_call(tr, [&] { st = DFP::make_delaunay<decltype(tag)>(tr); }, s);
                         });
    }
  }

  // 5. Random triples.
  if(o.wants("random")) {
    Rng rng{seed_for(o.seed, "random/" + dist, n)};
    const std::vector<Face> faces = random_triples(n, 2 * n - 5, rng);
    measure_prediction(reps, report, new_row("random", "2n-5 random triples"), points, faces);
  }

  // 6. Peak heap of case 1 (the prediction used) and of case 5 (the fallback: under
  //    Parallel_tag the region build) (see namespace counting): ours vs CGAL's from-scratch
  //    build, each measured once (the counts are deterministic), triangulation construction
  //    included.
  if(o.wants("memory")) {
    Signature reference;
    std::size_t cgal_bytes = 0;
    {
      counting::Peak_scope scope;
      DT dt;
      dt.insert(points.begin(), points.end());
      cgal_bytes = scope.bytes();
      reference = signature(dt);
    }
    auto measure_memory = [&](const std::string& param, const std::vector<Face>& faces) {
      Row row = new_row("memory", param);
      row.memory = true;
      row.cgal_bytes = cgal_bytes;
      Signature s;
      {
        counting::Peak_scope scope;
        DT dt;
        try {
          row.stats = DFP::delaunay_from_prediction(points, faces, dt);
          row.has_stats = true;
        } catch(const std::exception& e) {
          row.ok = false;
          row.failure = std::string("exception: ") + e.what();
        }
        row.our_bytes = scope.bytes();
        s = signature(dt);
      }
      if(row.ok && s != reference) {
        row.ok = false;
        row.failure = "ours: " + s.str() + "; CGAL: " + reference.str();
      }
      report.add(row);
#ifdef CGAL_LINKED_WITH_TBB
      if(parallel_threads > 0) { // the same call with CGAL::Parallel_tag in the arena
        Row par = parallel_row(row);
        {
          counting::Peak_scope scope;
          DT dt;
          in_arena([&] {
            par.stats = DFP::delaunay_from_prediction<CGAL::Parallel_tag>(points, faces, dt);
            return 0.;
          });
          par.our_bytes = scope.bytes();
          s = signature(dt);
        }
        par.ok = s == reference;
        if(!par.ok)
          par.failure = "ours: " + s.str() + "; CGAL: " + reference.str();
        report.add(par);
      }
#endif
    };
    measure_memory("peak heap, shuffled", shuffled_faces);
    Rng rng{seed_for(o.seed, "random/" + dist, n)}; // the triples of case 5
    measure_memory("peak heap, random triples", random_triples(n, 2 * n - 5, rng));
  }

  // 7. Kinetic: make_delaunay() on CGAL's DT with point indices in info(), every vertex moved
  //    by noise of scale sigma x mean spacing (point i by the i-th draw, the same field for
  //    every sigma), strategies carve, t_division and flips. Every repetition copies the moved DT and
  //    times make_delaunay() alone. CGAL builds the moved points from scratch (plain DT, range
  //    insert), its repetitions shared by both strategies.
  const std::size_t t = o.region_size != 0 ? o.region_size : DFP::internal::default_region_size(n);
  if(o.wants("kinetic")) {
    const double spacing = mean_spacing(points);
    for(const std::string& noise : o.noises) {
      const std::uint64_t noise_seed = seed_for(o.seed, "kinetic/" + dist + "/" + noise, n);
      for(double sigma : {0.001, 0.01, 0.1, 0.5, 1.0}) {
        const double step = sigma * spacing;
        const std::vector<Point> moved_points = noisy_points(points, noise, step, noise_seed);
        DTI moved_tr = indexed;
        for(auto v = moved_tr.finite_vertices_begin(); v != moved_tr.finite_vertices_end(); ++v)
          v->set_point(moved_points[v->info()]);
        const auto damage = inverted_and_flat_faces(moved_tr);
        std::vector<Row> rows;
        std::vector<Our_call> calls;
        std::vector<std::pair<std::size_t, std::size_t>> pairs; // (sequential, parallel) rows
        for(const Named_strategy& st : repair_strategies) {
          if(!o.runs(st.name))
            continue;
          std::ostringstream param;
          param << "sigma=" << sigma << " " << (noise == "gaussian" ? "gauss" : noise) << ", "
                << st.name;
          Row row = new_row("kinetic", param.str());
          row.strategy = st.name;
          row.repair_details = true;
          row.inverted = (long long)damage.first;
          row.flat = (long long)damage.second;
          const DFP::Strategy strategy = st.strategy;
          // Strategy::regions takes its own default region size (it depends on the threads).
          const std::size_t t_of_call = strategy == DFP::Strategy::regions ? o.region_size : t;
          auto call = [&moved_tr, strategy, t_of_call](auto tag, DFP::Statistics& stats, Signature& s) {
            DTI tr = moved_tr; // untimed copy
            return time_call(
                tr,
                [&] {
                  stats = t_of_call == 0
                              ? DFP::make_delaunay<decltype(tag)>(tr, DFP::parameters::strategy(strategy))
                              : DFP::make_delaunay<decltype(tag)>(
                                    tr, DFP::parameters::strategy(strategy, DFP::parameters::region_size(t_of_call)));
                },
                s);
          };
          rows.push_back(row);
          calls.push_back([call](DFP::Statistics& stats, Signature& s) { return call(CGAL::Sequential_tag(), stats, s); });
#ifdef CGAL_LINKED_WITH_TBB
          if(parallel_threads > 0) {
            pairs.emplace_back(rows.size() - 1, rows.size());
            rows.push_back(parallel_row(row));
            calls.push_back([call](DFP::Statistics& stats, Signature& s) {
              return in_arena([&] { return call(CGAL::Parallel_tag(), stats, s); });
            });
          }
#endif
        }
        std::vector<Row*> row_pointers;
        for(Row& row : rows)
          row_pointers.push_back(&row);
        measure_all(reps, row_pointers, [&](Signature& s) { return time_cgal(moved_points, s); }, calls);
        report_with_speedups(report, rows, pairs);
      }
    }
  }

  // 8. Deleted faces: the Delaunay faces, each deleted with probability 1% or 10%, the rest
  //    shuffled (as in case 3), strategies carve, t_division and flips. CGAL builds the points
  //    from scratch, its repetitions shared by the strategies.
  if(o.wants("deleted")) {
    for(double fraction : {0.01, 0.1}) {
      Rng rng{seed_for(o.seed, "deleted/" + dist + "/" + percent(fraction), n)};
      std::vector<Face> faces;
      const std::vector<Face> all = export_faces(indexed);
      for(const Face& f : all)
        if(!(rng.uniform() < fraction))
          faces.push_back(f);
      shuffle_faces(faces, rng);
      std::vector<Row> rows;
      std::vector<Our_call> calls;
      for(const Named_strategy& st : repair_strategies) {
        if(!o.runs(st.name))
          continue;
        Row row = new_row("deleted", percent(fraction) + " of faces, " + st.name);
        row.strategy = st.name;
        row.repair_details = true;
        row.deleted = (long long)(all.size() - faces.size());
        rows.push_back(row);
        const DFP::Strategy strategy = st.strategy;
        calls.push_back([&points, &faces, strategy, t](DFP::Statistics& stats, Signature& s) {
          return time_prediction(points, faces, stats, s,
                                 DFP::parameters::strategy(strategy, DFP::parameters::region_size(t)));
        });
      }
      std::vector<Row*> row_pointers;
      for(Row& row : rows)
        row_pointers.push_back(&row);
      measure_all(reps, row_pointers, [&](Signature& s) { return time_cgal(points, s); }, calls);
      for(const Row& row : rows)
        report.add(row);
    }
  }
}

} // namespace

int main(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  parallel_threads = o.threads;

  // Allocator policy (see keep_freed_memory()), fixed before the first allocation of any input.
  std::string policy = "glibc default (mmap threshold and trimming as glibc decides)";
  if(o.malloc_policy == "keep") {
    const bool ok = keep_freed_memory();
    policy = ok ? "keep: mallopt(M_MMAP_MAX, 0) + mallopt(M_TRIM_THRESHOLD, -1): no mmap'd blocks, "
                  "freed memory is never returned to the OS and is reused"
                : "keep requested but mallopt FAILED: glibc default in effect";
  }

  std::string command;
  for(int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const bool quote = a.empty() || a.find_first_of(" \t'\"$\\") != std::string::npos;
    command += (i ? " " : "") + (quote ? "'" + a + "'" : a);
  }
  cpu_set_t set;
  int cpus_allowed = 0;
  if(sched_getaffinity(0, sizeof set, &set) == 0)
    cpus_allowed = CPU_COUNT(&set);
  const std::string date = local_date_time();
  std::string sizes, dists, cases;
  for(std::size_t n : o.sizes)
    sizes += (sizes.empty() ? "" : ",") + std::to_string(n);
  for(const auto& d : o.dists)
    dists += (dists.empty() ? "" : ",") + d;
  for(const auto& c : o.cases)
    cases += (cases.empty() ? "" : ",") + c;
  std::string noises;
  for(const auto& d : o.noises)
    noises += (noises.empty() ? "" : ",") + d;

  std::ostringstream header;
  header << "Delaunay_from_prediction benchmark, " << date << "\n"
         << "command:  " << command << "\n"
         << "machine:  nproc " << cpus_allowed << " (online " << sysconf(_SC_NPROCESSORS_ONLN)
         << "), CPU " << read_first("/proc/cpuinfo", "model name") << ", RAM "
         << read_first("/proc/meminfo", "MemTotal") << ", loadavg " << read_line("/proc/loadavg") << "\n"
         << "build:    " << build_description() << "\n"
         << "setup:    Epick, CGAL::Delaunay_triangulation_2<Epick> for CGAL and for us, one thread,\n"
         << "          CGAL::Real_timer (wall clock), median of " << o.reps << " repetition(s), seed "
         << o.seed << "\n"
         << "n:        " << sizes << "    dist: " << dists << "    cases: " << cases << "\n"
         << "malloc:   " << policy << "\n"
         << "memory:   peak bytes held through a counting global operator new/delete (malloc_usable_size)\n"
         << "          during the call, minus those held when it started: result included, inputs excluded\n"
         << "ratio:    median CGAL from-scratch time / median ours (> 1: we are faster). CGAL: range\n"
         << "          insert of the same points (hilbert: the sorted points; move, kinetic: the moved\n"
         << "          points), its repetitions interleaved with ours. path: predict = prediction used,\n"
         << "          FALLBACK = built from scratch, repair = used after local repair (faces carved or\n"
         << "          holes refilled). D_local: predicted edges not locally Delaunay. flips: flips made.\n";
  if(o.wants("kinetic") || o.wants("deleted"))
    header << "repair:   kinetic and deleted time strategies carve, t_division and flips (no local repair) in\n"
           << "          the same repetitions, against the same CGAL times. Second line: the damage\n"
           << "          before the call and the call's statistics; us/reinserted pt = median time of the\n"
           << "          whole call / points reinserted (an upper bound of the cost per point).\n";
  if(o.wants("kinetic"))
    header << "kinetic:  ours: make_delaunay() on a DT<Epick> with vertex info (point index) whose points\n"
           << "          moved by " << noises << " noise of scale sigma x sqrt(bounding box area / n);\n"
           << "          each repetition copies the moved DT (untimed). inverted/flat: finite faces of\n"
           << "          the moved DT that are clockwise or flat.\n";
  if(o.threads > 0)
    header << "threads:  rows '| par " << o.threads << "': the same call with CGAL::Parallel_tag in a tbb::task_arena of "
           << o.threads << " threads,\n"
           << "          in the same repetitions; CGAL's build stays sequential (it has no parallel 2D build)\n";
  header << "check:    every result of ours vs CGAL's: counts + hash of the face set (untimed)\n";
  std::printf("%s\n", header.str().c_str());
  Report report(o.csv);
  if(report.csv()) {
    std::istringstream lines(header.str());
    std::string line;
    while(std::getline(lines, line))
      report.csv() << "# " << line << '\n';
    report.csv() << "dist,n,case,param,reps,cgal_s,ours_s,ratio,cgal_all_s,ours_all_s,fell_back,"
                    "fallback_reason,flips,faces_in,faces_certified,points_reinserted,edges_tested,"
                    "edges_not_locally_delaunay,points_unused,cgal_peak_bytes,ours_peak_bytes,"
                    "mem_ratio_ours_over_cgal,check,strategy,inverted_faces_before,flat_faces_before,"
                    "faces_deleted,faces_carved,holes_refilled,carve_rounds,us_per_reinserted_point\n";
  }
  report.table_header();

  CGAL::Real_timer total;
  total.start();
  for(std::size_t n : o.sizes)
    for(const std::string& dist : o.dists)
      run(o, dist, n, report);
  total.stop();

  std::printf("\ntotal %.1f s. ", total.time());
  if(report.failures() == 0) {
    std::printf("All checks passed (every result equal to CGAL's).\n");
    return 0;
  }
  std::printf("!!!!!!!! %d CHECK(S) FAILED !!!!!!!!\n", report.failures());
  std::fprintf(stderr, "!!!!!!!! %d CHECK(S) FAILED !!!!!!!!\n", report.failures());
  return 1;
}
