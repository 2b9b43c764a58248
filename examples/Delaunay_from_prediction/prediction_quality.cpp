// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// How good is a predictor? This example measures predictions of the Delaunay triangulation of
// random points with the closeness measures of the paper's Table 1, then uses each to compute
// the Delaunay triangulation. The predictions come from the package's generators: the
// Delaunay triangulation of the points before they moved (a simulation's previous frame),
// and the rho model of the paper (a random fraction rho of the Delaunay edges kept, the rest
// completed adversarially).
// Usage: prediction_quality [n]   (default 10000 points). Returns 0 only if every result
// equals CGAL's own triangulation and the measures satisfy the paper's inequalities.

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/measures.h>
#include <CGAL/Delaunay_from_prediction/prediction_models.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cstddef>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using DT = CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>>>;
namespace DFP = CGAL::Delaunay_from_prediction;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::size_t(std::atol(argv[1])) : 10000;
  CGAL::Random random(42);
  std::vector<Point> points;
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(random.get_double(), random.get_double());
  const std::vector<DFP::Indexed_triangle> truth = DFP::delaunay_triangles(points);

  struct Prediction { std::string name; std::vector<DFP::Indexed_triangle> faces; };
  const std::vector<Prediction> predictions = {
      {"Delaunay itself", truth},
      {"previous frame, moves of 0.05 spacing", DFP::moved_points_prediction(points, 0.05, 1)},
      {"previous frame, moves of 0.3 spacing", DFP::moved_points_prediction(points, 0.3, 1)},
      {"rho model, rho = 0.9, adversarial", DFP::rho_model_prediction(points, 0.9, 1)},
      {"rho model, rho = 0.5, adversarial", DFP::rho_model_prediction(points, 0.5, 1)},
  };

  std::cout << std::left << std::setw(40) << "prediction" << std::right << std::setw(8) << "D"
            << std::setw(9) << "D_local" << std::setw(9) << "D_cross" << std::setw(9) << "d_cross"
            << std::setw(10) << "D_vio" << std::setw(8) << "d_vio" << std::setw(8) << "Lawson"
            << "  result\n";
  bool ok = true;
  for(const Prediction& p : predictions) {
    const DFP::Prediction_measures m = DFP::prediction_measures(points, p.faces);
    DT dt;
    const DFP::Statistics stats = DFP::delaunay_from_prediction(points, p.faces, dt);
    std::cout << std::left << std::setw(40) << p.name << std::right << std::setw(8) << m.D
              << std::setw(9) << m.D_local << std::setw(9) << m.D_cross << std::setw(9) << m.d_cross
              << std::setw(10) << m.D_vio << std::setw(8) << m.d_vio << std::setw(8)
              << (m.D_flip_upper ? std::to_string(*m.D_flip_upper) : std::string("-"))
              << "  " << stats.flips << " flips" << (stats.fell_back ? ", rebuilt" : "") << "\n";
    if(!m.is_triangulation)
      std::cout << "    (not a triangulation of the points: " << m.not_a_triangulation << ")\n";
    // The paper's inequalities, for predictions that are triangulations.
    if(m.is_triangulation &&
       !(m.D_local <= m.D && m.D <= *m.D_flip_upper && *m.D_flip_upper <= m.D_cross && m.D == m.D_missing))
      ok = false;
    // The result is CGAL's triangulation: as many faces, and no edge that is not Delaunay.
    std::vector<DFP::Indexed_triangle> result;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      result.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    const DFP::Prediction_measures r = DFP::prediction_measures(points, result);
    ok = ok && r.D == 0 && r.D_missing == 0 && r.is_triangulation && result.size() == truth.size();
  }
  std::cout << (ok ? "all results equal CGAL's Delaunay triangulation\n" : "FAILED\n");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
