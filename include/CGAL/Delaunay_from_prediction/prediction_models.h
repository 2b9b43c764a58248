// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Generators of predictions for experiments and tests, all seeded and reproducible: the rho
// model of Section 1.3 of "Delaunay Triangulations with Predictions", the random-flip model of
// its Lemma 6.5, order-k Delaunay triangulations (its Section 7), k random flips, Delaunay
// triangulations of moved points, the sorting and list-merging configurations of its Figures 1
// and 2, and non-triangulations (holes, self-crossing labelings, random triples).
//
// Every generator that changes a triangulation does it by edge flips on a CGAL triangulation
// data structure built from DT(P); a flip is made only when the two faces form a strictly
// convex quadrilateral (orientation tests with the kernel's predicates), so the result is a
// proper triangulation of the points for a kernel with exact predicates.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_PREDICTION_MODELS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_PREDICTION_MODELS_H

#include <CGAL/Delaunay_from_prediction/measures.h>
#include <CGAL/Delaunay_from_prediction/internal/repair/flips.h>
#include <CGAL/Delaunay_from_prediction/internal/measures/prediction_generators.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>
#include <CGAL/Delaunay_from_prediction/internal/build/rebuild.h>
#include <CGAL/Delaunay_from_prediction/internal/import/spatial_order.h>

#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/// \ingroup PkgDelaunayFromPredictionRef
/// A triangle given by three point indices, the format every generator returns.
using Indexed_triangle = std::array<std::size_t, 3>;

/*!
\ingroup PkgDelaunayFromPredictionRef
A generated point set together with a prediction of its Delaunay triangulation.
\tparam Point the point type.
*/
template <class Point>
struct Prediction_instance
{
  /// the points.
  std::vector<Point> points;
  /// the prediction, counterclockwise triangles of indices into `points`.
  std::vector<Indexed_triangle> faces;
};

/// \ingroup PkgDelaunayFromPredictionRef
/// How `rho_model_prediction()` completes the kept Delaunay edges to a triangulation.
enum class Completion {
  /// flips every other edge that is locally Delaunay, while it can: a triangulation that is
  /// locally as far from Delaunay as the kept edges allow (long, thin triangles).
  adversarial,
  /// a random walk of flips of the other edges, eight attempts per edge.
  random
};

/*!
\ingroup PkgDelaunayFromPredictionRef
returns the Delaunay triangulation of `points` as index triples (counterclockwise), exactly the
triangulation `CGAL::Delaunay_triangulation_2` builds. Points at the same position appear
under their smallest index. Fewer than three non-collinear points give no face.
\tparam PointRange a random-access range of points of a CGAL kernel.
\param points the points.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> delaunay_triangles(const PointRange& points)
{
  return internal::faces_of(internal::indexed_delaunay(points));
}

/*!
\ingroup PkgDelaunayFromPredictionRef
the random-flip model of Lemma 6.5 of the paper: starting from \f$DT(P)\f$ with \f$m\f$ edges,
\f$\lfloor (1-\rho) m \rfloor\f$ times, draw an edge uniformly at random and flip it if its two
faces form a strictly convex quadrilateral. The flip distance to \f$DT(P)\f$ is at most
\f$(1-\rho) m\f$, and \f$d_{cross} = O((1/\rho)\log n)\f$ with high probability.
\param points the points.
\param rho in \f$[0, 1]\f$; 1 gives \f$DT(P)\f$.
\param seed the seed; the same seed gives the same triangulation.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> random_flip_prediction(const PointRange& points, double rho,
                                                     std::uint64_t seed)
{
  internal::check_probability(rho, "rho");
  auto dt = internal::indexed_delaunay(points);
  const internal::Random_edges<decltype(dt)> edges(dt);
  internal::Splitmix64 random{seed};
  const std::size_t attempts = std::size_t((1.0 - rho) * double(edges.number_of_edges()));
  typename decltype(dt)::Face_handle f;
  int i;
  for(std::size_t k = 0; k < attempts; ++k)
    if(edges.draw(random, f, i))
      internal::flip_if_convex(dt, f, i);
  return internal::faces_of(dt);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
\f$DT(P)\f$ after exactly `k` flips of uniformly drawn edges whose faces form a strictly convex
quadrilateral (draws that cannot be flipped do not count), so \f$D \le D_{flip} \le k\f$. Stops
early only if \f$64(k + m)\f$ draws find too few flippable edges (fewer than four points in
convex position).
\param points the points.
\param k the number of flips.
\param seed the seed.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> k_flip_prediction(const PointRange& points, std::size_t k,
                                                std::uint64_t seed)
{
  auto dt = internal::indexed_delaunay(points);
  const internal::Random_edges<decltype(dt)> edges(dt);
  internal::Splitmix64 random{seed};
  typename decltype(dt)::Face_handle f;
  int i;
  std::size_t flips = 0;
  for(std::size_t draws = 64 * (k + edges.number_of_edges()); flips < k && draws > 0; --draws)
    if(edges.draw(random, f, i) && internal::flip_if_convex(dt, f, i))
      ++flips;
  return internal::faces_of(dt);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
an order-\f$k\f$ Delaunay triangulation (the setting of Section 7 of the paper: a triangulation
with \f$d_{vio} \le k\f$): starting from \f$DT(P)\f$ with \f$m\f$ edges, `draws` times (default
\f$m\f$), draw an edge uniformly at random and flip it if its two faces form a strictly convex
quadrilateral and each of the two faces the flip makes has at most `k` points of \f$P\f$
strictly inside its (perturbed) circumcircle. Every face of the result is a face of
\f$DT(P)\f$ or was made by such a flip, so \f$d_{vio} \le k\f$, as `prediction_measures()`
counts it; `k` = 0 gives \f$DT(P)\f$ (a flip puts a point inside one of its faces' circles),
and a `k` of \f$n\f$ or more gives the random-flip model with \f$(1 - \rho) m\f$ = `draws`.
Each test counts the points inside a circle by a search in \f$DT(P)\f$ that stops past `k`:
\f$O(k)\f$ work a draw, apart from high-degree vertices.
\param points the points.
\param k the largest number of points inside a face's circumcircle.
\param seed the seed; the same seed gives the same triangulation.
\param draws the number of edges drawn; (std::numeric_limits<std::size_t>::max)() means \f$m\f$.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> order_k_prediction(const PointRange& points, std::size_t k,
                                                 std::uint64_t seed,
                                                 std::size_t draws = (std::numeric_limits<std::size_t>::max)())
{
  const auto delaunay = internal::indexed_delaunay(points);
  using DT = std::remove_const_t<decltype(delaunay)>;
  using Vertex_handle = typename DT::Vertex_handle;
  DT dt = delaunay; // flipped; `delaunay` answers the circle counts
  std::vector<Vertex_handle> vertex_of(std::size_t(std::distance(std::begin(points), std::end(points))));
  for(auto v = delaunay.finite_vertices_begin(); v != delaunay.finite_vertices_end(); ++v)
    vertex_of[v->info()] = v;
  const internal::Random_edges<DT> edges(dt);
  internal::Splitmix64 random{seed};
  if(draws == (std::numeric_limits<std::size_t>::max)())
    draws = edges.number_of_edges();
  std::vector<std::uint32_t> mark(vertex_of.size(), 0);
  std::uint32_t stamp = 0;
  std::vector<Vertex_handle> queue;
  // Points of P strictly inside the circle of the ccw triangle (a, b, c), at most k + 1.
  const auto inside = [&](Vertex_handle a, Vertex_handle b, Vertex_handle c) {
    if(++stamp == 0) { // wrapped around: clear the marks
      std::fill(mark.begin(), mark.end(), 0);
      stamp = 1;
    }
    return internal::count_points_in_circle(delaunay, vertex_of[a->info()], vertex_of[b->info()],
                                            vertex_of[c->info()], mark, stamp, queue, k);
  };
  typename DT::Face_handle f;
  int i;
  for(std::size_t draw = 0; draw < draws; ++draw) {
    if(!edges.draw(random, f, i) || dt.is_infinite(f->neighbor(i)))
      continue;
    // The flip of the edge b c of the ccw face (a, b, c), d across it, makes (a, b, d) and (a, d, c).
    const Vertex_handle a = f->vertex(i), b = f->vertex(DT::ccw(i)), c = f->vertex(DT::cw(i)),
                        d = f->neighbor(i)->vertex(dt.tds().mirror_index(f, i));
    if(!internal::flip_makes_ccw_faces(dt.geom_traits(), a->point(), b->point(), c->point(), d->point()))
      continue;
    if(inside(a, b, d) <= k && inside(a, d, c) <= k)
      dt.tds().flip(f, i);
  }
  return internal::faces_of(dt);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
the \f$\rho\f$ model of Section 1.3 of the paper: every edge of \f$DT(P)\f$ is kept
independently with probability \f$\rho\f$ (the set \f$R\f$), and \f$R\f$ is completed to a
triangulation of \f$P\f$ by flips of the other edges only, so the result contains every kept
edge.

With `Completion::adversarial` every edge not in \f$R\f$ that is locally Delaunay and flippable is
flipped, repeatedly (each such flip raises the lifted surface, so this ends; with an inexact
kernel it stops after \f$64m\f$ flips): a completion with no locally Delaunay flippable edge
outside \f$R\f$, which makes edges as long as \f$R\f$ lets them be. Its cost is the number of
flips, which grows like \f$n \cdot d_{cross}\f$ and so like \f$(n/\rho)\log n\f$.
With `Completion::random`, \f$8m\f$ random flip attempts on edges outside \f$R\f$.

\param points the points.
\param rho the probability of keeping an edge, in \f$[0, 1]\f$.
\param seed the seed.
\param completion how to complete \f$R\f$.
\param kept_edges if not null, receives \f$R\f$, as pairs of indices (smaller first).
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle>
rho_model_prediction(const PointRange& points, double rho, std::uint64_t seed,
                     Completion completion = Completion::adversarial,
                     std::vector<std::pair<std::size_t, std::size_t>>* kept_edges = nullptr)
{
  internal::check_probability(rho, "rho");
  auto dt = internal::indexed_delaunay(points);
  using DT = decltype(dt);
  using Face_handle = typename DT::Face_handle;
  internal::Splitmix64 random{seed};
  // One draw per edge in the order of the edges' index pairs: CGAL's edge iterator visits
  // an edge from whichever of its faces has the smaller address, which varies between runs.
  std::vector<std::uint64_t> kept;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    kept.push_back(internal::edge_key_of<DT>(e->first, e->second));
  std::sort(kept.begin(), kept.end());
  std::size_t kept_count = 0;
  for(const std::uint64_t key : kept)
    if(random.uniform() < rho)
      kept[kept_count++] = key;
  kept.resize(kept_count);
  if(kept_edges != nullptr) {
    kept_edges->clear();
    for(const std::uint64_t key : kept)
      kept_edges->emplace_back(std::size_t(key >> 32), std::size_t(key & 0xffffffffu));
  }
  auto is_kept = [&](Face_handle f, int i) {
    return std::binary_search(kept.begin(), kept.end(), internal::edge_key_of<DT>(f, i));
  };
  const internal::Random_edges<DT> edges(dt);
  if(completion == Completion::random) {
    Face_handle f;
    int i;
    for(std::size_t k = 8 * edges.number_of_edges(); k > 0; --k)
      if(edges.draw(random, f, i) && !is_kept(f, i))
        internal::flip_if_convex(dt, f, i);
  } else {
    // The flip loop of flips.h, flipping the other way: locally Delaunay edges not in R.
    const auto& gt = dt.geom_traits();
    std::vector<std::pair<Face_handle, int>> stack;
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      for(int i = 0; i < 3; ++i)
        stack.emplace_back(f, i);
    auto locally_delaunay_and_free = [&](Face_handle f, int i, const auto& a, const auto& b,
                                         const auto& c, const auto& d) {
      return !is_kept(f, i) && internal::is_locally_delaunay(gt, a, b, c, d);
    };
    std::size_t flips = 0;
    internal::flip_edges_while(dt, stack, locally_delaunay_and_free, 64 * edges.number_of_edges(),
                               flips, static_cast<std::vector<Face_handle>*>(nullptr));
  }
  return internal::faces_of(dt);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
the Delaunay triangulation of the points moved by independent Gaussian noise, as a prediction
for the points where they are: the situation of a simulation's previous frame. The noise has
standard deviation `noise` times the mean spacing \f$\sqrt{A/n}\f$ (\f$A\f$ the area of the
bounding box), so `noise` = 0.1 moves points by a tenth of their typical distance. Faces may be
inverted with respect to `points` (then it is not a triangulation of them).
\param points the points.
\param noise the standard deviation in units of the mean spacing; 0 gives \f$DT(P)\f$.
\param seed the seed.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> moved_points_prediction(const PointRange& points, double noise,
                                                      std::uint64_t seed)
{
  using Point = typename std::iterator_traits<decltype(std::begin(points))>::value_type;
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  internal::check_points_are_finite(std::begin(points), n);
  if(n == 0)
    return {};
  double x0 = CGAL::to_double(std::begin(points)[0].x()), x1 = x0;
  double y0 = CGAL::to_double(std::begin(points)[0].y()), y1 = y0;
  for(const auto& p : points) {
    x0 = (std::min)(x0, CGAL::to_double(p.x()));
    x1 = (std::max)(x1, CGAL::to_double(p.x()));
    y0 = (std::min)(y0, CGAL::to_double(p.y()));
    y1 = (std::max)(y1, CGAL::to_double(p.y()));
  }
  // The spacing in coordinates scaled by unit_scale() (the box's area and sides would
  // overflow or underflow at 1e+-200); a noise that takes a point beyond the largest double
  // leaves it there.
  const double scale = internal::unit_scale(x0, x1, y0, y1);
  const double width = x1 * scale - x0 * scale, height = y1 * scale - y0 * scale;
  const double area = width * height;
  const double spacing = area > 0 ? std::sqrt(area / double(n)) : std::hypot(width, height) / double(n);
  const double sigma = noise * spacing; // scaled
  const double huge = (std::numeric_limits<double>::max)();
  internal::Splitmix64 random{seed};
  std::vector<Point> moved;
  moved.reserve(n);
  for(const auto& p : points) {
    const double dx = sigma * random.normal() / scale, dy = sigma * random.normal() / scale;
    moved.emplace_back(std::clamp(CGAL::to_double(p.x()) + dx, -huge, huge),
                       std::clamp(CGAL::to_double(p.y()) + dy, -huge, huge));
  }
  return delaunay_triangles(moved);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
the list-merging configuration of Figure 2 of the paper: \f$k\f$ lists of \f$m\f$ random
x-sorted numbers in \f$(0, 1)\f$ and a triangulation built from each list on its own, whose
Delaunay triangulation merges the lists.

Construction (the figure itself is not in the paper's text, so this is ours with the same
properties). List \f$j\f$ lies on the row \f$y = j\f$, after a left end point \f$L_j\f$; an apex
\f$A_j\f$ far right between rows \f$j\f$ and \f$j+1\f$ sees both rows. The prediction is
the fan from \f$A_j\f$ to row \f$j\f$ and the fan from \f$A_j\f$ to row \f$j+1\f$, the triangle
\f$L_j A_j L_{j+1}\f$, and the triangles \f$A_j A_{j+1}\f$ with the right end of row \f$j+1\f$.
The \f$L_j\f$ and \f$A_j\f$ lie on convex arcs, so the faces cover the convex hull. Then all
\f$y\f$ are scaled by a power of two \f$\varepsilon < 1/(nk)\f$ (exactly). In the limit the
in-circle test becomes the lifting \f$(x, y) \mapsto (x, y, x^2)\f$, under which points
consecutive in x are always Delaunay neighbours (so \f$DT(P)\f$ merges the lists and
\f$D = \Theta(n)\f$), while every row edge and fan edge is locally Delaunay because each apex
is far to the right: \f$D_{local} = O(k)\f$.

\tparam K a CGAL kernel.
\param k the number of lists, at least 2.
\param m the length of each list, at least 1.
\param seed the seed.
\returns \f$k(m + 1) + k - 1\f$ points: row by row, \f$L_j\f$ then the list; then the apexes.
*/
template <class K>
Prediction_instance<typename K::Point_2> merging_lists_configuration(std::size_t k, std::size_t m,
                                                                     std::uint64_t seed)
{
  if(k < 2 || m < 1)
    throw std::invalid_argument("Delaunay_from_prediction: merging_lists_configuration needs k >= 2 and m >= 1");
  Prediction_instance<typename K::Point_2> out;
  internal::Splitmix64 random{seed};
  const double rows = double(k - 1);
  // Arcs bulging outwards (concave in y); the small slope breaks the symmetry, so that no two
  // of these points share an x.
  auto bulge = [&](double y) { return 4.0 * y * (rows - y) / (rows * rows); };
  const std::size_t n = k * (m + 1) + k - 1;
  double epsilon = 1.0;
  while(epsilon * double(n) * double(k) > 1.0 / 256)
    epsilon *= 0.5;
  std::vector<double> list(m);
  std::vector<std::size_t> row_start(k);
  for(std::size_t j = 0; j < k; ++j) {
    row_start[j] = out.points.size();
    const double y = double(j);
    out.points.emplace_back(-0.5 - 0.5 * bulge(y) - 1e-3 * y / rows, y * epsilon);
    for(double& x : list)
      x = 1e-3 + 0.998 * random.uniform();
    std::sort(list.begin(), list.end());
    for(double x : list)
      out.points.emplace_back(x, y * epsilon);
  }
  const std::size_t apex_start = out.points.size();
  for(std::size_t j = 0; j + 1 < k; ++j) {
    const double y = double(j) + 0.5;
    out.points.emplace_back(1.5 + 0.5 * bulge(y) + 1e-3 * y / rows, y * epsilon);
  }
  auto row_point = [&](std::size_t j, std::size_t t) { return row_start[j] + t; }; // t = 0..m
  for(std::size_t j = 0; j + 1 < k; ++j) {
    const std::size_t apex = apex_start + j;
    for(std::size_t t = 0; t < m; ++t) {
      out.faces.push_back({row_point(j, t), row_point(j, t + 1), apex});         // fan above row j
      out.faces.push_back({row_point(j + 1, t + 1), row_point(j + 1, t), apex}); // fan below row j+1
    }
    out.faces.push_back({row_point(j, 0), apex, row_point(j + 1, 0)});
    if(j + 2 < k)
      out.faces.push_back({row_point(j + 1, m), apex, apex + 1});
  }
  return out;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
the sorting configuration of Figure 1 of the paper: `merging_lists_configuration()` with
\f$n\f$ lists of one number each. The prediction depends only on the order in which the
numbers are given; \f$DT(P)\f$ sorts them, so \f$D = \Theta(n)\f$.
\tparam K a CGAL kernel.
\param n the number of numbers to sort, at least 2.
\param seed the seed.
\returns the points and the faces of the configuration.
*/
template <class K>
Prediction_instance<typename K::Point_2> sorting_configuration(std::size_t n, std::uint64_t seed)
{
  return merging_lists_configuration<K>(n, 1, seed);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
`faces` with each face deleted independently with probability `fraction`: a prediction with
holes (not a triangulation once a face is gone).
\param faces the faces.
\param fraction the probability of deleting a face, in \f$[0, 1]\f$.
\param seed the seed.
\returns the faces, each three point indices.
*/
inline std::vector<Indexed_triangle> delete_faces(const std::vector<Indexed_triangle>& faces,
                                                  double fraction, std::uint64_t seed)
{
  internal::check_probability(fraction, "fraction");
  internal::Splitmix64 random{seed};
  std::vector<Indexed_triangle> kept;
  for(const Indexed_triangle& t : faces)
    if(!(random.uniform() < fraction))
      kept.push_back(t);
  return kept;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
a combinatorial triangulation drawn with crossings: \f$DT(P)\f$ with the labels of `swaps` pairs
of points exchanged, each pair a random point and a random point two edges away from it. The
faces still form a triangulated disk combinatorially, but edges at the swapped points cross
and faces are inverted. Needs fewer than \f$2^{32}\f$ points.
\param points the points.
\param swaps the number of label exchanges.
\param seed the seed.
\returns the faces, each three point indices.
*/
template <class PointRange>
std::vector<Indexed_triangle> self_crossing_prediction(const PointRange& points, std::size_t swaps,
                                                       std::uint64_t seed)
{
  auto dt = internal::indexed_delaunay(points);
  std::vector<Indexed_triangle> faces = internal::faces_of(dt);
  if(faces.empty())
    return faces;
  using Vertex_handle = typename decltype(dt)::Vertex_handle;
  std::vector<Vertex_handle> vertices;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    vertices.push_back(v);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  std::vector<std::size_t> label(n);
  for(std::size_t i = 0; i < n; ++i)
    label[i] = i;
  internal::Splitmix64 random{seed};
  auto random_neighbour = [&](Vertex_handle v) {
    std::vector<Vertex_handle> around;
    auto vc = dt.incident_vertices(v), done = vc;
    do
      if(!dt.is_infinite(vc))
        around.push_back(vc);
    while(++vc != done);
    return around[random.below(around.size())];
  };
  for(std::size_t s = 0; s < swaps; ++s) {
    const Vertex_handle a = vertices[random.below(vertices.size())];
    const Vertex_handle b = random_neighbour(random_neighbour(a));
    if(a != b)
      std::swap(label[a->info()], label[b->info()]);
  }
  for(Indexed_triangle& t : faces)
    for(std::size_t& i : t)
      i = label[i];
  return faces;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
`count` triples of distinct indices in \f$[0, n)\f$ drawn uniformly: a prediction with no
information at all (needs \f$n \ge 3\f$).
\param n the number of points.
\param count the number of triples.
\param seed the seed.
\returns the faces, each three point indices.
*/
inline std::vector<Indexed_triangle> random_triples(std::size_t n, std::size_t count, std::uint64_t seed)
{
  if(n < 3)
    throw std::invalid_argument("Delaunay_from_prediction: random_triples needs n >= 3");
  internal::Splitmix64 random{seed};
  std::vector<Indexed_triangle> faces(count);
  for(Indexed_triangle& t : faces) {
    t[0] = random.below(n);
    do t[1] = random.below(n); while(t[1] == t[0]);
    do t[2] = random.below(n); while(t[2] == t[0] || t[2] == t[1]);
  }
  return faces;
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_PREDICTION_MODELS_H
