// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Section 3 of the paper as written (Lemma 3.2 and the rounds of Theorem 3.3;
// Strategy::section_3): DT(P) from a spanning tree T of P through nested random samples
// R_1 ⊂ R_2 ⊂ ... ⊂ R_l = P of the multiset where each point appears deg_T(p) times, of sizes
// |P^|/s_i with s_1 = n, s_{i+1} = floor(log2 s_i), ..., s_l = 1. Each round, given DT(R_i):
//  1. Lemma 3.2: every point of P is located in DT(R_i) by walking along the tree edges from
//     its parent's face, a walk capped at log2 n faces, then a point location;
//  2. from its face, the graph search of Lemma 3.2 lists the faces of DT(R_i) in conflict with
//     each point (its circumcircle holds the point: the conflict list of the face's Voronoi
//     vertex), and the lists are inverted per face;
//  3. DT(R_{i+1}) is computed from the conflict information.
// The paper's 3D words map to the plane as follows: a vertex of LE(R*) is a face of DT(R), its
// conflict list the points inside that face's circumcircle; a cell of Decomp(R*) is a third of
// a Voronoi cell, and its conflict list the union of those of its three Voronoi vertices.
//
// What differs from the paper, and why (the substitutions are named in the manual too):
// - Step 3 computes the lower envelope of each cell's new planes with the standard randomized
//   incremental algorithm with conflict lists (Clarkson and Shor), all cells in one
//   triangulation, so that gluing them is nothing: the new points, in the random order of
//   the sample, are inserted by Lawson's insertion (flat_insertion.h) into the face their
//   bucket names; the points in the buckets of the faces an insertion changes are moved to
//   the new faces by a walk from the new vertex. Clarkson and Shor bound its expected work
//   by the cost the proof charges for the cells, O((n / s_{i+1}) log(s_i / s_{i+1})).
// - The point location of Lemma 3.2 (Kirkpatrick's, O(log r)) is a jump to a face of a
//   vertex of R_i recorded in a uniform grid (two resolutions), then an uncapped walk: short
//   on well-spread points, not bounded by a proof.
// - The paper adds a bounding triangle so that DT(R_1) has faces; here R_1 grows along the
//   random order of the sample until its points span a triangle (CGAL's infinite vertex plays
//   the bounding triangle's part). Points on one line have no rounds: they are inserted as a
//   build from scratch inserts them.
// - The tree is the breadth-first spanning forest of the given graph (preorder_spanning_forest()
//   of spanning_tree_insertion.h); a walk from a vertex of R_i to its child starts from any face
//   of that vertex instead of the face the ray crosses (at most the vertex's degree more).
//   Each further component's root is located like a walk that passed its cap.
// Every decision is an exact predicate of the traits (orientation, CGAL's perturbed in-circle
// test), on a Delaunay triangulation where the visibility walks cannot cycle: the result is
// the unique perturbed Delaunay triangulation, CGAL's.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_CONFLICT_LIST_ROUNDS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_CONFLICT_LIST_ROUNDS_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/build/flat_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/build/spanning_tree_insertion.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/grid.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Theorem 3.3's divisors: s_1 = n, s_{i+1} = floor(log2 s_i), down to s_l = 1.
inline std::vector<std::size_t> theorem_3_3_divisors(std::size_t n)
{
  std::vector<std::size_t> s{(std::max)(n, std::size_t(1))};
  while(s.back() > 1) {
    std::size_t log2 = 0;
    for(std::size_t m = s.back(); m > 1; m >>= 1)
      ++log2;
    s.push_back((std::max)(std::size_t(1), (std::min)(log2, s.back() - 1)));
  }
  return s;
}

// Nested random samples of the multiset P^ where the point of rank r appears max(1,
// deg_T(r)) times: a uniformly random permutation of the copies, sample i its first
// |P^| / s_i copies. `order` lists the ranks by the position of their first copy (so every
// sample is a prefix of it, in random order), `end[i]` is the number of distinct points in
// sample i (the last sample, s = 1, holds every point).
struct Nested_samples
{
  std::vector<std::uint32_t> order;
  std::vector<std::size_t> end;
};

inline Nested_samples sample_multiset(const Preorder_forest& forest, const std::vector<std::size_t>& divisors,
                                      std::uint64_t seed)
{
  const std::size_t n = forest.order.size();
  std::vector<std::uint32_t> copy_owner;
  for(std::size_t r = 0; r < n; ++r)
    copy_owner.insert(copy_owner.end(), (std::max)(std::uint32_t(1), forest.degree[r]), std::uint32_t(r));
  const std::size_t m = copy_owner.size();
  Splitmix64 random{seed};
  for(std::size_t k = m; k > 1; --k) // Fisher and Yates
    std::swap(copy_owner[k - 1], copy_owner[random.below(k)]);
  Nested_samples samples;
  samples.order.reserve(n);
  std::vector<unsigned char> seen(n, 0);
  std::size_t i = 0;
  for(std::size_t position = 0; position < m; ++position) {
    while(i < divisors.size() && position >= m / divisors[i]) // sample i is complete
      samples.end.push_back(samples.order.size()), ++i;
    const std::uint32_t r = copy_owner[position];
    if(!seen[r]) {
      seen[r] = 1;
      samples.order.push_back(r);
    }
  }
  while(i < divisors.size())
    samples.end.push_back(samples.order.size()), ++i;
  return samples;
}

// The faces of DT(R_i) in conflict with the points of P outside R_i (Lemma 3.2's output),
// per face: the ranks in conflict with face t are ranks[offsets[t]] .. ranks[offsets[t + 1] - 1].
struct Conflict_lists
{
  std::vector<std::uint32_t> offsets, ranks;
  std::size_t size_of(std::size_t t) const { return offsets[t + 1] - offsets[t]; }
};

// The rounds of Theorem 3.3 on the flat triangulation of the points in tree preorder.
template <class Gt>
class Conflict_list_rounds
{
public:
  using Flat = Flat_delaunay<Gt>;
  using Point = typename Flat::Point;
  static constexpr std::uint32_t none = Flat::infinite;

  // point_at(r): the point of preorder rank r.
  template <class PointAt>
  Conflict_list_rounds(const Gt& gt, const Preorder_forest& forest, PointAt point_at, Statistics& stats)
      : flat_(gt), forest_(forest), stats_(stats), n_(forest.order.size()),
        grid_(n_, [&](std::size_t r) -> decltype(point_at(0)) { return point_at(r); }), cap_(0)
  {
    flat_.store(n_, point_at);
    for(std::size_t m = n_; m > 1; m >>= 1)
      ++cap_; // Lemma 3.2's cap: log2 n faces
    in_sample_.assign(n_, 0);
    location_.assign(n_, 0);
    at_vertex_.assign(n_, 0);
  }

  const Flat& flat() const { return flat_; }
  const std::vector<std::uint32_t>& location() const { return location_; }
  bool in_sample(std::size_t r) const { return in_sample_[r] != 0; }
  bool located_at_vertex(std::size_t r) const { return at_vertex_[r] != 0; }

  // DT(R_1): the ranks order[0, count), in that order. False when they span no triangle.
  bool start(const std::vector<std::uint32_t>& order, std::size_t count)
  {
    if(!flat_.start_with(count, [&](std::size_t k) { return order[k]; }))
      return false;
    for(std::size_t k = 0; k < count; ++k)
      in_sample_[order[k]] = 1;
    return true;
  }

  // Lemma 3.2, first part: the face of DT(R_i) holding each point outside R_i (location()),
  // found by walking from its parent's face along the tree, in preorder (parents first); a
  // walk past log2 n faces, and a root, start again from the grid's face near the point. A
  // point of R_i is located at a face of its vertex.
  void locate_along_tree()
  {
    const std::size_t faces = flat_.number_of_faces();
    for(std::size_t t = 0; t < faces; ++t)
      for(int i = 0; i < 3; ++i)
        if(flat_.vertex(t, i) != none)
          location_[flat_.vertex(t, i)] = std::uint32_t(t);
    for(std::size_t r = 0; r < n_; ++r)
      if(in_sample_[r] && flat_.representative(r) == r)
        grid_.record(flat_.point(std::uint32_t(r)), location_[r]);
    const std::size_t longest = 2 * faces + 16;
    for(std::size_t r = 0; r < n_; ++r) {
      if(in_sample_[r]) {
        location_[r] = location_[flat_.representative(r)];
        continue;
      }
      const Point& p = flat_.point(std::uint32_t(r));
      const std::uint32_t parent = forest_.parent[r];
      std::size_t steps = 0;
      typename Flat::Location at;
      if(parent != no_rank)
        at = flat_.walk(p, location_[parent], cap_, steps);
      if(!at.found) {
        ++stats_.walk_fallbacks;
        at = flat_.walk(p, grid_.near(p), longest, steps);
      }
      ++stats_.points_located;
      stats_.faces_visited += steps;
      location_[r] = at.face;
      at_vertex_[r] = !flat_.is_infinite(at.face) && at.collinear == 2;
    }
  }

  // Lemma 3.2, second part: the faces in conflict with each point outside R_i, by a graph
  // search from its face over the faces in conflict (they are connected: the faces its
  // insertion would destroy), inverted into lists per face. A point at a vertex (a duplicate)
  // conflicts with no face.
  Conflict_lists conflict_lists()
  {
    const std::size_t faces = flat_.number_of_faces();
    std::vector<std::uint32_t> count(faces + 1, 0), face_of, rank_of, stack;
    stamp_.assign(faces, none);
    for(std::size_t r = 0; r < n_; ++r) {
      if(in_sample_[r] || at_vertex_[r])
        continue;
      const Point& p = flat_.point(std::uint32_t(r));
      const std::uint32_t start = location_[r];
      CGAL_assertion(flat_.in_conflict(start, p));
      stamp_[start] = std::uint32_t(r);
      stack.push_back(start);
      while(!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        face_of.push_back(t);
        rank_of.push_back(std::uint32_t(r));
        ++count[t + 1];
        for(int i = 0; i < 3; ++i) {
          const std::uint32_t u = std::uint32_t(flat_.neighbor(t, i));
          if(stamp_[u] != r && flat_.in_conflict(u, p)) {
            stamp_[u] = std::uint32_t(r);
            stack.push_back(u);
          }
        }
      }
    }
    Conflict_lists lists;
    for(std::size_t t = 0; t < faces; ++t) {
      stats_.largest_conflict_list = (std::max)(stats_.largest_conflict_list, std::size_t(count[t + 1]));
      count[t + 1] += count[t];
    }
    lists.offsets = count;
    lists.ranks.resize(face_of.size());
    for(std::size_t k = 0; k < face_of.size(); ++k)
      lists.ranks[count[face_of[k]]++] = rank_of[k];
    stats_.conflict_list_entries += face_of.size();
    return lists;
  }

  // DT(R_{i+1}) from DT(R_i): the ranks order[from, to) (R_{i+1} minus R_i, in random order)
  // inserted by the randomized incremental construction with conflict lists: each point
  // waits in the bucket of the face that holds it (from locate_along_tree()), is inserted
  // from there, and the points in the buckets of the faces its insertion changes are moved,
  // by a walk from its vertex, to the faces that now hold them.
  void insert(const std::vector<std::uint32_t>& order, std::size_t from, std::size_t to)
  {
    head_.assign(2 * n_ + 8, none); // at most 2n - 2 faces, the infinite ones included
    next_.resize(n_);
    face_of_.resize(n_);
    for(std::size_t k = from; k < to; ++k)
      put(order[k], location_[order[k]]);
    const std::size_t longest = 2 * (2 * n_ + 8);
    for(std::size_t k = from; k < to; ++k) {
      const std::uint32_t r = order[k];
      touched_.clear();
      flat_.insert_from(r, face_of_[r], &touched_);
      in_sample_[r] = 1;
      moved_.clear();
      for(const std::uint32_t t : touched_) {
        for(std::uint32_t x = head_[t]; x != none; x = next_[x])
          if(!in_sample_[x])
            moved_.push_back(x);
        head_[t] = none;
      }
      for(const std::uint32_t x : moved_) {
        std::size_t steps = 0;
        put(x, flat_.walk(flat_.point(x), flat_.last_face(), longest, steps).face);
      }
      stats_.points_relocated += moved_.size();
    }
  }

private:
  void put(std::uint32_t r, std::uint32_t t)
  {
    face_of_[r] = t;
    next_[r] = head_[t];
    head_[t] = r;
  }

  Flat flat_;
  const Preorder_forest& forest_;
  Statistics& stats_;
  std::size_t n_;
  Vertex_grid<std::uint32_t> grid_; // a face of a vertex of the sample near each cell
  std::size_t cap_;
  std::vector<unsigned char> in_sample_, at_vertex_;
  std::vector<std::uint32_t> location_, stamp_;
  std::vector<std::uint32_t> head_, next_, face_of_, touched_, moved_; // the buckets
};

// Theorem 3.3's rounds up to sample `last`: DT(R_1), grown along the sample's order until
// it spans a triangle (the bounding triangle's part), then DT(R_2), ..., DT(R_last), each
// from the previous one's conflict lists; `on_round(rounds, conflict_lists)` sees each
// round's lists before the next triangulation is built. Returns the number of points of
// samples.order inserted, 0 when they are all on one line (no round can start).
template <class Gt, class OnRound>
std::size_t run_conflict_list_rounds(Conflict_list_rounds<Gt>& rounds, const Nested_samples& samples, std::size_t last,
                                     OnRound on_round)
{
  const std::size_t n = samples.order.size();
  std::size_t inserted = (std::min)(n, (std::max)(samples.end[0], std::size_t(3)));
  while(!rounds.start(samples.order, inserted)) {
    if(inserted == n)
      return 0;
    inserted = (std::min)(n, 2 * inserted);
  }
  for(std::size_t i = 1; i <= last; ++i) {
    if(samples.end[i] <= inserted)
      continue;
    rounds.locate_along_tree();
    const Conflict_lists lists = rounds.conflict_lists();
    on_round(rounds, lists);
    rounds.insert(samples.order, inserted, samples.end[i]);
    inserted = samples.end[i];
  }
  return inserted;
}

// Builds DT(points) into the empty `dt` (exact predicates; fewer than no_rank points) from the
// graph whose edge ends are listed in pairs, by Theorem 3.3's rounds along its spanning
// forest. `on_round(rounds, conflict_lists)`, if given, sees each round's conflict lists
// before DT(R_{i+1}) is built (the tests check them).
template <class DT, class PointIterator, class OnRound = std::nullptr_t>
void build_by_conflict_list_rounds(DT& dt, PointIterator points, std::size_t n, const std::vector<std::uint32_t>& ends,
                                   Statistics& stats, OnRound on_round = nullptr,
                                   std::uint64_t seed = 0x5ec710e3ull)
{
  using Gt = typename DT::Geom_traits;
  if(n == 0)
    return;
  const Preorder_forest forest = preorder_spanning_forest(adjacency_of(ends, n));
  const Nested_samples samples = sample_multiset(forest, theorem_3_3_divisors(n), seed);
  stats.insertion_rounds = samples.end.size();
  std::size_t duplicates = 0;
  auto on_vertex = [&](std::size_t i, auto v, bool is_new) { record_index_info(v, i, is_new, duplicates); };
  Conflict_list_rounds<Gt> rounds(dt.geom_traits(), forest,
                                  [&](std::size_t r) -> decltype(points[0]) { return points[forest.order[r]]; },
                                  stats);
  const std::size_t inserted =
      run_conflict_list_rounds(rounds, samples, samples.end.size() - 1, [&](const auto& r, const Conflict_lists& lists) {
        if constexpr(!std::is_same<OnRound, std::nullptr_t>::value)
          on_round(r, lists);
      });
  if(inserted == 0) { // collinear points: no rounds
    std::vector<std::size_t> indices(n);
    for(std::size_t i = 0; i < n; ++i)
      indices[i] = i;
    insert_points(dt, points, indices, stats);
    return;
  }
  write_flat_triangulation(dt, rounds.flat(), n, [&](std::size_t r) { return std::size_t(forest.order[r]); },
                           on_vertex);
  stats.points_reinserted += n;
  stats.duplicate_points += duplicates;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_CONFLICT_LIST_ROUNDS_H
