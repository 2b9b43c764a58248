// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Stage 1 of the pipeline (check): structural validation of the caller's input. Everything
// here runs before any caller data is touched, and throws Invalid_prediction naming the
// offending point, face or index.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_INPUT_CHECK_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_INPUT_CHECK_H

#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/code_size.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/concurrency.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/predicates.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace internal {

// Whether a coordinate is finite, read from its interval so that no exact value is computed:
// an Epeck number made from a NaN or an infinity raises SIGFPE in GMP when its exact value is
// asked for (CGAL::is_finite() and CGAL::to_double() may ask), while its interval is the
// double itself. The interval of a finite number is never NaN, and is one infinity only
// when the number is that infinity ([DBL_MAX, inf] for a finite number past the doubles).
template <class FT>
bool is_finite_coordinate(const FT& x)
{
  const std::pair<double, double> i = CGAL::to_interval(x);
  if(i.first != i.first || i.second != i.second) // NaN
    return false;
  return !(i.first == i.second && (i.first == std::numeric_limits<double>::infinity() ||
                                   i.first == -std::numeric_limits<double>::infinity()));
}

template <class Point>
bool is_finite_point(const Point& p)
{
  return is_finite_coordinate(p.x()) && is_finite_coordinate(p.y());
}

template <class Point>
void write_coordinates(std::ostream& out, const Point& p)
{
  out << "(" << CGAL::to_interval(p.x()).first << ", " << CGAL::to_interval(p.y()).first << ")";
}

// The messages of the exceptions below, built out of line: one copy in a program, whatever
// the types of the points and indices (code_size.h).
[[noreturn]] CGAL_DFP_RARELY_RUN inline void throw_non_finite(const char* what, std::size_t k, const char* order,
                                                             double x, double y)
{
  std::ostringstream msg;
  msg << "Delaunay_from_prediction: " << what << " " << k << order << " has a non-finite coordinate (" << x << ", "
      << y << ")";
  throw Invalid_prediction(msg.str());
}
[[noreturn]] CGAL_DFP_RARELY_RUN inline void throw_index_out_of_range(const char* item, std::size_t k,
                                                                     const std::string& raw, const char* slot,
                                                                     int j, std::size_t n)
{
  std::ostringstream msg;
  msg << "Delaunay_from_prediction: " << item << " " << k << " has index " << raw << " (" << slot << " " << j
      << "), outside the point range [0, " << n << ")";
  throw Invalid_prediction(msg.str());
}
[[noreturn]] CGAL_DFP_RARELY_RUN inline void throw_repeated_index(std::size_t k, const std::size_t v[3], int j)
{
  std::ostringstream msg;
  msg << "Delaunay_from_prediction: face " << k << " repeats index " << v[j] << " (" << v[0] << ", " << v[1] << ", "
      << v[2] << ")";
  throw Invalid_prediction(msg.str());
}

// Throws if a coordinate of any point is not finite (NaN or infinite).
template <class PointIterator>
void check_points_are_finite(PointIterator points, std::size_t n)
{
  for(std::size_t i = 0; i < n; ++i) {
    const auto& p = points[i];
    if(!is_finite_point(p))
      throw_non_finite("point", i, "", CGAL::to_interval(p.x()).first, CGAL::to_interval(p.y()).first);
  }
}

// Throws if a coordinate of a vertex of `tr` is not finite, naming the vertex by its rank in
// finite-vertex order (as the duplicate check names vertices). O(n), before `tr` is touched:
// every predicate on such a point is meaningless, and Epeck's would raise SIGFPE.
template <class Triangulation>
void check_vertices_are_finite(const Triangulation& tr)
{
  std::size_t rank = 0;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v, ++rank) {
    const auto& p = v->point();
    if(!is_finite_point(p))
      throw_non_finite("vertex", rank, " (in finite-vertex order)", CGAL::to_interval(p.x()).first,
                       CGAL::to_interval(p.y()).first);
  }
}

// An index into n points read from item `k` (a face or an edge), at `slot` `j` of it:
// throws naming them if it is not in [0, n) (a negative signed index included).
template <class Raw>
std::size_t checked_index(const Raw raw, std::size_t n, const char* item, std::size_t k, const char* slot, int j)
{
  static_assert(std::is_integral<Raw>::value, "Delaunay_from_prediction: indices must be integers");
  bool out_of_range = false;
  if constexpr(std::is_signed<Raw>::value)
    out_of_range = raw < 0 || static_cast<unsigned long long>(raw) >= n;
  else
    out_of_range = static_cast<unsigned long long>(raw) >= n;
  if(out_of_range)
    throw_index_out_of_range(item, k, std::to_string(+raw), slot, j, n);
  return static_cast<std::size_t>(raw);
}

// Reads the three indices of face number `k` and validates them: each in [0, n), all three
// different. Works for any face type with operator[](0..2) returning an integer.
template <class Face>
void read_face(const Face& face, std::size_t k, std::size_t n, std::size_t out[3])
{
  for(int j = 0; j < 3; ++j)
    out[j] = checked_index(face[j], n, "face", k, "position", j);
  for(int j = 0; j < 3; ++j)
    if(out[j] == out[ccw(j)])
      throw_repeated_index(k, out, j);
}

// Reads and validates every face (read_face()) into `triples`, three 32-bit indices a face.
// Returns false, with `triples` empty after the faces are validated, when the indices do not
// fit in 32 bits (a CGAL triangulation of that many points needs hundreds of GB anyway).
// With `parallel` and a random-access range, in blocks on TBB's threads; a malformed face
// throws as in order: the first one, from the first block that has one.
template <class FaceRange, class Parallel = bool>
bool read_index_triples(const FaceRange& faces, std::size_t n, std::size_t number_of_faces,
                        std::vector<std::uint32_t>& triples, Parallel parallel = false)
{
  const bool fits = n < std::size_t(std::uint32_t(-1)) && number_of_faces < (std::size_t(1) << 31);
  triples.assign(fits ? 3 * number_of_faces : 0, 0);
  using Iterator = decltype(std::begin(faces));
  if constexpr(may_run_in_parallel<Parallel>() &&
                std::is_base_of<std::random_access_iterator_tag,
                                typename std::iterator_traits<Iterator>::iterator_category>::value) {
    constexpr std::size_t block = 1 << 16;
    const std::size_t blocks = (number_of_faces + block - 1) / block;
    if(parallel && blocks > 1) {
      std::vector<std::exception_ptr> failure(blocks);
      for_each_block(true, blocks, [&](std::size_t b) {
        try {
          std::size_t idx[3];
          const Iterator first = std::begin(faces);
          for(std::size_t k = b * block, end = (std::min)(number_of_faces, k + block); k < end; ++k) {
            read_face(first[std::ptrdiff_t(k)], k, n, idx);
            if(fits)
              for(int j = 0; j < 3; ++j)
                triples[3 * k + std::size_t(j)] = std::uint32_t(idx[j]);
          }
        } catch(...) {
          failure[b] = std::current_exception();
        }
      });
      for(const std::exception_ptr& e : failure)
        if(e)
          std::rethrow_exception(e);
      return fits;
    }
  }
  std::uint32_t* out = triples.data();
  std::size_t k = 0, idx[3];
  for(const auto& face : faces) {
    read_face(face, k++, n, idx);
    if(fits)
      for(int j = 0; j < 3; ++j)
        *out++ = std::uint32_t(idx[j]);
  }
  return fits;
}

template <class Edge, class = void>
struct has_first_and_second : std::false_type {};
template <class Edge>
struct has_first_and_second<Edge, std::void_t<decltype(std::declval<const Edge&>().first),
                                              decltype(std::declval<const Edge&>().second)>>
    : std::true_type {};

template <class Edge, class = void>
struct has_subscript : std::false_type {};
template <class Edge>
struct has_subscript<Edge, std::void_t<decltype(std::declval<const Edge&>()[0])>> : std::true_type {};

// The end j (0 or 1) of an edge given as a pair, as anything with operator[], or as a tuple.
template <class Edge>
auto edge_end(const Edge& e, int j)
{
  if constexpr(has_first_and_second<Edge>::value)
    return j == 0 ? e.first : e.second;
  else if constexpr(has_subscript<Edge>::value)
    return e[j];
  else
    return j == 0 ? std::get<0>(e) : std::get<1>(e);
}

// Compile-time checks of the argument types, called first in each entry point, so that a
// wrong type is reported by one plain message at the call instead of deep in the algorithm.
template <class Range, class = void>
struct range_value // not a range: void
{
  using type = void;
};
template <class Range>
struct range_value<Range, std::void_t<decltype(*std::begin(std::declval<const Range&>())),
                                      decltype(std::end(std::declval<const Range&>()))>>
{
  using type = std::decay_t<decltype(*std::begin(std::declval<const Range&>()))>;
};

template <class Edge, class = void>
struct first_of_tuple // not tuple-like: void
{
  using type = void;
};
template <class Edge>
struct first_of_tuple<Edge, std::void_t<decltype(std::get<0>(std::declval<const Edge&>())),
                                        decltype(std::get<1>(std::declval<const Edge&>()))>>
{
  using type = std::decay_t<decltype(std::get<0>(std::declval<const Edge&>()))>;
};

// Whether read_face() reads three integer indices from a Face.
template <class Face>
constexpr bool is_index_triple()
{
  if constexpr(has_subscript<Face>::value)
    return std::is_integral<std::decay_t<decltype(std::declval<const Face&>()[0])>>::value;
  else
    return false;
}

// Whether edge_end() reads two integer indices from an Edge.
template <class Edge>
constexpr bool is_index_pair()
{
  if constexpr(has_first_and_second<Edge>::value)
    return std::is_integral<std::decay_t<decltype(std::declval<const Edge&>().first)>>::value;
  else if constexpr(has_subscript<Edge>::value)
    return std::is_integral<std::decay_t<decltype(std::declval<const Edge&>()[0])>>::value;
  else
    return std::is_integral<typename first_of_tuple<Edge>::type>::value;
}

template <class Point, class Range, class = void>
struct is_contiguous_range_of : std::false_type
{
};
template <class Point, class Range>
struct is_contiguous_range_of<Point, Range, std::void_t<decltype(std::data(std::declval<const Range&>()))>>
    : std::is_same<decltype(std::data(std::declval<const Range&>())), const Point*>
{
};

template <class PointRange, class Point>
constexpr void check_point_range_type()
{
  static_assert(std::is_convertible<typename range_value<PointRange>::type, Point>::value,
                "Delaunay_from_prediction: `points` must be a range of the triangulation's points "
                "(DT::Point, e.g. std::vector<K::Point_2> for a triangulation of kernel K)");
}

// The iterator the stages read `points` through: a pointer when the range stores exactly
// `Point`s contiguously (std::vector, std::array, a C array), so that every such range, and the
// copies the stages make, share one instantiation of the code that reads points; the range's
// own iterator otherwise.
template <class Point, class PointRange>
auto point_iterator(const PointRange& points)
{
  if constexpr(is_contiguous_range_of<Point, PointRange>::value)
    return static_cast<const Point*>(std::data(points));
  else
    return std::begin(points);
}

template <class FaceRange>
constexpr void check_face_range_type()
{
  static_assert(is_index_triple<typename range_value<FaceRange>::type>(),
                "Delaunay_from_prediction: `faces` must be a range of faces, each three integer indices into "
                "`points` read as face[0], face[1], face[2] (e.g. std::vector<std::array<int, 3>>)");
}

template <class EdgeRange>
constexpr void check_edge_range_type()
{
  static_assert(is_index_pair<typename range_value<EdgeRange>::type>(),
                "Delaunay_from_prediction: `edges` must be a range of edges, each two integer indices into "
                "`points` (e.g. std::vector<std::pair<int, int>> or std::vector<std::array<int, 2>>)");
}

// Reads and validates edge number k: both ends in [0, n) and different.
template <class Edge>
std::pair<std::size_t, std::size_t> read_edge(const Edge& e, std::size_t k, std::size_t n)
{
  std::size_t out[2];
  for(int j = 0; j < 2; ++j)
    out[j] = checked_index(edge_end(e, j), n, "edge", k, "end", j);
  if(out[0] == out[1]) {
    std::ostringstream msg;
    msg << "Delaunay_from_prediction: edge " << k << " joins index " << out[0] << " to itself";
    throw Invalid_prediction(msg.str());
  }
  return {out[0], out[1]};
}

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_CHECK_INPUT_CHECK_H
