// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The concurrency tag on the five entry points: CGAL::Sequential_tag (the default),
// CGAL::Parallel_if_available_tag with TBB limited to one thread and to two. Every result must
// be CGAL's Delaunay_triangulation_2 of the same points, whatever the tag and the thread count,
// on degenerate inputs too (grids, co-circular lattice points, collinear sets, duplicates, huge
// and tiny coordinates). make_delaunay's parallel certification cuts a triangulation into
// blocks of at least 32 faces, so even these small inputs cross many block boundaries; moves
// large enough to invert many faces exercise the early stop shared between the blocks.
// Lawson's flips and make_delaunay's untangling flips in cells are tested on their own too
// (flips_in_cells, untangling_in_cells), on enough flips that the cells flip edges of their
// own and leave those across their boundaries to the final pass.

#include <CGAL/Delaunay_from_prediction_2.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_predicted_edges_2.h>
#include <CGAL/Delaunay_from_prediction/brio_dc.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/prediction_generators.h>
#include <CGAL/Delaunay_from_prediction/spanning_graph.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_hierarchy_vertex_base_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>

using namespace dfp_test;

// Sizes a fifth as large in unoptimized or sanitized builds (scripts/sanitize.sh), which run
// about 20 times slower.
inline std::size_t sized(std::size_t n) { return time_limit_scale == 1 ? n : (std::max)(n / 5, std::size_t(40)); }

// CGAL's definition of CGAL::Parallel_if_available_tag, which the package relies on (it has
// no case of its own for it).
#ifdef CGAL_LINKED_WITH_TBB
static_assert(std::is_same<CGAL::Parallel_if_available_tag, CGAL::Parallel_tag>::value, "");
static_assert(DFP::internal::runs_in_parallel<CGAL::Parallel_tag>(), "");
#else
static_assert(std::is_same<CGAL::Parallel_if_available_tag, CGAL::Sequential_tag>::value, "");
#endif
static_assert(!DFP::internal::runs_in_parallel<CGAL::Sequential_tag>(), "");

// `faces` with a copy of its first face at the end.
Faces with_first_face_repeated(Faces faces)
{
  if(!faces.empty())
    faces.push_back(faces.front());
  return faces;
}

template <class K>
struct Parallel_test
{
  using Point = typename K::Point_2;
  using Points = std::vector<Point>;
  CGAL::Random rng{2323};
  // Parallel certifications stopped early for too many faces not ccw (the shared stop).
  std::size_t parallel_stops = 0;
  // The certification counts of the sequential call, by (number of points, prediction, mode).
  std::map<std::tuple<std::size_t, int, int>, std::array<std::size_t, 4>> sequential_counts;

  // Every entry point that takes points, with the current concurrency, against CGAL's DT.
  void entry_points(const Points& points)
  {
    const std::size_t n = points.size();
    const auto reference = indexed_delaunay<K>(points);
    const Faces dt_faces = faces_by_info(reference);
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for(const Face& f : dt_faces)
      for(int j = 0; j < 3; ++j)
        edges.emplace_back(f[j], f[(j + 1) % 3]);
    std::vector<std::pair<std::size_t, std::size_t>> path = random_path(n, rng);
    // The first two predictions are the same for every concurrency: their counts are compared
    // below, and the order of the faces steers some strategies (Strategy::regions grows its
    // regions from the faces in their order).
    CGAL::Random order_rng{static_cast<unsigned>(n) + 1}, flip_rng{static_cast<unsigned>(n)};
    const Faces predictions[] = {shuffled(dt_faces, order_rng), flipped_delaunay_faces<K>(points, n / 8 + 1, flip_rng),
                                 with_faces_deleted(shuffled(dt_faces, rng), dt_faces.size() / 20 + 1, rng),
                                 random_triples(n, 2 * n, rng), with_first_face_repeated(dt_faces)};
    // Random triples overlap inside a chunk of the parallel import; a face repeated at the end
    // (inputs under 4096 points keep their order) overlaps its copy across chunks, at a seam.
    const char* names[] = {"the DT, shuffled", "the DT after n/8 flips", "the DT with 5% of faces deleted",
                           "random triples", "the DT with its first face repeated last"};
    for(int k = 0; k < 5; ++k) {
      Scope s("delaunay_from_prediction, ", names[k]);
      for(const Mode mode : strategy_modes) {
        Scope m(name_of(mode));
        DT_with_info<K> dt;
        const DFP::Statistics st = with_mode(mode, [&](const auto& np) {
          return with_concurrency(
              [&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, predictions[k], dt, np); });
        });
        check_is_cgal_delaunay(dt, points);
        // The parallel import pairs and tests the same edges: for a prediction that is a
        // triangulation, the certification's counts are the sequential call's. Not so for
        // Strategy::regions, whose region size follows the number of threads.
        if(k < 2 && mode != Mode::regions) {
          const std::array<std::size_t, 4> counts = {st.edges_tested, st.edges_not_locally_delaunay, st.points_unused,
                                                     std::size_t(st.fell_back)};
          auto& sequential = sequential_counts[{n, k, int(mode)}];
          if(current_concurrency() == Concurrency::sequential)
            sequential = counts;
          else
            DFP_CHECK(counts == sequential);
        }
      }
    }
    {
      Scope s("delaunay_from_predicted_edges");
      DT_with_info<K> dt;
      with_concurrency([&](auto tag) { return DFP::delaunay_from_predicted_edges<decltype(tag)>(points, edges, dt); });
      check_is_cgal_delaunay(dt, points);
    }
    {
      Scope s("delaunay_from_spanning_graph, a random path");
      DT_with_info<K> dt;
      with_concurrency([&](auto tag) { return DFP::delaunay_from_spanning_graph<decltype(tag)>(points, path, dt); });
      check_is_cgal_delaunay(dt, points);
    }
    {
      Scope s("brio_dc_delaunay");
      DT_with_info<K> dt;
      with_concurrency([&](auto tag) { return DFP::brio_dc_delaunay<decltype(tag)>(points, dt); });
      check_is_cgal_delaunay(dt, points);
    }
  }

  // make_delaunay after moving every vertex by `amplitude` (up to, in each coordinate), on a
  // DT with info, a Triangulation_2 and a hierarchy, with each strategy.
  void moves(const Points& points, double amplitude)
  {
    Scope s("make_delaunay after moves of ", amplitude);
    for(const Mode mode : strategy_modes) {
      if(mode == Mode::section_3 || mode == Mode::theorem_4_1 || mode == Mode::theorem_5_4) // make_delaunay: the rebuild, run already
        continue;
      Scope m(name_of(mode));
      DT_with_info<K> tr = indexed_delaunay<K>(points);
      // Vertex k (in vertex order) gets info k and the k-th moved point (duplicate points
      // are one vertex).
      std::vector<Point> vertex_points;
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
        v->info() = vertex_points.size();
        const Point& p = v->point();
        if(amplitude > 0) // (CGAL::Random::get_double(a, a) does not return)
          v->set_point(make_point<K>(CGAL::to_double(p.x()) + rng.get_double(-amplitude, amplitude),
                                     CGAL::to_double(p.y()) + rng.get_double(-amplitude, amplitude)));
        vertex_points.push_back(v->point());
      }
      try {
        const DFP::Statistics st = with_mode(mode, [&](const auto& np) {
          return with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr, np); });
        });
        check_is_cgal_delaunay(tr, vertex_points);
        if(current_concurrency() != Concurrency::sequential && reason_is(st, DFP::Outcome::too_many_inverted_faces))
          ++parallel_stops;
      } catch(const DFP::Invalid_prediction&) {
        // Two vertices moved onto the same point: then the triangulation is as it was.
        DFP_CHECK(tr.tds().is_valid());
      }
    }
  }

  void point_set(const char* name, const XYs& xy, bool all_modes_of_make_delaunay = true)
  {
    Scope s(name);
    const Points points = to_points<K>(xy);
    for_each_concurrency([&] {
      DFP_RUN(entry_points(points));
      if(all_modes_of_make_delaunay) {
        // Moves in units of the mean spacing, from none to twice it (many faces inverted).
        double xmin = xy[0].x, xmax = xmin, ymin = xy[0].y, ymax = ymin;
        for(const auto& p : xy) {
          xmin = (std::min)(xmin, p.x);
          xmax = (std::max)(xmax, p.x);
          ymin = (std::min)(ymin, p.y);
          ymax = (std::max)(ymax, p.y);
        }
        const double spacing = (std::max)(xmax - xmin, ymax - ymin) / std::sqrt(double(xy.size()));
        for(const double amplitude : {0., 0.01 * spacing, 0.3 * spacing, 2. * spacing})
          DFP_RUN(moves(points, amplitude));
      }
    });
  }
};

// make_delaunay on a hierarchy: level 0 repaired with the tag, the levels above sampled anew.
void hierarchy_case(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_hierarchy_vertex_base_2<CGAL::Triangulation_vertex_base_2<K>>;
  using H = CGAL::Triangulation_hierarchy_2<
      CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>>;
  const std::vector<K::Point_2> points = to_points<K>(uniform_points(sized(3000), rng));
  for_each_concurrency([&] {
    H h(points.begin(), points.end());
    std::vector<K::Point_2> moved;
    for(auto v = h.finite_vertices_begin(); v != h.finite_vertices_end(); ++v) {
      v->set_point(K::Point_2(v->point().x() + rng.get_double(-0.01, 0.01), v->point().y()));
      moved.push_back(v->point());
    }
    with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(h); });
    check_is_cgal_delaunay(h, moved);
  });
}

// The reordering of the import (spatial_order.h) with and without the parallel counting sort
// gives the same order: the parallel passes start at 65536 items, so 70,000 points and their
// 140,000 faces take them; and the counting sort on its own, against std::stable_sort.
void reordering_is_the_same(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<K::Point_2> points = to_points<K>(uniform_points(70000, rng));
  std::vector<std::uint32_t> triples;
  for(const Face& f : shuffled(faces_by_info(indexed_delaunay<K>(points)), rng))
    for(int j = 0; j < 3; ++j)
      triples.push_back(std::uint32_t(f[j]));
  std::vector<std::uint32_t> in_parallel = triples;
  DFP::internal::Spatial_order sequential_order, parallel_order;
  sequential_order.compute(K(), points.begin(), points.size(), triples, false);
  for_each_concurrency([&] {
    if(current_concurrency() != Concurrency::parallel_2_threads)
      return;
    parallel_order.compute(K(), points.begin(), points.size(), in_parallel, true);
  });
  DFP_CHECK(sequential_order.renumbered() && sequential_order.faces_sorted());
  DFP_CHECK(parallel_order.renumbered() && parallel_order.faces_sorted());
  DFP_CHECK(in_parallel == triples);
  bool same_numbering = true;
  for(std::uint32_t v = 0; v < points.size(); ++v)
    same_numbering = same_numbering && sequential_order.old_index(v) == parallel_order.old_index(v);
  DFP_CHECK(same_numbering);

  for(const std::size_t buckets : {std::size_t(1), std::size_t(7), std::size_t(5000), std::size_t(3000000)}) {
    Scope s("counting_sort, ", buckets, " buckets");
    std::vector<std::uint32_t> key(200000);
    for(std::uint32_t& k : key)
      k = std::uint32_t(rng.get_int(0, int(buckets)));
    std::vector<std::uint32_t> expected(key.size()), sorted(key.size()), end, expected_end(buckets, 0);
    for(std::uint32_t k = 0; k < key.size(); ++k)
      expected[k] = k;
    std::stable_sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    for(const std::uint32_t k : key) // end[b]: the number of keys up to b
      ++expected_end[k];
    for(std::size_t b = 1; b < buckets; ++b)
      expected_end[b] += expected_end[b - 1];
    for(const bool parallel : {false, true}) {
      std::fill(sorted.begin(), sorted.end(), 0);
      DFP::internal::counting_sort(
          key.size(), buckets, [&](std::size_t k) { return key[k]; },
          [&](std::size_t k) { return std::uint32_t(k); },
          [&](std::size_t position, std::uint32_t k) { sorted[position] = k; }, parallel, end);
      DFP_CHECK(sorted == expected);
      DFP_CHECK(end == expected_end);
    }
  }
}

// Every (finite face, index) of `tr`: each interior edge twice, from both of its faces.
template <class Tr>
std::vector<std::pair<typename Tr::Face_handle, int>> every_edge_of(Tr& tr)
{
  std::vector<std::pair<typename Tr::Face_handle, int>> edges;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    for(int i = 0; i < 3; ++i)
      edges.emplace_back(f, i);
  return edges;
}

// Lawson's flips in cells (flips.h, flip_in_cells()) on a DT of uniform points and on a
// co-circular grid, after random flips of convex quadrilaterals: the result is CGAL's DT in
// every concurrency, with every edge listed and with only those around the flips; with a budget too
// small, the call fails and leaves a valid triangulation. Enough flips that the cells run
// flips of their own and leave flips across their boundaries to the final pass.
void flips_in_cells(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Tr = DT_with_info<K>;
  using Face_handle = Tr::Face_handle;
  const XYs sets[] = {uniform_points(sized(20000), rng), grid_points(time_limit_scale == 1 ? 120 : 40, time_limit_scale == 1 ? 120 : 40, rng)};
  for(const XYs& xy : sets) {
    const std::vector<K::Point_2> points = to_points<K>(xy);
    for(const bool all_edges : {false, true}) {
      Scope s(all_edges ? "every edge listed" : "the edges of the flips listed");
      for_each_concurrency([&] {
        Tr tr = indexed_delaunay<K>(points);
        std::vector<Face_handle> faces;
        for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
          faces.push_back(f);
        std::vector<std::pair<Face_handle, int>> stack;
        CGAL::Random flip_rng{4242};
        for(std::size_t k = 0; k < points.size() / 4; ++k) {
          const Face_handle f = faces[std::size_t(flip_rng.get_int(0, int(faces.size())))];
          const int i = flip_rng.get_int(0, 3);
          const Face_handle g = f->neighbor(i);
          const int j = tr.tds().mirror_index(f, i);
          // After the flip, f's edge ccw(i) is the new one; the edges around it may fail too.
          if(!DFP::internal::flip_if_convex(tr, f, i))
            continue;
          for(const int k : {i, tr.ccw(i), tr.cw(i)})
            stack.emplace_back(f, k);
          stack.emplace_back(g, j);
          stack.emplace_back(g, tr.cw(j));
        }
        if(all_edges)
          stack = every_edge_of(tr);
        DFP_CHECK(stack.size() >= 16 * DFP::internal::min_edges_to_flip_in_cells);
        const bool parallel = current_concurrency() != Concurrency::sequential;
        Tr too_few;
        too_few.copy_triangulation(tr); // (a copy constructor asserts that it is Delaunay)
        {
          std::vector<std::pair<Face_handle, int>> few_stack = every_edge_of(too_few);
          std::vector<Face_handle> touched;
          std::size_t flips = 0;
          DFP_CHECK(!DFP::internal::lawson_flip(too_few, few_stack, 10, flips, touched, parallel));
          DFP_CHECK(static_cast<const Tr::Triangulation&>(too_few).is_valid()); // not Delaunay yet
        }
        std::vector<Face_handle> touched;
        std::size_t flips = 0;
        DFP_CHECK(DFP::internal::lawson_flip(tr, stack, 4 * points.size(), flips, touched, parallel));
        DFP_CHECK(flips > 0 && touched.size() == 2 * flips);
        check_is_cgal_delaunay(tr, points);
      });
    }
  }
}

// The flip budget of the flips in cells: a few flips close together (most often in one cell),
// every edge listed, every budget from 0 up. A call that succeeds must leave CGAL's DT (a task
// that runs out of budget alone must fail the call even when the total is within it); one
// that fails, a valid triangulation; and 16 flips are enough.
void flip_budget_in_cells(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Tr = DT_with_info<K>;
  using Face_handle = Tr::Face_handle;
  const std::vector<K::Point_2> points = to_points<K>(uniform_points(2000, rng));
  for_each_concurrency([&] {
    const bool parallel = current_concurrency() != Concurrency::sequential;
    for(int start = 0; start < 12; ++start) {
      Tr damaged = indexed_delaunay<K>(points);
      std::vector<Face_handle> faces;
      for(auto f = damaged.finite_faces_begin(); f != damaged.finite_faces_end(); ++f)
        faces.push_back(f);
      // A walk of flips: each flips an edge of the faces the previous one made.
      CGAL::Random flip_rng{static_cast<unsigned>(100 + start)};
      Face_handle f = faces[std::size_t(flip_rng.get_int(0, int(faces.size())))];
      std::size_t made = 0;
      for(int tries = 0; tries < 40 && made < 3; ++tries) {
        const int i = flip_rng.get_int(0, 3);
        const Face_handle g = f->neighbor(i);
        if(!DFP::internal::flip_if_convex(damaged, f, i))
          continue;
        ++made;
        f = flip_rng.get_int(0, 2) == 0 ? f : g;
      }
      bool some_budget_is_enough = false;
      for(std::size_t budget = 0; budget <= 16; ++budget) {
        Scope s("walk ", start, ", budget ", budget);
        Tr tr;
        tr.copy_triangulation(damaged); // (a copy constructor asserts that it is Delaunay)
        std::vector<std::pair<Face_handle, int>> stack = every_edge_of(tr);
        std::vector<Face_handle> touched;
        std::size_t flips = 0;
        if(DFP::internal::lawson_flip(tr, stack, budget, flips, touched, parallel)) {
          check_is_cgal_delaunay(tr, points);
          DFP_CHECK(flips <= budget);
          some_budget_is_enough = true;
        } else {
          DFP_CHECK(static_cast<const Tr::Triangulation&>(tr).is_valid());
        }
      }
      DFP_CHECK(some_budget_is_enough); // 16 flips are enough to undo 3
    }
  });
}

// The untangling flips of make_delaunay in cells (flips.h, untangle_by_flips()) on a DT of
// uniform points and on a grid whose vertices moved by up to 0.5 spacing (thousands of
// inverted faces, enough that cells take faces of their own and leave those across their
// boundaries to the final pass): in every concurrency the faces returned are exactly those
// still not counterclockwise, every flip is logged, and undoing the log restores the
// triangulation (vertex objects, points, connectivity); make_delaunay then gives CGAL's DT.
void untangling_in_cells(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Tr = DT_with_info<K>;
  using Face_handle = Tr::Face_handle;
  namespace I = DFP::internal;
  const XYs sets[] = {uniform_points(sized(20000), rng), grid_points(time_limit_scale == 1 ? 120 : 40, time_limit_scale == 1 ? 120 : 40, rng)};
  for(const XYs& xy : sets) {
    Scope s(&xy == &sets[0] ? "uniform" : "grid");
    const std::vector<K::Point_2> points = to_points<K>(xy);
    Tr moved = indexed_delaunay<K>(points);
    std::vector<K::Point_2> moved_points = points;
    CGAL::Random move_rng{31};
    double xmin = points[0].x(), xmax = xmin, ymin = points[0].y(), ymax = ymin;
    for(const K::Point_2& p : points) {
      xmin = (std::min)(xmin, p.x());
      xmax = (std::max)(xmax, p.x());
      ymin = (std::min)(ymin, p.y());
      ymax = (std::max)(ymax, p.y());
    }
    const double step = 0.5 * std::sqrt((xmax - xmin) * (ymax - ymin) / double(points.size())); // half the spacing
    for(auto v = moved.finite_vertices_begin(); v != moved.finite_vertices_end(); ++v) {
      const K::Point_2 p(v->point().x() + step * move_rng.get_double(-1, 1),
                         v->point().y() + step * move_rng.get_double(-1, 1));
      v->set_point(p);
      moved_points[v->info()] = p;
    }
    for_each_concurrency([&] {
      const bool parallel = current_concurrency() != Concurrency::sequential;
      Tr tr;
      tr.copy_triangulation(moved); // (a copy constructor asserts that it is Delaunay)
      const Snapshot<Tr> before(tr);
      std::vector<std::pair<Face_handle, int>> stack;
      std::vector<Face_handle> bad, touched;
      std::size_t tested = 0;
      bool hull_is_convex = false;
      DFP_CHECK(I::certify_faces(tr, stack, tested, hull_is_convex, &bad, tr.number_of_faces()) ==
                DFP::Outcome::ok);
      DFP_CHECK_MSG(bad.size() >= 4 * I::min_faces_to_untangle_in_cells, bad.size());
      const std::size_t stacked = stack.size();
      I::Flip_log<Tr> log;
      I::untangle_by_flips(tr, bad, stack, log, touched, parallel);
      DFP_CHECK(!log.empty() && touched.size() == 2 * log.size() && stack.size() == stacked + 6 * log.size());
      std::vector<Face_handle> not_ccw;
      for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
        if(CGAL::orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) != CGAL::LEFT_TURN)
          not_ccw.push_back(f);
      std::sort(not_ccw.begin(), not_ccw.end());
      DFP_CHECK(bad == not_ccw);
      DFP_CHECK(tr.tds().is_valid());
      I::undo_flips(tr, log);
      check_unchanged(tr, before);
      Tr repaired;
      repaired.copy_triangulation(moved);
      DFP::make_delaunay<CGAL::Parallel_if_available_tag>(repaired);
      check_is_cgal_delaunay(repaired, moved_points);
    });
  }
}

// A malformed face read in parallel blocks throws as in order: for the first one.
void first_malformed_face_is_named(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const std::vector<K::Point_2> points = to_points<K>(uniform_points(1000, rng));
  Faces faces = random_triples(points.size(), 200000, rng);
  faces[150000][1] = 5000;
  faces[70001][2] = 1000;
  faces[70001][0] = 1000;
  for_each_concurrency([&] {
    DT_with_info<K> dt;
    try {
      with_concurrency([&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt); });
      DFP_CHECK_MSG(false, "no exception");
    } catch(const DFP::Invalid_prediction& e) {
      const std::string what = e.what();
      DFP_CHECK_MSG(what.find("70001") != std::string::npos && what.find("150000") == std::string::npos, what);
    }
    DFP_CHECK(dt.number_of_vertices() == 0);
  });
}

// The region-parallel build (block_parallel_build.h) with 2 to 64 blocks, so that small sets
// have many seams, on degenerate sets too: CGAL's DT with the duplicates counted, the blocks'
// kept faces and the seams' faces meeting at walls that are all locally Delaunay (so nothing
// was left to repair), and faces kept (not everything redone in the seams). A set on one line
// has no region build: false, and the triangulation left empty.
void regions_build(CGAL::Random& rng)
{
  auto run = [&](auto kernel, const char* name, const XYs& xy) {
    using K = decltype(kernel);
    Scope s(name);
    const std::vector<typename K::Point_2> points = to_points<K>(xy);
    const std::size_t n = points.size();
    const DT_with_info<K> reference = indexed_delaunay<K>(points);
    for_each_concurrency([&] {
      const bool parallel = current_concurrency() != Concurrency::sequential;
      for(const std::size_t blocks : {2, 4, 16, 64}) {
        Scope b(blocks, " blocks");
        DT_with_info<K> dt;
        DFP::Statistics st;
        DFP::internal::Block_build_counts report;
        const bool built = DFP::internal::build_in_blocks(dt, points.begin(), n, st, blocks, parallel, &report);
        DFP_CHECK(built == (reference.dimension() == 2));
        if(!built) {
          DFP_CHECK(dt.number_of_vertices() == 0 && dt.tds().is_valid());
          continue;
        }
        check_is_cgal_delaunay(dt, points);
        DFP_CHECK_MSG(st.duplicate_points == n - reference.number_of_vertices(), st.duplicate_points);
        DFP_CHECK_MSG(report.walls_failing == 0, report.walls_failing << " of " << report.walls);
        DFP_CHECK(report.blocks == blocks);
        if(n >= 1000 && blocks <= 4)
          DFP_CHECK_MSG(report.kept_faces > dt.number_of_faces() / 2 && report.walls > 0,
                        report.kept_faces << " kept of " << dt.number_of_faces());
      }
    });
  };
  using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
  run(Epick(), "uniform", uniform_points(sized(3000), rng));
  run(Epick(), "clustered", clustered_points(sized(3000), rng));
  run(Epick(), "grid (co-circular)", grid_points(time_limit_scale == 1 ? 50 : 20, time_limit_scale == 1 ? 50 : 20, rng));
  run(Epick(), "lattice circles (co-circular)", lattice_circle_points(time_limit_scale == 1 ? 40 : 20, rng, 5));
  run(Epick(), "collinear", collinear_points(sized(300), rng));
  run(Epick(), "uniform with 30% duplicates", with_duplicates(uniform_points(sized(1500), rng), sized(450), rng));
  run(Epick(), "uniform scaled by 1e290", transformed(uniform_points(sized(1500), rng), 1e290, 0.));
  run(Epick(), "uniform scaled by 1e-290", transformed(uniform_points(sized(1500), rng), 1e-290, 0.));
  run(Epick(), "uniform offset by 1e15", transformed(uniform_points(sized(1500), rng), 1., 1e15));
  run(Epick(), "three points", uniform_points(3, rng));
  run(CGAL::Exact_predicates_exact_constructions_kernel(), "Epeck grid (co-circular)", grid_points(20, 20, rng));
}

// The entry points build by regions on two threads once the size threshold is lowered (Tuning): a
// prediction that falls back, a rebuild requested, make_delaunay after large moves.
void regions_in_entry_points(CGAL::Random& rng)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  DFP_CHECK(DFP::internal::default_block_count(std::size_t(1) << 20, 1) == 1);
  DFP_CHECK(DFP::internal::default_block_count(std::size_t(1) << 20, 2) == 1);
  DFP_CHECK(DFP::internal::default_block_count(std::size_t(1) << 20, 4) == 8);
  DFP_CHECK(DFP::internal::default_block_count(std::size_t(1) << 20, 8) == 16);
  DFP_CHECK(DFP::internal::default_block_count(std::size_t(1) << 16, 8) == 2);
  DFP::Tuning tuning; // blocks of 200 points from 2 threads, passed to every call below
  tuning.min_points_per_block = 200;
  tuning.min_threads_for_blocks = 2;
  const auto small_blocks = DFP::parameters::tuning(tuning);
  const std::size_t n = 3000;
  DFP_CHECK(DFP::internal::default_block_count(n, 2, tuning) == 4 &&
            DFP::internal::default_block_count(n, 1, tuning) == 1);
  const std::vector<K::Point_2> points = to_points<K>(with_duplicates(uniform_points(n, rng), 50, rng));
  const XYs grid = grid_points(40, 40, rng);
  const Faces triples = random_triples(points.size(), 2 * points.size(), rng);
  for_each_concurrency([&] {
    {
      Scope s("random triples");
      DT_with_info<K> dt;
      const DFP::Statistics st =
          with_concurrency([&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, triples, dt, small_blocks); });
      DFP_CHECK(st.fell_back && st.duplicate_points == 50);
      check_is_cgal_delaunay(dt, points);
    }
    {
      Scope s("make_delaunay, rebuild");
      DT_with_info<K> tr = indexed_delaunay<K>(points);
      std::vector<K::Point_2> moved;
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
        v->info() = moved.size();
        v->set_point(K::Point_2(v->point().x() + rng.get_double(-0.01, 0.01), v->point().y()));
        moved.push_back(v->point());
      }
      with_concurrency([&](auto tag) {
        return DFP::make_delaunay<decltype(tag)>(tr, DFP::parameters::strategy(DFP::Strategy::rebuild).tuning(tuning));
      });
      check_is_cgal_delaunay(tr, moved);
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
        DFP_CHECK(v->point() == moved[v->info()]);
    }
    for(const bool duplicate : {false, true}) {
      Scope s("make_delaunay, a co-circular grid's points permuted", duplicate ? ", two at one point" : "");
      DT_with_info<K> tr = indexed_delaunay<K>(to_points<K>(grid));
      std::vector<std::size_t> permutation(grid.size());
      for(std::size_t k = 0; k < grid.size(); ++k)
        permutation[k] = k;
      shuffle(permutation, rng);
      if(duplicate)
        permutation[1] = permutation[0];
      std::vector<K::Point_2> moved;
      for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
        v->info() = moved.size();
        v->set_point(K::Point_2(grid[permutation[moved.size()]].x, grid[permutation[moved.size()]].y));
        moved.push_back(v->point());
      }
      auto face_set = [&] {
        Faces faces = faces_by_info(tr);
        for(Face& f : faces)
          f = canonical(f);
        std::sort(faces.begin(), faces.end());
        return faces;
      };
      const Faces before = face_set();
      try {
        const DFP::Statistics st =
            with_concurrency([&](auto tag) { return DFP::make_delaunay<decltype(tag)>(tr, small_blocks); });
        DFP_CHECK(!duplicate && st.fell_back);
        check_is_cgal_delaunay(tr, moved);
      } catch(const DFP::Invalid_prediction&) {
        DFP_CHECK(duplicate && tr.tds().is_valid() && face_set() == before); // `tr` as it was
      }
    }
  });
}

int main()
{
  CGAL::Random rng(777);
  DFP_RUN(reordering_is_the_same(rng));
  DFP_RUN(first_malformed_face_is_named(rng));
  DFP_RUN(flips_in_cells(rng));
  DFP_RUN(flip_budget_in_cells(rng));
  DFP_RUN(untangling_in_cells(rng));
  DFP_RUN(regions_build(rng));
  DFP_RUN(regions_in_entry_points(rng));
  {
    Scope s("Epick");
    Parallel_test<CGAL::Exact_predicates_inexact_constructions_kernel> t;
    t.point_set("uniform", uniform_points(sized(3000), rng));
    t.point_set("clustered", clustered_points(sized(3000), rng));
    t.point_set("grid (co-circular)", grid_points(time_limit_scale == 1 ? 40 : 18, time_limit_scale == 1 ? 40 : 18, rng));
    t.point_set("lattice circles (co-circular)", lattice_circle_points(time_limit_scale == 1 ? 65 : 25, rng, time_limit_scale == 1 ? 25 : 5));
    t.point_set("collinear", collinear_points(sized(200), rng));
    t.point_set("uniform with 30% duplicates", with_duplicates(uniform_points(sized(1000), rng), sized(300), rng));
    t.point_set("uniform scaled by 1e290", transformed(uniform_points(sized(1000), rng), 1e290, 0.));
    t.point_set("uniform scaled by 1e-290", transformed(uniform_points(sized(1000), rng), 1e-290, 0.));
    t.point_set("uniform offset by 1e15", transformed(uniform_points(sized(1000), rng), 1., 1e15));
    DFP_CHECK(t.parallel_stops > 0);
  }
  {
    Scope s("Epeck");
    Parallel_test<CGAL::Exact_predicates_exact_constructions_kernel> t;
    t.point_set("grid (co-circular)", grid_points(time_limit_scale == 1 ? 20 : 10, time_limit_scale == 1 ? 20 : 10, rng), false);
    t.point_set("uniform", uniform_points(sized(1000), rng), false);
  }
  DFP_RUN(hierarchy_case(rng));
  return finish("test_parallel");
}
