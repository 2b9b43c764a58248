// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The parallel build from scratch in blocks: spatial blocks of the points triangulated on their
// own, on TBB's threads, the seams between them by one more triangulation, the pieces joined
// without any search and certified by exact predicates.
//
// The points are split by medians into 2^k blocks of equal size (a k-d tree, each block a
// rectangle whose sides are split lines or infinite). Each block's Delaunay triangulation is
// built by the package's insertion (rebuild.h). A face whose circumdisk lies inside its block's
// rectangle has no point of any block in its disk, so it is a face of DT(all points): it is kept.
// A vertex of a face not kept (or of the block's hull) is a seam vertex, and every face of
// DT(all points) that is not kept has only seam vertices (a vertex whose faces in its block
// are all kept has the same star in the whole triangulation). Those faces are faces of
// DT(seam vertices), built next on one thread (about 1% of the points at 1e6 with 8 blocks):
// the faces of it reached from the seam side of the kept faces' boundary edges (the walls),
// without crossing one, are the seams' faces. With the same perturbation of co-circular points
// everywhere (CGAL's, symbolic), kept and seam faces are DT(all points).
//
// Why it is robust: the disk test is double arithmetic on coordinates scaled into the unit
// box (grid.h) and only steers, with a margin. The result is certified whatever it said (see
// build_in_blocks()): if a wall fails the exact in-circle test, Lawson's flips repair it; if
// the pieces do not fit together (a wall that is not an edge of DT(seam vertices), a hull that
// is not convex), the build gives up and the caller builds sequentially.
//
// This is also the engine the paper's Section 5 needs: regions triangulated independently,
// the faces each region can vouch for kept, the rest triangulated again and certified.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BLOCK_PARALLEL_BUILD_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BLOCK_PARALLEL_BUILD_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/parameters.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// When the entry points build in blocks instead of sequentially: from
// Tuning::min_threads_for_blocks threads and 2 blocks of Tuning::min_points_per_block points.
// Measured at 1e6 points on 2 threads (bench_region_build.cpp, results/region_build_blocks_1e6.txt):
// 1.58x the sequential build with 4 blocks, 1.23x with 2 (one half may wait for the other), 1.51x
// with 8 (more seams); on one thread the build in 4 blocks took 0.6877 s where CGAL's build took
// 0.6514 s (results/region_build_stages_1thread_1e6.txt).
// Smaller blocks make the seams' share grow (1.2% of the points with 8 blocks at 1e6).
//
// The number of blocks for `n` points on `threads` threads: a power of two, about two per
// thread so that TBB can balance uneven blocks, with at least min_points_per_block points
// each; below 2, the build is sequential.
inline std::size_t default_block_count(std::size_t n, std::size_t threads, const Tuning& t = Tuning())
{
  if(threads < (std::max)(std::size_t(2), t.min_threads_for_blocks))
    return 1;
  std::size_t blocks = 1;
  while(blocks < 2 * threads && n / (2 * blocks) >= t.min_points_per_block)
    blocks *= 2;
  return blocks;
}

template <class Gt>
struct Block_triangulation
{
  // vertex info: the point's index; face info: kept (1), wall bits (2 << i), reached (16)
  using Vb = Triangulation_vertex_base_with_info_2<std::uint32_t, Gt>;
  using Fb = Triangulation_face_base_with_info_2<std::uint32_t, Gt>;
  using type = Delaunay_triangulation_2<Gt, Triangulation_data_structure_2<Vb, Fb>>;
};

// One block: its points order[begin, end) and its rectangle, in scaled coordinates, with
// infinite sides where it meets the outside of the whole box.
struct Build_block
{
  std::size_t begin = 0, end = 0;
  double xlo = -std::numeric_limits<double>::infinity(), xhi = std::numeric_limits<double>::infinity();
  double ylo = -std::numeric_limits<double>::infinity(), yhi = std::numeric_limits<double>::infinity();
};

// The circumdisk of the triangle (a, b, c), in scaled coordinates: centre (x, y) and a radius
// enlarged by a margin. The relative error of the centre and radius is a few ulps times the
// triangle's condition; the margin (1e-9 of the unit box plus 1e-6 of the radius) covers any
// triangle that is not nearly flat, and a nearly flat one has a huge disk. Not finite (inf or
// NaN) for a flat or tiny triangle: callers test finite().
struct Scaled_disk
{
  double x, y, r;
  bool finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(r); }
};
inline Scaled_disk scaled_circumdisk(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                     const std::array<double, 2>& c)
{
  const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const double d = 2 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  return Scaled_disk{a[0] + ux, a[1] + uy, std::sqrt(ux * ux + uy * uy) * (1 + 1e-6) + 1e-9};
}

// Whether the circumdisk of the triangle (a, b, c), in scaled coordinates, lies inside the
// rectangle of `block` with the margin of scaled_circumdisk(). False for flat or tiny
// triangles whose circumcentre is not finite (NaN compares false): their face goes to the
// seams, which is always safe.
inline bool circumdisk_inside(const std::array<double, 2>& a, const std::array<double, 2>& b,
                              const std::array<double, 2>& c, const Build_block& block)
{
  const Scaled_disk disk = scaled_circumdisk(a, b, c);
  return disk.x - disk.r > block.xlo && disk.x + disk.r < block.xhi && disk.y - disk.r > block.ylo &&
         disk.y + disk.r < block.yhi;
}

// Splits order[block.begin, block.end) at its median along the longer side of `extent` (the
// block's rectangle clipped to the box), 2^depth blocks in all, appended to `blocks` in order.
inline void split_into_blocks(std::vector<std::uint32_t>& order, const std::vector<std::array<double, 2>>& xy,
                               Build_block block, std::array<double, 4> extent, int depth,
                               std::vector<Build_block>& blocks, bool parallel)
{
  if(depth == 0 || block.end - block.begin < 2) {
    if(depth == 0)
      blocks.push_back(block);
    else
      for(int k = 0; k < (1 << depth); ++k) // keep the count: empty blocks after a tiny one
        blocks.push_back(k == 0 ? block : Build_block{block.end, block.end, block.xlo, block.xhi, block.ylo, block.yhi});
    return;
  }
  const int axis = extent[1] - extent[0] >= extent[3] - extent[2] ? 0 : 1;
  const std::size_t mid = block.begin + (block.end - block.begin) / 2;
  std::nth_element(order.begin() + std::ptrdiff_t(block.begin), order.begin() + std::ptrdiff_t(mid),
                   order.begin() + std::ptrdiff_t(block.end),
                   [&](std::uint32_t i, std::uint32_t j) { return xy[i][std::size_t(axis)] < xy[j][std::size_t(axis)]; });
  const double split = xy[order[mid]][std::size_t(axis)];
  Build_block low = block, high = block;
  low.end = high.begin = mid;
  std::array<double, 4> low_extent = extent, high_extent = extent;
  if(axis == 0) {
    low.xhi = high.xlo = low_extent[1] = high_extent[0] = split;
  } else {
    low.yhi = high.ylo = low_extent[3] = high_extent[2] = split;
  }
  std::vector<Build_block> low_blocks, high_blocks;
  // The two halves are disjoint ranges of `order`: split on two threads.
  for_each_block(parallel, 2, [&](std::size_t half) {
    if(half == 0)
      split_into_blocks(order, xy, low, low_extent, depth - 1, low_blocks, parallel);
    else
      split_into_blocks(order, xy, high, high_extent, depth - 1, high_blocks, parallel);
  });
  blocks.insert(blocks.end(), low_blocks.begin(), low_blocks.end());
  blocks.insert(blocks.end(), high_blocks.begin(), high_blocks.end());
}

// What a build in blocks did, counted for tests and benchmarks (no clock is read).
struct Block_build_counts
{
  std::size_t blocks = 0;
  std::size_t kept_faces = 0;    // faces of the blocks kept as they are
  std::size_t seam_points = 0;   // points triangulated again for the seams
  std::size_t walls = 0;         // edges between kept faces and seam faces
  std::size_t walls_failing = 0; // of them, not locally Delaunay (repaired by flips)
};

// The stages of triangulate_blocks() (see there), sharing the blocks' outputs, DT(seam
// vertices) and the faces created for the seams and the hull. Each stage that can find that
// the pieces do not fit returns false.
template <class DT, class PointIterator, class Kept>
class Block_assembly
{
  using Gt = typename DT::Geom_traits;
  using Rt = typename Block_triangulation<Gt>::type;
  using Region_vertex = typename Rt::Vertex_handle;
  using Region_face = typename Rt::Face_handle;
  using Tds = typename DT::Triangulation_data_structure;
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  using Face_range = typename Tds::Face_range;
  using Inserted = std::vector<std::pair<const void*, std::uint32_t>>; // (vertex, point) in order

  struct Wall // kept face `face`'s edge i, from point u to point w (counterclockwise in it)
  {
    Face_handle face;
    int i;
    std::uint32_t u, w;
  };
  struct Block_output
  {
    std::unique_ptr<DT> dt;
    std::vector<std::uint32_t> seam_points;
    std::vector<Wall> walls;
    std::size_t duplicates = 0, kept_faces = 0;
  };
  struct Wall_side // a wall's edge i of a face of DT(seam vertices), on the seam side
  {
    Region_face face;
    int i;
  };
  static constexpr std::uint32_t reached = 8; // face info bit of the seam faces

public:
  Block_assembly(DT& dt, PointIterator points, std::size_t n, double scale, const std::vector<std::uint32_t>& order,
                 const std::vector<Build_block>& region, const Kept& kept_in_block, bool parallel)
      : dt_(dt), gt_(dt.geom_traits()), points_(points), n_(n), scale_(scale), order_(order), region_(region),
        kept_in_block_(kept_in_block), parallel_(parallel), vertex_of_(n), out_(region.size())
  {}

  // The blocks, the seams, the faces linked, then spliced into `dt_` and certified.
  bool run(Statistics& stats, Block_build_counts* counts)
  {
    for_each_block(parallel_, region_.size(), [&](std::size_t b) { triangulate_block(b); });
    if(!triangulate_seams() || !mark_walls())
      return false;
    if(!reach_seam_faces())
      return false;
    create_seam_faces();
    if(!link_seam_faces() || !link_walls() || !link_hull() || !drop_duplicates())
      return false;
    return splice_and_certify(stats, counts);
  }

private:
  // Block b, on a thread: its triangulation, built in a triangulation of the caller's type
  // whose vertices and kept faces become the result's (their containers spliced at the end).
  // The other faces and the infinite vertex are deleted; the seam vertices' face() is set
  // again by the seams.
  void triangulate_block(std::size_t b)
  {
    const Build_block& block = region_[b];
    Block_output& o = out_[b];
    o.dt.reset(new DT(gt_));
    DT& bdt = *o.dt;
    std::vector<std::size_t> indices(order_.begin() + std::ptrdiff_t(block.begin),
                                     order_.begin() + std::ptrdiff_t(block.end));
    Inserted inserted;
    inserted.reserve(indices.size());
    insert_by_index(bdt, points_, indices, [&](std::size_t i, Vertex_handle v, bool is_new) {
      if(is_new) {
        set_index_info(v, i);
        inserted.emplace_back(&*v, std::uint32_t(i));
      } else {
        merge_index_info(v, i);
        ++o.duplicates;
      }
    });
    std::vector<Face_handle> dropped;
    Hash_map<const void*, std::uint32_t> seam(64);
    find_dropped_faces(b, bdt, inserted, dropped, seam);
    record_seam_points(bdt, inserted, seam, o);
    Inserted().swap(inserted);
    if(bdt.dimension() == 2)
      record_walls(b, bdt, dropped, seam, o);
    for(const std::uint32_t i : o.seam_points)
      vertex_of_[i]->set_face(Face_handle());
    for(const Face_handle f : dropped)
      bdt.tds().delete_face(f);
    bdt.tds().delete_vertex(bdt.infinite_vertex());
    o.kept_faces = bdt.tds().faces().size();
  }

  // The face f of DT(block b) is kept: finite, and steered inside by `kept_in_block_`.
  bool kept(std::size_t b, const DT& bdt, Face_handle f) const
  {
    auto xy_of = [&](Vertex_handle v) {
      return std::array<double, 2>{CGAL::to_double(v->point().x()) * scale_, CGAL::to_double(v->point().y()) * scale_};
    };
    return !bdt.is_infinite(f) && kept_in_block_(b, xy_of(f->vertex(0)), xy_of(f->vertex(1)), xy_of(f->vertex(2)));
  }

  // The faces of DT(block b) not kept (`dropped`) and their finite vertices, the seam
  // vertices (keys of `seam`, their points filled in next).
  void find_dropped_faces(std::size_t b, DT& bdt, const Inserted& inserted, std::vector<Face_handle>& dropped,
                          Hash_map<const void*, std::uint32_t>& seam) const
  {
    const Vertex_handle block_infinite = bdt.infinite_vertex();
    if(bdt.dimension() < 2) { // every vertex to the seams, every face dropped
      for(auto f = bdt.tds().faces().begin(); f != bdt.tds().faces().end(); ++f)
        dropped.push_back(f);
      for(const auto& v : inserted)
        seam.insert(v.first, v.second);
    } else {
      for(auto f = bdt.all_faces_begin(); f != bdt.all_faces_end(); ++f)
        if(!kept(b, bdt, f)) {
          dropped.push_back(f);
          for(int i = 0; i < 3; ++i)
            if(f->vertex(i) != block_infinite)
              seam.insert(&*f->vertex(i), 0);
        }
    }
  }

  // The seam points' indices, in the order of insertion, and their vertices in vertex_of_.
  void record_seam_points(DT& bdt, const Inserted& inserted, Hash_map<const void*, std::uint32_t>& seam,
                          Block_output& o)
  {
    for(const auto& v : inserted)
      if(std::uint32_t* index = seam.find(v.first)) {
        *index = v.second;
        o.seam_points.push_back(v.second);
        vertex_of_[v.second] =
            bdt.tds().vertices().iterator_to(*static_cast<typename Tds::Vertex*>(const_cast<void*>(v.first)));
      }
  }

  // The walls of block b: the edges of its kept faces shared with a dropped face.
  void record_walls(std::size_t b, const DT& bdt, const std::vector<Face_handle>& dropped,
                    const Hash_map<const void*, std::uint32_t>& seam, Block_output& o) const
  {
    for(const Face_handle f : dropped)
      for(int i = 0; i < 3; ++i) {
        const Face_handle g = f->neighbor(i);
        if(kept(b, bdt, g)) {
          const int j = g->index(f);
          o.walls.push_back({g, j, *seam.find(&*g->vertex(ccw(j))), *seam.find(&*g->vertex(cw(j)))});
        }
      }
  }

  // The seams: DT(seam vertices); a seam point merged there with another block's vertex at the
  // same point is a duplicate, its vertex dropped.
  bool triangulate_seams()
  {
    std::vector<std::size_t> seam_indices;
    for(const Block_output& o : out_)
      seam_indices.insert(seam_indices.end(), o.seam_points.begin(), o.seam_points.end());
    seam_points_ = seam_indices.size();
    seams_.emplace(gt_);
    seam_vertex_.resize(n_);
    insert_by_index(*seams_, points_, seam_indices, [&](std::size_t i, Region_vertex v, bool is_new) {
      seam_vertex_[i] = v;
      if(is_new)
        v->info() = std::uint32_t(i);
      else
        merged_.push_back({std::uint32_t(i), v->info()});
    });
    std::vector<std::size_t>().swap(seam_indices);
    // (Below 2 only when every point is on one line: the sequential build is quick.)
    return seams_->dimension() == 2;
  }

  // The walls found in DT(seam vertices), marked on their seam side (face info bit 1 << i);
  // the faces beyond them are the seeds of the seam faces (stack_).
  bool mark_walls()
  {
    Rt& seams = *seams_;
    for(auto f = seams.all_faces_begin(); f != seams.all_faces_end(); ++f)
      f->info() = 0;
    for(const Block_output& o : out_)
      walls_ += o.walls.size();
    wall_side_.reserve(walls_);
    for(const Block_output& o : out_)
      for(const Wall& wall : o.walls) {
        const Region_vertex u = seam_vertex_[wall.u], w = seam_vertex_[wall.w];
        Region_face f;
        int i;
        // A wall's ends must be the seam vertices of their own points (not merged away).
        if(u == Region_vertex() || w == Region_vertex() || u->info() != wall.u || w->info() != wall.w ||
           !seams.is_edge(u, w, f, i))
          return false;
        if(f->vertex(Rt::ccw(i)) != w) { // the seam side has the edge from w to u
          const Region_face g = f->neighbor(i);
          i = g->index(f);
          f = g;
        }
        if(f->info() & (1u << i))
          return false; // two walls on one edge
        f->info() |= 1u << i;
        wall_side_.push_back({f, i});
        if(!seams.is_infinite(f) && !(f->info() & reached)) {
          f->info() |= reached;
          stack_.push_back(f);
        }
      }
    return true;
  }

  // The seam faces: those reached from the walls' seam side without crossing a wall (bit 8),
  // numbered in reached_faces_ (the number kept in the face info, above the flags).
  bool reach_seam_faces()
  {
    Rt& seams = *seams_;
    if(walls_ == 0) // no face kept: the seams are everything
      for(auto f = seams.finite_faces_begin(); f != seams.finite_faces_end(); ++f) {
        f->info() |= reached;
        stack_.push_back(f);
      }
    while(!stack_.empty()) {
      const Region_face f = stack_.back();
      stack_.pop_back();
      f->info() |= std::uint32_t(reached_faces_.size()) << 4; // its number, above the flags
      reached_faces_.push_back(f);
      for(int i = 0; i < 3; ++i) {
        const Region_face g = f->neighbor(i);
        if(!(f->info() & (1u << i)) && !(g->info() & reached) && !seams.is_infinite(g)) {
          g->info() |= reached;
          stack_.push_back(g);
        }
      }
    }
    return reached_faces_.size() < (std::size_t(1) << 28);
  }

  // A face of the result for each seam face, on the blocks' vertices; the vertices' face()
  // set to it.
  void create_seam_faces()
  {
    seam_face_.resize(reached_faces_.size());
    for(std::size_t k = 0; k < reached_faces_.size(); ++k) {
      const Region_face f = reached_faces_[k];
      seam_face_[k] = seam_faces_.emplace(vertex_of_[f->vertex(0)->info()], vertex_of_[f->vertex(1)->info()],
                                          vertex_of_[f->vertex(2)->info()]);
      for(int i = 0; i < 3; ++i)
        seam_face_[k]->vertex(i)->set_face(seam_face_[k]);
    }
  }

  Face_handle seam_face_of(Region_face f) const { return seam_face_[f->info() >> 4]; }

  // The hull's infinite face outside edge i of f: face (b, a, inf) outside the hull edge from a
  // to b; its neighbour 0 is the infinite face whose vertex 0 is a (linked by link_hull()).
  void link_to_outside(Face_handle f, int i)
  {
    const Face_handle g = infinite_faces_.emplace(f->vertex(cw(i)), f->vertex(ccw(i)), dt_.infinite_vertex());
    f->set_neighbor(i, g);
    g->set_neighbor(2, f);
    g->vertex(0)->set_face(g);
    g->vertex(1)->set_face(g);
    hull_.emplace_back(&*g->vertex(0), g);
  }

  // Links between seam faces, as in DT(seam vertices), and to the hull's infinite faces.
  bool link_seam_faces()
  {
    for(std::size_t k = 0; k < reached_faces_.size(); ++k) {
      const Region_face f = reached_faces_[k];
      for(int i = 0; i < 3; ++i) {
        if(f->info() & (1u << i))
          continue; // a wall, linked below
        const Region_face g = f->neighbor(i);
        if(seams_->is_infinite(g)) {
          link_to_outside(seam_face_[k], i);
          continue;
        }
        const int j = g->index(f);
        if(g->info() & (1u << j))
          return false; // the other side is a wall's seam side too
        seam_face_[k]->set_neighbor(i, seam_face_of(g));
      }
    }
    return true;
  }

  // Links across the walls (or to the hull's infinite faces), each wall's two sides checked
  // to be the same edge; the walls that are not locally Delaunay go to failing_.
  bool link_walls()
  {
    std::size_t wall_index = 0;
    for(const Block_output& o : out_)
      for(const Wall& wall : o.walls) {
        const Wall_side side = wall_side_[wall_index++];
        if(seams_->is_infinite(side.face)) {
          link_to_outside(wall.face, wall.i);
          continue;
        }
        const Face_handle g = seam_face_of(side.face);
        const Face_handle f = wall.face;
        if(g->vertex(ccw(side.i)) != f->vertex(cw(wall.i)) || g->vertex(cw(side.i)) != f->vertex(ccw(wall.i)))
          return false;
        f->set_neighbor(wall.i, g);
        g->set_neighbor(side.i, f);
        if(!is_locally_delaunay(gt_, f->vertex(wall.i)->point(), f->vertex(ccw(wall.i))->point(),
                                f->vertex(cw(wall.i))->point(), g->vertex(side.i)->point()))
          failing_.emplace_back(f, wall.i);
      }
    return true;
  }

  // Links the hull's infinite faces around the hull, found by their vertex 0 (sorted by
  // address); each hull vertex must be on it once, the hull at least a triangle.
  bool link_hull()
  {
    std::sort(hull_.begin(), hull_.end(),
              [](const auto& a, const auto& b) { return std::less<const void*>()(a.first, b.first); });
    for(std::size_t k = 0; k < hull_.size(); ++k) {
      if(k > 0 && hull_[k].first == hull_[k - 1].first)
        return false; // a vertex twice on the hull
      const Face_handle g = hull_[k].second;
      const void* a = &*g->vertex(1);
      const auto next = std::lower_bound(hull_.begin(), hull_.end(), a, [](const auto& h, const void* v) {
        return std::less<const void*>()(h.first, v);
      });
      if(next == hull_.end() || next->first != a)
        return false;
      g->set_neighbor(0, next->second);
      next->second->set_neighbor(1, g);
    }
    return hull_.size() >= 3;
  }

  // The duplicates merged into the vertex of their point (dropped_); every seam vertex must be
  // in a face again (the others are in their kept faces).
  bool drop_duplicates()
  {
    for(const auto& m : merged_) {
      dropped_.push_back(vertex_of_[m[0]]);
      merge_index_info_of(vertex_of_[m[1]], vertex_of_[m[0]]); // which holds its block's duplicates
      ++duplicates_;
    }
    std::sort(dropped_.begin(), dropped_.end());
    for(const Block_output& o : out_) {
      duplicates_ += o.duplicates;
      kept_faces_ += o.kept_faces;
      for(const std::uint32_t i : o.seam_points)
        if((vertex_of_[i]->face() == Face_handle()) !=
           std::binary_search(dropped_.begin(), dropped_.end(), vertex_of_[i]))
          return false; // a seam vertex in no face, or a dropped one in a face
    }
    return true;
  }

  // Spliced into the triangulation, checked, the failing walls flipped; `dt_` cleared if the
  // check fails.
  bool splice_and_certify(Statistics& stats, Block_build_counts* counts)
  {
    auto& tds = dt_.tds();
    tds.faces().clear(); // the constructor's face of dimension -1
    tds.set_dimension(2);
    for(Block_output& o : out_) {
      tds.vertices().merge(o.dt->tds().vertices());
      tds.faces().merge(o.dt->tds().faces());
      o.dt.reset();
    }
    tds.faces().merge(seam_faces_);
    dt_.infinite_vertex()->set_face(hull_.front().second);
    tds.faces().merge(infinite_faces_);
    for(const Vertex_handle v : dropped_)
      tds.delete_vertex(v);
    const std::size_t walls_failing = failing_.size();
    std::size_t flips = 0;
    std::vector<Face_handle> touched;
    if(!hull_is_convex_and_wound_once(dt_) ||
       !lawson_flip(dt_, failing_, default_max_flips(n_), flips, touched, parallel_)) {
      dt_.clear();
      return false;
    }
    stats.points_reinserted += n_;
    stats.duplicate_points += duplicates_;
    if(counts != nullptr)
      *counts = Block_build_counts{region_.size(), kept_faces_, seam_points_, walls_, walls_failing};
    return true;
  }

  DT& dt_;
  const Gt& gt_;
  PointIterator points_;
  const std::size_t n_;
  const double scale_;
  const std::vector<std::uint32_t>& order_;
  const std::vector<Build_block>& region_;
  const Kept& kept_in_block_;
  const bool parallel_;
  // Declared in the order the stages fill them.
  std::vector<Vertex_handle> vertex_of_; // each block writes its own seam points' entries
  std::vector<Block_output> out_;
  std::size_t seam_points_ = 0;
  std::optional<Rt> seams_;                                 // DT(seam vertices)
  std::vector<Region_vertex> seam_vertex_;                  // the vertex in seams_ of each seam point
  std::vector<std::array<std::uint32_t, 2>> merged_;        // (point, point of the seam vertex)
  std::vector<Wall_side> wall_side_;                        // of each wall, in the blocks' order
  std::vector<Region_face> stack_;
  std::size_t walls_ = 0;
  Face_range seam_faces_;
  std::vector<Region_face> reached_faces_;                  // the seam faces of seams_, numbered
  std::vector<Face_handle> seam_face_;                      // the result's face of each
  Face_range infinite_faces_;
  std::vector<std::pair<const void*, Face_handle>> hull_;   // (vertex 0, infinite face)
  std::vector<std::pair<Face_handle, int>> failing_;        // walls not locally Delaunay
  std::vector<Vertex_handle> dropped_;                      // duplicates' vertices, sorted
  std::size_t duplicates_ = 0, kept_faces_ = 0;
};

// Builds DT(points[0, n)) into `dt` (no vertex yet) from blocks of the points: block b is
// order[region[b].begin, region[b].end) (every point in exactly one block; its rectangle is not
// read here). `kept(b, p, q, r)` says, on the scaled coordinates (`scale`, grid.h) of a face of
// DT(block b), whether no point of another block can lie in the face's circumdisk: it only
// steers, the result is certified as described below. Returns false, with `dt` still empty,
// when the pieces do not fit; then the caller builds otherwise. `counts`, if given, receives
// what the build did.
//
// The triangulation is assembled without any search: each block creates the vertices of its
// points and its kept faces in containers of its own (CGAL's containers are not thread-safe),
// linked to each other as in the block; the seams' faces and the hull's infinite faces are
// created next, linked to each other as in DT(seam vertices) and to the kept faces across
// the walls, found once in DT(seam vertices); the containers are then spliced. Its
// certificate: every face is counterclockwise and every half-edge is linked to a twin of
// opposite direction (checked across walls), or lies on the hull, checked convex and wound
// once (predicates.h), so the faces tile the hull (the argument of import_prediction.h); an
// edge between two kept faces is locally Delaunay because it is one in its block's Delaunay
// triangulation with the same two faces, one between seam faces likewise in DT(seam
// vertices), and the walls are tested by the exact in-circle test. Walls that fail (none
// when the steering is right) are flipped by Lawson's algorithm.
template <class DT, class PointIterator, class Kept>
bool triangulate_blocks(DT& dt, PointIterator points, std::size_t n, double scale,
                        const std::vector<std::uint32_t>& order, const std::vector<Build_block>& region,
                        const Kept& kept_in_block, Statistics& stats, bool parallel, Block_build_counts* counts)
{
  CGAL_precondition(dt.number_of_vertices() == 0);
  return Block_assembly<DT, PointIterator, Kept>(dt, points, n, scale, order, region, kept_in_block, parallel)
      .run(stats, counts);
}

// Builds DT(points[0, n)) into `dt` (no vertex yet) in blocks (see the file's comment):
// `blocks` blocks (a power of two, at least 2) on TBB's threads when `parallel`. Every point is
// a vertex with its index as info(), duplicates merged (the smallest index kept, counted in
// `stats.duplicate_points`). Returns false, with `dt` still empty, when the steering went
// wrong; then the caller builds sequentially. `counts`, if given, receives what it did.
template <class DT, class PointIterator>
bool build_in_blocks(DT& dt, PointIterator points, std::size_t n, Statistics& stats, std::size_t blocks,
                      bool parallel = true, Block_build_counts* counts = nullptr)
{
  CGAL_precondition(dt.number_of_vertices() == 0);
  if(blocks < 2 || n < 3 || n >= std::size_t(std::uint32_t(-1)))
    return false;
  int depth = 0;
  while((std::size_t(1) << depth) < blocks)
    ++depth;

  // Scaled coordinates: exact (a power of two), the box's larger side in [1, 2] (grid.h).
  const Box box = bounding_box(n, [&](std::size_t i) -> decltype(points[0]) { return points[i]; });
  const double scale = unit_scale(box);
  std::vector<std::array<double, 2>> xy(n);
  for_each_range(parallel, n, 65536, [&](std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i)
      xy[i] = {CGAL::to_double(points[i].x()) * scale, CGAL::to_double(points[i].y()) * scale};
  });
  std::vector<std::uint32_t> order(n);
  for(std::size_t i = 0; i < n; ++i)
    order[i] = std::uint32_t(i);
  std::vector<Build_block> region;
  Build_block all;
  all.end = n;
  split_into_blocks(order, xy, all,
                     {box.xmin * scale, box.xmax * scale, box.ymin * scale, box.ymax * scale}, depth, region, parallel);
  std::vector<std::array<double, 2>>().swap(xy);
  auto inside_rectangle = [&](std::size_t b, const std::array<double, 2>& p, const std::array<double, 2>& q,
                              const std::array<double, 2>& r) { return circumdisk_inside(p, q, r, region[b]); };
  return triangulate_blocks(dt, points, n, scale, order, region, inside_rectangle, stats, parallel, counts);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_BLOCK_PARALLEL_BUILD_H
