// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Theorem 4.1 of the paper (Strategy::theorem_4_1): DT(P) from a predicted triangulation G in
// expected O(n + D log n) time.
//  1. Theorem 3.3's rounds along a spanning tree of G's edges (conflict_list_rounds.h),
//     stopped after l = 3 rounds: DT(R_3) for the sample with s_3 = floor(log2 floor(log2 n)),
//     with the conflict lists of its faces (Lemma 3.2).
//  2. Cells, each with the conflict list of the points that can own a piece of it; the
//     exceptional ones (list longer than 6 b s_3, b = s_3) are computed at once.
//  3. Supercells: the cells divided into connected groups of about t = s_3^4 cells.
//  4. Walls: between two supercells, the lower envelope of the candidate sites along each
//     wall gives a chain of DT(P) edges.
//  5. The chains cut DT(P) into regions, each inside one supercell; a supercell is good when
//     every edge of its regions' boundary is an edge of G and G's faces inside (a flood fill
//     from the boundary) are counterclockwise and locally Delaunay: then they are DT(P)'s
//     faces there (the paper's footnote 4). The cells of the bad supercells are computed.
//  6. The faces (G's in good supercells, the computed ones elsewhere) are returned as index
//     triples; the caller imports them with the package's certificate (O(n)), the proof's
//     assertion made at run time.
//
// The plane's exact form of the paper's 3D objects, and what differs (named in the manual):
// - A vertex of LE(P*) is a Delaunay triangle of P, at its circumcentre; a point of the plane
//   belongs to the Voronoi cell of its nearest site of R_3. The cells here are those Voronoi
//   cells (the paper's cells of Decomp(R*) are their thirds; a Voronoi cell is the union of
//   O(degree) of them, so the expected costs keep their order): a triangle of DT(P) is owned
//   by the site of R_3 nearest to its circumcentre, ties to the smaller rank, decided exactly
//   (voronoi_predicates.h). A point that can own part of the cell of site v lies in the
//   circumdisk (or, for an infinite face, the open half-plane) of a face of DT(R_3) around v,
//   because the disk centred at a point x of the cell through v lies in their union; so the
//   cell's conflict list is the union of those faces' lists, and its candidates are v, its
//   neighbours and that list.
// - LE(P_tau*) within a cell: the Delaunay triangulation of the candidates (flat_insertion.h),
//   of which the triangles the cell owns are DT(P)'s: their circumdisks hold no candidate,
//   and no other point can lie in them. O(m log m) expected for m candidates, as the paper's
//   envelope computation.
// - Supercells: grow_regions() (region_growing.h), breadth-first region growing on the cells'
//   adjacency, not Frederickson's t-division: no O(sqrt t) bound on a supercell's walls.
// - Walls: the Voronoi edges of R_3 between cells of different supercells, each the segment
//   (or ray) between the circumcentres of the edge's two faces. The sites that own a piece of
//   it are in the two faces' lists (the disks centred on the edge through its ends are covered
//   by the two circumdisks). The chain is traced from one end by always taking the next
//   crossing (O(m k) for m candidates and k crossings, instead of an O(m log m) envelope).
// - Ties the paper's general position excludes, but which are the rule here: every sample
//   point is a point of P, so a Delaunay triangle of P with two sample points as vertices has
//   its circumcentre on their wall, and a face of DT(R_3) with an empty list is a face of
//   DT(P) with its circumcentre at the end of three walls. A point on a wall belongs to the
//   cell of the end of smaller rank, so each wall is traced as if moved by an infinitesimal
//   towards the other end (the tilt of voronoi_predicates.h), a crossing exactly at a wall's
//   end is left out, and the edges of the faces of DT(R_3) with an empty list join the chains
//   where the owner changes across them (add_sample_face_sides()).
// - Good test: as the paper's, with spikes (an edge with the same supercell on both sides)
//   dropped. An edge of G with no face beyond must be a hull edge of P, which is read off the
//   triangulation of the hull's candidates (the hull vertices of R_3 and the points in the
//   lists of its infinite faces). Faces of G listed clockwise are turned first. A flood that
//   passes a budget (about four times the supercell's candidates) marks its supercell bad,
//   so a G that is no triangulation costs no more.
// In general position every step is exact and the faces returned are DT(P)'s. Where the
// input is degenerate (a circumcentre of DT(P) on a Voronoi edge of R_3, as on co-circular
// grids) a candidate on a circle may be missed; the caller's certificate then finds the
// failing edges and the package's repair fixes them (Statistics counts them), so the result
// is exact whatever the input.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SUPERCELLS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SUPERCELLS_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/build/conflict_list_rounds.h>
#include <CGAL/Delaunay_from_prediction/internal/build/flat_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/region_growing.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/voronoi_predicates.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Theorem 4.1's parameters for n points: the last round's divisor s_3, the exceptional
// cells' threshold b s_3 with the paper's b = s_3, times 6 because a Voronoi cell is the union
// of about six cells of Decomp(R*), and the supercell size t = s_3^4 (cells).
struct Theorem_4_1_parameters
{
  std::size_t s = 1, exceptional_list = 0, supercell = 1;
  explicit Theorem_4_1_parameters(const std::vector<std::size_t>& divisors)
  {
    s = divisors.size() > 2 ? divisors[2] : 1;
    exceptional_list = 6 * s * s;
    supercell = (std::max)(std::size_t(16), s * s * s * s);
  }
};

// The prediction's faces (three ranks each) with their adjacency: corner c = 3f + i starts the
// edge g[c] -> g[3f + ccw(i)], with face f on its left; across[c] is the corner of the face
// beyond that starts the opposite edge, `none` at a boundary, `conflicted` where faces overlap
// (an edge with two faces on one side).
struct Prediction_adjacency
{
  static constexpr std::uint32_t none = std::uint32_t(-1), conflicted = std::uint32_t(-3);
  const std::vector<std::uint32_t>& g;
  std::vector<std::uint32_t> first, corners, across; // corners around each vertex, by counting sort

  Prediction_adjacency(const std::vector<std::uint32_t>& faces, std::size_t n) : g(faces), first(n + 1, 0)
  {
    for(const std::uint32_t v : g)
      ++first[v + 1];
    for(std::size_t v = 0; v < n; ++v)
      first[v + 1] += first[v];
    corners.resize(g.size());
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for(std::uint32_t c = 0; c < g.size(); ++c)
      corners[next[g[c]]++] = c;
    across.resize(g.size());
    for(std::uint32_t c = 0; c < g.size(); ++c)
      across[c] = corner_left_of(g[3 * (c / 3) + ccw(int(c % 3))], g[c]);
  }

  // The corner starting p -> q, `none` or `conflicted`.
  std::uint32_t corner_left_of(std::uint32_t p, std::uint32_t q) const
  {
    std::uint32_t found = none;
    for(std::uint32_t k = first[p]; k < first[p + 1]; ++k) {
      const std::uint32_t c = corners[k];
      if(g[3 * (c / 3) + ccw(int(c % 3))] == q)
        found = found == none ? c : conflicted;
    }
    return found;
  }
};

// A wall's line of a site (voronoi_predicates.h), in NT.
template <class NT>
struct Line_view
{
  NT intercept, slope, tilt;
  template <class L>
  explicit Line_view(const L& l) : intercept(l.intercept), slope(l.slope), tilt(l.tilt)
  {}
  Line_view(const NT& a, const NT& b, const NT& t) : intercept(a), slope(b), tilt(t) {}
};

// Steps 2 to 5 on DT(R_3) with its conflict lists. Ranks are the points' preorder ranks.
template <class Gt>
class Supercells
{
public:
  using Flat = Flat_delaunay<Gt>;
  using Point = typename Flat::Point;
  static constexpr std::uint32_t infinite = Flat::infinite;
  static constexpr std::uint32_t none = std::uint32_t(-1);
  static constexpr std::uint32_t conflicted = std::uint32_t(-3);

  Supercells(const Gt& gt, const Flat& sample, const Conflict_lists& lists, const Theorem_4_1_parameters& parameters,
             std::size_t n, Statistics& stats)
      : gt_(gt), sample_(sample), lists_(lists), parameters_(parameters), n_(n), stats_(stats), local_(gt)
  {
    stamp_.assign(n, 0);
    vertex_face_.assign(n, none);
    const std::size_t faces = sample_.number_of_faces();
    for(std::size_t t = 0; t < faces; ++t)
      for(int i = 0; i < 3; ++i)
        if(sample_.vertex(t, i) != infinite)
          vertex_face_[sample_.vertex(t, i)] = std::uint32_t(t);
  }

  // Step 2: the cells' list sizes; the exceptional cells' triangles computed now.
  void compute_exceptional_cells()
  {
    list_size_.assign(n_, 0);
    std::vector<std::uint32_t> candidates;
    for(std::uint32_t v = 0; v < n_; ++v) {
      if(!is_site(v))
        continue;
      list_size_[v] = std::uint32_t(collect_candidates(v, candidates));
      if(list_size_[v] > parameters_.exceptional_list) {
        ++stats_.exceptional_cells;
        triangulate_cell(v, candidates, exceptional_triangles_);
        while(exceptional_site_.size() < exceptional_triangles_.size() / 3)
          exceptional_site_.push_back(v);
      }
    }
  }

  // Step 3: the supercells, grown over the cells' adjacency (the edges of DT(R_3)).
  void divide()
  {
    supercell_.assign(n_, outside_regions);
    for(std::uint32_t v = 0; v < n_; ++v)
      if(is_site(v))
        supercell_[v] = no_region;
    supercells_ = grow_regions(supercell_, parameters_.supercell, [&](std::uint32_t v, auto&& f) {
      for_each_neighbor(v, [&](std::uint32_t u) {
        if(u != infinite)
          f(u);
      });
    });
    stats_.supercells = supercells_;
    budget_.assign(supercells_, 64);
    for(std::uint32_t v = 0; v < n_; ++v)
      if(is_site(v))
        budget_[supercell_[v]] += 4 * (list_size_[v] + 8);
  }

  // Step 4: the chains along every wall between two supercells, as directed edges with the
  // supercell on their left; spikes dropped.
  void trace_walls(const Hash_map<std::uint64_t, std::uint32_t>& hull)
  {
    // (supercell, p, q, 0): the supercell is left of p -> q, one record per crossing
    std::vector<std::array<std::uint32_t, 4>> sides;
    add_sample_face_sides(hull, sides);
    std::vector<std::uint32_t> candidates, chain;
    const std::size_t faces = sample_.number_of_faces();
    for(std::uint32_t t = 0; t < faces; ++t)
      for(int i = 0; i < 3; ++i) {
        std::uint32_t u = sample_.vertex(t, ccw(i)), w = sample_.vertex(t, cw(i));
        if(u == infinite || w == infinite || u > w || supercell_[u] == supercell_[w])
          continue;
        std::uint32_t left = t, right = std::uint32_t(sample_.neighbor(t, i));
        if(sample_.is_infinite(right)) {
          std::swap(u, w);
          std::swap(left, right);
        }
        ++stats_.walls;
        collect_wall_candidates(left, right, candidates);
        trace_chain(u, w, left, right, candidates, chain);
        for(std::size_t k = 0; k + 1 < chain.size(); ++k) {
          sides.push_back({supercell_[u], chain[k], chain[k + 1], 0});
          sides.push_back({supercell_[w], chain[k + 1], chain[k], 0});
        }
        stats_.chain_edges += chain.empty() ? 0 : chain.size() - 1;
      }
    // Each record is one crossing of the supercell's boundary: a Delaunay edge that crosses
    // it an even number of times (a spike) has both sides in the same region and is dropped,
    // one that crosses it an odd number of times keeps its net direction.
    // The side of a hull edge of P beyond the hull is no region (a chain on a ray crosses the
    // hull edges' rays).
    sides.erase(std::remove_if(sides.begin(), sides.end(),
                               [&](const auto& side) { return hull.contains(directed_edge_key(side[2], side[1])); }),
                sides.end());
    for(auto& side : sides)
      if(side[1] > side[2])
        side = {side[0], side[2], side[1], std::uint32_t(-1)};
    std::sort(sides.begin(), sides.end(), [](const auto& x, const auto& y) {
      return std::make_tuple(x[0], x[1], x[2]) < std::make_tuple(y[0], y[1], y[2]);
    });
    boundary_offsets_.assign(supercells_ + 1, 0);
    for(std::size_t k = 0; k < sides.size();) {
      std::size_t end = k;
      int net = 0;
      for(; end < sides.size() && sides[end][0] == sides[k][0] && sides[end][1] == sides[k][1] &&
            sides[end][2] == sides[k][2];
          ++end)
        net += sides[end][3] == 0 ? 1 : -1;
      if(net != 0) {
        boundary_.push_back(net > 0 ? std::array<std::uint32_t, 2>{sides[k][1], sides[k][2]}
                                    : std::array<std::uint32_t, 2>{sides[k][2], sides[k][1]});
        ++boundary_offsets_[sides[k][0] + 1];
      }
      k = end;
    }
    for(std::size_t g = 0; g < supercells_; ++g)
      boundary_offsets_[g + 1] += boundary_offsets_[g];
  }

  // The faces of DT(R_3) with an empty list are faces of DT(P), with their circumcentre at a
  // corner of three cells: owned by the smallest rank of the three. The DT(P) face beyond
  // each edge p -> q has its circumcentre on the wall of p q (owned by the smaller of p and
  // q) unless it is the face of DT(R_3) beyond, with an empty list too, or none (a hull edge).
  void add_sample_face_sides(const Hash_map<std::uint64_t, std::uint32_t>& hull,
                             std::vector<std::array<std::uint32_t, 4>>& sides) const
  {
    const std::size_t faces = sample_.number_of_faces();
    auto corner_owner = [&](std::size_t t) {
      return (std::min)((std::min)(sample_.vertex(t, 0), sample_.vertex(t, 1)), sample_.vertex(t, 2));
    };
    for(std::size_t t = 0; t < faces; ++t) {
      if(sample_.is_infinite(t) || lists_.size_of(t) != 0)
        continue;
      const std::uint32_t owner = supercell_[corner_owner(t)];
      for(int i = 0; i < 3; ++i) {
        const std::uint32_t p = sample_.vertex(t, ccw(i)), q = sample_.vertex(t, cw(i));
        const std::size_t beyond = sample_.neighbor(t, i);
        std::uint32_t other;
        if(!sample_.is_infinite(beyond) && lists_.size_of(beyond) == 0) {
          if(beyond < t) // seen from there
            continue;
          other = supercell_[corner_owner(beyond)];
        } else if(sample_.is_infinite(beyond) && hull.contains(directed_edge_key(p, q)))
          continue;
        else
          other = supercell_[(std::min)(p, q)];
        if(other != owner) {
          sides.push_back({owner, p, q, 0});
          sides.push_back({other, q, p, 0});
        }
      }
    }
  }

  // Step 5: the good test of every supercell against G (`g` in ranks, three per face), with
  // `hull` the directed hull edges of P (interior on the left). `on_good_face(f)` gets the
  // faces of G that the good supercells keep; the bad supercells' triangles are then given,
  // in ranks, to `on_triangle(a, b, c)`.
  template <class OnGoodFace, class OnTriangle>
  void test_and_compute(const std::vector<std::uint32_t>& g, const Hash_map<std::uint64_t, std::uint32_t>& hull,
                        OnGoodFace on_good_face, OnTriangle on_triangle)
  {
    const std::size_t faces = g.size() / 3;
    const Prediction_adjacency adjacency(g, n_);
    // The supercell whose boundary each face's edge is on (edge i of face f: g[3f + i] ->
    // g[3f + ccw(i)], the face on its left), `conflicted` for the boundary of two.
    std::vector<std::uint32_t> stop(3 * faces, none);
    for(std::uint32_t s = 0; s < supercells_; ++s)
      for(std::uint32_t k = boundary_offsets_[s]; k < boundary_offsets_[s + 1]; ++k) {
        const std::uint32_t c = adjacency.corner_left_of(boundary_[k][0], boundary_[k][1]);
        if(c < 3 * faces)
          stop[c] = stop[c] == none || stop[c] == s ? s : conflicted;
      }
    std::vector<std::uint32_t> visited_by(faces, none), flood;
    bad_.assign(supercells_, 0);
    for(std::uint32_t s = 0; s < supercells_; ++s) {
      const bool good = supercells_ > 1 && flood_is_good(s, g, adjacency, stop, hull, visited_by, flood);
      if(good) {
        for(const std::uint32_t f : flood)
          on_good_face(f);
      } else {
        bad_[s] = 1;
        ++stats_.bad_supercells;
      }
    }
    std::vector<std::uint32_t> candidates, triangles;
    for(std::uint32_t v = 0; v < n_; ++v)
      if(is_site(v) && bad_[supercell_[v]] && list_size_[v] <= parameters_.exceptional_list) {
        triangles.clear();
        collect_candidates(v, candidates);
        triangulate_cell(v, candidates, triangles);
        for(std::size_t k = 0; k < triangles.size(); k += 3)
          on_triangle(triangles[k], triangles[k + 1], triangles[k + 2]);
      }
    for(std::size_t k = 0; k < exceptional_site_.size(); ++k)
      if(bad_[supercell_[exceptional_site_[k]]])
        on_triangle(exceptional_triangles_[3 * k], exceptional_triangles_[3 * k + 1],
                    exceptional_triangles_[3 * k + 2]);
  }

private:
  bool is_site(std::uint32_t v) const { return vertex_face_[v] != none && sample_.representative(v) == v; }
  const Point& point(std::uint32_t v) const { return sample_.point(v); }

  // f(t, i) for every face t of DT(R_3) around the site v, with v = vertex(t, i), ccw.
  template <class F>
  void for_each_face_around(std::uint32_t v, F f) const
  {
    const std::uint32_t first = vertex_face_[v];
    std::uint32_t t = first;
    do {
      int i = 0;
      while(sample_.vertex(t, i) != v)
        ++i;
      f(t, i);
      t = std::uint32_t(sample_.neighbor(t, ccw(i)));
    } while(t != first);
  }
  template <class F>
  void for_each_neighbor(std::uint32_t v, F f) const
  {
    for_each_face_around(v, [&](std::uint32_t t, int i) { f(sample_.vertex(t, ccw(i))); });
  }

  // Marks v as seen in the current pass (a fresh stamp per pass); false if it was already.
  bool mark(std::uint32_t v)
  {
    if(stamp_[v] == pass_)
      return false;
    stamp_[v] = pass_;
    return true;
  }
  void new_pass()
  {
    if(++pass_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      pass_ = 1;
    }
  }

  // The candidates of the cell of v: v, its neighbours and the union of the lists of the faces
  // around it, sorted by rank (so that a point given twice is represented by its smaller
  // rank, as everywhere). Returns the size of the union of the lists.
  std::size_t collect_candidates(std::uint32_t v, std::vector<std::uint32_t>& candidates)
  {
    new_pass();
    candidates.clear();
    mark(v);
    candidates.push_back(v);
    std::size_t listed = 0;
    for_each_face_around(v, [&](std::uint32_t t, int i) {
      const std::uint32_t u = sample_.vertex(t, ccw(i));
      if(u != infinite && mark(u))
        candidates.push_back(u);
      for(std::uint32_t k = lists_.offsets[t]; k < lists_.offsets[t + 1]; ++k)
        if(mark(lists_.ranks[k])) {
          candidates.push_back(lists_.ranks[k]);
          ++listed;
        }
    });
    std::sort(candidates.begin(), candidates.end());
    return listed;
  }

  // Whether the site v owns the circumcentre x of the counterclockwise triangle (a, b, c): no
  // site of R_3 is nearer to x, and none as near has a smaller rank. A Delaunay neighbour of v
  // is nearer whenever some site is (a walk towards x through the cells), and the sites as
  // near as v lie on an empty circle, connected by its polygon's edges.
  bool owns(std::uint32_t v, std::uint32_t ra, std::uint32_t rb, std::uint32_t rc)
  {
    const Point &a = point(ra), &b = point(rb), &c = point(rc);
    auto is_corner = [&](std::uint32_t r) { return r == ra || r == rb || r == rc; };
    const bool v_is_corner = is_corner(v);
    bool tie = false;
    bool nearer = false;
    for_each_neighbor(v, [&](std::uint32_t u) {
      if(nearer || u == infinite)
        return;
      // Two corners are on the circle: as near as each other, no test needed.
      const int s = v_is_corner && is_corner(u) ? 0 : compare_distances_to_circumcentre(a, b, c, point(u), point(v));
      nearer = s < 0;
      tie = tie || s == 0;
    });
    if(nearer)
      return false;
    if(!tie)
      return true;
    std::vector<std::uint32_t> queue{v};
    new_pass();
    mark(v);
    for(std::size_t head = 0; head < queue.size(); ++head)
      for_each_neighbor(queue[head], [&](std::uint32_t u) {
        if(u != infinite && stamp_[u] != pass_ &&
           ((v_is_corner && is_corner(u)) || compare_distances_to_circumcentre(a, b, c, point(u), point(v)) == 0)) {
          mark(u);
          queue.push_back(u);
        }
      });
    return *std::min_element(queue.begin(), queue.end()) == v;
  }

  // LE(P_tau*) within the cell of v: the triangles of DT(candidates) that v owns, appended to
  // `out` in ranks.
  void triangulate_cell(std::uint32_t v, const std::vector<std::uint32_t>& candidates,
                        std::vector<std::uint32_t>& out)
  {
    ++stats_.cells_computed;
    if(!local_.build(candidates.size(), [&](std::size_t k) { return point(candidates[k]); }))
      return;
    const std::size_t faces = local_.number_of_faces();
    for(std::size_t t = 0; t < faces; ++t) {
      if(local_.is_infinite(t))
        continue;
      const std::uint32_t a = candidates[local_.vertex(t, 0)], b = candidates[local_.vertex(t, 1)],
                          c = candidates[local_.vertex(t, 2)];
      if(owns(v, a, b, c))
        out.insert(out.end(), {a, b, c});
    }
  }

  // The sites that may own a piece of the wall between the faces `left` and `right` (right
  // finite): their vertices and lists.
  void collect_wall_candidates(std::uint32_t left, std::uint32_t right, std::vector<std::uint32_t>& candidates)
  {
    new_pass();
    candidates.clear();
    for(const std::uint32_t t : {left, right}) {
      for(int i = 0; i < 3; ++i)
        if(sample_.vertex(t, i) != infinite && mark(sample_.vertex(t, i)))
          candidates.push_back(sample_.vertex(t, i));
      for(std::uint32_t k = lists_.offsets[t]; k < lists_.offsets[t + 1]; ++k)
        if(mark(lists_.ranks[k]))
          candidates.push_back(lists_.ranks[k]);
    }
    std::sort(candidates.begin(), candidates.end());
  }

  // The sites owning the wall of the edge u -> w (face `left` on its left, `right` finite on
  // its right) in order from the right face's circumcentre: consecutive sites p, q make the
  // DT(P) edge p -> q, which has u's side of the wall on its left.
  void trace_chain(std::uint32_t u, std::uint32_t w, std::uint32_t left, std::uint32_t right,
                   const std::vector<std::uint32_t>& candidates, std::vector<std::uint32_t>& chain)
  {
    using FT = std::decay_t<decltype(point(0).x())>;
    using Exact = Voronoi_exact<FT>;
    Voronoi_wall<Point> wall;
    wall.a = point(sample_.vertex(right, 0));
    wall.b = point(sample_.vertex(right, 1));
    wall.c = point(sample_.vertex(right, 2));
    wall.segment = !sample_.is_infinite(left);
    if(wall.segment) {
      wall.a2 = point(sample_.vertex(left, 0));
      wall.b2 = point(sample_.vertex(left, 1));
      wall.c2 = point(sample_.vertex(left, 2));
    } else {
      wall.from = point(u);
      wall.to = point(w);
    }
    wall.low = point((std::min)(u, w));
    wall.high = point((std::max)(u, w));
    const std::size_t m = candidates.size();
    chain.clear();
    Protect_FPU_rounding<true> upward;
    const auto frame = wall.template frame<Voronoi_interval>();
    intercept_.resize(m);
    slope_.resize(m);
    tilt_.resize(m);
    for(std::size_t k = 0; k < m; ++k)
      wall.line(frame, point(candidates[k]), intercept_[k], slope_[k], tilt_[k]);
    bool exact_ready = false;
    typename Voronoi_wall<Point>::template Frame<Exact> exact_frame;
    struct Exact_line
    {
      Exact intercept, slope, tilt;
    };
    auto exact_line = [&](std::size_t k) {
      if(!exact_ready) {
        exact_frame = wall.template frame<Exact>();
        exact_ready = true;
      }
      Exact_line l;
      wall.line(exact_frame, point(candidates[k]), l.intercept, l.slope, l.tilt);
      return l;
    };
    // Each test is the sign of an expression of the lines' coefficients, `of(intercept, slope,
    // tilt...)`, evaluated on the intervals and, if they do not decide it, exactly.
    auto sign_of = [&](auto expression, auto... k) {
      const int s = certain_sign(expression(Line_view<Voronoi_interval>{intercept_[k], slope_[k], tilt_[k]}...));
      if(s != 2)
        return s;
      return int(CGAL::sign(expression(Line_view<Exact>{exact_line(k)}...)));
    };
    // Ties known without a test, which would otherwise take the exact path: the right face's
    // vertices are as near as each other at the start (equal intercepts), the left face's at
    // the end (equal intercept + slope), and the wall's ends all along it (equal lines).
    enum : unsigned char { on_right = 1, on_left = 2, at_end = 4 };
    role_.assign(m, 0);
    for(std::size_t k = 0; k < m; ++k) {
      const std::uint32_t r = candidates[k];
      for(int i = 0; i < 3; ++i) {
        role_[k] |= sample_.vertex(right, i) == r ? on_right : 0;
        role_[k] |= wall.segment && sample_.vertex(left, i) == r ? on_left : 0;
      }
      role_[k] |= r == u || r == w ? at_end : 0;
    }
    auto both = [&](std::size_t j, std::size_t k, unsigned char role) { return (role_[j] & role_[k] & role) != 0; };
    // g_j - g_k just after the start (l = f with e << f << 1): intercepts, then slopes, then tilts.
    auto compare_at_start = [&](std::size_t j, std::size_t k) {
      int s = 0;
      if(!both(j, k, on_right | at_end))
        s = sign_of([](const auto& lj, const auto& lk) { return lj.intercept - lk.intercept; }, j, k);
      if(s == 0 && !both(j, k, at_end))
        s = sign_of([](const auto& lj, const auto& lk) { return lj.slope - lk.slope; }, j, k);
      if(s == 0)
        s = sign_of([](const auto& lj, const auto& lk) { return lj.tilt - lk.tilt; }, j, k);
      return s;
    };
    auto compare_slopes = [&](std::size_t j, std::size_t k) {
      return both(j, k, at_end) ? 0 : sign_of([](const auto& lj, const auto& lk) { return lj.slope - lk.slope; }, j, k);
    };
    // The sign of l_j - l_k, l_j = (A_j + e T_j - A_p - e T_p) / (B_p - B_j) the crossing of
    // j's line with p's (both denominators positive).
    auto compare_crossings = [&](std::size_t p, std::size_t j, std::size_t k) {
      const bool same_point = both(j, k, at_end) || (role_[p] & role_[j] & role_[k] & on_left) != 0;
      int s = same_point ? 0 : sign_of(
          [](const auto& lp, const auto& lj, const auto& lk) {
            return (lj.intercept - lp.intercept) * (lp.slope - lk.slope) -
                   (lk.intercept - lp.intercept) * (lp.slope - lj.slope);
          },
          p, j, k);
      if(s == 0)
        s = sign_of(
            [](const auto& lp, const auto& lj, const auto& lk) {
              return (lj.tilt - lp.tilt) * (lp.slope - lk.slope) - (lk.tilt - lp.tilt) * (lp.slope - lj.slope);
            },
            p, j, k);
      return s;
    };
    // The sign of l_j - 1 for e = 0: a crossing at the end itself, where the left face is then
    // a face of DT(P) (its list is empty), is left to that face (add_sample_face_sides()).
    auto compare_crossing_to_end = [&](std::size_t p, std::size_t j) {
      return both(p, j, on_left) ? 0
                                 : sign_of([](const auto& lp, const auto& lj) {
                                     return (lj.intercept - lp.intercept) - (lp.slope - lj.slope);
                                   }, p, j);
    };
    // The owner at the start: the lowest line, then the steepest, then the smaller rank.
    std::size_t p = 0;
    for(std::size_t k = 1; k < m; ++k) {
      if(compare_at_start(k, p) < 0)
        p = k;
    }
    chain.push_back(candidates[p]);
    for(std::size_t steps = 0; steps < m; ++steps) {
      std::size_t next = m;
      for(std::size_t k = 0; k < m; ++k) {
        if(k == p || compare_slopes(k, p) >= 0)
          continue;
        if(next == m) {
          next = k;
          continue;
        }
        int s = compare_crossings(p, k, next);
        if(s == 0)
          s = compare_slopes(k, next);
        if(s < 0)
          next = k;
      }
      if(next == m || (wall.segment && compare_crossing_to_end(p, next) >= 0))
        break;
      p = next;
      chain.push_back(candidates[p]);
    }
  }

  // The flood of the good test in G from the faces left of supercell s's boundary edges.
  bool flood_is_good(std::uint32_t s, const std::vector<std::uint32_t>& g, const Prediction_adjacency& adjacency,
                     const std::vector<std::uint32_t>& stop, const Hash_map<std::uint64_t, std::uint32_t>& hull,
                     std::vector<std::uint32_t>& visited_by, std::vector<std::uint32_t>& flood)
  {
    flood.clear();
    const std::size_t corners = g.size();
    for(std::uint32_t k = boundary_offsets_[s]; k < boundary_offsets_[s + 1]; ++k) {
      const std::uint32_t c = adjacency.corner_left_of(boundary_[k][0], boundary_[k][1]);
      if(c >= corners) // not an edge of G, or one with two faces on the same side
        return false;
      if(visited_by[c / 3] != s) {
        visited_by[c / 3] = s;
        flood.push_back(c / 3);
      }
    }
    auto orientation = gt_.orientation_2_object();
    for(std::size_t head = 0; head < flood.size(); ++head) {
      if(flood.size() > budget_[s])
        return false;
      const std::uint32_t f = flood[head];
      const Point &a = point(g[3 * f]), &b = point(g[3 * f + 1]), &c = point(g[3 * f + 2]);
      if(orientation(a, b, c) != LEFT_TURN)
        return false;
      for(int i = 0; i < 3; ++i) {
        if(stop[3 * f + i] == s || stop[3 * f + i] == conflicted)
          continue;
        const std::uint32_t beyond = adjacency.across[3 * f + i];
        if(beyond == none) {
          if(!hull.contains(directed_edge_key(g[3 * f + i], g[3 * f + ccw(i)])))
            return false;
          continue;
        }
        if(beyond == conflicted)
          return false;
        const std::uint32_t h = beyond / 3; // the face beyond, whose corner beyond / 3 starts q -> p
        if(side_of_oriented_circle_perturbed(gt_, a, b, c, point(g[3 * h + cw(int(beyond % 3))])) == ON_POSITIVE_SIDE)
          return false;
        if(visited_by[h] != s) {
          visited_by[h] = s;
          flood.push_back(h);
        }
      }
    }
    return true;
  }

  const Gt& gt_;
  const Flat& sample_;
  const Conflict_lists& lists_;
  Theorem_4_1_parameters parameters_;
  std::size_t n_;
  Statistics& stats_;
  Flat local_; // the cells' triangulations, one at a time
  std::vector<std::uint32_t> stamp_, vertex_face_, list_size_, supercell_, budget_;
  std::uint32_t pass_ = 0;
  std::uint32_t supercells_ = 0;
  std::vector<std::uint32_t> exceptional_triangles_, exceptional_site_;
  std::vector<std::array<std::uint32_t, 2>> boundary_;
  std::vector<std::uint32_t> boundary_offsets_;
  std::vector<unsigned char> bad_;
  std::vector<Voronoi_interval> intercept_, slope_, tilt_;
  std::vector<unsigned char> role_; // a wall's candidates: vertex of its right face, left face, end
};

// The directed hull edges of P (interior on the left), from DT(R_3): the hull of its hull
// vertices and of the points in its infinite faces' lists, triangulated on their own.
template <class Gt>
Hash_map<std::uint64_t, std::uint32_t> hull_edges(const Gt& gt, const Flat_delaunay<Gt>& sample,
                                                  const Conflict_lists& lists)
{
  std::vector<std::uint32_t> candidates;
  std::vector<unsigned char> seen;
  auto add = [&](std::uint32_t r) {
    if(r >= seen.size())
      seen.resize(std::size_t(r) + 1, 0);
    if(!seen[r]) {
      seen[r] = 1;
      candidates.push_back(r);
    }
  };
  for(std::size_t t = 0; t < sample.number_of_faces(); ++t)
    if(sample.is_infinite(t)) {
      for(int i = 0; i < 3; ++i)
        if(sample.vertex(t, i) != Flat_delaunay<Gt>::infinite)
          add(sample.vertex(t, i));
      for(std::uint32_t k = lists.offsets[t]; k < lists.offsets[t + 1]; ++k)
        add(lists.ranks[k]);
    }
  std::sort(candidates.begin(), candidates.end());
  Hash_map<std::uint64_t, std::uint32_t> hull(2 * candidates.size() + 64);
  Flat_delaunay<Gt> flat(gt);
  if(!flat.build(candidates.size(), [&](std::size_t k) { return sample.point(candidates[k]); }))
    return hull;
  for(std::size_t t = 0; t < flat.number_of_faces(); ++t)
    for(int i = 0; i < 3; ++i)
      if(flat.vertex(t, i) == Flat_delaunay<Gt>::infinite) // (a, b, infinite) lies left of a -> b
        hull.insert(directed_edge_key(candidates[flat.vertex(t, cw(i))], candidates[flat.vertex(t, ccw(i))]), 0);
  return hull;
}

// Theorem 4.1: the faces of DT(points) as index triples in `result`, from the prediction's
// faces `triples` (validated indices, three per face), the predicted faces that the good
// supercells keep first (`kept` of them). False, with `result` empty, when the points span
// no triangle (the caller then goes on with the prediction).
template <class Gt, class PointIterator>
bool delaunay_faces_by_supercells(const Gt& gt, PointIterator points, std::size_t n,
                                  const std::vector<std::uint32_t>& triples, std::vector<std::uint32_t>& result,
                                  std::size_t& kept, Statistics& stats, std::uint64_t seed = 0x5ec710e3ull)
{
  result.clear();
  kept = 0;
  if(n < 3)
    return false;
  std::vector<std::uint32_t> ends;
  ends.reserve(4 * (triples.size() / 3));
  for(std::size_t t = 0; t < triples.size(); t += 3)
    ends.insert(ends.end(), {triples[t], triples[t + 1], triples[t + 1], triples[t + 2]});
  const Preorder_forest forest = preorder_spanning_forest(adjacency_of(ends, n));
  std::vector<std::uint32_t>().swap(ends);
  const std::vector<std::size_t> divisors = theorem_3_3_divisors(n);
  const Theorem_4_1_parameters parameters(divisors);
  const Nested_samples samples = sample_multiset(forest, divisors, seed);
  const std::size_t last = (std::min)(std::size_t(2), samples.end.size() - 1);
  stats.insertion_rounds = last + 1;
  // 1. The rounds, stopped at R_3, and the conflict lists of DT(R_3).
  Conflict_list_rounds<Gt> rounds(
      gt, forest, [&](std::size_t r) -> decltype(points[0]) { return points[forest.order[r]]; }, stats);
  const std::size_t inserted =
      run_conflict_list_rounds(rounds, samples, last, [](const auto&, const Conflict_lists&) {});
  if(inserted == 0)
    return false;
  const auto& sample = rounds.flat();
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    result.insert(result.end(), {forest.order[a], forest.order[b], forest.order[c]});
  };
  if(inserted == n) { // s_3 = 1: DT(R_3) is DT(P)
    for(std::size_t t = 0; t < sample.number_of_faces(); ++t)
      if(!sample.is_infinite(t))
        emit(sample.vertex(t, 0), sample.vertex(t, 1), sample.vertex(t, 2));
    return true;
  }
  rounds.locate_along_tree();
  const Conflict_lists lists = rounds.conflict_lists();
  Supercells<Gt> cells(gt, sample, lists, parameters, n, stats);
  // 2. The exceptional cells. 3. The supercells. 4. The walls' chains.
  const Hash_map<std::uint64_t, std::uint32_t> hull = hull_edges(gt, sample, lists);
  cells.compute_exceptional_cells();
  cells.divide();
  cells.trace_walls(hull);
  // 5. The good test against G (in ranks), and the cells of the bad supercells.
  std::vector<std::uint32_t> rank_of(n), g(triples.size());
  for(std::size_t r = 0; r < n; ++r)
    rank_of[forest.order[r]] = std::uint32_t(r);
  for(std::size_t k = 0; k < triples.size(); ++k)
    g[k] = rank_of[triples[k]];
  // Faces given clockwise are the same faces (the import turns them too).
  auto orientation = gt.orientation_2_object();
  for(std::size_t k = 0; k < g.size(); k += 3)
    if(orientation(sample.point(g[k]), sample.point(g[k + 1]), sample.point(g[k + 2])) == RIGHT_TURN)
      std::swap(g[k + 1], g[k + 2]);
  cells.test_and_compute(
      g, hull,
      [&](std::uint32_t f) {
        result.insert(result.end(), {triples[3 * f], triples[3 * f + 1], triples[3 * f + 2]});
        ++kept;
      },
      emit);
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_SUPERCELLS_H
