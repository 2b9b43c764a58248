// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Periodic domains (periodic_2.h) against CGAL's Periodic_2_Delaunay_triangulation_2 built by
// range insertion from the same points, interleaved repetition by repetition (median of the
// per-repetition ratios): uniform points in the unit torus moved by Gaussian steps of a
// fraction of the spacing (wrapped into the domain), then
//  - make_delaunay(t) on the previous frame's triangulation whose points were moved with
//    set_point() (the moves are not timed, the call is);
//  - delaunay_from_prediction(points, faces, t) with the previous frame's faces as index
//    triples, and with the faces of the points' own Delaunay triangulation (D = 0);
// each result checked against CGAL's build as a set of (point index, offset) triples. Peak
// memory: the growth of the peak resident size over one call, in a fresh process.
// Usage: bench_periodic [--sizes 100000,1000000] [--moves 0.01,0.1,0.5] [--reps 5] [--seed S]

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/periodic_2.h>

#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>

#include <unistd.h>

#include <map>
#include <tuple>

using namespace dfp_bench;

namespace {

using Gt = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Gt, CGAL::Periodic_2_triangulation_vertex_base_2<Gt>>;
using P2DT2 = CGAL::Periodic_2_Delaunay_triangulation_2<
    Gt, CGAL::Triangulation_data_structure_2<Vb, CGAL::Periodic_2_triangulation_face_base_2<Gt>>>;
using Corner = std::tuple<std::uint32_t, int, int>;
using Triple = std::array<Corner, 3>;

// CGAL's build, each vertex's info() its point index.
void build_cgal(const std::vector<Point>& points, P2DT2& t)
{
  t.clear();
  t.insert(points.begin(), points.end());
}

void number_vertices(P2DT2& t, const std::vector<Point>& points)
{
  std::map<std::pair<double, double>, std::uint32_t> index;
  for(std::uint32_t i = 0; i < points.size(); ++i)
    index[{points[i].x(), points[i].y()}] = i;
  for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
    v->info() = index[{v->point().x(), v->point().y()}];
}

// The faces as (point index, offset) triples, offsets to least value 0, least corner first.
std::vector<Triple> triples_of(const P2DT2& t)
{
  std::vector<Triple> out;
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f) {
    Triple tr;
    int lx = 2, ly = 2;
    for(int i = 0; i < 3; ++i) {
      lx = (std::min)(lx, (f->offset(i) >> 1) & 1);
      ly = (std::min)(ly, f->offset(i) & 1);
    }
    for(int i = 0; i < 3; ++i)
      tr[i] = Corner{f->vertex(i)->info(), ((f->offset(i) >> 1) & 1) - lx, (f->offset(i) & 1) - ly};
    std::rotate(tr.begin(), std::min_element(tr.begin(), tr.end()), tr.end());
    out.push_back(tr);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Face> index_faces(const P2DT2& t)
{
  std::vector<Face> faces;
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f)
    faces.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return faces;
}

double wrap01(double x)
{
  double y = x - std::floor(x);
  return y < 1 ? y : 0;
}

std::vector<Point> moved(const std::vector<Point>& points, double sigma, Rng& rng)
{
  std::vector<Point> out;
  out.reserve(points.size());
  for(const Point& p : points)
    out.emplace_back(wrap01(p.x() + sigma * rng.normal()), wrap01(p.y() + sigma * rng.normal()));
  return out;
}

double seconds_of(const std::function<void()>& call)
{
  CGAL::Real_timer timer;
  timer.start();
  call();
  timer.stop();
  return timer.time();
}

// The resident size (KiB) named `key` ("VmRSS", "VmHWM") of this process.
long resident_kib(const char* key) { return std::atol(read_first("/proc/self/status", key).c_str()); }

// Peak memory of a call: the growth of the peak resident size over the call, measured in a
// fresh process (this program run again with --peak-of, so that no freed memory of earlier
// work is reused): it prepares the case's input, resets its peak to the current size, runs
// the call once and prints the growth in KiB.
long peak_growth_kib(int argc, char** argv, const std::string& which)
{
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if(length <= 0)
    return -1;
  self[length] = 0;
  std::string command = std::string("'") + self + "'";
  for(int i = 1; i < argc; ++i)
    command += std::string(" '") + argv[i] + "'";
  command += " --peak-of '" + which + "'";
  FILE* pipe = popen(command.c_str(), "r");
  long kib = -1;
  if(pipe != nullptr) {
    if(std::fscanf(pipe, "%ld", &kib) != 1)
      kib = -1;
    pclose(pipe);
  }
  return kib;
}

void usage(const char* program)
{
  std::printf("usage: %s [--sizes 100000,1000000] [--moves 0.01,0.1,0.5] [--reps 5] [--seed S]\n", program);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes{100000, 1000000};
  std::vector<double> moves{0.01, 0.1, 0.5};
  int reps = 5;
  std::uint64_t seed = 4601;
  std::string peak_of; // in a child run: "n/case" whose peak memory to print
  for(int i = 1; i < argc; ++i) {
    const std::string o = argv[i];
    if(o == "--sizes")
      sizes = sizes_of(option_value(argc, argv, i));
    else if(o == "--moves") {
      moves.clear();
      for(const std::string& m : split(option_value(argc, argv, i)))
        moves.push_back(std::stod(m));
    } else if(o == "--reps")
      reps = std::atoi(option_value(argc, argv, i).c_str());
    else if(o == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else if(o == "--peak-of")
      peak_of = option_value(argc, argv, i);
    else
      help_or_unknown(o, argv[0], usage);
  }
  if(peak_of.empty())
    keep_freed_memory();
  else
    std::freopen("/dev/null", "w", stderr);
  if(peak_of.empty())
  std::printf("# bench_periodic: CGAL %s, %s, %d repetitions, seed %llu\n", CGAL_VERSION_STR, local_date_time().c_str(),
              reps, static_cast<unsigned long long>(seed));
  if(peak_of.empty())
  std::printf("# ratio = CGAL's periodic build (range insertion) / the call, median over repetitions; "
              "peak = growth of the peak resident size over one call in a fresh process (MiB)\n");
  if(peak_of.empty())
  std::printf("%9s %-28s %9s %9s %7s %6s %9s %9s %9s %s\n", "n", "case", "cgal_s", "call_s", "ratio", "rebuilt",
              "flips", "peak_cgal", "peak_call", "outcome");
  if(peak_of.empty()) {
    // How many points it takes: the call writes its own faces (no rebuild) only when no empty
    // circle is wider than about 0.144 periods, so that CGAL's covering is surely 1-sheeted.
    std::printf("# D = 0 from index triples, 20 uniform point sets per size: how many the call wrote as a "
                "1-sheeted covering (the others CGAL built), and how many CGAL built 1-sheeted\n");
    for(const std::size_t n : {250, 500, 1000, 2000}) {
      int written = 0, cgal_one_sheeted = 0;
      for(int draw = 0; draw < 20; ++draw) {
        const std::vector<Point> points = uniform_points(n, seed + 1000 + std::uint64_t(draw));
        P2DT2 expected;
        build_cgal(points, expected);
        number_vertices(expected, points);
        P2DT2 t;
        const DFP::Statistics s = DFP::delaunay_from_prediction(points, index_faces(expected), t);
        written += s.fell_back ? 0 : 1;
        cgal_one_sheeted += expected.is_1_cover() ? 1 : 0;
        if(triples_of(t) != triples_of(expected))
          return 1;
      }
      std::printf("# n = %5zu: written by the call %2d of 20, CGAL's build 1-sheeted %2d of 20\n", n, written,
                  cgal_one_sheeted);
    }
  }
  for(const std::size_t n : sizes) {
    const std::vector<Point> points = uniform_points(n, seed);
    const double spacing = 1 / std::sqrt(double(n));
    P2DT2 before_t;
    build_cgal(points, before_t);
    number_vertices(before_t, points);
    const std::vector<Face> before_faces = index_faces(before_t);
    struct Case
    {
      std::string name;
      std::vector<Point> after;
      bool in_place;
      bool own_faces;
    };
    std::vector<Case> cases;
    cases.push_back({"D = 0, index triples", points, false, true});
    Rng rng{seed + n};
    for(const double m : moves) {
      char name[64];
      const std::vector<Point> after = moved(points, m * spacing, rng);
      std::snprintf(name, sizeof name, "moves %.2g sp., make_delaunay", m);
      cases.push_back({name, after, true, false});
      std::snprintf(name, sizeof name, "moves %.2g sp., index triples", m);
      cases.push_back({name, after, false, false});
    }
    for(const Case& c : cases) {
      const std::string id = std::to_string(n) + "/" + c.name;
      if(!peak_of.empty() && peak_of != id && peak_of != id + "/cgal")
        continue;
      P2DT2 expected_t;
      build_cgal(c.after, expected_t);
      number_vertices(expected_t, c.after);
      const std::vector<Triple> expected = triples_of(expected_t);
      std::vector<Face> own_faces;
      if(c.own_faces)
        own_faces = index_faces(expected_t);
      const std::vector<Face>& faces = c.own_faces ? own_faces : before_faces;
      std::vector<double> ratios, cgal_s, call_s;
      DFP::Statistics stats;
      bool exact = true;
      // The call's input, prepared before each repetition (not timed): for make_delaunay, the
      // previous frame's triangulation with its points moved.
      auto prepare = [&](P2DT2& t) {
        if(!c.in_place)
          return;
        t = before_t;
        for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
          v->set_point(c.after[v->info()]);
      };
      auto call = [&](P2DT2& t) {
        stats = c.in_place ? DFP::make_delaunay(t) : DFP::delaunay_from_prediction(c.after, faces, t);
      };
      if(!peak_of.empty()) { // the child run: one call, after its input, in this fresh process
        P2DT2 t;
        if(peak_of == id)
          prepare(t);
        std::ofstream("/proc/self/clear_refs") << "5"; // the peak resident size := the current one
        const long before = resident_kib("VmRSS");
        if(peak_of == id)
          call(t);
        else
          build_cgal(c.after, t);
        std::printf("%ld\n", resident_kib("VmHWM") - before);
        return 0;
      }
      for(int r = 0; r < reps; ++r) {
        P2DT2 cgal_t, t;
        const double a = seconds_of([&] { build_cgal(c.after, cgal_t); });
        prepare(t);
        const double b = seconds_of([&] { call(t); });
        if(r == 0) // delaunay_from_prediction() numbered the vertices; make_delaunay() kept their numbers
          exact = t.is_1_cover() == expected_t.is_1_cover() && triples_of(t) == expected;
        cgal_s.push_back(a);
        call_s.push_back(b);
        ratios.push_back(a / b);
      }
      const long peak_cgal = peak_growth_kib(argc, argv, id + "/cgal");
      const long peak_call = peak_growth_kib(argc, argv, id);
      std::printf("%9zu %-28s %9.3f %9.3f %7.2f %6s %9zu %9.1f %9.1f %s%s\n", n, c.name.c_str(), median(cgal_s),
                  median(call_s), median(ratios), stats.fell_back ? "yes" : "no", stats.flips, peak_cgal / 1024.,
                  peak_call / 1024., DFP::to_string(stats.outcome), exact ? "" : " MISMATCH");
      std::fflush(stdout);
      if(!exact)
        return 1;
    }
  }
  return 0;
}
