// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// A real mesher's output as the prediction: delaunay_from_prediction(points, faces, dt) on a
// mesh read from Triangle files (MESH.node, MESH.ele), against CGAL's from-scratch range
// insert of the same points, the two interleaved per repetition (CGAL first in even
// repetitions, ours first in odd ones) as in a program that allocates other things too; the
// medians of each and the median of the per-repetition ratios. glibc's allocator keeps its
// default policy unless --malloc keep. Every result is checked against CGAL's (the signature of
// benchmark_util.h), and once, outside the timers, as a set of index triples.
//
// The meshes: scripts/make_gmsh_plate.py (a plate with four holes, gmsh's Frontal-Delaunay;
// needs python3-gmsh). A mesh whose files are absent is skipped with a message.
//
// Usage: bench_mesh_prediction [--reps 9] [--malloc default|keep] MESH...
//   e.g. scripts/make_gmsh_plate.py 2e5 plate_2e5.node plate_2e5.ele
//        bench_mesh_prediction plate_2e5

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/file_io.h>

#include <iostream>

using namespace dfp_bench;

namespace {

void usage(const char* program)
{
  std::printf("usage: %s [--reps 9] [--malloc default|keep] MESH...\n"
              "  MESH: the prefix of Triangle files MESH.node and MESH.ele (scripts/make_gmsh_plate.py)\n",
              program);
}

// Finite faces of `t` as index triples, each rotated to start at its smallest index
// (orientation kept), sorted.
std::vector<Face> canonical_faces(const DTI& t)
{
  std::vector<Face> faces = export_faces(t);
  for(Face& f : faces)
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(faces.begin(), faces.end());
  return faces;
}

// False if the result differs from CGAL's; true, with a message, if the files are absent or
// unreadable (the mesh is skipped).
bool run_mesh(const std::string& mesh, int reps)
{
  std::vector<Point> points;
  std::vector<Face> faces;
  try {
    DFP::IO::read_points(mesh + ".node", points);
    for(const auto& t : DFP::IO::read_faces(mesh + ".ele", points.size()))
      faces.push_back({std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
  } catch(const std::exception& e) {
    std::printf("%s: skipped (%s; make it with scripts/make_gmsh_plate.py)\n", mesh.c_str(), e.what());
    return true;
  }
  // Once, untimed: our result as index triples, against CGAL's.
  DFP::Statistics stats;
  {
    DTI ours;
    stats = DFP::delaunay_from_prediction(points, faces, ours);
    const bool same = canonical_faces(ours) == canonical_faces(build_indexed(points));
    std::printf("%s: %zu points, %zu faces; index triples %s CGAL's\n  %s\n", mesh.c_str(), points.size(),
                faces.size(), same ? "equal to" : "DIFFERENT FROM", [&] {
                  std::ostringstream s;
                  s << stats;
                  std::string line = s.str();
                  std::replace(line.begin(), line.end(), '\n', ' ');
                  return line;
                }().c_str());
    if(!same)
      return false;
  }
  std::vector<double> cgal, ours, ratio;
  Signature reference, got;
  bool ok = true;
  for(int r = 0; r < reps; ++r) {
    double c = 0, o = 0;
    for(int turn = 0; turn < 2; ++turn)
      if((turn + r) % 2 == 0) {
        c = time_cgal(points, got);
        if(r == 0 && turn == 0)
          reference = got;
        ok = ok && got == reference;
      } else {
        o = time_prediction(points, faces, stats, got); // after CGAL's in repetition 0
        ok = ok && got == reference;
      }
    cgal.push_back(c);
    ours.push_back(o);
    ratio.push_back(c / o);
  }
  const auto [lo, hi] = std::minmax_element(ratio.begin(), ratio.end());
  std::printf("  CGAL %.4f s | ours %.4f s | ratio %.2f (median of %d; min %.2f, max %.2f) | %s\n", median(cgal),
              median(ours), median(ratio), reps, *lo, *hi, ok ? "ok" : "RESULT DIFFERS FROM CGAL'S");
  std::printf("  CGAL:");
  for(double t : cgal)
    std::printf(" %.4f", t);
  std::printf("\n  ours:");
  for(double t : ours)
    std::printf(" %.4f", t);
  std::printf("\n");
  std::fflush(stdout);
  return ok;
}

} // namespace

int main(int argc, char** argv)
{
  int reps = 9;
  bool keep = false;
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--malloc") {
      const std::string v = option_value(argc, argv, i);
      if(v != "keep" && v != "default") {
        usage(argv[0]);
        return 2;
      }
      keep = v == "keep";
    } else if(!a.empty() && a[0] != '-')
      meshes.push_back(a);
    else
      help_or_unknown(a, argv[0], usage);
  }
  if(meshes.empty()) {
    usage(argv[0]);
    return 2;
  }
  if(keep && !keep_freed_memory())
    keep = false;
  std::printf("# bench_mesh_prediction, %s, %s, machine: %s, malloc policy %s, one thread, Epick\n",
              local_date_time().c_str(), build_description().c_str(), read_first("/proc/cpuinfo", "model name").c_str(),
              keep ? "keep" : "default (no tuning)");
  bool ok = true;
  for(const std::string& mesh : meshes)
    ok = run_mesh(mesh, reps) && ok;
  return ok ? 0 : 1;
}
