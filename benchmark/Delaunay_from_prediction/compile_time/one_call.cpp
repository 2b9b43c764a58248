// The compile-time benchmark's user program (compile_time.sh): one call of each entry point,
// Epick, a triangulation whose vertices hold their point's index.
#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <iostream>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
namespace DFP = CGAL::Delaunay_from_prediction;

int main()
{
  std::vector<K::Point_2> points = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  std::vector<std::array<int, 3>> faces = {{0, 1, 2}, {1, 3, 2}};
  DT dt;
  DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, dt);
#ifndef ONE_ENTRY_POINT
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    v->set_point(K::Point_2(v->point().x() * 1.01, v->point().y()));
  s = DFP::make_delaunay(dt);
#endif
  std::cout << dt.number_of_faces() << " faces, " << s.flips << " flips\n";
}
