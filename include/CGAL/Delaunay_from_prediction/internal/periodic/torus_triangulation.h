// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// The stages of the periodic entry points (periodic_2.h) on a triangulation of the flat torus
// held in flat arrays: three corners a face, each with its point index, the lattice
// translation of that point in the face's frame and the corner opposite the same edge in the
// neighbouring face. It is built from index triples by the minimum-image convention or read
// from a CGAL Periodic_2_Delaunay_triangulation_2, certified to tile the torus exactly once,
// made Delaunay by Lawson's flips, and written back into CGAL's data structure as a 1-sheeted
// covering.
//
// Why it is robust: everything that decides the result is decided by the traits' exact
// predicates on the translated points (orientation, in-circle with CGAL's symbolic
// perturbation, lexicographic order), or by interval arithmetic that gives up, and lets CGAL
// build, when it cannot decide (how many times the faces cover the torus, which covering
// CGAL's own insertion ends in). Doubles only steer: the minimum image of an edge, which when
// chosen wrongly only makes a wrong prediction.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_TORUS_TRIANGULATION_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_TORUS_TRIANGULATION_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/import/hole_tracing.h>
#include <CGAL/Delaunay_from_prediction/internal/import/open_halfedges.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/dense_index.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// A translation of the domain's lattice, in periods.
struct Lattice_offset
{
  std::int32_t x = 0, y = 0;
};
inline Lattice_offset operator+(Lattice_offset a, Lattice_offset b) { return {a.x + b.x, a.y + b.y}; }
inline Lattice_offset operator-(Lattice_offset a, Lattice_offset b) { return {a.x - b.x, a.y - b.y}; }
inline bool operator==(Lattice_offset a, Lattice_offset b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Lattice_offset a, Lattice_offset b) { return !(a == b); }

// Faces of a triangulation of the torus, counterclockwise, three corners each: corner 3f + i is
// vertex i of face f, and also the half-edge opposite it, from vertex ccw(i) to vertex cw(i).
struct Torus_triangulation
{
  static constexpr std::uint32_t no_twin = std::uint32_t(-1);
  std::vector<std::uint32_t> vertex;  // the point index of each corner
  std::vector<Lattice_offset> offset; // the translation of that point in the face's frame
  std::vector<std::uint32_t> twin;    // the corner across the half-edge opposite each corner
  std::vector<unsigned char> flipped; // per face: whether a flip changed it

  std::size_t number_of_faces() const { return vertex.size() / 3; }
  void resize(std::size_t faces)
  {
    vertex.assign(3 * faces, 0);
    offset.assign(3 * faces, Lattice_offset());
    twin.assign(3 * faces, no_twin);
    flipped.assign(faces, 0);
  }
  std::size_t faces_never_flipped() const { return std::size_t(std::count(flipped.begin(), flipped.end(), 0)); }
  // The translation that takes the frame of the face across half-edge h into the frame of
  // h's face: the two faces' translations of a vertex they share differ by it.
  Lattice_offset translation_across(std::size_t h) const
  {
    const std::size_t t = twin[h];
    return offset[h - h % 3 + std::size_t(ccw(int(h % 3)))] - offset[t - t % 3 + std::size_t(cw(int(t % 3)))];
  }
  // Whether the two vertices face f shares with the face across h have the same translation
  // between the faces' frames (false: the faces do not fit together in the plane).
  bool frames_agree(std::size_t h) const
  {
    const std::size_t t = twin[h], f = h - h % 3, g = t - t % 3;
    const int i = int(h % 3), j = int(t % 3);
    return offset[f + std::size_t(ccw(i))] - offset[g + std::size_t(cw(j))] ==
           offset[f + std::size_t(cw(i))] - offset[g + std::size_t(ccw(j))];
  }
  // Translates face f so that each coordinate of its offsets has least value 0 (CGAL stores
  // face offsets so).
  void normalize_face(std::size_t f)
  {
    Lattice_offset* o = offset.data() + 3 * f;
    const Lattice_offset low{(std::min)({o[0].x, o[1].x, o[2].x}), (std::min)({o[0].y, o[1].y, o[2].y})};
    for(int i = 0; i < 3; ++i)
      o[i] = o[i] - low;
  }
};

// The points of the torus and the traits' predicates on them, translated by lattice offsets.
// `Gt` is a Periodic_2_Delaunay_triangulation_traits_2 whose domain is the torus's.
template <class Gt>
class Torus_geometry
{
public:
  using Point = typename Gt::Point_2;
  using Offset = typename Gt::Periodic_2_offset_2;

  Torus_geometry(const Gt& gt, std::vector<const Point*> points) : gt_(gt), point_(std::move(points))
  {
    const auto& domain = gt.get_domain();
    xmin_ = CGAL::to_double(domain.xmin());
    ymin_ = CGAL::to_double(domain.ymin());
    width_ = CGAL::to_double(domain.xmax()) - xmin_;
    height_ = CGAL::to_double(domain.ymax()) - ymin_;
    width_interval_ = CGAL::to_interval(domain.xmax() - domain.xmin());
    xmin_interval_ = CGAL::to_interval(domain.xmin());
    ymin_interval_ = CGAL::to_interval(domain.ymin());
    reach_ = (std::max)({std::abs(CGAL::to_double(domain.xmin())), std::abs(CGAL::to_double(domain.xmax())),
                         std::abs(CGAL::to_double(domain.ymin())), std::abs(CGAL::to_double(domain.ymax()))}) +
             (std::max)(width_, height_);
    xy_.resize(2 * point_.size());
    for(std::size_t i = 0; i < point_.size(); ++i) {
      xy_[2 * i] = CGAL::to_double(point_[i]->x());
      xy_[2 * i + 1] = CGAL::to_double(point_[i]->y());
    }
    Protect_FPU_rounding<true> upward;
    unit_xy_.resize(2 * point_.size());
    for(std::size_t i = 0; i < point_.size(); ++i) {
      unit_xy_[2 * i] = (interval(CGAL::to_interval(point_[i]->x())) - interval(xmin_interval_)) / interval(width_interval_);
      unit_xy_[2 * i + 1] =
          (interval(CGAL::to_interval(point_[i]->y())) - interval(ymin_interval_)) / interval(width_interval_);
    }
  }

  std::size_t size() const { return point_.size(); }
  const Point& point(std::size_t i) const { return *point_[i]; }

  // The translation of b that puts it nearest to a, each coordinate in {-1, 0, 1} periods
  // (steering only: a wrong choice makes a face that does not close, or an inverted one).
  Lattice_offset minimum_image(std::size_t a, std::size_t b) const
  {
    return {step(xy_[2 * b] - xy_[2 * a], width_), step(xy_[2 * b + 1] - xy_[2 * a + 1], height_)};
  }

  // The orientation of the translated points. Points of one translation (most faces, those
  // inside the domain) take the kernel's predicate on the points themselves: a translation
  // changes neither an orientation nor an in-circle test nor the lexicographic order.
  Orientation orientation(std::size_t a, Lattice_offset oa, std::size_t b, Lattice_offset ob, std::size_t c,
                          Lattice_offset oc) const
  {
    if(oa == ob && oa == oc)
      return gt_.orientation_2_object()(point(a), point(b), point(c));
    return gt_.orientation_2_object()(point(a), point(b), point(c), offset(oa), offset(ob), offset(oc));
  }

  // The side of the circle through the counterclockwise (a, b, c) that d lies on, ties broken
  // by CGAL's symbolic perturbation (the one Periodic_2_Delaunay_triangulation_2 uses: the
  // lexicographic order of the translated points), through the package's perturbed in-circle
  // test on translated points.
  Oriented_side side_of_circle(std::size_t a, Lattice_offset oa, std::size_t b, Lattice_offset ob, std::size_t c,
                               Lattice_offset oc, std::size_t d, Lattice_offset od) const
  {
    if(oa == ob && oa == oc && oa == od) // with the package's inline filter for Epick's doubles
      return side_of_oriented_circle_perturbed(gt_, point(a), point(b), point(c), point(d));
    const Translated_point pa{&point(a), offset(oa)}, pb{&point(b), offset(ob)}, pc{&point(c), offset(oc)},
        pd{&point(d), offset(od)};
    return exact_side_of_oriented_circle_perturbed(Translated_predicates{gt_}, pa, pb, pc, pd);
  }

  // Twice the signed area of the translated triangle, in interval arithmetic (under
  // Protect_FPU_rounding<true>), in units of the domain's area (so that neither tiny nor huge
  // domains underflow or overflow).
  Interval_nt<false> twice_area(std::size_t a, Lattice_offset oa, std::size_t b, Lattice_offset ob, std::size_t c,
                                Lattice_offset oc) const
  {
    const Interval_nt<false> ax = x(a, oa), ay = y(a, oa);
    return (x(b, ob) - ax) * (y(c, oc) - ay) - (y(b, ob) - ay) * (x(c, oc) - ax);
  }
  // The square of the diameter of the circle through the translated triangle, in interval
  // arithmetic, in squared periods (unbounded when the triangle may be flat).
  Interval_nt<false> squared_circumdiameter(std::size_t a, Lattice_offset oa, std::size_t b, Lattice_offset ob,
                                            std::size_t c, Lattice_offset oc) const
  {
    const Interval_nt<false> ax = x(a, oa), ay = y(a, oa), bx = x(b, ob), by = y(b, ob), cx = x(c, oc),
                             cy = y(c, oc);
    const Interval_nt<false> ab = CGAL::square(bx - ax) + CGAL::square(by - ay);
    const Interval_nt<false> bc = CGAL::square(cx - bx) + CGAL::square(cy - by);
    const Interval_nt<false> ca = CGAL::square(ax - cx) + CGAL::square(ay - cy);
    const Interval_nt<false> area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if(!(area2.inf() > 0))
      return Interval_nt<false>(std::numeric_limits<double>::infinity());
    return ab * bc * ca / CGAL::square(area2);
  }
  // The rounding error of a translated coordinate, relative to the period: CGAL's
  // constructions of translated points err by about this much.
  double relative_rounding() const { return std::numeric_limits<double>::epsilon() * reach_ / width_; }

  // A point translated by a lattice offset, as the perturbed in-circle test and the ear
  // clipping read it.
  struct Translated_point
  {
    const Point* point;
    Offset offset;
  };
  // The traits' predicates with offsets, on translated points.
  struct Translated_predicates
  {
    const Gt& gt;
    auto side_of_oriented_circle_2_object() const
    {
      return [this](const Translated_point& p, const Translated_point& q, const Translated_point& r,
                    const Translated_point& s) {
        return gt.side_of_oriented_circle_2_object()(*p.point, *q.point, *r.point, *s.point, p.offset, q.offset,
                                                     r.offset, s.offset);
      };
    }
    auto orientation_2_object() const
    {
      return [this](const Translated_point& p, const Translated_point& q, const Translated_point& r) {
        return gt.orientation_2_object()(*p.point, *q.point, *r.point, p.offset, q.offset, r.offset);
      };
    }
    auto compare_xy_2_object() const
    {
      return [this](const Translated_point& p, const Translated_point& q) { // as CGAL's compare_xy()
        const Comparison_result x = gt.compare_x_2_object()(*p.point, *q.point, p.offset, q.offset);
        return x != EQUAL ? x : gt.compare_y_2_object()(*p.point, *q.point, p.offset, q.offset);
      };
    }
  };

  Translated_point translated(std::size_t i, Lattice_offset o) const { return {&point(i), offset(o)}; }
  Translated_predicates translated_predicates() const { return Translated_predicates{gt_}; }

private:
  static std::int32_t step(double d, double period) { return d > 0.5 * period ? -1 : (d < -0.5 * period ? 1 : 0); }
  static Offset offset(Lattice_offset o) { return Offset(o.x, o.y); }
  // A translated coordinate in periods from the domain's lower side (both in periods of x: CGAL's
  // domains are square).
  Interval_nt<false> x(std::size_t i, Lattice_offset o) const { return unit_xy_[2 * i] + double(o.x); }
  Interval_nt<false> y(std::size_t i, Lattice_offset o) const { return unit_xy_[2 * i + 1] + double(o.y); }
  static Interval_nt<false> interval(std::pair<double, double> i) { return Interval_nt<false>(i.first, i.second); }

  const Gt& gt_;
  std::vector<const Point*> point_;
  std::vector<double> xy_;
  std::vector<Interval_nt<false>> unit_xy_; // (coordinate - domain's low side) / period
  double xmin_ = 0, ymin_ = 0, width_ = 1, height_ = 1, reach_ = 1;
  std::pair<double, double> width_interval_, xmin_interval_, ymin_interval_;
};

// Face f gets the vertices a, b, c at its corners, in this order, and their translations by the
// minimum-image convention (each edge from a taken as its shortest image). Outcome::ok, or
// Outcome::faces_do_not_close when the shortest image of bc does not close the face.
template <class Gt>
Outcome set_face_by_minimum_image(Torus_triangulation& tt, std::size_t f, std::uint32_t a, std::uint32_t b,
                                  std::uint32_t c, const Torus_geometry<Gt>& geometry)
{
  const Lattice_offset ob = geometry.minimum_image(a, b), oc = geometry.minimum_image(a, c);
  if(geometry.minimum_image(b, c) != oc - ob)
    return Outcome::faces_do_not_close;
  tt.vertex[3 * f] = a;
  tt.vertex[3 * f + 1] = b;
  tt.vertex[3 * f + 2] = c;
  tt.offset[3 * f] = Lattice_offset();
  tt.offset[3 * f + 1] = ob;
  tt.offset[3 * f + 2] = oc;
  tt.normalize_face(f);
  return Outcome::ok;
}

// Reverses the faces marked in `reverse` (corners 1 and 2 swapped), their half-edges' twins
// renumbered to match.
inline void reverse_faces(Torus_triangulation& tt, const std::vector<unsigned char>& reverse)
{
  auto renumbered = [&](std::size_t h) {
    const std::size_t i = h % 3;
    return reverse[h / 3] && i != 0 ? h - i + (3 - i) : h;
  };
  std::vector<std::uint32_t> twin(tt.twin.size());
  for(std::size_t h = 0; h < twin.size(); ++h)
    twin[renumbered(h)] = std::uint32_t(renumbered(tt.twin[h]));
  tt.twin.swap(twin);
  for(std::size_t f = 0; f < reverse.size(); ++f)
    if(reverse[f]) {
      std::swap(tt.vertex[3 * f + 1], tt.vertex[3 * f + 2]);
      std::swap(tt.offset[3 * f + 1], tt.offset[3 * f + 2]);
    }
}

// The faces given as index triples (validated: in range, three different indices), in any
// orientation, with translations by the minimum-image convention. Their half-edges are paired
// by undirected edge (Open_halfedges: the faces come sorted by smallest index from
// Spatial_order, so the open ones stay few and in cache); the faces are then oriented
// consistently, face by face across the edges from the first face of each component
// (counterclockwise), so that a face the prediction got inverted stays inverted (the
// untangling's). Outcome::ok when every half-edge has a twin and the faces fit together (they
// close up into an oriented surface without boundary); the orientation of the whole is
// orient_to_cover_once()'s. An edge of four faces is paired two by two: such a surface covers
// the torus more than once near that edge, which the covering test and the untangling refuse.
template <class Gt>
Outcome import_index_triples(const std::vector<std::uint32_t>& triples, const Torus_geometry<Gt>& geometry,
                             Torus_triangulation& tt)
{
  const std::size_t faces = triples.size() / 3;
  tt.resize(faces);
  for(std::size_t f = 0; f < faces; ++f) {
    const Outcome why = set_face_by_minimum_image(tt, f, triples[3 * f], triples[3 * f + 1], triples[3 * f + 2], geometry);
    if(why != Outcome::ok)
      return why;
  }
  auto from = [&](std::size_t h) { return tt.vertex[h - h % 3 + std::size_t(ccw(int(h % 3)))]; };
  auto to = [&](std::size_t h) { return tt.vertex[h - h % 3 + std::size_t(cw(int(h % 3)))]; };
  Open_halfedges open(geometry.size());
  for(std::size_t h = 0; h < 3 * faces; ++h) {
    const std::uint32_t a = from(h), b = to(h);
    std::uintptr_t twin = 0;
    if(open.take_or_open((std::min)(a, b), (std::max)(a, b), h, twin)) {
      tt.twin[h] = std::uint32_t(twin);
      tt.twin[twin] = std::uint32_t(h);
    }
  }
  if(open.size() != 0)
    return Outcome::holes_or_not_a_triangulation;
  // Orientation across each edge: the two faces must run along it in opposite directions.
  std::vector<unsigned char> reverse(faces, 0), seen(faces, 0);
  std::vector<std::uint32_t> stack;
  for(std::size_t seed = 0; seed < faces; ++seed) {
    if(seen[seed])
      continue;
    seen[seed] = 1;
    const std::size_t c = 3 * seed;
    reverse[seed] = geometry.orientation(tt.vertex[c], tt.offset[c], tt.vertex[c + 1], tt.offset[c + 1],
                                         tt.vertex[c + 2], tt.offset[c + 2]) == CLOCKWISE;
    stack.push_back(std::uint32_t(seed));
    while(!stack.empty()) {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t h = 3 * f; h < 3 * f + 3; ++h) {
        const std::size_t t = tt.twin[h], g = t / 3;
        const bool opposite = from(h) == to(t);
        const unsigned char wanted = (opposite ? 0 : 1) ^ reverse[f];
        if(!seen[g]) {
          seen[g] = 1;
          reverse[g] = wanted;
          stack.push_back(std::uint32_t(g));
        } else if(reverse[g] != wanted) {
          return Outcome::holes_or_not_a_triangulation; // not orientable
        }
      }
    }
  }
  reverse_faces(tt, reverse);
  for(std::size_t h = 0; h < 3 * faces; ++h)
    if(!tt.frames_agree(h))
      return Outcome::faces_do_not_close;
  return Outcome::ok;
}

// Outcome::ok when every one of the n points is a vertex of some face.
inline Outcome check_every_point_used(const Torus_triangulation& tt, std::size_t n)
{
  std::vector<unsigned char> used(n, 0);
  for(std::uint32_t v : tt.vertex)
    used[v] = 1;
  return std::find(used.begin(), used.end(), 0) == used.end() ? Outcome::ok : Outcome::point_without_face;
}

// Orients the faces, closed up into an oriented surface (import_index_triples(),
// set_offsets_by_minimum_image()), so that they cover the torus once counterclockwise, or tells
// that they do not. Their signed areas add up to d times the domain's, d the degree of the map
// from that surface onto the torus: a whole number, kept by every flip. d = -1 turns into 1 by
// reversing every face. With d = 1 and every face counterclockwise (the untangling's), the faces
// are a triangulation of the torus; d is told by interval arithmetic, which gives up (the faces
// are rebuilt) when it cannot tell.
template <class Gt>
Outcome orient_to_cover_once(Torus_triangulation& tt, const Torus_geometry<Gt>& geometry)
{
  Interval_nt<false> sum(0);
  {
    Protect_FPU_rounding<true> upward;
    for(std::size_t f = 0; f < tt.number_of_faces(); ++f) {
      const std::size_t c = 3 * f;
      sum += geometry.twice_area(tt.vertex[c], tt.offset[c], tt.vertex[c + 1], tt.offset[c + 1], tt.vertex[c + 2],
                                 tt.offset[c + 2]);
    }
  }
  // In units of the domain's area: the sum is close to 2d.
  const bool once = sum.inf() > 1 && sum.sup() < 3;
  const bool once_reversed = -sum.sup() > 1 && -sum.inf() < 3;
  if(once_reversed)
    reverse_faces(tt, std::vector<unsigned char>(tt.number_of_faces(), 1));
  return once || once_reversed ? Outcome::ok : Outcome::faces_do_not_tile_domain;
}

// Whether the edge of half-edge h is locally Delaunay: the vertex across it, translated into
// the frame of h's face, is not inside that face's circle (perturbed as CGAL does).
template <class Gt>
bool is_locally_delaunay(const Torus_triangulation& tt, std::size_t h, const Torus_geometry<Gt>& geometry)
{
  const std::size_t f = h - h % 3, t = tt.twin[h];
  return geometry.side_of_circle(tt.vertex[f], tt.offset[f], tt.vertex[f + 1], tt.offset[f + 1], tt.vertex[f + 2],
                                 tt.offset[f + 2], tt.vertex[t], tt.offset[t] + tt.translation_across(h)) !=
         ON_POSITIVE_SIDE;
}

// The in-circle test of every edge (once, from its lower half-edge): the half-edges of the
// failing ones, in increasing order whatever the threads. On TBB's threads when `parallel`.
template <class Gt>
std::vector<std::uint32_t> failing_edges(const Torus_triangulation& tt, const Torus_geometry<Gt>& geometry,
                                         bool parallel, std::size_t& edges_tested)
{
  constexpr std::size_t block = 1 << 14;
  const std::size_t half_edges = tt.twin.size();
  const std::size_t blocks = (half_edges + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> failing(blocks);
  std::vector<std::size_t> tested(blocks, 0);
  for_each_block(parallel, blocks, [&](std::size_t b) {
    for(std::size_t h = b * block, end = (std::min)(half_edges, h + block); h < end; ++h) {
      if(tt.twin[h] < h)
        continue;
      ++tested[b];
      if(!is_locally_delaunay(tt, h, geometry))
        failing[b].push_back(std::uint32_t(h));
    }
  });
  std::vector<std::uint32_t> all;
  for(std::size_t b = 0; b < blocks; ++b) {
    all.insert(all.end(), failing[b].begin(), failing[b].end());
    edges_tested += tested[b];
  }
  return all;
}

// Flips the edge of half-edge h (shared by the counterclockwise faces f = (a, b, c), h opposite
// a, and g = (d, c, b)) into the edge ad: f becomes (a, b, d) and g (d, c, a), every offset in
// f's frame, then each face translated back to offsets of least value 0. The four outer
// half-edges keep their twins. Returns false, changing nothing, when f and g are adjacent
// along another edge too (only on tori of very few points, which CGAL covers 9 times anyway).
inline bool flip(Torus_triangulation& tt, std::size_t h)
{
  const std::size_t t = tt.twin[h], f = h - h % 3, g = t - t % 3;
  const std::size_t i = h % 3, j = t % 3;
  const std::size_t ia = f + i, ib = f + std::size_t(ccw(int(i))), ic = f + std::size_t(cw(int(i)));
  const std::size_t jd = g + j, jc = g + std::size_t(ccw(int(j))), jb = g + std::size_t(cw(int(j)));
  const std::uint32_t twin_ca = tt.twin[ib], twin_ab = tt.twin[ic], twin_bd = tt.twin[jc], twin_dc = tt.twin[jb];
  for(std::uint32_t outer : {twin_ca, twin_ab, twin_bd, twin_dc})
    if(outer - outer % 3 == f || outer - outer % 3 == g)
      return false;
  const Lattice_offset shift = tt.translation_across(h);
  const std::uint32_t a = tt.vertex[ia], b = tt.vertex[ib], c = tt.vertex[ic], d = tt.vertex[jd];
  const Lattice_offset oa = tt.offset[ia], ob = tt.offset[ib], oc = tt.offset[ic], od = tt.offset[jd] + shift;
  // f = (a, b, d): corner 0 across bd, 1 across da (g's corner 1), 2 across ab.
  tt.vertex[f] = a, tt.vertex[f + 1] = b, tt.vertex[f + 2] = d;
  tt.offset[f] = oa, tt.offset[f + 1] = ob, tt.offset[f + 2] = od;
  // g = (d, c, a): corner 0 across ca, 1 across ad (f's corner 1), 2 across dc.
  tt.vertex[g] = d, tt.vertex[g + 1] = c, tt.vertex[g + 2] = a;
  tt.offset[g] = od, tt.offset[g + 1] = oc, tt.offset[g + 2] = oa;
  auto link = [&](std::size_t x, std::uint32_t y) {
    tt.twin[x] = y;
    tt.twin[y] = std::uint32_t(x);
  };
  link(f, twin_bd);
  link(f + 2, twin_ab);
  link(g, twin_ca);
  link(g + 2, twin_dc);
  link(f + 1, std::uint32_t(g + 1));
  tt.normalize_face(f / 3);
  tt.normalize_face(g / 3);
  tt.flipped[f / 3] = tt.flipped[g / 3] = 1;
  return true;
}

// Lawson's flips from the half-edges in `stack` (in-circle failures): each flip's four outer
// edges are tested again. Returns false when `max_flips` flips did not finish, or a flip was
// refused (flip()); the triangulation is then left as it was when that happened.
template <class Gt>
bool lawson_flips(Torus_triangulation& tt, std::vector<std::uint32_t> stack, const Torus_geometry<Gt>& geometry,
                  std::size_t max_flips, std::size_t& flips)
{
  while(!stack.empty()) {
    const std::size_t h = stack.back();
    stack.pop_back();
    if(is_locally_delaunay(tt, h, geometry))
      continue;
    if(flips >= max_flips || !flip(tt, h))
      return false;
    ++flips;
    const std::size_t f = h - h % 3, g = tt.twin[f + 1] - tt.twin[f + 1] % 3;
    for(std::size_t outer : {f, f + 2, g, g + 2})
      stack.push_back(std::uint32_t(outer));
  }
  return true;
}

// Whether the face of corner f0 (its first corner) is counterclockwise.
template <class Gt>
bool is_counterclockwise(const Torus_triangulation& tt, std::size_t f0, const Torus_geometry<Gt>& geometry)
{
  return geometry.orientation(tt.vertex[f0], tt.offset[f0], tt.vertex[f0 + 1], tt.offset[f0 + 1], tt.vertex[f0 + 2],
                              tt.offset[f0 + 2]) == COUNTERCLOCKWISE;
}

// Whether flipping the edge of half-edge h (as flip() does) gives two counterclockwise faces.
template <class Gt>
bool flip_makes_counterclockwise(const Torus_triangulation& tt, std::size_t h, const Torus_geometry<Gt>& geometry)
{
  const std::size_t t = tt.twin[h], f = h - h % 3;
  const std::size_t ia = h, ib = f + std::size_t(ccw(int(h % 3))), ic = f + std::size_t(cw(int(h % 3)));
  const Lattice_offset od = tt.offset[t] + tt.translation_across(h);
  return geometry.orientation(tt.vertex[ia], tt.offset[ia], tt.vertex[ib], tt.offset[ib], tt.vertex[t], od) ==
             COUNTERCLOCKWISE &&
         geometry.orientation(tt.vertex[t], od, tt.vertex[ic], tt.offset[ic], tt.vertex[ia], tt.offset[ia]) ==
             COUNTERCLOCKWISE;
}

// Finds, by a visibility walk from face f, the face that contains point v translated by `ov`
// (in f's frame): on return f is that face and ov is in its frame. Returns false when the walk
// takes more than `max_steps` steps, or when the point is not strictly inside a face (on an
// edge or at a vertex).
template <class Gt>
bool locate(const Torus_triangulation& tt, std::uint32_t v, std::size_t& f, Lattice_offset& ov,
            const Torus_geometry<Gt>& geometry, std::size_t max_steps)
{
  for(std::size_t step = 0; step < max_steps; ++step) {
    const std::size_t c = 3 * f;
    bool inside = true, on_an_edge_line = false;
    for(int k = 0; k < 3; ++k) {
      const int i = int((step + std::size_t(k)) % 3); // vary the first edge tried, so that the walk cannot cycle
      const std::size_t b = c + std::size_t(ccw(i)), e = c + std::size_t(cw(i));
      const Orientation o = geometry.orientation(tt.vertex[b], tt.offset[b], tt.vertex[e], tt.offset[e], v, ov);
      if(o == CLOCKWISE) { // beyond the edge opposite corner i
        const std::size_t h = c + std::size_t(i);
        ov = ov - tt.translation_across(h);
        f = tt.twin[h] / 3;
        inside = false;
        break;
      }
      on_an_edge_line = on_an_edge_line || o == COLLINEAR;
    }
    if(inside)
      return !on_an_edge_line;
  }
  return false;
}

// Takes the vertex v of corner `corner` out of the triangulation and puts it back where its
// point now is: its star is replaced by an ear-clipping triangulation of its link (every ear strictly
// counterclockwise with no other link vertex in it), then the face that contains v's point is
// found by a walk and split into three. The faces keep their number (the star's k faces make
// k - 2 ears and two more faces at the split). A vertex of two faces (a fold, which untangling
// flips can leave) has no ear: the outer sides of its link's two edges are glued. Every new face is counterclockwise, and the
// signed areas add up as before, so the faces still cover the torus once.
enum class Reinsertion { done, refused, failed }; // refused: nothing changed; failed: tt is left broken
template <class Gt>
Reinsertion reinsert_vertex(Torus_triangulation& tt, std::size_t corner, const Torus_geometry<Gt>& geometry)
{
  constexpr std::size_t max_link = 64;
  const std::uint32_t v = tt.vertex[corner];
  // The star around v, counterclockwise, each face's translation into the first face's frame.
  std::vector<std::uint32_t> star_corner, link_vertex, carried;
  std::vector<Lattice_offset> link_offset;
  Lattice_offset shift; // the frame of the current face in the first face's frame
  std::size_t c = corner;
  do {
    const std::size_t f = c - c % 3;
    const int i = int(c % 3);
    const std::size_t x = f + std::size_t(ccw(i));
    star_corner.push_back(std::uint32_t(c));
    link_vertex.push_back(tt.vertex[x]);
    link_offset.push_back(tt.offset[x] + shift);
    carried.push_back(tt.twin[c]); // the outer half-edge across the link edge x -> y
    const std::size_t across = f + std::size_t(ccw(i)); // the half-edge of the edge v-y, to the next face
    shift = shift + tt.translation_across(across);
    const std::size_t t = tt.twin[across];
    c = t - t % 3 + std::size_t(ccw(int(t % 3)));
    if(star_corner.size() > max_link)
      return Reinsertion::refused;
  } while(c != corner);
  const std::size_t k = star_corner.size();
  if(shift != Lattice_offset() || k < 2)
    return Reinsertion::refused;
  // The walk will start at the outer face across the first link edge, v's offset in its frame.
  std::size_t f = carried[0] / 3;
  Lattice_offset at = tt.offset[corner] - tt.translation_across(corner);
  for(std::size_t a = 0; a < k; ++a)
    for(std::size_t b = a + 1; b < k; ++b)
      if(link_vertex[a] == link_vertex[b])
        return Reinsertion::refused;
  for(std::uint32_t t : carried) // an outer face inside the star: v's link touches itself
    for(std::uint32_t s : star_corner)
      if(t / 3 == s / 3)
        return Reinsertion::refused;
  // Ear clipping (the package's one polygon triangulator), planned before anything changes.
  std::vector<std::array<std::size_t, 3>> ears; // none for k = 2: a fold of two faces, whose outer sides meet
  if(k > 2) {
    std::vector<typename Torus_geometry<Gt>::Translated_point> link(k);
    for(std::size_t a = 0; a < k; ++a)
      link[a] = geometry.translated(link_vertex[a], link_offset[a]);
    std::vector<std::size_t> prev, next;
    if(!clip_ears(geometry.translated_predicates(), k,
                  [&](std::size_t a) -> const typename Torus_geometry<Gt>::Translated_point& { return link[a]; }, ears,
                  prev, next))
      return Reinsertion::refused;
  }
  // Write the ears into the star's first k - 2 face slots; the half-edge on each link edge or
  // diagonal (local a -> b) is linked when its other side appears.
  std::vector<std::size_t> slot(k);
  for(std::size_t a = 0; a < k; ++a)
    slot[a] = star_corner[a] - star_corner[a] % 3;
  auto link = [&](std::size_t x, std::uint32_t y) {
    tt.twin[x] = y;
    tt.twin[y] = std::uint32_t(x);
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> open; // (a -> b, half-edge) awaiting a twin
  if(k == 2)
    link(carried[0], carried[1]);
  for(std::size_t a = 0; a < k && k > 2; ++a)
    open.push_back({std::uint64_t(a) << 32 | ((a + 1) % k), carried[a]}); // the outer side, b -> a as seen from outside
  for(std::size_t e = 0; e < ears.size(); ++e) {
    const std::size_t f = slot[e];
    for(int i = 0; i < 3; ++i) {
      tt.vertex[f + std::size_t(i)] = link_vertex[ears[e][std::size_t(i)]];
      tt.offset[f + std::size_t(i)] = link_offset[ears[e][std::size_t(i)]];
    }
    tt.flipped[f / 3] = 1;
    for(int i = 0; i < 3; ++i) { // the half-edge opposite corner i runs from corner ccw(i) to cw(i)
      const std::uint64_t from = ears[e][std::size_t(ccw(i))], to = ears[e][std::size_t(cw(i))];
      const auto waiting = std::find_if(open.begin(), open.end(),
                                        [&](const auto& o) { return o.first == (from << 32 | to); });
      if(waiting != open.end()) {
        link(f + std::size_t(i), waiting->second);
        open.erase(waiting);
      } else {
        open.push_back({to << 32 | from, std::uint32_t(f + std::size_t(i))});
      }
    }
  }
  CGAL_assertion(open.empty());
  // Put v back.
  const bool found = locate(tt, v, f, at, geometry, 4 * tt.number_of_faces() + 16);
  if(!found)
    return Reinsertion::failed; // v is out, two faces are stale: the caller gives up the faces
  const std::size_t s1 = slot[k - 2], s2 = slot[k - 1], g = 3 * f;
  const std::uint32_t x = tt.vertex[g], y = tt.vertex[g + 1], z = tt.vertex[g + 2];
  const Lattice_offset ox = tt.offset[g], oy = tt.offset[g + 1], oz = tt.offset[g + 2];
  const std::uint32_t tx = tt.twin[g], ty = tt.twin[g + 1], tz = tt.twin[g + 2];
  auto set = [&](std::size_t h, std::uint32_t a, Lattice_offset oa, std::uint32_t b, Lattice_offset ob) {
    tt.vertex[h] = a, tt.vertex[h + 1] = b, tt.vertex[h + 2] = v;
    tt.offset[h] = oa, tt.offset[h + 1] = ob, tt.offset[h + 2] = at;
    tt.flipped[h / 3] = 1;
  };
  set(g, x, ox, y, oy);   // (x, y, v)
  set(s1, y, oy, z, oz);  // (y, z, v)
  set(s2, z, oz, x, ox);  // (z, x, v)
  link(g + 2, tz);
  link(s1 + 2, tx);
  link(s2 + 2, ty);
  link(g, std::uint32_t(s1 + 1));
  link(s1, std::uint32_t(s2 + 1));
  link(s2, std::uint32_t(g + 1));
  for(std::size_t a = 0; a < k; ++a)
    tt.normalize_face(slot[a] / 3);
  return Reinsertion::done;
}

// Makes every face counterclockwise: by flips that each turn an inverted or flat face and its
// neighbour into two counterclockwise faces (a vertex moved across the opposite edge of one of
// its faces), in rounds while they make progress; then, for a face no flip repairs, by taking a
// vertex of it, or else a vertex across one of its edges, out and putting it back
// (reinsert_vertex()). Outcome::ok when none is left;
// otherwise Outcome::too_many_inverted_faces (more than `max_inverted`, counted first, or the
// flip budget spent) or Outcome::inverted_face (a face that neither repairs).
template <class Gt>
Outcome untangle(Torus_triangulation& tt, const Torus_geometry<Gt>& geometry, bool parallel, std::size_t max_inverted,
                 std::size_t max_flips, std::size_t& flips, std::size_t& inverted, std::size_t& reinserted)
{
  constexpr std::size_t block = 1 << 14;
  const std::size_t faces = tt.number_of_faces(), blocks = (faces + block - 1) / block;
  std::vector<std::vector<std::uint32_t>> found(blocks);
  for_each_block(parallel, blocks, [&](std::size_t b) {
    for(std::size_t f = b * block, end = (std::min)(faces, f + block); f < end; ++f)
      if(!is_counterclockwise(tt, 3 * f, geometry))
        found[b].push_back(std::uint32_t(f));
  });
  std::vector<std::uint32_t> bad;
  for(const auto& list : found)
    bad.insert(bad.end(), list.begin(), list.end());
  inverted = bad.size();
  if(bad.size() > max_inverted)
    return Outcome::too_many_inverted_faces;
  bool by_flips = true;
  const std::size_t max_reinserted = reinserted + inverted / 2 + 16; // 822 for 4580 inverted faces at 1e5 points moved by 0.1 spacing
  while(!bad.empty()) {
    std::vector<std::uint32_t> left;
    bool changed = false;
    for(const std::uint32_t f : bad) {
      if(is_counterclockwise(tt, 3 * std::size_t(f), geometry))
        continue;
      bool repaired = false;
      if(by_flips) {
        for(std::size_t h = 3 * std::size_t(f); h < 3 * std::size_t(f) + 3 && !repaired; ++h) {
          if(!flip_makes_counterclockwise(tt, h, geometry))
            continue;
          if(flips >= max_flips)
            return Outcome::too_many_inverted_faces;
          repaired = flip(tt, h);
          flips += repaired ? 1 : 0;
        }
        changed = changed || repaired;
      } else {
        // f's own vertices, then the vertices across its edges (whose stars may be what
        // tangles f's vertices' links).
        std::uint32_t corners[6];
        for(int i = 0; i < 3; ++i) {
          corners[i] = std::uint32_t(3 * f + std::uint32_t(i));
          corners[3 + i] = tt.twin[3 * std::size_t(f) + std::size_t(i)];
        }
        for(std::uint32_t c : corners) {
          const Reinsertion r = reinsert_vertex(tt, c, geometry);
          if(r == Reinsertion::failed)
            return Outcome::inverted_face;
          if(r == Reinsertion::done) {
            if(++reinserted > max_reinserted)
              return Outcome::inverted_face;
            repaired = changed = true;
            break;
          }
        }
      }
      // A reinsertion across an edge may leave f as it was: it stays on the list.
      if(!repaired || !is_counterclockwise(tt, 3 * std::size_t(f), geometry))
        left.push_back(f);
    }
    if(!changed) {
      if(!by_flips)
        return Outcome::inverted_face;
      by_flips = false; // no flip helps any more: reinsert vertices, one round
    } else {
      by_flips = true;
    }
    bad.swap(left);
  }
  return Outcome::ok;
}

// Whether CGAL's range insertion of the points surely ends in a 1-sheeted covering. It inserts
// dummy points first (a 1-sheeted covering), then the points, then removes the dummy points,
// each removal refused in that covering (and the covering made 9-sheeted for good) when the
// bounding box of the removed vertex's star has a diagonal whose square reaches 0.166 squared
// periods. Every triangulation it holds is of a superset of the points, whose edges are chords
// of circles empty of the points: at most delta long, delta the widest such circle (the widest
// circumcircle of the Delaunay faces). A star then fits in a box of side 2 delta, of diagonal
// 2 sqrt(2) delta; below sqrt(0.166) periods (delta below 0.144 periods), no removal is refused.
// Decided in interval arithmetic, with a margin for CGAL's rounding; false when it cannot tell,
// and then CGAL builds.
template <class Gt>
bool surely_one_sheeted(const Torus_triangulation& tt, const Torus_geometry<Gt>& geometry)
{
  Protect_FPU_rounding<true> upward;
  const double limit = std::sqrt(0.166 / 8) * (1 - 1e-6) - 16 * geometry.relative_rounding(); // in periods
  if(!(limit > 0))
    return false;
  const double limit_squared = limit * limit;
  for(std::size_t f = 0; f < tt.number_of_faces(); ++f) {
    const std::size_t c = 3 * f;
    const Interval_nt<false> d2 = geometry.squared_circumdiameter(tt.vertex[c], tt.offset[c], tt.vertex[c + 1],
                                                                  tt.offset[c + 1], tt.vertex[c + 2], tt.offset[c + 2]);
    if(!(d2.sup() < limit_squared))
      return false;
  }
  // The diameter bounds every edge's length: below the threshold, each face's offsets span at
  // most one period per coordinate, as CGAL's face base stores them.
  return true;
}

// Reads the faces of a 1-sheeted CGAL periodic triangulation `t` of dimension 2 into `tt`, in
// the order of its face container and in their orientation: each vertex numbered by
// `index_of(vertex handle)`, the offsets CGAL stored, the neighbours from the data structure.
template <class P2T2, class IndexOf>
void read_periodic_triangulation(const P2T2& t, const IndexOf& index_of, Torus_triangulation& tt)
{
  const auto& tds = t.tds();
  const Dense_index<typename P2T2::Triangulation_data_structure::Face_range> face_index(tds.faces());
  tt.resize(face_index.size());
  std::size_t f = 0;
  for(auto fh = tds.faces().begin(); fh != tds.faces().end(); ++fh, ++f)
    for(int i = 0; i < 3; ++i) {
      const std::size_t c = 3 * f + std::size_t(i);
      tt.vertex[c] = std::uint32_t(index_of(fh->vertex(i)));
      tt.offset[c] = Lattice_offset{(fh->offset(i) >> 1) & 1, fh->offset(i) & 1}; // CGAL's encoding: 2x + y
      // No two faces of a 1-sheeted covering share two edges: the neighbour holds fh once.
      tt.twin[c] = std::uint32_t(3 * face_index.of(fh->neighbor(i)) + std::size_t(fh->neighbor(i)->index(fh)));
    }
}

// Recomputes every face's offsets by the minimum-image convention, keeping its vertices in
// their order (the points may have moved, some across a side, since the offsets were set; an
// inverted face stays inverted, for the untangling). Outcome::ok, or why the faces are not a
// triangulation of the torus at the points as they are.
template <class Gt>
Outcome set_offsets_by_minimum_image(Torus_triangulation& tt, const Torus_geometry<Gt>& geometry)
{
  for(std::size_t f = 0; f < tt.number_of_faces(); ++f) {
    const Outcome why =
        set_face_by_minimum_image(tt, f, tt.vertex[3 * f], tt.vertex[3 * f + 1], tt.vertex[3 * f + 2], geometry);
    if(why != Outcome::ok)
      return why;
  }
  for(std::size_t h = 0; h < tt.twin.size(); ++h)
    if(!tt.frames_agree(h))
      return Outcome::faces_do_not_close;
  return Outcome::ok;
}

// Clears every vertex's offset, as CGAL leaves it after each of its own operations. CGAL's
// default vertex constructor leaves the offset flag indeterminate (and its insert_first()
// creates vertices with it), so that copying the triangulation would read an indeterminate
// bool; every periodic triangulation the package hands back goes through this.
template <class P2T2>
void clear_vertex_offsets(P2T2& t)
{
  for(auto v = t.tds().vertices().begin(); v != t.tds().vertices().end(); ++v)
    v->clear_offset();
}

// Replaces the faces of the periodic triangulation `t` by those of `tt` (a Delaunay
// triangulation of the torus that surely_one_sheeted() accepted), on the vertex objects
// `vertices` (indexed as tt's vertices), as a 1-sheeted covering: the vertex objects, their
// points and info() are kept, the face objects are new.
template <class P2T2>
void write_periodic_triangulation(const Torus_triangulation& tt, const std::vector<typename P2T2::Vertex_handle>& vertices,
                                  P2T2& t)
{
  auto& tds = t.tds();
  tds.faces().clear();
  const std::size_t faces = tt.number_of_faces();
  std::vector<typename P2T2::Face_handle> face(faces);
  for(std::size_t f = 0; f < faces; ++f) {
    const std::size_t c = 3 * f;
    face[f] = tds.create_face(vertices[tt.vertex[c]], vertices[tt.vertex[c + 1]], vertices[tt.vertex[c + 2]]);
    auto bits = [&](std::size_t k) {
      CGAL_assertion(tt.offset[k].x >= 0 && tt.offset[k].x <= 1 && tt.offset[k].y >= 0 && tt.offset[k].y <= 1);
      return int(((tt.offset[k].x & 1) << 1) | (tt.offset[k].y & 1)); // CGAL's encoding of a face offset
    };
    face[f]->set_offsets(bits(c), bits(c + 1), bits(c + 2));
  }
  for(std::size_t f = 0; f < faces; ++f)
    for(int i = 0; i < 3; ++i) {
      face[f]->set_neighbor(i, face[tt.twin[3 * f + std::size_t(i)] / 3]);
      vertices[tt.vertex[3 * f + std::size_t(i)]]->set_face(face[f]);
    }
  tds.set_dimension(2);
  clear_vertex_offsets(t);
}

// Whether every face's offsets span at most one period per coordinate (CGAL's face base holds
// offsets 0 and 1 only).
inline bool offsets_fit_face_base(const Torus_triangulation& tt)
{
  for(const Lattice_offset& o : tt.offset)
    if(o.x < 0 || o.x > 1 || o.y < 0 || o.y > 1)
      return false;
  return true;
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_PERIODIC_TORUS_TRIANGULATION_H
