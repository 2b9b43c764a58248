// The compile-time benchmark's reference (compile_time.sh): the same program with CGAL's own
// range insertion, of (point, index) pairs, in place of each entry point.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <iostream>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;

int main()
{
  std::vector<std::pair<K::Point_2, std::size_t>> points = {{{0, 0}, 0}, {{1, 0}, 1}, {{0, 1}, 2}, {{1, 1}, 3}};
  DT dt;
  dt.insert(points.begin(), points.end());
#ifndef ONE_ENTRY_POINT
  for(auto& p : points)
    p.first = K::Point_2(p.first.x() * 1.01, p.first.y());
  dt.clear();
  dt.insert(points.begin(), points.end());
#endif
  std::cout << dt.number_of_faces() << " faces\n";
}
