// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Builds from scratch on flat arrays: Lawson's incremental insertion (locate by a visibility
// walk from the last point, split the face or the edge, flip the edges around the new
// vertex while they fail the perturbed in-circle test) on index arrays, with CGAL's
// infinite vertex as one more index, then the faces written into a CGAL TDS in one pass
// with their neighbours known. The points are copied in insertion order (a biased
// randomized grid order), so that consecutive points, their faces and their neighbours sit
// close in memory: measured about 1.3x faster than the same insertion on a TDS's faces at
// 1e6 points (benchmark/README.md, rebuild rows). insertion.h remains the engine for
// insertions into an existing triangulation.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_FLAT_INSERTION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_FLAT_INSERTION_H

#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// The Delaunay triangulation of points given in insertion order, on arrays: vertex k is the
// k-th point (its rank), `infinite` is CGAL's infinite vertex. Face t has vertices
// vertex(t, 0..2) in ccw order (an infinite face (a, b, infinite) lies left of a -> b), and
// neighbour(t, i) is the face across the edge opposite vertex(t, i), as in CGAL's TDS.
// Why it gives exactly CGAL's triangulation: every decision is an exact predicate of the
// traits (orientation; the in-circle test with CGAL's symbolic perturbation, and CGAL's test
// for infinite faces: the orientation of their finite edge), and the perturbed Delaunay
// triangulation of a point set is unique. A point equal to an earlier one is not inserted:
// its representative is that point's rank.
// Whether a face or vertex type has info().
template <class T, class = void>
struct has_info : std::false_type
{};
template <class T>
struct has_info<T, std::void_t<decltype(std::declval<T&>().info())>> : std::true_type
{};

template <class Gt>
class Flat_delaunay
{
public:
  using Point = typename Gt::Point_2;
  static constexpr std::uint32_t infinite = std::uint32_t(-1);

  explicit Flat_delaunay(const Gt& gt) : gt_(gt) {}

  // Builds the triangulation of point_at(0), ..., point_at(m - 1), inserted in this order
  // (m < 2^32 - 1). Returns false, with nothing built, when the points do not span the plane
  // (fewer than three points off one line): the caller's insertion handles dimensions 0 and 1.
  template <class PointAt>
  bool build(std::size_t m, PointAt point_at)
  {
    store(m, point_at);
    return start_with(m, [](std::size_t k) { return std::uint32_t(k); });
  }

  // Stores the points point_at(0), ..., point_at(m - 1) as ranks 0..m-1 (m < 2^32 - 1), and
  // no face: start_with() and insert_from() insert them, in any order.
  template <class PointAt>
  void store(std::size_t m, PointAt point_at)
  {
    CGAL_precondition(m < std::size_t(infinite));
    points_.clear();
    points_.reserve(m);
    for(std::size_t k = 0; k < m; ++k)
      points_.push_back(point_at(k));
    representative_.resize(m);
    for(std::size_t k = 0; k < m; ++k)
      representative_[k] = std::uint32_t(k);
    vertices_.clear();
    adjacent_.clear();
  }

  // Builds the triangulation of the stored points of ranks rank_at(0), ..., rank_at(count - 1),
  // inserted in this order, each located from the previous one. Returns false, with nothing
  // built, when they do not span the plane.
  template <class RankAt>
  bool start_with(std::size_t count, RankAt rank_at)
  {
    vertices_.clear();
    adjacent_.clear();
    if(count < 3)
      return false;
    auto orientation = gt_.orientation_2_object();
    const std::uint32_t a = rank_at(0);
    std::size_t b = 1;
    while(b < count && points_[rank_at(b)] == points_[a])
      ++b;
    std::size_t c = b + 1;
    while(c < count && orientation(points_[a], points_[rank_at(b)], points_[rank_at(c)]) == COLLINEAR)
      ++c;
    if(c >= count)
      return false;
    vertices_.reserve(6 * points_.size());
    adjacent_.reserve(6 * points_.size());
    if(orientation(points_[a], points_[rank_at(b)], points_[rank_at(c)]) == LEFT_TURN)
      start(a, rank_at(b), rank_at(c));
    else
      start(a, rank_at(c), rank_at(b));
    for(std::size_t k = 1; k < count; ++k)
      if(k != b && k != c)
        insert(rank_at(k));
    return true;
  }

  std::size_t number_of_faces() const { return vertices_.size() / 3; }
  std::uint32_t vertex(std::size_t t, int i) const { return vertices_[3 * t + i]; }
  std::size_t neighbor(std::size_t t, int i) const { return adjacent_[3 * t + i] / 3; }
  // The rank of the vertex at point k's position: k itself, or an earlier point's rank.
  std::uint32_t representative(std::size_t k) const { return representative_[k]; }
  const Point& point(std::uint32_t v) const { return points_[v]; }
  bool is_infinite(std::size_t t) const
  {
    return vertices_[3 * t] == infinite || vertices_[3 * t + 1] == infinite || vertices_[3 * t + 2] == infinite;
  }

  // Where a visibility walk towards p ended: in `face`, whose closure holds p when `found`
  // (with `collinear` edges of a finite face on p: 0 strictly inside, 1 on the edge opposite
  // vertex `on_edge`, 2 at a vertex), or in an infinite face when p is strictly outside the
  // hull; `found` false: the walk stopped at its cap.
  struct Location
  {
    std::uint32_t face = 0;
    int collinear = 0, on_edge = 0;
    bool found = false;
  };

  // Visibility walk from face t towards p: cross an edge while p is strictly on its far side.
  // It ends on a Delaunay triangulation (the lifting map orders the faces), in the face whose
  // closure holds p, or in an infinite face when p is strictly outside the hull; or after
  // `cap` faces entered. `steps` counts the faces entered.
  Location walk(const Point& p, std::uint32_t t, std::size_t cap, std::size_t& steps) const
  {
    auto orientation = gt_.orientation_2_object();
    if(is_infinite(t)) {
      int i = 0;
      while(vertices_[3 * t + i] != infinite)
        ++i;
      t = adjacent_[3 * t + i] / 3;
    }
    Location at;
    std::uint32_t previous = infinite;
    for(std::size_t entered = 0;;) {
      bool moved = false;
      at.collinear = 0;
      for(int i = 0; i < 3; ++i) {
        const std::uint32_t next = adjacent_[3 * t + i] / 3;
        if(next == previous)
          continue;
        const Orientation o = orientation(point(vertices_[3 * t + ccw(i)]), point(vertices_[3 * t + cw(i)]), p);
        if(o == RIGHT_TURN) {
          previous = t;
          t = next;
          moved = true;
          break;
        }
        if(o == COLLINEAR) {
          ++at.collinear;
          at.on_edge = i;
        }
      }
      if(moved) {
        ++steps;
        if(++entered > cap && !is_infinite(t)) {
          at.face = t;
          return at;
        }
      }
      if(!moved || is_infinite(t))
        break;
    }
    at.face = t;
    at.found = true;
    return at;
  }

  // Inserts the stored point of rank q, walking from face t; with `touched` set, every face
  // whose vertices the insertion changes (or creates) is appended to it. A point equal to a
  // vertex's is not inserted (representative()). Afterwards last_face() is a face of q's
  // vertex.
  void insert_from(std::uint32_t q, std::uint32_t t, std::vector<std::uint32_t>* touched = nullptr)
  {
    last_ = t;
    touched_ = touched;
    insert(q);
    touched_ = nullptr;
  }
  std::uint32_t last_face() const { return last_; }

  // Whether the point p is in conflict with face t, as Delaunay_triangulation_2 decides it:
  // strictly inside the circumcircle with CGAL's symbolic perturbation, or, for an infinite
  // face, strictly on the outer side of its finite edge. (Its conflict faces are those the
  // insertion of p destroys.)
  bool in_conflict(std::uint32_t t, const Point& p) const
  {
    const std::uint32_t a = vertices_[3 * t], b = vertices_[3 * t + 1], c = vertices_[3 * t + 2];
    auto orientation = gt_.orientation_2_object();
    if(a == infinite)
      return orientation(point(b), point(c), p) == LEFT_TURN;
    if(b == infinite)
      return orientation(point(c), point(a), p) == LEFT_TURN;
    if(c == infinite)
      return orientation(point(a), point(b), p) == LEFT_TURN;
    return side_of_oriented_circle_perturbed(gt_, point(a), point(b), point(c), p) == ON_POSITIVE_SIDE;
  }

  // Writes the faces into `tds`, whose faces are replaced: `vertex_of(rank)` gives the TDS
  // vertex of each inserted rank, `infinite_vertex` CGAL's infinite vertex. The TDS's face
  // objects are reused (their info(), if any, value-initialized), the missing ones created,
  // the extra ones deleted: rebuilding a triangulation in place allocates nothing and
  // touches no new page (fresh pages cost as much as the insertion itself at 1e6 points).
  // Sets the dimension to 2 and every vertex's face.
  template <class Tds, class VertexOf>
  void write_faces(Tds& tds, typename Tds::Vertex_handle infinite_vertex, VertexOf vertex_of) const
  {
    using Vertex_handle = typename Tds::Vertex_handle;
    using Face_handle = typename Tds::Face_handle;
    const std::size_t faces = number_of_faces();
    std::vector<Face_handle> face;
    face.reserve(faces);
    auto f = tds.faces().begin();
    for(; f != tds.faces().end() && face.size() < faces; ++f) {
      if constexpr(has_info<typename Tds::Face>::value)
        f->info() = std::decay_t<decltype(f->info())>();
      face.push_back(f);
    }
    std::vector<Face_handle> extra;
    for(; f != tds.faces().end(); ++f)
      extra.push_back(f);
    for(const Face_handle g : extra)
      tds.delete_face(g);
    while(face.size() < faces)
      face.push_back(tds.create_face());
    auto handle = [&](std::uint32_t v) -> Vertex_handle { return v == infinite ? infinite_vertex : vertex_of(v); };
    tds.set_dimension(2);
    for(std::size_t t = 0; t < faces; ++t) {
      const Face_handle g = face[t];
      g->set_vertices(handle(vertex(t, 0)), handle(vertex(t, 1)), handle(vertex(t, 2)));
      g->set_neighbors(face[neighbor(t, 0)], face[neighbor(t, 1)], face[neighbor(t, 2)]);
      for(int i = 0; i < 3; ++i)
        g->vertex(i)->set_face(g);
    }
  }

private:
  // The triangle (a, b, c), ccw, and the three infinite faces around it.
  void start(std::uint32_t a, std::uint32_t b, std::uint32_t c)
  {
    const std::uint32_t abc[3] = {a, b, c};
    vertices_.insert(vertices_.end(), abc, abc + 3);
    adjacent_.resize(3);
    for(int k = 0; k < 3; ++k) {
      // Outside the edge opposite abc[k]: (abc[cw k], abc[ccw k], infinite).
      const std::uint32_t face = 1 + k;
      vertices_.push_back(abc[cw(k)]);
      vertices_.push_back(abc[ccw(k)]);
      vertices_.push_back(infinite);
      adjacent_[k] = 3 * face + 2;
      adjacent_.push_back(3 * (1 + cw(k)) + 1);
      adjacent_.push_back(3 * (1 + ccw(k)) + 0);
      adjacent_.push_back(3 * 0 + k);
    }
    last_ = 0;
  }

  std::uint32_t new_face()
  {
    vertices_.resize(vertices_.size() + 3);
    adjacent_.resize(adjacent_.size() + 3);
    return std::uint32_t(vertices_.size() / 3 - 1);
  }
  void link(std::uint32_t e, std::uint32_t f)
  {
    adjacent_[e] = f;
    adjacent_[f] = e;
  }

  void insert(std::uint32_t q)
  {
    const Point& p = point(q);
    std::size_t steps = 0;
    const Location at = walk(p, last_, std::size_t(-1), steps);
    const std::uint32_t t = at.face;
    const int collinear = at.collinear, on_edge = at.on_edge;
    if(is_infinite(t) || collinear == 0) {
      split_face(t, q);
    } else if(collinear == 1) {
      split_edge(t, on_edge, q);
    } else {
      for(int i = 0; i < 3; ++i)
        if(point(vertices_[3 * t + i]) == p)
          representative_[q] = vertices_[3 * t + i];
      CGAL_assertion(representative_[q] != q);
      return;
    }
    flip_around(q);
    last_ = t;
  }

  // p inside face t (or strictly outside the hull edge of the infinite face t): three faces.
  void split_face(std::uint32_t t, std::uint32_t q)
  {
    const std::uint32_t t1 = new_face(), t2 = new_face();
    const std::uint32_t a = vertices_[3 * t], b = vertices_[3 * t + 1], c = vertices_[3 * t + 2];
    const std::uint32_t n1 = adjacent_[3 * t + 1], n2 = adjacent_[3 * t + 2];
    vertices_[3 * t] = q;
    if(touched_ != nullptr)
      touched_->push_back(t);
    set_face(t1, a, q, c);
    set_face(t2, a, b, q);
    link(3 * t + 1, 3 * t1 + 0);
    link(3 * t + 2, 3 * t2 + 0);
    link(3 * t1 + 2, 3 * t2 + 1);
    link(3 * t1 + 1, n1);
    link(3 * t2 + 2, n2);
    stack_.push_back(3 * t + 0);
    stack_.push_back(3 * t1 + 1);
    stack_.push_back(3 * t2 + 2);
  }

  // p on the edge opposite vertex i of the finite face t, strictly inside it: four faces.
  void split_edge(std::uint32_t t, int i, std::uint32_t q)
  {
    const std::uint32_t f = adjacent_[3 * t + i], u = f / 3;
    const int j = int(f % 3);
    const std::uint32_t x = vertices_[3 * t + i], y = vertices_[3 * t + ccw(i)], z = vertices_[3 * t + cw(i)];
    const std::uint32_t w = vertices_[f];
    const std::uint32_t opposite_y = adjacent_[3 * t + ccw(i)], opposite_z = adjacent_[3 * t + cw(i)];
    const std::uint32_t u_opposite_z = adjacent_[3 * u + ccw(j)], u_opposite_y = adjacent_[3 * u + cw(j)];
    const std::uint32_t t2 = new_face(), u2 = new_face();
    set_face(t, x, y, q);
    set_face(t2, x, q, z);
    set_face(u, w, z, q);
    set_face(u2, w, q, y);
    link(3 * t + 0, 3 * u2 + 0);
    link(3 * t + 1, 3 * t2 + 2);
    link(3 * t2 + 0, 3 * u + 0);
    link(3 * u + 1, 3 * u2 + 2);
    link(3 * t + 2, opposite_z);
    link(3 * t2 + 1, opposite_y);
    link(3 * u + 2, u_opposite_y);
    link(3 * u2 + 1, u_opposite_z);
    stack_.push_back(3 * t + 2);
    stack_.push_back(3 * t2 + 1);
    stack_.push_back(3 * u + 2);
    stack_.push_back(3 * u2 + 1);
  }

  void set_face(std::uint32_t t, std::uint32_t a, std::uint32_t b, std::uint32_t c)
  {
    if(touched_ != nullptr)
      touched_->push_back(t);
    vertices_[3 * t] = a;
    vertices_[3 * t + 1] = b;
    vertices_[3 * t + 2] = c;
  }

  // Lawson's flips around the new vertex q: each stacked slot holds q, and the edge opposite
  // it is flipped when the face across is in conflict with q, as Delaunay_triangulation_2
  // decides it (perturbed in-circle test; for an infinite face, the orientation of its
  // finite edge).
  void flip_around(std::uint32_t q)
  {
    auto orientation = gt_.orientation_2_object();
    const Point& p = point(q);
    while(!stack_.empty()) {
      const std::uint32_t e = stack_.back();
      stack_.pop_back();
      const std::uint32_t t = e / 3, f = adjacent_[e], u = f / 3;
      const int i = int(e % 3), j = int(f % 3);
      const std::uint32_t b = vertices_[3 * t + ccw(i)], c = vertices_[3 * t + cw(i)], d = vertices_[f];
      bool conflict = false;
      if(d == infinite)
        conflict = false; // the edge (b, c) is a hull edge and p is inside
      else if(b == infinite)
        conflict = orientation(point(d), point(c), p) == LEFT_TURN;
      else if(c == infinite)
        conflict = orientation(point(b), point(d), p) == LEFT_TURN;
      else
        conflict = side_of_oriented_circle_perturbed(gt_, point(d), point(c), point(b), p) == ON_POSITIVE_SIDE;
      if(!conflict)
        continue;
      // (q, b, c) and (d, c, b) become (q, b, d) and (q, d, c).
      const std::uint32_t t_opposite_b = adjacent_[3 * t + ccw(i)], t_opposite_c = adjacent_[3 * t + cw(i)];
      const std::uint32_t u_opposite_c = adjacent_[3 * u + ccw(j)], u_opposite_b = adjacent_[3 * u + cw(j)];
      set_face(t, q, b, d);
      set_face(u, q, d, c);
      link(3 * t + 0, u_opposite_c);
      link(3 * t + 2, t_opposite_c);
      link(3 * u + 0, u_opposite_b);
      link(3 * u + 1, t_opposite_b);
      link(3 * t + 1, 3 * u + 2);
      stack_.push_back(3 * t + 0);
      stack_.push_back(3 * u + 0);
    }
  }

  const Gt& gt_;
  std::vector<Point> points_;
  std::vector<std::uint32_t> representative_;
  std::vector<std::uint32_t> vertices_, adjacent_; // 3 per face; adjacent_: 3 * face + slot of the twin
  std::vector<std::uint32_t> stack_;
  std::uint32_t last_ = 0; // a face holding the last point inserted
  std::vector<std::uint32_t>* touched_ = nullptr; // insert_from()'s record of the faces changed
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_BUILD_FLAT_INSERTION_H
