// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The closeness measures of Table 1 of the paper between a prediction and DT(P)
// (prediction_measures()): keys and sorts of edges and faces by point index, the crossings of a
// straight walk along a wrong edge, the points inside a wrong face's circumcircle.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_MEASURES_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_MEASURES_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/check/input_check.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// DT(P) with each vertex's info the smallest index of its point.
template <class K>
using Indexed_delaunay_2 = CGAL::Delaunay_triangulation_2<
    K, CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>,
                                            CGAL::Triangulation_face_base_2<K>>>;

inline std::uint64_t edge_key(std::size_t a, std::size_t b)
{
  if(a > b)
    std::swap(a, b);
  return (std::uint64_t(a) << 32) | std::uint64_t(b);
}

// Sorts `items` with `less`, given that the high 32 bits of `key(item)` are a point index below
// `n` and that `less` orders by key first: a counting sort on the point index, then a sort of
// each bucket (a vertex's few edges or faces). At 1e6 points this is several times faster
// than sorting the whole array, which was a third of the cost of prediction_measures().
template <class T, class Key, class Less>
void sort_by_point_index(std::vector<T>& items, std::size_t n, Key key, Less less)
{
  std::vector<std::uint32_t> end(n + 1, 0);
  for(const T& t : items)
    ++end[std::size_t(key(t) >> 32) + 1];
  for(std::size_t i = 0; i < n; ++i)
    end[i + 1] += end[i];
  std::vector<T> sorted(items.size());
  for(const T& t : items)
    sorted[end[std::size_t(key(t) >> 32)]++] = t; // afterwards end[i] is the end of bucket i
  std::size_t begin = 0;
  for(std::size_t i = 0; i < n; ++i) {
    if(end[i] - begin > 1)
      std::sort(sorted.begin() + std::ptrdiff_t(begin), sorted.begin() + std::ptrdiff_t(end[i]), less);
    begin = end[i];
  }
  items.swap(sorted);
}

// A face as a key: its sorted indices (a, b, c) as (a, b) packed and c, and where it came from.
struct Face_key
{
  std::uint64_t low_pair;
  std::uint32_t high, face;
  bool operator<(const Face_key& other) const
  {
    return low_pair < other.low_pair || (low_pair == other.low_pair && high < other.high);
  }
  bool same_face(const Face_key& other) const { return low_pair == other.low_pair && high == other.high; }
};

inline Face_key face_key(std::size_t a, std::size_t b, std::size_t c, std::uint32_t face)
{
  if(a > b) std::swap(a, b);
  if(b > c) std::swap(b, c);
  if(a > b) std::swap(a, b);
  return {edge_key(a, b), std::uint32_t(c), face};
}

// Counts the edges of `dt` whose relative interior the segment from u to w crosses in a single
// point, u and w being vertices of `dt` that are not neighbours. The walk goes face by face
// along the segment; where the segment passes through a vertex it starts again from that
// vertex (edges at that vertex touch the segment, they do not cross it). With exact
// predicates the count is exact; with an inexact kernel a step limit keeps it finite.
template <class DT>
std::size_t count_crossings(const DT& dt, typename DT::Vertex_handle u, typename DT::Vertex_handle w)
{
  using Vertex_handle = typename DT::Vertex_handle;
  using Face_handle = typename DT::Face_handle;
  const auto& gt = dt.geom_traits();
  auto orientation = gt.orientation_2_object();
  auto strictly_between = gt.collinear_are_strictly_ordered_along_line_2_object();
  const auto& target = w->point();
  std::size_t crossings = 0;
  std::size_t steps_left = 2 * dt.number_of_faces() + dt.number_of_vertices() + 8;
  Vertex_handle s = u;
  while(steps_left-- > 0) {
    // The face at s that the segment enters, or the neighbour of s the segment runs through.
    Face_handle first;
    Vertex_handle through;
    auto fc = dt.incident_faces(s), done = fc;
    do {
      if(dt.is_infinite(fc))
        continue;
      const int i = fc->index(s);
      const Vertex_handle a = fc->vertex(ccw(i)), b = fc->vertex(cw(i));
      if(a == w || b == w)
        return crossings;
      const Orientation oa = orientation(s->point(), a->point(), target);
      if(oa == COLLINEAR && strictly_between(s->point(), a->point(), target)) {
        through = a;
        break;
      }
      const Orientation ob = orientation(s->point(), b->point(), target);
      if(ob == COLLINEAR && strictly_between(s->point(), b->point(), target)) {
        through = b; // seen here too when the face beyond (s, b) is infinite
        break;
      }
      if(oa == LEFT_TURN && ob == RIGHT_TURN) {
        first = fc;
        break;
      }
    } while(++fc != done);
    if(through != Vertex_handle()) {
      s = through;
      continue;
    }
    if(first == Face_handle())
      return crossings; // only with an inexact kernel
    // The segment crosses the edge (right, left) of `f` opposite to `behind`.
    Face_handle f = first;
    Vertex_handle behind = s;
    Vertex_handle right = f->vertex(ccw(f->index(s))), left = f->vertex(cw(f->index(s)));
    ++crossings;
    bool restarted = false;
    while(steps_left-- > 0) {
      const int k = f->index(behind);
      const Face_handle g = f->neighbor(k);
      if(dt.is_infinite(g))
        return crossings; // only with an inexact kernel
      const Vertex_handle c = g->vertex(dt.tds().mirror_index(f, k));
      if(c == w)
        return crossings;
      const Orientation oc = orientation(s->point(), target, c->point());
      if(oc == COLLINEAR) {
        s = c;
        restarted = true;
        break;
      }
      if(oc == LEFT_TURN) {
        behind = left;
        left = c;
      } else {
        behind = right;
        right = c;
      }
      f = g;
      ++crossings;
    }
    if(!restarted)
      break;
  }
  return crossings;
}

// Number of vertices of `dt` strictly inside the perturbed circumcircle of the ccw triangle
// (a, b, c) of vertices of `dt`. Why a search from a, b, c that never leaves the circle finds
// them all: lift the (perturbed) points to the paraboloid; the points inside the circle are
// the lifted points below the plane h through the lifts of a, b, c, and DT's edges are the
// edges of the lower hull. A linear function on a polyhedron has a strictly decreasing edge
// at every vertex that is not a minimizer, so every vertex below h has a descending path to
// the lowest vertex that stays below h, and a (on h, not lowest when some point is below h)
// has a neighbour below h. So the vertices below h and a form one connected subgraph of DT.
// `mark` has one entry per vertex info; `stamp` is new for each call. The search stops once
// more than `limit` points are found (it then returns limit + 1).
template <class DT>
std::size_t count_points_in_circle(const DT& dt, typename DT::Vertex_handle a,
                                   typename DT::Vertex_handle b, typename DT::Vertex_handle c,
                                   std::vector<std::uint32_t>& mark, std::uint32_t stamp,
                                   std::vector<typename DT::Vertex_handle>& queue,
                                   std::size_t limit = (std::numeric_limits<std::size_t>::max)())
{
  const auto& gt = dt.geom_traits();
  std::size_t inside = 0;
  queue.clear();
  for(const auto& v : {a, b, c}) {
    mark[v->info()] = stamp;
    queue.push_back(v);
  }
  for(std::size_t head = 0; head < queue.size(); ++head) {
    auto vc = dt.incident_vertices(queue[head]), done = vc;
    do {
      if(dt.is_infinite(vc) || mark[vc->info()] == stamp)
        continue;
      mark[vc->info()] = stamp;
      if(side_of_oriented_circle_perturbed(gt, a->point(), b->point(), c->point(), vc->point()) ==
         ON_POSITIVE_SIDE) {
        if(++inside > limit)
          return inside;
        queue.push_back(vc);
      }
    } while(++vc != done);
  }
  return inside;
}

// What the stages of measure_prediction() share: DT(P) by point index, and G in the canonical
// indices of DT(P)'s vertices (each vertex's info).
template <class DT>
struct Measured_prediction
{
  using Triple = std::array<std::size_t, 3>;
  struct Half_edge { std::uint64_t key; std::uint32_t face; std::uint8_t slot; };
  std::vector<typename DT::Vertex_handle> vertex_of; // each index's vertex
  std::vector<std::uint64_t> dt_edges;               // DT's edges, sorted keys
  std::vector<std::size_t> degree;                   // in DT, by canonical index
  std::vector<Triple> g_faces;                       // G's faces, ccw
  std::vector<char> degenerate;                      // per face of G: flat or repeated index
  std::vector<Half_edge> half_edges;                 // G's, each carrying its face and slot
  std::vector<char> used;                            // per index: whether a face of G has it
};

// Each index's vertex into `vertex_of`; equal points share the vertex of the smallest index.
// Returns how many indices are such copies.
template <class PointIterator, class DT>
std::size_t vertices_by_point_index(const DT& dt, PointIterator point_at, std::size_t n,
                                    std::vector<typename DT::Vertex_handle>& vertex_of)
{
  using Vertex_handle = typename DT::Vertex_handle;
  vertex_of.assign(n, Vertex_handle());
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    vertex_of[v->info()] = v;
  std::size_t duplicates = 0;
  for(std::size_t i = 0; i < n; ++i) {
    if(vertex_of[i] != Vertex_handle())
      continue;
    if(dt.dimension() == 0) { // one vertex: locate() has no face to return
      vertex_of[i] = dt.finite_vertices_begin();
    } else {
      typename DT::Locate_type lt;
      int li;
      const auto f = dt.locate(point_at[i], lt, li);
      CGAL_assertion(lt == DT::VERTEX);
      vertex_of[i] = f->vertex(li);
    }
    ++duplicates;
  }
  return duplicates;
}

// DT's edges as sorted keys of canonical indices, and the degrees.
template <class DT>
void delaunay_edge_keys(const DT& dt, std::size_t n, Measured_prediction<DT>& g)
{
  g.degree.assign(n, 0);
  g.dt_edges.reserve(3 * n);
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const std::size_t a = e->first->vertex(internal::ccw(e->second))->info();
    const std::size_t b = e->first->vertex(internal::cw(e->second))->info();
    g.dt_edges.push_back(internal::edge_key(a, b));
    ++g.degree[a];
    ++g.degree[b];
  }
  internal::sort_by_point_index(g.dt_edges, n, [](std::uint64_t key) { return key; },
                                std::less<std::uint64_t>());
}

// G's `face_count` faces in canonical indices, ccw; degenerate ones flagged. Half-edges carry
// their face; the indices the faces use are marked.
template <class PointIterator, class FaceRange, class DT>
void predicted_faces_in_canonical_indices(const DT& dt, PointIterator point_at, std::size_t n,
                                          const FaceRange& faces, std::size_t face_count,
                                          Measured_prediction<DT>& g)
{
  using Triple = typename Measured_prediction<DT>::Triple;
  auto orientation = dt.geom_traits().orientation_2_object();
  auto canonical = [&](std::size_t i) { return std::size_t(g.vertex_of[i]->info()); };
  g.used.assign(n, 0);
  g.g_faces.reserve(face_count);
  g.half_edges.reserve(3 * face_count);
  std::size_t k = 0, idx[3];
  for(const auto& face : faces) {
    internal::read_face(face, k++, n, idx); // cannot throw: delaunay_from_prediction checked
    g.used[idx[0]] = g.used[idx[1]] = g.used[idx[2]] = 1;
    Triple t{canonical(idx[0]), canonical(idx[1]), canonical(idx[2])};
    bool flat = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    if(!flat) {
      const Orientation o = orientation(point_at[t[0]], point_at[t[1]], point_at[t[2]]);
      flat = o == COLLINEAR;
      if(o == RIGHT_TURN)
        std::swap(t[1], t[2]);
    }
    const std::uint32_t id = std::uint32_t(g.g_faces.size());
    for(std::uint8_t j = 0; j < 3; ++j) {
      const std::size_t a = t[internal::ccw(j)], b = t[internal::cw(j)];
      if(a != b)
        g.half_edges.push_back({internal::edge_key(a, b), id, j});
    }
    g.g_faces.push_back(t);
    g.degenerate.push_back(flat ? 1 : 0);
  }
}

// D, D_missing, D_local, D_cross, d_cross: one group of half-edges per edge of G, merged with
// DT's sorted edges. A missing edge's crossings are counted by a walk in DT (planar DT only).
template <class Measures, class PointIterator, class DT>
void measure_edges(Measures& m, const DT& dt, PointIterator point_at, std::size_t n, Measured_prediction<DT>& g)
{
  using Half_edge = typename Measured_prediction<DT>::Half_edge;
  using Triple = typename Measured_prediction<DT>::Triple;
  const auto& gt = dt.geom_traits();
  std::vector<Half_edge>& half_edges = g.half_edges;
  internal::sort_by_point_index(half_edges, n, [](const Half_edge& x) { return x.key; },
                                [](const Half_edge& x, const Half_edge& y) { return x.key < y.key; });
  std::size_t common = 0;
  const bool planar = dt.dimension() == 2;
  auto next_dt_edge = g.dt_edges.begin(); // both lists sorted: a merge, not a search per edge
  for(std::size_t h = 0; h < half_edges.size();) {
    std::size_t end = h + 1;
    while(end < half_edges.size() && half_edges[end].key == half_edges[h].key)
      ++end;
    const std::uint64_t key = half_edges[h].key;
    ++m.edges;
    const std::size_t a = std::size_t(key >> 32), b = std::size_t(key & 0xffffffffu);
    while(next_dt_edge != g.dt_edges.end() && *next_dt_edge < key)
      ++next_dt_edge;
    if(next_dt_edge != g.dt_edges.end() && *next_dt_edge == key) {
      ++common;
    } else {
      ++m.D;
      if(planar) {
        // Start from the endpoint of smaller degree: the walk begins with a turn around it.
        const bool from_a = g.degree[a] <= g.degree[b];
        const std::size_t crossings =
            internal::count_crossings(dt, g.vertex_of[from_a ? a : b], g.vertex_of[from_a ? b : a]);
        m.D_cross += crossings;
        m.d_cross = (std::max)(m.d_cross, crossings);
      }
    }
    if(end - h > 2) {
      ++m.edges_with_more_than_two_faces;
    } else if(end - h == 2) {
      const Triple& f = g.g_faces[half_edges[h].face];
      const Triple& e = g.g_faces[half_edges[h + 1].face];
      const int sf = half_edges[h].slot, se = half_edges[h + 1].slot;
      const std::size_t c = f[sf], d = e[se];
      if(!g.degenerate[half_edges[h].face] && !g.degenerate[half_edges[h + 1].face] && c != d) {
        // Faces on both sides: the test is symmetric, one suffices. Folded faces (both on one
        // side, not in a triangulation): the edge counts if either test fails.
        const bool same_side = f[internal::ccw(sf)] == e[internal::ccw(se)];
        if(!internal::is_locally_delaunay(gt, point_at[f[0]], point_at[f[1]], point_at[f[2]], point_at[d]) ||
           (same_side &&
            !internal::is_locally_delaunay(gt, point_at[e[0]], point_at[e[1]], point_at[e[2]], point_at[c])))
          ++m.D_local;
      }
    }
    h = end;
  }
  m.D_missing = m.delaunay_edges - common;
  m.D_flip_lower = m.D;
}

// D_vio, d_vio over the distinct faces of G; a face of DT(P) has no point inside. (Their
// cost is D_vio, which a few long faces along the hull make quadratic: `violations` false
// leaves them 0, for benchmarks that need d_cross on large inputs.) Counts the degenerate
// faces too; returns whether a face is listed twice.
template <class Measures, class DT>
bool measure_circle_violations(Measures& m, const DT& dt, std::size_t n, const Measured_prediction<DT>& g,
                               bool violations)
{
  using Triple = typename Measured_prediction<DT>::Triple;
  using internal::Face_key;
  const bool planar = dt.dimension() == 2;
  auto low_pair_of = [](const Face_key& f) { return f.low_pair; };
  std::vector<Face_key> face_keys(g.g_faces.size()), dt_face_keys;
  for(std::uint32_t k = 0; k < g.g_faces.size(); ++k)
    face_keys[k] = internal::face_key(g.g_faces[k][0], g.g_faces[k][1], g.g_faces[k][2], k);
  internal::sort_by_point_index(face_keys, n, low_pair_of, std::less<Face_key>());
  if(planar) {
    dt_face_keys.reserve(2 * n);
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      dt_face_keys.push_back(internal::face_key(f->vertex(0)->info(), f->vertex(1)->info(),
                                                f->vertex(2)->info(), 0));
    internal::sort_by_point_index(dt_face_keys, n, low_pair_of, std::less<Face_key>());
  }
  auto next_dt_face = dt_face_keys.begin(); // a merge again
  std::vector<std::uint32_t> mark(n, 0);
  std::vector<typename DT::Vertex_handle> queue;
  std::uint32_t stamp = 0;
  bool repeated_face = false;
  for(std::size_t k = 0; k < face_keys.size(); ++k) {
    if(k > 0 && face_keys[k].same_face(face_keys[k - 1])) {
      repeated_face = true;
      continue;
    }
    if(!violations && !g.degenerate[face_keys[k].face])
      continue;
    const std::uint32_t face = face_keys[k].face;
    if(g.degenerate[face]) {
      ++m.degenerate_faces;
      continue;
    }
    while(next_dt_face != dt_face_keys.end() && *next_dt_face < face_keys[k])
      ++next_dt_face;
    if(!planar || (next_dt_face != dt_face_keys.end() && next_dt_face->same_face(face_keys[k])))
      continue; // a face of DT(P): no point inside
    const Triple& t = g.g_faces[face];
    if(++stamp == 0) { // wrapped around: clear the marks
      std::fill(mark.begin(), mark.end(), 0);
      stamp = 1;
    }
    const std::size_t inside = internal::count_points_in_circle(
        dt, g.vertex_of[t[0]], g.vertex_of[t[1]], g.vertex_of[t[2]], mark, stamp, queue);
    m.D_vio += inside;
    m.d_vio = (std::max)(m.d_vio, inside);
  }
  return repeated_face;
}

// Is G a triangulation of P? The import certified it (orientation, twins, convex hull wound
// once) unless it failed; what it tolerates (unused points) is checked here.
template <class Measures>
void judge_triangulation(Measures& m, std::size_t n, std::size_t duplicates, const std::vector<char>& used,
                         bool repeated_face, const Statistics& stats)
{
  const bool out_of_budget =
      stats.fell_back && stats.outcome == Outcome::flip_budget_exhausted;
  if(n < 3 || m.faces == 0)
    m.not_a_triangulation = "fewer than three points or no face";
  else if(duplicates > 0)
    m.not_a_triangulation = "two points are at the same position";
  else if(stats.fell_back && !out_of_budget)
    m.not_a_triangulation = to_string(stats.outcome);
  else if(std::count(used.begin(), used.end(), char(0)) > 0)
    m.not_a_triangulation = "some points are used by no face";
  else if(repeated_face)
    m.not_a_triangulation = "a face is listed twice";
  m.is_triangulation = m.not_a_triangulation.empty();
  if(m.is_triangulation && !out_of_budget)
    m.D_flip_upper = stats.flips;
}

// The measures of Table 1 into `m` (a Prediction_measures whose points and faces are set),
// from DT(P) as `dt` (each vertex's info the smallest index of its point) and the statistics
// of the delaunay_from_prediction() call that built it from the faces (Strategy::flips).
template <class Measures, class PointIterator, class FaceRange, class DT>
void measure_prediction(Measures& m, PointIterator point_at, std::size_t n, const FaceRange& faces, DT& dt,
                        const Statistics& stats, bool violations = true)
{
  Measured_prediction<DT> g;
  const std::size_t duplicates = vertices_by_point_index(dt, point_at, n, g.vertex_of);
  delaunay_edge_keys(dt, n, g);
  m.delaunay_edges = g.dt_edges.size();
  predicted_faces_in_canonical_indices(dt, point_at, n, faces, m.faces, g);
  measure_edges(m, dt, point_at, n, g);
  const bool repeated_face = measure_circle_violations(m, dt, n, g, violations);
  judge_triangulation(m, n, duplicates, g.used, repeated_face, stats);
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_MEASURES_PREDICTION_MEASURES_H
