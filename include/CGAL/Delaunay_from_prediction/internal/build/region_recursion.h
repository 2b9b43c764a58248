// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Theorem 5.4 of the paper (Strategy::theorem_5_4): DT(P) from a predicted triangulation G in
// O(n log* n + n log d_cross) time, d_cross the largest number of edges of DT(P) an edge of G
// crosses, by a recursion over G's regions. For a region gamma_0 of mu faces and vertices V:
//   1. a t-division of gamma_0's faces (their dual graph) into regions gamma of at most about
//      t faces, t = max(ceil(log2 mu)^2, b^2);
//   2. DT(V_gamma) of each region recursively (from scratch when mu <= b^2: the base case);
//   3. X_gamma, the edges of DT(V_gamma) that cross the boundary of gamma, by walking along
//      each boundary segment through DT(V_gamma); Y_gamma, the edges inside gamma, by a
//      traversal of DT(V_gamma)'s triangles that stops at X_gamma and at the boundary;
//   4. G'_gamma: the triangles of DT(V_gamma) that lie inside gamma, uncut by its boundary;
//   5. G', the union of the G'_gamma;
//   6. the D-sensitive repair of G' into DT(V) (the caller's `Repair`: the package's pipeline,
//      import with its certificate, local repair of the seams, Lawson's flips).
// At the top level step 6 is the caller's pipeline itself: the driver returns G'.
//
// The guess of d_cross (the proof's last paragraph): b = 2^(2^j) for j = ceil(log2 log* mu),
// j + 1, ..., each run capped at mu 2^j units of the work that grows with d_cross: the edges
// the boundary walks cross, the repairs' flips, m log2 m for a region of m points the repair
// rebuilt. (The rest, O(mu) a level for O(log* mu) levels and O(mu log b) for the base cases,
// is what the first j = ceil(log2 log* mu) pays for: it is not counted.) A run past its cap is
// abandoned for the next j. The run with b^2 >= mu is the base case, from scratch, and always
// ends.
//
// Substitutions, named in the manual:
// - the t-division is the package's breadth-first region growing (region_growing.h), not
//   Frederickson's: regions of at most t faces (fragments joined to a neighbour may pass t)
//   but no O(sqrt t) bound on their boundaries;
// - X_gamma by walks along the boundary segments through DT(V_gamma), O(1) per crossing plus
//   the star of the segment's first vertex, instead of Lemma 5.2's ray shooting (the same
//   set of edges);
// - step 4 keeps the triangles of DT(V_gamma) inside gamma that no boundary segment enters;
//   the non-triangular faces of Y_gamma and the boundary (the triangles the boundary cuts)
//   are left open, and step 6's import fills them with the package's hole tracer (an edge of
//   Y_gamma between two cut triangles is not kept: at most 2 |X_gamma| of them).
// - a region whose DT(V_gamma) cannot be walked (its points collinear, a boundary vertex a
//   duplicate point) keeps G's own faces as G'_gamma.
//
// Why it is robust: every decision on the geometry is an exact predicate of the traits
// (orientation, compare_xy) or is made by the base case's exact insertion and step 6's
// certificate; G' is only a prediction, which the caller's pipeline certifies and repairs.
// Whatever G is (crossing, inverted, overlapping faces), the recursion only produces index
// triples: its walks are capped by the number of triangles of the region.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REGION_RECURSION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REGION_RECURSION_H

#include <CGAL/Delaunay_from_prediction/internal/build/flat_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/hash_map.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/region_growing.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// log* x: how many times log2 must be applied to x to reach 1 or less.
inline std::size_t iterated_log2(double x)
{
  std::size_t k = 0;
  for(; x > 1; ++k)
    x = std::log2(x);
  return k;
}

// ceil(log2 x) for x >= 1.
inline std::size_t ceil_log2(std::size_t x)
{
  std::size_t k = 0;
  while(k < 63 && (std::size_t(1) << k) < x)
    ++k;
  return k;
}

// b^2 for the guess b = 2^(2^j), saturated.
inline std::size_t guess_squared(std::size_t j)
{
  return j + 1 >= 6 ? std::numeric_limits<std::size_t>::max() : std::size_t(1) << (std::size_t(1) << (j + 1));
}

// The first j of the guesses b = 2^(2^j): ceil(log2 log* mu), as in the proof.
inline std::size_t first_guess_level(std::size_t mu)
{
  return ceil_log2((std::max)(std::size_t(1), iterated_log2(double(mu))));
}

// What one run of the recursion counted.
struct Region_recursion_counts
{
  std::vector<std::size_t> regions_per_level; // the regions of each level's t-divisions
  std::size_t crossings = 0;                  // |X_gamma| over all regions and levels
  std::size_t regions_keeping_prediction = 0; // regions whose G'_gamma is G's faces
  std::size_t top_boundary_edges = 0;         // the boundary edges of level 0's regions, summed
  std::size_t predicted_faces_kept = 0;       // faces of G' at level 0 that are faces of G
  std::size_t work = 0;                       // the units the cap counts
};

// The triangles of a triangulation given as counterclockwise index triples, with the
// triangles around each vertex (a CSR array) and the triangle of each directed edge. An edge
// a -> b is found by a scan of a's triangles; only the edges of the few vertices of high degree
// (fans in bad predictions) go to a hash map, so a lookup is O(1) and the memory 4 words a
// triangle, not a hash slot per directed edge.
class Indexed_triangles
{
  static constexpr std::uint32_t max_scanned_degree = 32;

public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  Indexed_triangles(const std::vector<std::uint32_t>& triples, std::size_t vertices)
      : triples_(triples), first_(vertices + 1, 0)
  {
    for(std::size_t k = 0; k < triples.size(); ++k)
      ++first_[triples[k] + 1];
    for(std::size_t v = 0; v < vertices; ++v)
      first_[v + 1] += first_[v];
    around_.resize(triples.size());
    std::vector<std::uint32_t> at(first_.begin(), first_.end() - 1);
    for(std::size_t k = 0; k < triples.size(); ++k)
      around_[at[triples[k]]++] = std::uint32_t(k);
    // Edges out of high-degree vertices, in increasing k as the scan meets them: the first
    // triangle of a repeated directed edge wins either way.
    for(std::size_t v = 0; v < vertices; ++v)
      if(first_[v + 1] - first_[v] > max_scanned_degree)
        for(std::uint32_t j = first_[v]; j < first_[v + 1]; ++j)
          of_edge_.insert(directed_edge_key(std::uint32_t(v), next_vertex(around_[j])),
                          around_[j] / 3);
  }

  std::size_t size() const { return triples_.size() / 3; }
  std::uint32_t vertex(std::size_t t, std::size_t i) const { return triples_[3 * t + i % 3]; }
  // The triangle with the directed edge a -> b, or `none`.
  std::uint32_t with_edge(std::uint32_t a, std::uint32_t b) const
  {
    if(first_[a + 1] - first_[a] > max_scanned_degree) {
      const std::uint32_t* t = of_edge_.find(directed_edge_key(a, b));
      return t ? *t : none;
    }
    for(std::uint32_t j = first_[a]; j < first_[a + 1]; ++j)
      if(next_vertex(around_[j]) == b)
        return around_[j] / 3;
    return none;
  }
  // Calls f(t, i) for each triangle t with vertex(t, i) == v.
  template <class F>
  void for_each_around(std::uint32_t v, F f) const
  {
    for(std::uint32_t k = first_[v]; k < first_[v + 1]; ++k)
      f(std::size_t(around_[k] / 3), std::size_t(around_[k] % 3));
  }

private:
  // The vertex after the corner k (an index into triples_) in its triangle.
  std::uint32_t next_vertex(std::uint32_t k) const { return triples_[k % 3 == 2 ? k - 2 : k + 1]; }

  const std::vector<std::uint32_t>& triples_;
  std::vector<std::uint32_t> first_, around_;
  Hash_map<std::uint64_t, std::uint32_t> of_edge_;
};

// The recursion. `point_at(g)` is the point of index g; a level's points are given by their
// indices `global` (level index k is point global[k]). `repair(global, triples, budget, out,
// work)` is step 6: DT of the level's points from the faces `triples` (level indices) into
// `out`, adding its work to `work`; false when it would pass `budget`.
template <class Gt, class PointAt, class Repair>
class Region_recursion
{
public:
  Region_recursion(const Gt& gt, PointAt point_at, Repair& repair, std::size_t b_squared, std::size_t budget)
      : gt_(gt), point_at_(point_at), repair_(repair), b_squared_(b_squared), budget_(budget)
  {}

  const Region_recursion_counts& counts() const { return counts_; }

  // DT(V) into `out` (level indices) for the level's points `global` and its faces `triples`
  // (level indices, counterclockwise); at level 0, G' instead (step 6 is the caller's).
  // False when the work passed the budget.
  bool run(const std::vector<std::uint32_t>& global, const std::vector<std::uint32_t>& triples,
           std::vector<std::uint32_t>& out, std::size_t level)
  {
    out.clear();
    const std::size_t mu = triples.size() / 3;
    const std::size_t t = (std::max)(ceil_log2(mu) * ceil_log2(mu), b_squared_);
    if(mu <= b_squared_ || t >= mu) {
      base_case(global, out);
      return true;
    }
    // 1. The t-division of the faces' dual graph.
    const Indexed_triangles faces(triples, global.size());
    std::vector<std::uint32_t> region(mu, no_region);
    const std::uint32_t regions = grow_regions(region, t, [&](std::uint32_t f, auto&& visit) {
      for(std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t g = faces.with_edge(faces.vertex(f, i + 1), faces.vertex(f, i));
        if(g != Indexed_triangles::none)
          visit(g);
      }
    });
    if(regions < 2) {
      base_case(global, out);
      return true;
    }
    if(counts_.regions_per_level.size() <= level)
      counts_.regions_per_level.resize(level + 1, 0);
    counts_.regions_per_level[level] += regions;

    // The faces of each region, in compressed rows.
    std::vector<std::uint32_t> first(std::size_t(regions) + 1, 0), members(mu);
    for(const std::uint32_t r : region)
      ++first[r + 1];
    for(std::size_t r = 0; r < regions; ++r)
      first[r + 1] += first[r];
    {
      std::vector<std::uint32_t> at(first.begin(), first.end() - 1);
      for(std::uint32_t f = 0; f < mu; ++f)
        members[at[region[f]]++] = f;
    }

    // 2. to 5., region by region: G' in `completion` (level indices).
    std::vector<std::uint32_t> completion, sub_global, sub_triples, sub_dt, kept;
    completion.reserve(triples.size());
    std::vector<std::uint32_t> sub_of(global.size(), no_region);
    for(std::uint32_t r = 0; r < regions; ++r) {
      sub_global.clear();
      sub_triples.clear();
      for(std::uint32_t k = first[r]; k < first[r + 1]; ++k)
        for(std::size_t i = 0; i < 3; ++i) {
          const std::uint32_t v = faces.vertex(members[k], i);
          if(sub_of[v] == no_region) {
            sub_of[v] = std::uint32_t(sub_global.size());
            sub_global.push_back(v);
          }
          sub_triples.push_back(sub_of[v]);
        }
      // Region vertices as the caller's indices for the recursion, then back.
      std::vector<std::uint32_t> points_of(sub_global.size());
      for(std::size_t k = 0; k < sub_global.size(); ++k)
        points_of[k] = global[sub_global[k]];
      if(!run(points_of, sub_triples, sub_dt, level + 1))
        return false;
      // Boundary half-edges: those whose twin is in another region or in no face.
      std::vector<std::uint32_t> boundary;
      for(std::uint32_t k = first[r]; k < first[r + 1]; ++k)
        for(std::size_t i = 0; i < 3; ++i) {
          const std::uint32_t f = members[k], a = faces.vertex(f, i), b = faces.vertex(f, i + 1);
          const std::uint32_t g = faces.with_edge(b, a);
          if(g == Indexed_triangles::none || region[g] != r)
            boundary.insert(boundary.end(), {sub_of[a], sub_of[b]});
        }
      if(level == 0)
        counts_.top_boundary_edges += boundary.size() / 2;
      std::size_t predicted = 0;
      if(conform_to_region(points_of, sub_triples, boundary, sub_dt, kept, predicted))
        for(const std::uint32_t v : kept)
          completion.push_back(sub_global[v]);
      else {
        ++counts_.regions_keeping_prediction;
        predicted = sub_triples.size() / 3;
        for(const std::uint32_t v : sub_triples)
          completion.push_back(sub_global[v]);
      }
      if(level == 0)
        counts_.predicted_faces_kept += predicted;
      for(const std::uint32_t v : sub_global)
        sub_of[v] = no_region;
      if(counts_.work > budget_)
        return false;
    }
    // 6. The D-sensitive repair of G' (the caller's at level 0).
    if(level == 0) {
      out.swap(completion);
      return true;
    }
    const std::size_t left = budget_ > counts_.work ? budget_ - counts_.work : 0;
    return repair_(global, completion, left, out, counts_.work) && counts_.work <= budget_;
  }

private:

  decltype(auto) point(const std::vector<std::uint32_t>& global, std::uint32_t k) const
  {
    return point_at_(global[k]);
  }

  // DT of the level's points from scratch, in the package's biased randomized grid order:
  // O(m log m) expected, with m <= b^2 in the recursion.
  void base_case(const std::vector<std::uint32_t>& global, std::vector<std::uint32_t>& out)
  {
    std::vector<std::uint32_t> order(global.size());
    for(std::uint32_t k = 0; k < order.size(); ++k)
      order[k] = k;
    sort_along_grid(order, [&](std::uint32_t k) -> decltype(auto) { return point(global, k); }, true);
    Flat_delaunay<Gt> flat(gt_);
    out.clear();
    if(!flat.build(order.size(), [&](std::size_t k) -> decltype(auto) { return point(global, order[k]); }))
      return;
    for(std::size_t t = 0; t < flat.number_of_faces(); ++t)
      if(!flat.is_infinite(t))
        for(int i = 0; i < 3; ++i)
          out.push_back(order[flat.vertex(t, i)]);
  }

  // Steps 3 and 4 for one region: `dt` is DT(V_gamma) (region indices, counterclockwise),
  // `faces` the region's faces in G, `boundary` its boundary half-edges (pairs a, b with the
  // region on the left of a -> b). Puts into `kept` the triangles of `dt` inside the region
  // that no boundary segment enters, and counts X_gamma; `predicted`: how many of them are
  // faces of G. False when `dt` cannot be walked.
  bool conform_to_region(const std::vector<std::uint32_t>& global, const std::vector<std::uint32_t>& faces,
                         const std::vector<std::uint32_t>& boundary, const std::vector<std::uint32_t>& dt,
                         std::vector<std::uint32_t>& kept, std::size_t& predicted)
  {
    kept.clear();
    if(dt.empty())
      return false;
    const Indexed_triangles tri(dt, global.size());
    std::vector<char> cut(tri.size(), 0);
    // Edges of dt the flood must not cross: crossed by the boundary (X_gamma, value 1) or
    // along it (value 0).
    Hash_map<std::uint64_t, char> blocked(2 * boundary.size() + 16);
    auto orientation = gt_.orientation_2_object();
    auto compare_xy = gt_.compare_xy_2_object();
    auto p = [&](std::uint32_t k) -> decltype(auto) { return point(global, k); };
    // p(v) strictly between p(a) and p(b), given that the three are collinear.
    auto between = [&](std::uint32_t a, std::uint32_t v, std::uint32_t b) {
      const Comparison_result c = compare_xy(p(a), p(v));
      return c != EQUAL && c == compare_xy(p(v), p(b));
    };
    auto cross = [&](std::uint32_t u, std::uint32_t v) {
      if(blocked.insert(undirected_edge_key(u, v), 1).second)
        ++counts_.crossings;
    };
    const std::size_t cap = 4 * tri.size() + 16; // steps of one walk, past which dt is not a triangulation
    const std::size_t crossings_before = counts_.crossings;
    for(std::size_t s = 0; s < boundary.size(); s += 2) {
      std::uint32_t a = boundary[s];
      const std::uint32_t b = boundary[s + 1];
      if(p(a) == p(b))
        return false;
      std::size_t steps = 0;
      // The walk from a to b: from a vertex on the segment, the triangle around it that the
      // segment enters, then across the edges it crosses to the next vertex on it.
      while(a != b) {
        if(++steps > cap)
          return false;
        std::uint32_t next = a, left = Indexed_triangles::none, right = Indexed_triangles::none;
        bool found = false;
        tri.for_each_around(a, [&](std::size_t t, std::size_t i) {
          if(found)
            return;
          const std::uint32_t u = tri.vertex(t, i + 1), w = tri.vertex(t, i + 2);
          if(u == b || w == b) {
            blocked.insert(undirected_edge_key(a, b), 0);
            next = b;
            found = true;
            return;
          }
          const Orientation ou = orientation(p(a), p(b), p(u)), ow = orientation(p(a), p(b), p(w));
          if(ou == COLLINEAR && between(a, u, b)) {
            blocked.insert(undirected_edge_key(a, u), 0);
            next = u;
            found = true;
          } else if(ow == COLLINEAR && between(a, w, b)) {
            blocked.insert(undirected_edge_key(a, w), 0);
            next = w;
            found = true;
          } else if(ou == RIGHT_TURN && ow == LEFT_TURN) { // the segment enters t
            cut[t] = 1;
            cross(u, w);
            left = w;
            right = u;
            found = true;
          }
        });
        if(!found)
          return false;
        // Across the crossed edges: each next triangle has the directed edge left -> right.
        while(left != Indexed_triangles::none) {
          if(++steps > cap)
            return false;
          const std::uint32_t t = tri.with_edge(left, right);
          if(t == Indexed_triangles::none)
            return false;
          cut[t] = 1;
          std::uint32_t third = tri.vertex(t, 0);
          for(std::size_t i = 0; i < 3; ++i)
            if(tri.vertex(t, i) == left)
              third = tri.vertex(t, i + 2);
          if(third == b) {
            next = b;
            break;
          }
          const Orientation o = orientation(p(a), p(b), p(third));
          if(o == COLLINEAR) { // the segment passes through a vertex
            next = third;
            break;
          }
          if(o == LEFT_TURN) {
            cross(third, right);
            left = third;
          } else {
            cross(left, third);
            right = third;
          }
        }
        a = next;
      }
    }
    counts_.work += counts_.crossings - crossings_before;

    // Y_gamma by traversal: from the triangles known to be inside (left of a boundary edge of
    // dt, or a face of G), across edges neither crossed nor on the boundary, into uncut ones.
    std::vector<char> inside(tri.size(), 0);
    std::vector<std::uint32_t> queue;
    auto seed = [&](std::uint32_t t) {
      if(t != Indexed_triangles::none && !cut[t] && !inside[t]) {
        inside[t] = 1;
        queue.push_back(t);
      }
    };
    for(std::size_t s = 0; s < boundary.size(); s += 2)
      seed(tri.with_edge(boundary[s], boundary[s + 1]));
    std::vector<char> is_face_of_g(tri.size(), 0);
    for(std::size_t k = 0; k < faces.size(); k += 3) {
      const std::uint32_t t = tri.with_edge(faces[k], faces[k + 1]);
      if(t != Indexed_triangles::none &&
         (tri.vertex(t, 0) == faces[k + 2] || tri.vertex(t, 1) == faces[k + 2] || tri.vertex(t, 2) == faces[k + 2])) {
        is_face_of_g[t] = 1;
        seed(t);
      }
    }
    for(std::size_t head = 0; head < queue.size(); ++head) {
      const std::uint32_t t = queue[head];
      for(std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t u = tri.vertex(t, i), w = tri.vertex(t, i + 1);
        if(blocked.contains(undirected_edge_key(u, w)))
          continue;
        const std::uint32_t g = tri.with_edge(w, u);
        if(g != Indexed_triangles::none && !cut[g] && !inside[g]) {
          inside[g] = 1;
          queue.push_back(g);
        }
      }
    }
    predicted = 0;
    for(const std::uint32_t t : queue) {
      predicted += std::size_t(is_face_of_g[t]);
      for(std::size_t i = 0; i < 3; ++i)
        kept.push_back(tri.vertex(t, i));
    }
    return true;
  }

  const Gt& gt_;
  PointAt point_at_;
  Repair& repair_;
  std::size_t b_squared_, budget_;
  Region_recursion_counts counts_;
};

// What the driver did, for Statistics.
struct Region_recursion_report
{
  Region_recursion_counts counts;
  std::size_t guesses = 0;      // the values of j tried
  std::size_t last_guess_b = 0; // b of the run that ended (saturated)
};

// Theorem 5.4's driver: G' for the faces `triples` (three indices a face, each below n) of the
// points point_at(0..n), into `completion`, with the guesses of d_cross. `first_guess`: the
// first j, or -1 for the proof's. Faces that are flat are left out; the others are taken
// counterclockwise. False, with nothing computed, when no face is left.
template <class Gt, class PointAt, class Repair>
bool completion_by_region_recursion(const Gt& gt, PointAt point_at, std::size_t n,
                                    const std::vector<std::uint32_t>& triples, Repair& repair, int first_guess,
                                    std::vector<std::uint32_t>& completion, Region_recursion_report& report)
{
  auto orientation = gt.orientation_2_object();
  std::vector<std::uint32_t> faces;
  faces.reserve(triples.size());
  for(std::size_t k = 0; k + 2 < triples.size(); k += 3) {
    const std::uint32_t a = triples[k], b = triples[k + 1], c = triples[k + 2];
    const Orientation o = orientation(point_at(a), point_at(b), point_at(c));
    if(o == LEFT_TURN)
      faces.insert(faces.end(), {a, b, c});
    else if(o == RIGHT_TURN)
      faces.insert(faces.end(), {a, c, b});
  }
  if(faces.empty())
    return false;
  const std::size_t mu = faces.size() / 3;
  std::vector<std::uint32_t> global(n);
  for(std::uint32_t k = 0; k < n; ++k)
    global[k] = k;
  for(std::size_t j = first_guess >= 0 ? std::size_t(first_guess) : first_guess_level(mu);; ++j) {
    ++report.guesses;
    const std::size_t b_squared = guess_squared(j);
    report.last_guess_b = j >= 6 ? std::numeric_limits<std::size_t>::max() : std::size_t(1) << (std::size_t(1) << j);
    const std::size_t budget = j >= 40 ? std::numeric_limits<std::size_t>::max() : mu << j;
    Region_recursion<Gt, PointAt, Repair> recursion(gt, point_at, repair, b_squared, budget);
    const bool done = recursion.run(global, faces, completion, 0);
    report.counts = recursion.counts();
    if(done)
      return true;
  }
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_REGION_RECURSION_H
