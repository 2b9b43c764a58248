// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// file_io.h: reading points, faces and edges from Triangle, OFF and plain-text files, and
// writing triangulations. Checks that
//  - coordinates survive a write and a read bit for bit (huge, tiny, subnormal, negative zero);
//  - every format and variant is read (numbering from 0 and 1, attributes and markers, comments,
//    commas, CRLF, blank lines, no final newline, OFF counts on the OFF line, polygons as fans,
//    six-node triangles), also across the reader's buffer (many points, a line of megabytes);
//  - every malformed file throws File_error naming the file and the right line, and leaves the
//    caller's vector as it was;
//  - a triangulation written as .ele, OFF or .edge and read back as the prediction gives CGAL's
//    Delaunay triangulation with every face certified (collinear and duplicate points too).

#include <CGAL/Delaunay_from_prediction/file_io.h> // first: the header is self-contained

#include "test_util.h"

#include <CGAL/Delaunay_from_predicted_edges_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

using namespace dfp_test;
namespace IO = CGAL::Delaunay_from_prediction::IO;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Points = std::vector<Point>;

// A folder of its own for the test's files, removed at the end.
struct Folder
{
  std::string path;
  Folder()
  {
    char name[] = "/tmp/dfp_test_file_io_XXXXXX";
    const char* made = mkdtemp(name);
    path = made != nullptr ? made : "/tmp";
  }
  ~Folder() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string file(const std::string& name) const { return path + "/" + name; }
};

std::string write_text(const std::string& file, const std::string& text)
{
  std::ofstream out(file, std::ios::binary);
  out << text;
  return file;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void test_file_format()
{
  DFP_CHECK(IO::file_format("a.node") == IO::File_format::node);
  DFP_CHECK(IO::file_format("dir.off/A.NODE") == IO::File_format::node);
  DFP_CHECK(IO::file_format("x.Ele") == IO::File_format::ele);
  DFP_CHECK(IO::file_format("x.edge") == IO::File_format::edge);
  DFP_CHECK(IO::file_format("mesh.OFF") == IO::File_format::off);
  DFP_CHECK(IO::file_format("cloud.xyz") == IO::File_format::xyz);
  DFP_CHECK(IO::file_format("dir.off/points") == IO::File_format::xyz);
  DFP_CHECK(IO::file_format("points") == IO::File_format::xyz);
}

// Coordinates written by write_off() read back bit for bit.
void test_coordinates_round_trip(const Folder& folder)
{
  const double values[] = {0.1,
                           -0.0,
                           1e300,
                           -1.7976931348623157e308,
                           1e-300,
                           std::numeric_limits<double>::denorm_min(),
                           3.141592653589793,
                           -2.5e-310,
                           123456789012345678.0,
                           1.0 / 3.0};
  Points points;
  for(double x : values)
    for(double y : values)
      points.emplace_back(x, y);
  const std::string file = folder.file("round_trip.off");
  IO::write_off(file, points, std::vector<std::array<std::size_t, 3>>{{0, 1, 2}});
  Points read;
  DFP_CHECK(IO::read_points(file, read) == 0);
  DFP_CHECK(read.size() == points.size());
  bool same = read.size() == points.size();
  for(std::size_t i = 0; same && i < read.size(); ++i)
    same = same_bits(read[i].x(), points[i].x()) && same_bits(read[i].y(), points[i].y());
  DFP_CHECK_MSG(same, "coordinates changed in a write and a read");
  const auto faces = IO::read_faces(file, points.size());
  DFP_CHECK(faces.size() == 1 && faces[0] == (std::array<std::size_t, 3>{0, 1, 2}));
}

void test_point_formats(const Folder& folder)
{
  Points p;
  // .node numbered from 1, attributes and a marker, comments, CRLF, blank lines, no final newline.
  const std::string node1 = write_text(folder.file("one.node"), "# Triangle\r\n3 2 1 1 # header\r\n\r\n"
                                                                 "1 0.5 -2 7 0\r\n2  1e3\t4 7 1\r\n3 +5,6 7 0");
  DFP_CHECK(IO::read_points(node1, p) == 1);
  DFP_CHECK(p.size() == 3 && p[0] == Point(0.5, -2) && p[1] == Point(1000, 4) && p[2] == Point(5, 6));
  const std::string node0 = write_text(folder.file("zero.node"), "2 2 0 0\n0 1 2\n1 3 4\n");
  DFP_CHECK(IO::read_points(node0, p) == 0);
  DFP_CHECK(p.size() == 2 && p[1] == Point(3, 4));
  // A header without its optional fields.
  DFP_CHECK(IO::read_points(write_text(folder.file("short.node"), "1\n0 9 8\n"), p) == 0);
  DFP_CHECK(p.size() == 1 && p[0] == Point(9, 8));
  // OFF with the counts on the OFF line, z ignored; faces ignored when reading points.
  const std::string off = write_text(folder.file("inline.off"), "OFF 3 1 0\n0 0 5\n1 0 5\n0 1 5\n3 0 1 2\n");
  DFP_CHECK(IO::read_points(off, p) == 0);
  DFP_CHECK(p.size() == 3 && p[2] == Point(0, 1));
  // Plain text: x y, x y z, commas, comments.
  const std::string xyz = write_text(folder.file("cloud.xyz"), "# x y\n1 2\n3,4,9\n  5 6 # six\n\n");
  DFP_CHECK(IO::read_points(xyz, p) == 0);
  DFP_CHECK(p.size() == 3 && p[1] == Point(3, 4) && p[2] == Point(5, 6));
  // An empty text file: no points.
  DFP_CHECK(IO::read_points(write_text(folder.file("empty.txt"), ""), p) == 0);
  DFP_CHECK(p.empty());
}

// Many points and a line of megabytes: the reader refills and grows its buffer.
void test_large_files(const Folder& folder)
{
  CGAL::Random rng(31);
  Points points;
  for(int i = 0; i < 150000; ++i)
    points.emplace_back(rng.get_double(-1e6, 1e6), rng.get_double(-1e-6, 1e-6));
  const std::string off = folder.file("large.off");
  IO::write_off(off, points, std::vector<std::array<std::size_t, 3>>());
  Points read;
  IO::read_points(off, read);
  DFP_CHECK(read == points);

  std::string text = "1 2\n#" + std::string(3 << 20, 'c') + "\n3 4\n5 x\n";
  const std::string wide = write_text(folder.file("wide.xyz"), text);
  const std::string message = exception_message<IO::File_error>([&] { IO::read_points(wide, read); });
  DFP_CHECK_MSG(message == wide + ":4: expected the y coordinate, found 'x'", message);
  text.resize(text.size() - 4);
  IO::read_points(write_text(folder.file("wide2.xyz"), text), read);
  DFP_CHECK(read.size() == 2 && read[1] == Point(3, 4));
}

void test_face_formats(const Folder& folder)
{
  using Triples = std::vector<std::array<std::size_t, 3>>;
  // .ele from 1 with an attribute; from 0 with six nodes per triangle.
  const std::string ele1 = write_text(folder.file("one.ele"), "2 3 1\n1 1 2 3 0.5\n2 3 2 4 0.5\n");
  DFP_CHECK(IO::read_faces(ele1, 4) == (Triples{{0, 1, 2}, {2, 1, 3}}));
  const std::string ele6 = write_text(folder.file("six.ele"), "1 6 0\n0 0 1 2 3 4 5\n");
  DFP_CHECK(IO::read_faces(ele6, 6) == (Triples{{0, 1, 2}}));
  // OFF: a quadrilateral and a pentagon are fans; a colour after the indices is ignored.
  const std::string off = write_text(folder.file("poly.off"),
                                     "OFF\n6 2 0\n0 0\n1 0\n1 1\n0 1\n2 0\n2 1\n4 0 1 2 3 255 0 0\n5 1 4 5 2 3\n");
  DFP_CHECK(IO::read_faces(off, 6) == (Triples{{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}, {1, 2, 3}}));
  // .edge from 1 with markers.
  const std::string edge = write_text(folder.file("one.edge"), "2 1\n1 1 2 1\n2 2 3 0\n");
  DFP_CHECK(IO::read_edges(edge, 3) == (std::vector<std::array<std::size_t, 2>>{{0, 1}, {1, 2}}));
}

// Each malformed file throws File_error naming the file and `line`, and leaves `points` as it was.
void test_malformed(const Folder& folder)
{
  struct Case
  {
    const char* name;
    const char* text;
    std::size_t line;
    const char* message;
  };
  const Case point_cases[] = {
      {"a.node", "3 2 0 0\n1 0 0\n2 1 x\n3 0 1\n", 3, "expected the y coordinate, found 'x'"},
      {"b.node", "3 2 0 0\n1 0 0\n2 1 0\n", 3, "the header announces 3 vertices, the file ends after 2"},
      {"c.node", "2 3 0 0\n0 0 0 0\n1 1 1 1\n", 1, "the dimension must be 2"},
      {"d.node", "2 2 0 0\n2 0 0\n3 1 1\n", 2, "the first vertex is numbered 2"},
      {"e.node", "2 2 0 0\n0 0 0\n2 1 1\n", 3, "vertex number 2, expected 1"},
      {"f.node", "1 2 0 0\n0 0 0 5\n", 2, "more fields than the header's attributes and markers"},
      {"g.node", "1 2 0 0\n0 0 0\n\n# end\n1 1 1\n", 5, "more vertices than the 1 the header announces"},
      {"h.node", "-1 2 0 0\n", 1, "the number of vertices '-1' is negative"},
      {"i.node", "", 0, "empty file"},
      {"j.xyz", "0 0\n1 inf\n", 2, "the y coordinate 'inf' is not finite"},
      {"k.xyz", "0 0\n1e999 1\n", 2, "the x coordinate '1e999' is not representable as a double"},
      {"l.xyz", "0 0\n1\n", 2, "expected the y coordinate, found the end of the line"},
      {"m.xyz", "0 0\n1 2 3 4\n", 2, "unexpected '4' after the coordinates"},
      {"n.off", "COFF\n", 1, "expected 'OFF'"},
      {"o.off", "OFF\n2 0 0\n0 0 0\n", 3, "the header announces 2 vertices, the file ends after 1"},
      {"p.xyz", "0 0\r\n\r\n1 0x1p3\r\n", 3, "expected the y coordinate, found '0x1p3'"},
  };
  for(const Case& c : point_cases) {
    const std::string file = write_text(folder.file(c.name), c.text);
    Points points = {Point(7, 7)};
    std::size_t line = 999;
    std::string message;
    try {
      IO::read_points(file, points);
      message = "(no exception)";
    } catch(const IO::File_error& e) {
      line = e.line();
      message = e.what();
      DFP_CHECK(e.file() == file);
    }
    const std::string prefix = c.line == 0 ? file + ": " : file + ":" + std::to_string(c.line) + ": ";
    DFP_CHECK_MSG(line == c.line && message.rfind(prefix, 0) == 0 && message.find(c.message) != std::string::npos,
                  c.name << ": line " << line << ", message '" << message << "', expected line " << c.line << " and '"
                         << c.message << "'");
    DFP_CHECK_MSG(points.size() == 1 && points[0] == Point(7, 7), c.name << ": the caller's points changed");
  }

  const Case face_cases[] = {
      {"a.ele", "2 3 0\n1 1 2 3\n2 2 3 5\n", 3, "vertex index 5 is out of range: the points are numbered from 1 to 3"},
      {"b.ele", "2 3 0\n0 0 1 2\n1 0 1 4\n", 3, "vertex index 4 is out of range"},
      {"c.ele", "1 3 0\n1 1 2 1\n", 2, "the face repeats an index"},
      {"d.ele", "1 4 0\n1 1 2 3 4\n", 1, "triangles have 3 or 6 nodes, not 4"},
      {"e.ele", "2 3 0\n1 1 2 3\n", 2, "the header announces 2 triangles, the file ends after 1"},
      {"f.ele", "1 3 0\n1 1 2 -3\n", 2, "vertex index '-3' is negative"},
      {"g.ele", "1 3 0\n1 1 2 3 9\n", 2, "more fields than the header's nodes and attributes"},
      {"h.off", "OFF\n3 1 0\n0 0\n1 0\n0 1\n2 0 1\n", 6, "a face needs at least 3 vertices, not 2"},
      {"i.off", "OFF\n3 1 0\n0 0\n1 0\n0 1\n4 0 1 2\n", 6, "the face announces 4 vertices"},
      {"j.off", "OFF\n4 1 0\n0 0\n1 0\n0 1\n1 1\n3 0 1 2\n", 2, "the OFF file has 4 vertices, the points are 3"},
      {"k.xyz", "0 0\n", 0, "faces are read from .ele or .off files"},
  };
  for(const Case& c : face_cases) {
    const std::string file = write_text(folder.file(c.name), c.text);
    std::size_t line = 999;
    std::string message = "(no exception)";
    try {
      IO::read_faces(file, 3);
    } catch(const IO::File_error& e) {
      line = e.line();
      message = e.what();
    }
    DFP_CHECK_MSG(line == c.line && message.find(c.message) != std::string::npos,
                  c.name << ": line " << line << ", message '" << message << "'");
  }
  const std::string edge = write_text(folder.file("a.edge"), "2 0\n0 0 1\n1 2 2\n");
  const std::string message = exception_message<IO::File_error>([&] { IO::read_edges(edge, 3); });
  DFP_CHECK_MSG(message == edge + ":3: the edge joins a point to itself", message);
  const std::string missing = folder.file("missing.node");
  DFP_CHECK(exception_message<IO::File_error>([&] {
              Points p;
              IO::read_points(missing, p);
            }).rfind(missing + ": cannot open the file for reading", 0) == 0);
  DFP_CHECK(exception_message<IO::File_error>([&] {
              IO::write_ele(folder.file("no/such/folder.ele"), std::vector<std::array<std::size_t, 3>>());
            }).find("cannot open the file for writing") != std::string::npos);
  DT_with_info<K> dt;
  DFP_CHECK(throws_exception<IO::File_error>([&] { IO::write_triangulation(folder.file("out.xyz"), Points(), dt); }));
}

// A triangulation written in each format and read back as the prediction: every face is
// certified and the result is CGAL's triangulation.
void test_written_triangulation_is_read_back(const Folder& folder, const XYs& xy, const std::string& what)
{
  Scope scope(what);
  const Points points = to_points<K>(xy);
  DT_with_info<K> dt;
  DFP::delaunay_from_prediction(points, Faces(), dt);
  for(std::size_t first : {std::size_t(0), std::size_t(1)}) {
    const std::string ele = folder.file("dt.ele"), off = folder.file("dt.off"), edge = folder.file("dt.edge");
    IO::write_triangulation(ele, points, dt, first);
    IO::write_triangulation(off, points, dt, first);
    IO::write_triangulation(edge, points, dt, first);
    // The .ele and .edge files number from `first`; the reader follows the file's numbering.
    std::ifstream in(ele);
    std::size_t count = 0, dim = 0, attributes = 0, number = 99;
    in >> count >> dim >> attributes >> number;
    DFP_CHECK(dim == 3 && attributes == 0 && (count == 0 || number == first));

    for(const std::string& file : {ele, off}) {
      const auto faces = IO::read_faces(file, points.size());
      DFP_CHECK(faces.size() == (dt.dimension() == 2 ? dt.number_of_faces() : 0));
      DT_with_info<K> again;
      const DFP::Statistics s = DFP::delaunay_from_prediction(points, faces, again);
      DFP_CHECK_MSG(check_is_cgal_delaunay(again, points), file);
      DFP_CHECK_MSG(dt.dimension() < 2 || (s.faces_certified == s.faces_in && !s.fell_back), file);
    }
    const auto edges = IO::read_edges(edge, points.size());
    DFP_CHECK(edges.size() == dt.number_of_vertices() - 1 + (dt.dimension() == 2 ? dt.number_of_faces() : 0));
    DT_with_info<K> again;
    DFP::delaunay_from_predicted_edges(points, edges, again);
    DFP_CHECK(check_is_cgal_delaunay(again, points));
    Points read;
    IO::read_points(off, read);
    DFP_CHECK(read == points);
  }
}

} // namespace

int main()
{
  Folder folder;
  CGAL::Random rng(2525);
  DFP_RUN(test_file_format());
  DFP_RUN(test_coordinates_round_trip(folder));
  DFP_RUN(test_point_formats(folder));
  DFP_RUN(test_large_files(folder));
  DFP_RUN(test_face_formats(folder));
  DFP_RUN(test_malformed(folder));
  DFP_RUN(test_written_triangulation_is_read_back(folder, uniform_points(3000, rng), "uniform"));
  DFP_RUN(test_written_triangulation_is_read_back(folder, grid_points(30, 30, rng), "grid"));
  DFP_RUN(test_written_triangulation_is_read_back(folder, collinear_points(40, rng), "collinear"));
  DFP_RUN(test_written_triangulation_is_read_back(folder, with_duplicates(uniform_points(500, rng), 60, rng),
                                                  "duplicates"));
  DFP_RUN(test_written_triangulation_is_read_back(folder, transformed(uniform_points(500, rng), 1e290, 0),
                                                  "huge"));
  return finish("test_file_io");
}
