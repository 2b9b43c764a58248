// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// Two of the package's related systems on one point set: stations of two networks (say,
// wells and pumps) scattered in clusters. brio_dc_delaunay() triangulates all of them without
// a spatial sort (BrioDC: samples meeting every component of the nearest-neighbour graph,
// insertion along its edges); split_delaunay() then gives the triangulation of each network
// from the joint one, station indices carried in info(). Every triangulation is compared with
// CGAL's built from scratch, face by face as triples of station indices; the program returns
// 0 only if all agree.

#include <CGAL/Delaunay_from_prediction/brio_dc.h>
#include <CGAL/Delaunay_from_prediction/split.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iostream>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using DT = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
namespace DFP = CGAL::Delaunay_from_prediction;

// The faces of a triangulation whose vertex info is a station index, as sorted index triples.
std::vector<std::array<std::size_t, 3>> faces_of(const DT& t)
{
  std::vector<std::array<std::size_t, 3>> faces;
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> a = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    faces.push_back(a);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// CGAL's triangulation of the stations for which `keep` holds, info() = station index.
template <class Keep>
DT cgal_triangulation(const std::vector<Point>& stations, Keep keep)
{
  std::vector<std::pair<Point, std::size_t>> indexed;
  for(std::size_t i = 0; i < stations.size(); ++i)
    if(keep(i))
      indexed.emplace_back(stations[i], i);
  return DT(indexed.begin(), indexed.end());
}

int main()
{
  CGAL::Random rng(2718);
  // 60000 stations around 40 towns; every third one is a pump, the others are wells.
  std::vector<Point> towns, stations;
  for(int t = 0; t < 40; ++t)
    towns.emplace_back(rng.get_double(0, 100), rng.get_double(0, 100));
  for(int i = 0; i < 60000; ++i) {
    const Point& town = towns[std::size_t(rng.get_int(0, 40))];
    const double spread = rng.get_double(0.5, 6.0);
    stations.emplace_back(town.x() + spread * rng.get_double(-1, 1), town.y() + spread * rng.get_double(-1, 1));
  }
  auto is_pump = [](std::size_t i) { return i % 3 == 0; };

  DT all;
  const DFP::Statistics s = DFP::brio_dc_delaunay(stations, all); // info() = station index
  const bool all_equal = faces_of(all) == faces_of(cgal_triangulation(stations, [](std::size_t) { return true; }));
  std::cout << "BrioDC: " << all.number_of_faces() << " faces, " << s.insertion_rounds << " samples, "
            << double(s.faces_visited) / double((std::max)(s.points_located, std::size_t(1)))
            << " faces crossed per point, " << (all_equal ? "equal to" : "DIFFERENT FROM") << " CGAL's\n";

  DT pumps, wells;
  DFP::split_delaunay(all, [&](DT::Vertex_handle v) { return is_pump(v->info()); }, pumps, wells);
  const bool pumps_equal = faces_of(pumps) == faces_of(cgal_triangulation(stations, is_pump));
  const bool wells_equal =
      faces_of(wells) == faces_of(cgal_triangulation(stations, [&](std::size_t i) { return !is_pump(i); }));
  std::cout << "split: pumps " << pumps.number_of_faces() << " faces, " << (pumps_equal ? "equal to" : "DIFFERENT FROM")
            << " CGAL's; wells " << wells.number_of_faces() << " faces, "
            << (wells_equal ? "equal to" : "DIFFERENT FROM") << " CGAL's\n";
  return all_equal && pumps_equal && wells_equal ? 0 : 1;
}
