// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Helpers of the differential fuzzer (test_fuzz_differential.cpp): a case (plain data, so that
// it can be minimized and printed), the families it is drawn from, and the crash-safe runner
// (cases run in a forked child; a crash or a hang is reported with its seed and case number).

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_FUZZ_UTIL_H
#define CGAL_DELAUNAY_FROM_PREDICTION_FUZZ_UTIL_H

#include "test_util.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace dfp_fuzz {

using dfp_test::XY;
using dfp_test::XYs;
using Tri = std::array<long long, 3>; // a face; an edge has [2] == -1
using Tris = std::vector<Tri>;

enum Entry {
  E_DFP, E_MD, E_EDGES, E_SG, E_EMST, E_RNG, E_GABRIEL, E_IMPRECISE, E_SPLIT, E_BRIO, E_MALFORMED, E_PERIODIC, E_COUNT
};
inline const char* const entry_names[E_COUNT] = {"dfp",   "make_delaunay", "predicted_edges", "spanning_graph",
                                                 "emst",  "rng",           "gabriel",         "imprecise",
                                                 "split", "brio_dc",       "malformed",       "periodic"};
enum Kernel { K_EPICK, K_EPECK, K_SC, K_COUNT };
inline const char* const kernel_names[K_COUNT] = {"epick", "epeck", "sc"};
enum Output { O_INFO, O_PLAIN, O_HIER, O_COUNT };
inline const char* const output_names[O_COUNT] = {"info", "plain", "hierarchy"};

enum Point_family {
  P_UNIFORM, P_CLUSTERED, P_GRID, P_CIRCLE, P_COLLINEAR_H, P_COLLINEAR_V, P_COLLINEAR_D, P_DUPLICATES,
  P_HUGE, P_TINY, P_DENORMAL, P_OFFSET, P_FEW, P_COUNT
};
inline const char* const point_family_names[P_COUNT] = {
    "uniform", "clustered", "grid", "circle", "collinear_h", "collinear_v", "collinear_diag", "duplicates",
    "huge(1e300,1e160)", "tiny(1e-300,2.2e-308)", "denormal(2^-1022,2^-1020)", "offset(1e15)", "few(0-4)"};

enum Pred_family {
  F_EXACT, F_FLIPS, F_DELETED, F_DUPLICATED, F_FOREIGN, F_GARBAGE, F_SUBSET, F_OVERLAP, F_EMPTY, F_MOVED,
  F_CROSSING, // faces
  F_MD_NONE, F_MD_LITTLE, F_MD_LOT, F_MD_ONTO, F_MD_DIMENSION, // make_delaunay moves
  F_G_DT, F_G_EMST, F_G_TREE, F_G_GRAPH, F_G_CROSSING, F_G_EMPTY, // graphs
  F_I_INSIDE, F_I_ON, F_I_OUTSIDE, F_I_MIXED, // imprecise instances
  F_S_RANDOM, F_S_ALL, F_S_HALFPLANE, // split partitions
  F_NONE, // brio
  F_M_RANGE, F_M_NEGATIVE, F_M_REPEAT, F_M_NAN, F_M_INF, F_M_EDGE_RANGE, F_M_EDGE_LOOP, F_M_IMPRECISE,
  F_M_BRIO, // malformed
  F_COUNT
};
inline const char* const pred_family_names[F_COUNT] = {
    "faces:exact_shuffled", "faces:k_flips", "faces:deleted", "faces:duplicated", "faces:foreign",
    "faces:garbage", "faces:subset", "faces:overlapping", "faces:empty", "faces:moved_points",
    "faces:self_crossing", "moves:none", "moves:little", "moves:lot", "moves:onto_vertex", "moves:dimension",
    "graph:dt_edges", "graph:emst", "graph:random_tree", "graph:random_graph", "graph:crossing", "graph:empty",
    "disks:inside", "disks:on", "disks:outside", "disks:mixed", "split:random", "split:all_one_side",
    "split:half_plane", "none", "bad:index_range", "bad:negative_index", "bad:repeated_index", "bad:nan",
    "bad:inf", "bad:edge_range", "bad:edge_loop", "bad:imprecise_nan", "bad:brio_inf"};

// A case: plain data, fully determining the call (no hidden randomness), so that dropping
// points or faces gives another valid case.
struct Case
{
  int entry = E_DFP, kernel = K_EPICK, output = O_INFO;
  int point_family = P_UNIFORM, pred_family = F_EXACT;
  int strategy = -1;          // Strategy value, -1: not given
  long long max_flips = -1;   // -1: not given
  long long region_size = -1; // -1: not given
  int split_method = -1;      // Split_method value, -1: not given
  bool screen = true;         // screen_prediction
  bool t2 = false;            // make_delaunay on a plain Triangulation_2
  bool parallel = false;      // called with CGAL::Parallel_if_available_tag (the prediction entry points, make_delaunay)
  long long region_block_points = -1; // with `parallel`: Block_build_thresholds::min_points_per_block (-1: default)
  unsigned param_seed = 0;    // random_seed for brio / split (0: not given)
  double sample_probability = -1;
  XYs pts;                    // points; make_delaunay: initial points; imprecise: centres
  XYs pts2;                   // make_delaunay: moved points; imprecise: the instance
  std::vector<double> radii;  // imprecise
  std::vector<int> part;      // split
  Tris faces;                 // faces, or edges ([2] == -1)
};

inline std::string describe(const Case& c)
{
  std::ostringstream s;
  const char* const move_names[] = {"little", "a_lot", "onto_another"}; // the periodic entry's `output`
  s << "entry=" << entry_names[c.entry] << " kernel=" << kernel_names[c.kernel]
    << (c.entry == E_PERIODIC ? " moves=" : " output=")
    << (c.entry == E_PERIODIC ? move_names[c.output] : output_names[c.output])
    << " points=" << point_family_names[c.point_family]
    << " prediction=" << pred_family_names[c.pred_family] << " n=" << c.pts.size() << " faces=" << c.faces.size();
  if(c.strategy >= 0) s << " strategy=" << c.strategy;
  if(c.max_flips >= 0) s << " max_flips=" << c.max_flips;
  if(c.region_size >= 0) s << " region_size=" << c.region_size;
  if(c.split_method >= 0) s << " split_method=" << c.split_method;
  if(!c.screen) s << " screen_prediction=false";
  if(c.t2) s << " triangulation=Triangulation_2";
  if(c.parallel) s << " concurrency=Parallel_if_available_tag";
  if(c.region_block_points >= 0) s << " region_block_points=" << c.region_block_points;
  if(c.param_seed) s << " random_seed=" << c.param_seed;
  if(c.sample_probability > 0) s << " sample_probability=" << c.sample_probability;
  return s.str();
}

inline void print_xys(std::ostream& out, const char* name, const XYs& xy)
{
  out << "std::vector<std::array<double, 2>> " << name << " = {";
  char buf[96];
  for(std::size_t i = 0; i < xy.size(); ++i) {
    std::snprintf(buf, sizeof buf, "{%.17g, %.17g}", xy[i].x, xy[i].y);
    out << (i ? ", " : "") << buf;
  }
  out << "};\n";
}

// The case as C++ initializers, ready to paste into a test.
inline std::string as_cpp(const Case& c)
{
  std::ostringstream out;
  out << "// " << describe(c) << "\n";
  print_xys(out, c.entry == E_MD ? "initial_points" : c.entry == E_IMPRECISE ? "centres" : "points", c.pts);
  if(!c.pts2.empty() || c.entry == E_MD || c.entry == E_IMPRECISE)
    print_xys(out, c.entry == E_MD ? "moved_points" : "instance", c.pts2);
  if(!c.radii.empty()) {
    out << "std::vector<double> radii = {";
    char buf[48];
    for(std::size_t i = 0; i < c.radii.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g", c.radii[i]);
      out << (i ? ", " : "") << buf;
    }
    out << "};\n";
  }
  if(!c.part.empty()) {
    out << "std::vector<int> part = {"; // 0: in the first part (is_in_first true)
    for(std::size_t i = 0; i < c.part.size(); ++i)
      out << (i ? ", " : "") << c.part[i];
    out << "};\n";
  }
  const bool edges = !c.faces.empty() && c.faces[0][2] == -1;
  if(c.entry != E_MD && c.entry != E_IMPRECISE && c.entry != E_SPLIT && c.entry != E_BRIO) {
    out << (edges ? "std::vector<std::array<long long, 2>> edges = {" : "std::vector<std::array<long long, 3>> faces = {");
    for(std::size_t i = 0; i < c.faces.size(); ++i) {
      out << (i ? ", " : "") << "{" << c.faces[i][0] << ", " << c.faces[i][1];
      if(!edges)
        out << ", " << c.faces[i][2];
      out << "}";
    }
    out << "};\n";
  }
  return out.str();
}

// Drops point i everywhere (faces using it are dropped, higher indices shift down; indices out
// of range stay out of range).
inline void drop_point(Case& c, std::size_t i)
{
  auto erase = [&](auto& v) {
    if(i < v.size())
      v.erase(v.begin() + std::ptrdiff_t(i));
  };
  const std::size_t n = c.pts.size();
  erase(c.pts);
  if(c.pts2.size() == n)
    erase(c.pts2);
  if(c.radii.size() == n)
    erase(c.radii);
  if(c.part.size() == n)
    erase(c.part);
  Tris kept;
  for(Tri t : c.faces) {
    bool uses = false;
    for(int j = 0; j < 3; ++j)
      uses = uses || (t[j] == (long long)i && !(j == 2 && t[2] == -1));
    if(uses)
      continue;
    for(int j = 0; j < 3; ++j)
      if(t[j] > (long long)i)
        --t[j];
    kept.push_back(t);
  }
  c.faces = kept;
}

// ---------------------------------------------------------------------------------------------
// Shared counters (the runner's children write them; the parent reads them after a crash).
// ---------------------------------------------------------------------------------------------

struct Signature
{
  char key[160];
  long long count;
  long long first_case;
};

struct Shared
{
  long long current_case;
  long long cases, failures;
  long long by_entry[E_COUNT][2];
  long long by_points[P_COUNT][2];
  long long by_pred[F_COUNT][2];
  long long by_kernel[K_COUNT][2];
  // Simple_cartesian<double> results (exact, as the oracle checks) that the kernel's own
  // inexact is_valid() rejects, for information: not a failure (see the manual, Inexact kernels).
  long long inexact_checked, inexact_not_valid;
  int signatures;
  Signature signature[256];
};

inline Shared* shared_memory()
{
  static Shared* s = [] {
    void* p = mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if(p == MAP_FAILED) {
      std::perror("mmap");
      std::exit(2);
    }
    std::memset(p, 0, sizeof(Shared));
    return static_cast<Shared*>(p);
  }();
  return s;
}

// Records a failure signature; true if it is new (then the caller minimizes and prints it).
inline bool record_signature(const std::string& key, long long case_index)
{
  Shared* s = shared_memory();
  for(int i = 0; i < s->signatures; ++i)
    if(key == s->signature[i].key) {
      ++s->signature[i].count;
      return false;
    }
  if(s->signatures < 256) {
    Signature& g = s->signature[s->signatures++];
    std::snprintf(g.key, sizeof g.key, "%s", key.c_str());
    g.count = 1;
    g.first_case = case_index;
  }
  return true;
}

// Runs body() in a child (stderr and stdout silenced) and returns what it wrote to a pipe: its
// failure signature, "" for a pass, or "crash:SIGNAME" if it died.
template <class F>
std::string in_child(const F& body, unsigned timeout_s)
{
  int fd[2];
  if(pipe(fd) != 0)
    return "";
  std::cout.flush();
  std::cerr.flush();
  const pid_t child = fork();
  if(child == 0) {
    close(fd[0]);
    const int null = open("/dev/null", O_WRONLY);
    if(null >= 0) {
      dup2(null, 1);
      dup2(null, 2);
    }
    alarm(timeout_s);
    const std::string r = body();
    alarm(0);
    if(!r.empty())
      (void)!write(fd[1], r.data(), r.size());
    std::_Exit(0);
  }
  close(fd[1]);
  std::string got;
  char buf[512];
  for(ssize_t k; (k = read(fd[0], buf, sizeof buf)) > 0;)
    got.append(buf, std::size_t(k));
  close(fd[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if(WIFSIGNALED(status))
    return std::string("crash:") + (WTERMSIG(status) == SIGALRM ? "timeout" : strsignal(WTERMSIG(status)));
  return got;
}

// Greedy minimization: drops chunks of points (halving down to single points), then chunks of
// faces, while `fails` (the failure's signature is unchanged) holds. Bounded by `max_trials`.
template <class Fails>
Case minimize(Case c, const Fails& fails, int max_trials = 3000)
{
  int trials = 0;
  bool changed = true;
  while(changed && trials < max_trials) {
    changed = false;
    for(std::size_t chunk = std::max<std::size_t>(1, c.pts.size() / 2); chunk >= 1 && trials < max_trials; chunk /= 2) {
      for(std::size_t start = 0; start < c.pts.size() && trials < max_trials;) {
        Case d = c;
        const std::size_t end = std::min(c.pts.size(), start + chunk);
        for(std::size_t i = end; i-- > start;)
          drop_point(d, i);
        ++trials;
        if(fails(d)) {
          c = d;
          changed = true;
        } else
          start += chunk;
      }
      if(chunk == 1)
        break;
    }
    for(std::size_t chunk = std::max<std::size_t>(1, c.faces.size() / 2); chunk >= 1 && trials < max_trials; chunk /= 2) {
      for(std::size_t start = 0; start < c.faces.size() && trials < max_trials;) {
        Case d = c;
        const std::size_t end = std::min(c.faces.size(), start + chunk);
        d.faces.erase(d.faces.begin() + std::ptrdiff_t(start), d.faces.begin() + std::ptrdiff_t(end));
        ++trials;
        if(fails(d)) {
          c = d;
          changed = true;
        } else
          start += chunk;
      }
      if(chunk == 1)
        break;
    }
  }
  return c;
}

inline std::uint64_t splitmix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace dfp_fuzz

#endif // CGAL_DELAUNAY_FROM_PREDICTION_FUZZ_UTIL_H
