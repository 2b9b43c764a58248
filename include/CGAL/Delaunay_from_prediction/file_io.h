// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_FILE_IO_H
#define CGAL_DELAUNAY_FROM_PREDICTION_FILE_IO_H

#include <CGAL/Delaunay_from_prediction/internal/io/text_file.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/vertex_info.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
Reading points and predictions from files, and writing triangulations to files; the formats are
those of Shewchuk's Triangle (`.node`, `.ele`, `.edge`), OFF, and plain text. The `dfp`
command-line tool is built on these functions.

- **`.node`** (points): a first line `n 2 attributes markers`, then `n` lines `i x y
  [attributes] [marker]`. The vertices are numbered consecutively from 0 or from 1 (Triangle
  allows both); the first one says which.
- **`.ele`** (faces): a first line `m 3 attributes` (or `m 6 ...`: the first three nodes are
  the corners), then `m` lines `j a b c ...`. The indices count from the number of the first
  triangle (0 or 1), as Triangle writes them.
- **`.edge`** (edges): a first line `m markers`, then `m` lines `j a b [marker]`, numbered as
  `.ele` files are.
- **OFF** (points and faces): `OFF`, then `n f e`, then `n` lines `x y [z]`, then `f` lines
  `k v1 ... vk [colour]`, indices from 0. The z coordinate is ignored. A face of more than three
  vertices is read as the fan of triangles `v1 vi vi+1`.
- **plain text** (points; any other extension, `.xyz` for instance): one point per line, `x y`
  or `x y z` (z ignored).

In every format, `#` starts a comment that runs to the end of the line, blank lines are
skipped, and commas count as blanks. Coordinates must be finite doubles. The readers use memory
proportional to what they return (a buffer of about a megabyte holds the lines being read).
Every malformed line throws `IO::File_error`, whose message names the file and the line; an
index out of range, or a face repeating an index, is reported there, with its line.
*/
namespace IO {

/// \ingroup PkgDelaunayFromPredictionRef
/// The file formats of `file_io.h`.
enum class File_format {
  node, ///< Triangle's `.node`: points.
  ele,  ///< Triangle's `.ele`: triangles.
  edge, ///< Triangle's `.edge`: edges.
  off,  ///< OFF: points, and faces.
  xyz   ///< plain text, one point `x y [z]` per line.
};

/// \ingroup PkgDelaunayFromPredictionRef
/// tells the format of a file by its extension, ignoring case.
/// \param file a file name (a path).
/// \returns `File_format::node`, `ele`, `edge` or `off` for `.node`, `.ele`, `.edge`, `.off`,
///          and `File_format::xyz` for any other extension.
inline File_format file_format(const std::string& file)
{
  const std::size_t dot = file.find_last_of('.');
  const std::size_t slash = file.find_last_of("/\\");
  std::string extension;
  if(dot != std::string::npos && (slash == std::string::npos || dot > slash))
    extension = file.substr(dot + 1);
  for(char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  if(extension == "node")
    return File_format::node;
  if(extension == "ele")
    return File_format::ele;
  if(extension == "edge")
    return File_format::edge;
  if(extension == "off")
    return File_format::off;
  return File_format::xyz;
}

namespace internal_io {

using CGAL::Delaunay_from_prediction::internal::Fields;
using CGAL::Delaunay_from_prediction::internal::Line_reader;

inline void expect_end_of_line(Fields& fields, const Line_reader& reader, const char* what)
{
  std::string_view extra;
  if(fields.next(extra))
    reader.fail(std::string("unexpected '") + std::string(extra) + "' after " + what);
}

// The header of an OFF file: "OFF" (alone or followed by the counts), then "n f e".
inline void read_off_header(Line_reader& reader, std::uint64_t& n, std::uint64_t& f)
{
  std::string_view line;
  if(!reader.next_nonblank(line))
    reader.fail("empty file: expected the OFF header");
  Fields fields(line, reader);
  std::string_view keyword;
  fields.next(keyword);
  if(keyword != "OFF")
    reader.fail("expected 'OFF' (only plain OFF files are read), found '" + std::string(keyword) + "'");
  if(fields.remaining() == 0) {
    if(!reader.next_nonblank(line))
      reader.fail("expected the counts 'vertices faces edges' after 'OFF'");
    fields = Fields(line, reader);
  }
  n = fields.count("the number of vertices");
  f = fields.count("the number of faces");
  if(fields.remaining() > 0)
    fields.count("the number of edges");
  expect_end_of_line(fields, reader, "the counts");
}

inline std::size_t vertex_index(Fields& fields, const Line_reader& reader, std::uint64_t first,
                                std::size_t number_of_points, const char* what)
{
  const std::uint64_t raw = fields.count(what);
  if(raw < first || raw - first >= number_of_points)
    reader.fail(std::string(what) + " " + std::to_string(raw) + " is out of range: " +
                (number_of_points == 0 ? std::string("there are no points")
                                       : "the points are numbered from " + std::to_string(first) + " to " +
                                             std::to_string(first + number_of_points - 1)));
  return std::size_t(raw - first);
}

// The first number of a Triangle file's first item: the numbering base, 0 or 1.
inline std::uint64_t numbering_base(std::uint64_t number, const Line_reader& reader, const char* item)
{
  if(number > 1)
    reader.fail(std::string("the first ") + item + " is numbered " + std::to_string(number) +
                ": Triangle's files number from 0 or from 1");
  return number;
}

// A Triangle `.ele` or `.edge` file: the count and the rest of the header line, then each
// k-tuple of indices on a line of its own, tuples and indices numbered from `first_index`.
template <std::size_t k, class TupleRange>
void write_numbered_tuples(const std::string& file, const TupleRange& tuples, const char* rest_of_header,
                           std::size_t first_index)
{
  CGAL::Delaunay_from_prediction::internal::Text_writer out(file);
  out.number(std::size_t(std::distance(std::begin(tuples), std::end(tuples)))).text(rest_of_header);
  std::size_t i = first_index;
  for(const auto& t : tuples) {
    out.number(i++);
    for(std::size_t j = 0; j < k; ++j)
      out.text(" ").number(std::size_t(t[j]) + first_index);
    out.text("\n");
  }
  out.close();
}

} // namespace internal_io

/*!
\ingroup PkgDelaunayFromPredictionRef
reads the points of `file` into `points` (replaced), in the format its extension gives
(`.node`, `.off`, or plain text for any other).

\tparam Point a type constructible from two `double`s, such as a kernel's `Point_2`.
\param file the file name.
\param points receives the points, in the order of the file.
\returns the number of the first point in the file: 0 or 1 for a `.node` file, 0 for the others.
\throws IO::File_error if the file cannot be read or a line is malformed (a count that
        disagrees with the lines, a missing or non-finite coordinate, a `.node` file of another
        dimension than 2, vertices not numbered consecutively); `points` is then unchanged.
*/
template <class Point>
std::size_t read_points(const std::string& file, std::vector<Point>& points)
{
  using namespace internal_io;
  Line_reader reader(file);
  std::vector<Point> read;
  std::string_view line;
  std::size_t first = 0;
  const File_format format = file_format(file);
  if(format == File_format::node) {
    if(!reader.next_nonblank(line))
      reader.fail("empty file: expected the header 'vertices 2 attributes markers'");
    Fields header(line, reader);
    const std::uint64_t n = header.count("the number of vertices");
    if(header.remaining() > 0 && header.count("the dimension") != 2)
      reader.fail("the dimension must be 2");
    std::uint64_t extra = 0;
    if(header.remaining() > 0)
      extra += header.count("the number of attributes");
    if(header.remaining() > 0)
      extra += header.count("the number of boundary markers");
    expect_end_of_line(header, reader, "the header");
    read.reserve(std::size_t(std::min<std::uint64_t>(n, std::uint64_t(1) << 28)));
    for(std::uint64_t i = 0; i < n; ++i) {
      if(!reader.next_nonblank(line))
        reader.fail("the header announces " + std::to_string(n) + " vertices, the file ends after " +
                    std::to_string(i));
      Fields fields(line, reader);
      const std::uint64_t number = fields.count("the vertex number");
      if(i == 0)
        first = std::size_t(numbering_base(number, reader, "vertex"));
      else if(number != first + i)
        reader.fail("vertex number " + std::to_string(number) + ", expected " + std::to_string(first + i) +
                    " (vertices are numbered consecutively)");
      const double x = fields.real("the x coordinate");
      const double y = fields.real("the y coordinate");
      if(fields.remaining() > extra)
        reader.fail("more fields than the header's attributes and markers");
      read.emplace_back(x, y);
    }
    if(reader.next_nonblank(line))
      reader.fail("more vertices than the " + std::to_string(n) + " the header announces");
  } else if(format == File_format::off) {
    std::uint64_t n = 0, f = 0;
    read_off_header(reader, n, f);
    read.reserve(std::size_t(std::min<std::uint64_t>(n, std::uint64_t(1) << 28)));
    for(std::uint64_t i = 0; i < n; ++i) {
      if(!reader.next_nonblank(line))
        reader.fail("the header announces " + std::to_string(n) + " vertices, the file ends after " +
                    std::to_string(i));
      Fields fields(line, reader);
      const double x = fields.real("the x coordinate");
      const double y = fields.real("the y coordinate");
      if(fields.remaining() > 0)
        fields.real("the z coordinate");
      expect_end_of_line(fields, reader, "the coordinates");
      read.emplace_back(x, y);
    }
  } else {
    while(reader.next_nonblank(line)) {
      Fields fields(line, reader);
      const double x = fields.real("the x coordinate");
      const double y = fields.real("the y coordinate");
      if(fields.remaining() > 0)
        fields.real("the z coordinate");
      expect_end_of_line(fields, reader, "the coordinates 'x y [z]'");
      read.emplace_back(x, y);
    }
  }
  points.swap(read);
  return first;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
reads the faces of `file`, a `.ele` or an OFF file, as triangles of indices from 0 into
`number_of_points` points. A polygon of an OFF file becomes a fan of triangles.

\param file the file name.
\param number_of_points the number of points the indices refer to.
\returns the triangles, in the order of the file.
\throws IO::File_error if the file cannot be read, has another format, a line is malformed,
        an index is out of range, or a face repeats an index; also if an OFF file has another
        number of vertices than `number_of_points`.
*/
inline std::vector<std::array<std::size_t, 3>> read_faces(const std::string& file, std::size_t number_of_points)
{
  using namespace internal_io;
  const File_format format = file_format(file);
  if(format != File_format::ele && format != File_format::off)
    throw File_error(file, 0, "faces are read from .ele or .off files");
  Line_reader reader(file);
  std::vector<std::array<std::size_t, 3>> faces;
  std::string_view line;
  auto add = [&](const std::array<std::size_t, 3>& t) {
    if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      reader.fail("the face repeats an index");
    faces.push_back(t);
  };
  if(format == File_format::ele) {
    if(!reader.next_nonblank(line))
      reader.fail("empty file: expected the header 'triangles 3 attributes'");
    Fields header(line, reader);
    const std::uint64_t m = header.count("the number of triangles");
    std::uint64_t nodes = 3, attributes = 0;
    if(header.remaining() > 0)
      nodes = header.count("the number of nodes per triangle");
    if(nodes != 3 && nodes != 6)
      reader.fail("triangles have 3 or 6 nodes, not " + std::to_string(nodes));
    if(header.remaining() > 0)
      attributes = header.count("the number of attributes");
    expect_end_of_line(header, reader, "the header");
    faces.reserve(std::size_t(std::min<std::uint64_t>(m, std::uint64_t(1) << 28)));
    std::uint64_t first = 0;
    for(std::uint64_t i = 0; i < m; ++i) {
      if(!reader.next_nonblank(line))
        reader.fail("the header announces " + std::to_string(m) + " triangles, the file ends after " +
                    std::to_string(i));
      Fields fields(line, reader);
      const std::uint64_t number = fields.count("the triangle number");
      if(i == 0)
        first = numbering_base(number, reader, "triangle");
      std::array<std::size_t, 3> t;
      for(std::size_t& v : t)
        v = vertex_index(fields, reader, first, number_of_points, "vertex index");
      for(std::uint64_t k = 3; k < nodes; ++k)
        vertex_index(fields, reader, first, number_of_points, "vertex index");
      if(fields.remaining() > attributes)
        reader.fail("more fields than the header's nodes and attributes");
      add(t);
    }
    if(reader.next_nonblank(line))
      reader.fail("more triangles than the " + std::to_string(m) + " the header announces");
  } else {
    std::uint64_t n = 0, f = 0;
    read_off_header(reader, n, f);
    if(n != number_of_points)
      reader.fail("the OFF file has " + std::to_string(n) + " vertices, the points are " +
                  std::to_string(number_of_points));
    for(std::uint64_t i = 0; i < n; ++i)
      if(!reader.next_nonblank(line))
        reader.fail("the header announces " + std::to_string(n) + " vertices, the file ends after " +
                    std::to_string(i));
    faces.reserve(std::size_t(std::min<std::uint64_t>(f, std::uint64_t(1) << 28)));
    for(std::uint64_t i = 0; i < f; ++i) {
      if(!reader.next_nonblank(line))
        reader.fail("the header announces " + std::to_string(f) + " faces, the file ends after " +
                    std::to_string(i));
      Fields fields(line, reader);
      const std::uint64_t k = fields.count("the number of vertices of the face");
      if(k < 3)
        reader.fail("a face needs at least 3 vertices, not " + std::to_string(k));
      if(fields.remaining() < k)
        reader.fail("the face announces " + std::to_string(k) + " vertices, the line has fewer indices");
      const std::size_t v0 = vertex_index(fields, reader, 0, number_of_points, "vertex index");
      std::size_t previous = vertex_index(fields, reader, 0, number_of_points, "vertex index");
      for(std::uint64_t j = 2; j < k; ++j) {
        const std::size_t v = vertex_index(fields, reader, 0, number_of_points, "vertex index");
        add({v0, previous, v});
        previous = v;
      }
      // What follows the indices is a colour, ignored.
    }
  }
  return faces;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
reads the edges of `file`, a Triangle `.edge` file, as pairs of indices from 0 into
`number_of_points` points.

\param file the file name.
\param number_of_points the number of points the indices refer to.
\returns the edges, in the order of the file.
\throws IO::File_error if the file cannot be read, a line is malformed, an index is out of
        range, or an edge joins a point to itself.
*/
inline std::vector<std::array<std::size_t, 2>> read_edges(const std::string& file, std::size_t number_of_points)
{
  using namespace internal_io;
  if(file_format(file) != File_format::edge)
    throw File_error(file, 0, "edges are read from .edge files");
  Line_reader reader(file);
  std::string_view line;
  if(!reader.next_nonblank(line))
    reader.fail("empty file: expected the header 'edges markers'");
  Fields header(line, reader);
  const std::uint64_t m = header.count("the number of edges");
  std::uint64_t markers = 0;
  if(header.remaining() > 0)
    markers = header.count("the number of boundary markers");
  expect_end_of_line(header, reader, "the header");
  std::vector<std::array<std::size_t, 2>> edges;
  edges.reserve(std::size_t(std::min<std::uint64_t>(m, std::uint64_t(1) << 28)));
  std::uint64_t first = 0;
  for(std::uint64_t i = 0; i < m; ++i) {
    if(!reader.next_nonblank(line))
      reader.fail("the header announces " + std::to_string(m) + " edges, the file ends after " + std::to_string(i));
    Fields fields(line, reader);
    const std::uint64_t number = fields.count("the edge number");
    if(i == 0)
      first = numbering_base(number, reader, "edge");
    const std::size_t a = vertex_index(fields, reader, first, number_of_points, "vertex index");
    const std::size_t b = vertex_index(fields, reader, first, number_of_points, "vertex index");
    if(a == b)
      reader.fail("the edge joins a point to itself");
    if(fields.remaining() > markers)
      reader.fail("more fields than the header's boundary markers");
    edges.push_back({a, b});
  }
  if(reader.next_nonblank(line))
    reader.fail("more edges than the " + std::to_string(m) + " the header announces");
  return edges;
}

/*!
\ingroup PkgDelaunayFromPredictionRef
writes `points` and `faces` (triples of indices from 0) to `file` as OFF, with z = 0. The
coordinates are written in the shortest form that reads back to the same doubles.
\param file the file name.
\param points the points (any kernel's `Point_2`; coordinates converted to `double`).
\param faces the triangles, each with `t[0]`, `t[1]`, `t[2]`.
\throws IO::File_error if the file cannot be written.
*/
template <class PointRange, class FaceRange>
void write_off(const std::string& file, const PointRange& points, const FaceRange& faces)
{
  CGAL::Delaunay_from_prediction::internal::Text_writer out(file);
  const std::size_t n = std::size_t(std::distance(std::begin(points), std::end(points)));
  const std::size_t f = std::size_t(std::distance(std::begin(faces), std::end(faces)));
  out.text("OFF\n").number(n).text(" ").number(f).text(" 0\n");
  for(const auto& p : points)
    out.number(double(CGAL::to_double(p.x()))).text(" ").number(double(CGAL::to_double(p.y()))).text(" 0\n");
  for(const auto& t : faces)
    out.text("3 ").number(std::size_t(t[0])).text(" ").number(std::size_t(t[1])).text(" ").number(std::size_t(t[2])).text("\n");
  out.close();
}

/*!
\ingroup PkgDelaunayFromPredictionRef
writes `faces` (triples of indices from 0) to `file` as a Triangle `.ele` file whose triangles
and indices are numbered from `first_index` (0 or 1: the numbering of the `.node` file).
\param file the file name.
\param faces the triangles, each with `t[0]`, `t[1]`, `t[2]`.
\param first_index the number of the first triangle and of the first point.
\throws IO::File_error if the file cannot be written.
*/
template <class FaceRange>
void write_ele(const std::string& file, const FaceRange& faces, std::size_t first_index = 0)
{
  internal_io::write_numbered_tuples<3>(file, faces, " 3 0\n", first_index);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
writes `edges` (pairs of indices from 0) to `file` as a Triangle `.edge` file numbered from
`first_index` (0 or 1), without boundary markers.
\param file the file name.
\param edges the edges, each with `e[0]`, `e[1]`.
\param first_index the number of the first edge and of the first point.
\throws IO::File_error if the file cannot be written.
*/
template <class EdgeRange>
void write_edges(const std::string& file, const EdgeRange& edges, std::size_t first_index = 0)
{
  internal_io::write_numbered_tuples<2>(file, edges, " 0\n", first_index);
}

/*!
\ingroup PkgDelaunayFromPredictionRef
writes the triangles of a periodic triangulation to `file` as a Triangle `.ele` file with six
attributes: a first line `m 3 6`, then `j a b c ax ay bx by cx cy`, the corners' point indices
followed by each corner's offset in periods (the corner is the point translated by `ax` domain
widths in x and `ay` heights in y). Triangles and indices are numbered from `first_index` (0 or
1); `read_faces()` reads such a file back as index triples (the attributes are skipped), which is
the prediction the periodic `delaunay_from_prediction()` takes.
\param file the file name.
\param triangles the triangles, each with `vertices[k]` and `offsets[k][0]`, `offsets[k][1]`
       (non-negative), as `indexed_periodic_triangles()` returns them.
\param first_index the number of the first triangle and of the first point.
\throws IO::File_error if the file cannot be written.
*/
template <class TriangleRange>
void write_periodic_ele(const std::string& file, const TriangleRange& triangles, std::size_t first_index = 0)
{
  CGAL::Delaunay_from_prediction::internal::Text_writer out(file);
  out.number(std::size_t(std::distance(std::begin(triangles), std::end(triangles)))).text(" 3 6\n");
  std::size_t i = first_index;
  for(const auto& t : triangles) {
    out.number(i++);
    for(std::size_t k = 0; k < 3; ++k)
      out.text(" ").number(std::size_t(t.vertices[k]) + first_index);
    for(std::size_t k = 0; k < 3; ++k)
      out.text(" ").number(std::size_t(t.offsets[k][0])).text(" ").number(std::size_t(t.offsets[k][1]));
    out.text("\n");
  }
  out.close();
}

/*!
\ingroup PkgDelaunayFromPredictionRef
writes the triangulation `dt` of `points` to `file`, in the format its extension gives: its
finite faces (counter-clockwise) to a `.ele` or OFF file, its finite edges to a `.edge` file
(the only one of the three that holds anything when the points are collinear).

\tparam DT a `CGAL::Delaunay_triangulation_2` whose vertex `info()` is the index of its point
        in `points` (as `delaunay_from_prediction()` sets it).
\param file the file name; its extension chooses the format.
\param points the points of `dt`, indexed as its vertices' `info()`.
\param dt the triangulation.
\param first_index the numbering of `.ele` and `.edge` files (0 or 1); ignored for OFF.
\throws IO::File_error if the file cannot be written, or its extension is none of the three.
*/
template <class PointRange, class DT>
void write_triangulation(const std::string& file, const PointRange& points, const DT& dt, std::size_t first_index = 0)
{
  namespace dfp_internal = CGAL::Delaunay_from_prediction::internal;
  switch(file_format(file)) {
  case File_format::ele:
    write_ele(file, dfp_internal::faces_of(dt), first_index);
    break;
  case File_format::off:
    write_off(file, points, dfp_internal::faces_of(dt));
    break;
  case File_format::edge:
    write_edges(file, dfp_internal::edges_of(dt), first_index);
    break;
  default:
    throw File_error(file, 0, "the output is written as .ele, .off or .edge, by its extension");
  }
}

} // namespace IO
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_FILE_IO_H
