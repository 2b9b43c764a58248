// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Benchmark of the spanning-tree insertion (Section 3 of the paper): the Delaunay
// triangulation from a predicted tree or graph (delaunay_from_spanning_graph) and the EMST
// from a predicted tree, each as a ratio against CGAL in the same run.
//
// Rows, for each point distribution and n:
//   emst       the exact Euclidean minimum spanning tree as the prediction
//   wrong1/10  that tree with 1% / 10% of its edges replaced by random ones (still a tree)
//   random     a random spanning tree (each point joined to a random earlier one)
//   dt_edges   every edge of the Delaunay triangulation (a graph with cycles)
//   crossing1  the same with 1% of the points relabelled among themselves: a combinatorial
//              triangulation whose edges cross (Corollary 3.5, given as its edges)
//   faces0.1, faces0.3, faces1
//              the faces of the Delaunay triangulation with 0.1%, 0.3%, 1% of the points
//              relabelled (self-crossing faces), given to delaunay_from_prediction() with
//              its default strategy (local repair, or a rebuild in spatial order)
//   faces1_tree
//              the same as faces1 with Strategy::spanning_tree (built along the faces' edges)
// Columns: CGAL's range insert (spatial sort, then insertion), ours, our own from-scratch
// build (grid order, what the package falls back to), the ratios CGAL / ours, faces visited
// per located point, walks past their cap, whether the call fell back. Each result is checked
// against CGAL's (face set signature). Then the EMST row: euclidean_minimum_spanning_tree_
// from_prediction() from the exact EMST against CGAL's build + Kruskal over its edges sorted
// by squared length in double. Times are medians of --reps repetitions, the calls alternating.
//
// Point distributions: uniform in the unit square; clustered (1000 Gaussian clusters of
// standard deviation 0.002); graded (x = u^4, y = v^4: density varying over 8 orders of
// magnitude).

#include "benchmark_util.h"

#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace dfp_bench;

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
using Edges = std::vector<Edge>;

using DFP::internal::Union_find;

// Kruskal over the edges of `dt` (info = point index), as a user would write it: edges
// sorted by squared length in double, then by index pair (exact on these inputs, which have
// no ties).
template <class Tr>
Edges kruskal(const Tr& dt, const std::vector<Point>& points)
{
  std::vector<std::pair<double, Edge>> keyed;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const std::uint32_t a = e->first->vertex(dt.ccw(e->second))->info();
    const std::uint32_t b = e->first->vertex(dt.cw(e->second))->info();
    keyed.emplace_back(CGAL::squared_distance(points[a], points[b]), Edge((std::min)(a, b), (std::max)(a, b)));
  }
  std::sort(keyed.begin(), keyed.end());
  Edges edges;
  for(const auto& k : keyed)
    edges.push_back(k.second);
  Union_find uf(points.size());
  Edges tree;
  for(const Edge& e : edges)
    if(uf.join(e.first, e.second))
      tree.push_back(e);
  return tree;
}

Edges with_wrong_edges(Edges tree, double fraction, std::size_t n, Rng& rng)
{
  for(std::size_t k = tree.size(); k > 1; --k)
    std::swap(tree[k - 1], tree[rng.below(k)]);
  tree.erase(tree.begin(), tree.begin() + std::ptrdiff_t(fraction * double(tree.size())));
  Union_find uf(n);
  for(const Edge& e : tree)
    uf.join(e.first, e.second);
  while(tree.size() + 1 < n) {
    const std::uint32_t a = std::uint32_t(rng.below(n)), b = std::uint32_t(rng.below(n));
    if(uf.join(a, b))
      tree.emplace_back(a, b);
  }
  return tree;
}

void shuffle_edges(Edges& edges, Rng& rng)
{
  for(std::size_t k = edges.size(); k > 1; --k)
    std::swap(edges[k - 1], edges[rng.below(k)]);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> sizes = {"1e5", "1e6"}, dists = {"uniform", "clustered", "graded"},
                           cases = {"emst",      "wrong1",   "wrong10",  "random", "dt_edges",
                                    "crossing1", "faces0.1", "faces0.3", "faces1", "faces1_tree"};
  int reps = 3;
  std::string csv_file;
  std::uint64_t seed = 20261127;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--n")
      sizes = split(option_value(argc, argv, i));
    else if(a == "--dists")
      dists = split(option_value(argc, argv, i));
    else if(a == "--cases")
      cases = split(option_value(argc, argv, i));
    else if(a == "--reps")
      reps = std::max(1, std::atoi(option_value(argc, argv, i).c_str()));
    else if(a == "--csv")
      csv_file = option_value(argc, argv, i);
    else if(a == "--seed")
      seed = std::strtoull(option_value(argc, argv, i).c_str(), nullptr, 10);
    else {
      std::printf("usage: %s [--n 1e5,1e6] [--dists uniform,clustered,graded]\n"
                  "          [--cases emst,wrong1,wrong10,random,dt_edges,crossing1,faces0.1,faces0.3,faces1,\n"
                  "                   faces1_tree] [--reps 3] [--csv FILE] [--seed S]\n",
                  argv[0]);
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  const bool keep = keep_freed_memory();
  std::printf("# bench_spanning_tree, %s, %s, malloc policy %s, medians of %d\n", local_date_time().c_str(),
              build_description().c_str(), keep ? "keep" : "default", reps);
  std::printf("%-9s %-9s %-11s | %8s %8s %8s | %6s %6s | %6s %8s %3s %s\n", "dist", "n", "case", "CGAL s", "ours s",
              "rebuild", "ratio", "CGAL/rb", "f/pt", "capped", "fb", "check");
  std::FILE* csv = csv_file.empty() ? nullptr : std::fopen(csv_file.c_str(), "w");
  if(csv != nullptr)
    std::fprintf(csv, "dist,n,case,cgal_s,ours_s,rebuild_s,ratio,rebuild_ratio,faces_per_point,walk_fallbacks,"
                      "fell_back,same_as_cgal\n");
  bool all_same = true;
  for(const std::string& dist : dists) {
    for(const std::string& size : sizes) {
      const std::size_t n = std::size_t(std::atof(size.c_str()));
      const std::vector<Point> points = distribution_points(dist, n, salted_seed(0x5e77, seed, dist, n));
      const DTI reference = build_indexed(points);
      Signature cgal_sig;
      {
        DT d(points.begin(), points.end());
        cgal_sig = signature(d);
      }
      const Edges emst = kruskal(reference, points);
      Rng rng{salted_seed(0x7ee5, seed, dist, n)};
      for(const std::string& c : cases) {
        Edges prediction;
        std::vector<Face> faces; // the faces cases
        const bool faces_case = c.compare(0, 5, "faces") == 0;
        if(c == "emst")
          prediction = emst;
        else if(c == "wrong1")
          prediction = with_wrong_edges(emst, 0.01, n, rng);
        else if(c == "wrong10")
          prediction = with_wrong_edges(emst, 0.10, n, rng);
        else if(c == "random")
          for(std::uint32_t k = 1; k < n; ++k)
            prediction.emplace_back(k, std::uint32_t(rng.below(k)));
        else if(c == "dt_edges" || c == "crossing1" || faces_case) {
          // crossing1, facesX: 1% (X%) of the points exchange their labels (a random
          // permutation among them), so the triangulation's edges at those points cross others.
          std::vector<std::uint32_t> chosen;
          if(c != "dt_edges") {
            const std::uint64_t per_100000 = c == "faces0.1" ? 100 : c == "faces0.3" ? 300 : 1000;
            for(std::uint32_t k = 0; k < n; ++k)
              if(rng.below(100000) < per_100000)
                chosen.push_back(k);
          }
          const std::vector<std::uint32_t> label = permuted_among(n, chosen, rng);
          if(faces_case) {
            for(const Face& f : export_faces(reference))
              faces.push_back({label[f[0]], label[f[1]], label[f[2]]});
            shuffle_faces(faces, rng);
          } else {
            for(auto e = reference.finite_edges_begin(); e != reference.finite_edges_end(); ++e)
              prediction.emplace_back(label[e->first->vertex(DTI::ccw(e->second))->info()],
                                      label[e->first->vertex(DTI::cw(e->second))->info()]);
          }
        }
        else {
          std::fprintf(stderr, "unknown case %s\n", c.c_str());
          return 2;
        }
        shuffle_edges(prediction, rng);
        std::vector<double> t_cgal, t_ours, t_rebuild;
        DFP::Statistics stats;
        bool same = true;
        for(int r = 0; r < reps; ++r) {
          Signature sig;
          t_cgal.push_back(time_cgal(points, sig));
          {
            DT dt;
            const DFP::Strategy strategy = c == "faces1_tree" ? DFP::Strategy::spanning_tree : DFP::Strategy::automatic;
            t_ours.push_back(time_call(dt, [&] {
              stats = faces_case ? DFP::delaunay_from_prediction(points, faces, dt, DFP::parameters::strategy(strategy))
                                 : DFP::delaunay_from_spanning_graph(points, prediction, dt);
            }, sig));
            same = same && sig == cgal_sig;
          }
          {
            DFP::Statistics s2;
            t_rebuild.push_back(time_prediction(points, std::vector<Face>(), s2, sig));
            same = same && sig == cgal_sig;
          }
        }
        all_same = all_same && same;
        const double tc = median(t_cgal), to = median(t_ours), tr = median(t_rebuild);
        const double per_point = stats.points_located ? double(stats.faces_visited) / double(stats.points_located) : 0;
        std::printf("%-9s %-9s %-11s | %8.3f %8.3f %8.3f | %6.2f %6.2f | %6.2f %8zu %3s %s\n", dist.c_str(), size.c_str(),
                    c.c_str(), tc, to, tr, tc / to, tc / tr, per_point, stats.walk_fallbacks,
                    stats.fell_back ? "yes" : "no", same ? "same as CGAL" : "DIFFERENT");
        std::fflush(stdout);
        if(csv != nullptr)
          std::fprintf(csv, "%s,%zu,%s,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%zu,%d,%d\n", dist.c_str(), n, c.c_str(), tc, to,
                       tr, tc / to, tc / tr, per_point, stats.walk_fallbacks, int(stats.fell_back), int(same));
      }
      // EMST from the exact EMST as prediction, against CGAL's build + Kruskal.
      {
        Edges shuffled = emst;
        shuffle_edges(shuffled, rng);
        std::vector<double> t_cgal, t_ours;
        bool same = true;
        for(int r = 0; r < reps; ++r) {
          CGAL::Real_timer timer;
          timer.start();
          Edges from_cgal;
          {
            const DTI dt = build_indexed(points);
            from_cgal = kruskal(dt, points);
          }
          timer.stop();
          t_cgal.push_back(timer.time());
          timer.reset();
          timer.start();
          std::vector<std::pair<std::size_t, std::size_t>> ours;
          DFP::euclidean_minimum_spanning_tree_from_prediction(points, shuffled, std::back_inserter(ours));
          timer.stop();
          t_ours.push_back(timer.time());
          std::sort(from_cgal.begin(), from_cgal.end());
          same = same && ours.size() == from_cgal.size() &&
                 std::equal(ours.begin(), ours.end(), from_cgal.begin(), [](const auto& a, const Edge& b) {
                   return a.first == b.first && a.second == b.second;
                 });
        }
        all_same = all_same && same;
        const double tc = median(t_cgal), to = median(t_ours);
        std::printf("%-9s %-9s %-11s | %8.3f %8.3f %8s | %6.2f %6s | %6s %8s %3s %s\n", dist.c_str(), size.c_str(),
                    "EMST", tc, to, "-", tc / to, "-", "-", "-", "-", same ? "same as CGAL+Kruskal" : "DIFFERENT");
        if(csv != nullptr)
          std::fprintf(csv, "%s,%zu,EMST,%.4f,%.4f,,%.3f,,,,,%d\n", dist.c_str(), n, tc, to, tc / to, int(same));
      }
    }
  }
  if(csv != nullptr)
    std::fclose(csv);
  std::printf("# ratio = CGAL / ours; CGAL/rb = CGAL / our from-scratch build; f/pt = faces visited per located "
              "point; capped = walks past their cap; fb = fell back to the spatial-order insertion\n");
  return all_same ? 0 : 1;
}
