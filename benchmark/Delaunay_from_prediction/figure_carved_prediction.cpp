// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Draws the manual's figure of a carved prediction, the holes drawn over the mesh
// (doc/Delaunay_from_prediction/fig/carved_prediction.svg; scripts/experiments.sh runs it).
//
// The prediction: CGAL's Delaunay triangulation of n uniform points in the unit square (vertex
// info = point index), every vertex then moved with set_point() by Gaussian noise of standard
// deviation sigma times the mean spacing 1/sqrt(n), so that some faces are inverted. The
// program repeats what make_delaunay() does before it changes anything for good: the
// certificate collecting the faces that are not counterclockwise (with Lawson's flips between
// counterclockwise faces on its way, drawn as kept faces), untangle_by_flips(), and a
// Carve_repair with the star of the vertex opposite the longest edge of each face still bad
// carved (the choice of internal::carve_and_reinsert) and plan(default_carve_limits(n)). It does
// not commit: it reads is_removed() of every face and detached(), and draws
//   kept faces (light grey), faces flipped by the untangling (light orange), carved faces
//   (light red), the faces inverted before the untangling (dark red outlines), the boundary of
//   every hole (kept/carved edges and hull edges of carved faces, thick blue), the vertices to
//   reinsert (hollow black circles) and the others (dots), with a legend.
// Then make_delaunay() runs on a copy of the moved triangulation; its Statistics go to stdout
// on one line, and its result is checked against CGAL's Delaunay triangulation of the moved
// points (exit status 1 if they differ). What the figure shows goes to stderr.
//
// Usage: figure_carved_prediction OUTPUT.svg [--n N] [--sigma S] [--seed K]
//   N  number of points (default 400); S  sigma in units of the mean spacing (default 0.1);
//   K  seed of Splitmix64 (default 7).
// The defaults give the manual's figure: 26 inverted faces (4 with a hull vertex), 7 of them
// still inverted after the untangling, 6 holes. At 400 points a local repair takes at most
// n/16 + 16 = 41 inverted faces (default_carve_limits): moves of 0.25 spacing invert about 90
// (11% of the faces) and make_delaunay() rebuilds instead, so there would be nothing carved to
// draw; 0.15 inverts about 45. The program says so (exit status 2) when the certificate stops.

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/internal/toolbox/random.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace DFP = CGAL::Delaunay_from_prediction;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using Vertex_handle = DT::Vertex_handle;
using Face_handle = DT::Face_handle;
using Triple = std::array<std::size_t, 3>;

struct Options
{
  std::string output;
  std::size_t n = 400;
  double sigma = 0.1; // in units of the mean spacing 1/sqrt(n)
  std::uint64_t seed = 7;
};

[[noreturn]] void usage(const char* program, int status)
{
  std::fprintf(status == 0 ? stdout : stderr,
               "Usage: %s OUTPUT.svg [--n N] [--sigma S] [--seed K]\n"
               "  N: points (default 400); S: Gaussian moves in units of the mean spacing "
               "(default 0.1); K: seed (default 7)\n",
               program);
  std::exit(status);
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        usage(argv[0], 2);
      return argv[++i];
    };
    try {
      if(a == "--n")
        o.n = std::stoul(value());
      else if(a == "--sigma")
        o.sigma = std::stod(value());
      else if(a == "--seed")
        o.seed = std::stoull(value());
      else if(a == "--help" || a == "-h")
        usage(argv[0], 0);
      else if(!a.empty() && a[0] != '-' && o.output.empty())
        o.output = a;
      else
        usage(argv[0], 2);
    } catch(const std::exception&) {
      usage(argv[0], 2);
    }
  }
  if(o.output.empty() || o.n < 3 || !(o.sigma >= 0))
    usage(argv[0], 2);
  return o;
}

// A face as the indices of its points, rotated so that the smallest comes first (orientation
// kept): equal faces give equal triples.
Triple triple_of(Face_handle f)
{
  Triple t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

std::vector<Triple> faces_of(const DT& tr)
{
  std::vector<Triple> faces;
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    faces.push_back(triple_of(f));
  std::sort(faces.begin(), faces.end());
  return faces;
}

// ---------------------------------------------------------------------------------------------
// SVG output.
class Svg
{
public:
  // The drawing: `points` mapped into a square of `side` px at (margin, margin), y up.
  Svg(const std::vector<Point>& points, double side, double margin) : margin_(margin)
  {
    double x0 = points[0].x(), x1 = x0, y0 = points[0].y(), y1 = y0;
    for(const Point& p : points) {
      x0 = std::min(x0, p.x());
      x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y());
      y1 = std::max(y1, p.y());
    }
    scale_ = side / std::max(x1 - x0, y1 - y0);
    // Centre the drawing in the square.
    ox_ = x0 - 0.5 * (side / scale_ - (x1 - x0));
    oy_ = y1 + 0.5 * (side / scale_ - (y1 - y0));
  }
  double x(const Point& p) const { return margin_ + (p.x() - ox_) * scale_; }
  double y(const Point& p) const { return margin_ + (oy_ - p.y()) * scale_; }
  std::string xy(const Point& p) const
  {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f,%.2f", x(p), y(p));
    return buf;
  }

private:
  double margin_, scale_ = 1, ox_ = 0, oy_ = 0;
};

const char* const kept_fill = "#e4e4e4";
const char* const edge_color = "#9a9a9a";
const char* const untangled_fill = "#ffcc80";
const char* const carved_fill = "#f4a3a3";
const char* const inverted_color = "#8b0000";
const char* const hole_color = "#1f4fd6";

} // namespace

int main(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  const std::size_t n = o.n;

  // 1. The prediction: the Delaunay triangulation of uniform points, then every vertex moved.
  DFP::internal::Splitmix64 rng{o.seed};
  std::vector<std::pair<Point, std::size_t>> input(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double x = rng.uniform();
    input[i] = {Point(x, rng.uniform()), i};
  }
  DT tr;
  tr.insert(input.begin(), input.end());
  const double sigma = o.sigma / std::sqrt(double(n));
  std::vector<Point> moved(n);
  for(std::size_t i = 0; i < n; ++i) {
    const double dx = sigma * rng.normal();
    moved[i] = Point(input[i].first.x() + dx, input[i].first.y() + sigma * rng.normal());
  }
  // The vertices of the hull, before the moves: an inverted face with one of them is "near the
  // hull".
  std::set<std::size_t> hull;
  {
    DT::Vertex_circulator c = tr.incident_vertices(tr.infinite_vertex()), done = c;
    do
      hull.insert(c->info());
    while(++c != done);
  }
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    v->set_point(moved[v->info()]);
  DT copy(tr); // for make_delaunay()

  // 2. What make_delaunay() does before the repair commits (make_delaunay, carve_and_reinsert).
  std::vector<std::pair<Face_handle, int>> stack;
  std::vector<Face_handle> bad;
  std::size_t edges_tested = 0, flips = 0;
  bool hull_is_convex = false;
  const DFP::internal::Carve_limits limits = DFP::internal::default_carve_limits(tr.number_of_vertices());
  DFP::internal::Flip_log<DT> untangled; // every flip before the carve, as in make_delaunay()
  std::vector<Face_handle> touched;
  DFP::internal::Inline_flips<DT> inline_flips{DFP::internal::default_max_flips(tr.number_of_vertices()), flips,
                                               touched, untangled};
  const DFP::Outcome why = DFP::internal::certify_faces(
      tr, stack, edges_tested, hull_is_convex, &bad, limits.max_bad_faces, &inline_flips);
  if(why != DFP::Outcome::ok) {
    std::size_t not_ccw = 0;
    for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
      not_ccw += CGAL::orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) ==
                         CGAL::LEFT_TURN ? 0 : 1;
    std::fprintf(stderr, "the certificate stopped: %s (%zu of %zu faces not ccw, at most %zu allowed); "
                 "choose a smaller --sigma or another --seed\n", DFP::to_string(why), not_ccw, tr.number_of_faces(),
                 limits.max_bad_faces);
    return 2;
  }
  std::vector<Triple> inverted; // before the untangling, as point indices (faces get flipped)
  std::size_t inverted_near_hull = 0;
  for(const Face_handle f : bad) {
    inverted.push_back(triple_of(f));
    bool near = false;
    for(int i = 0; i < 3; ++i)
      near = near || hull.count(f->vertex(i)->info()) > 0;
    inverted_near_hull += near ? 1 : 0;
  }
  const std::size_t flipped_in_certification = untangled.size();
  DFP::internal::untangle_by_flips(tr, bad, stack, untangled, touched);

  DFP::internal::Carve_repair<DT> carve(tr, true);
  for(const Face_handle f : bad) { // the choice of carve_and_reinsert
    int crossing = 0;
    double longest = -1;
    for(int i = 0; i < 3; ++i) {
      const Point& p = f->vertex(DFP::internal::ccw(i))->point();
      const Point& q = f->vertex(DFP::internal::cw(i))->point();
      const double dx = p.x() - q.x(), dy = p.y() - q.y();
      if(dx * dx + dy * dy > longest) {
        longest = dx * dx + dy * dy;
        crossing = i;
      }
    }
    carve.carve_star(f->vertex(crossing));
  }
  const DFP::Outcome plan_failed = bad.empty() ? DFP::Outcome::ok : carve.plan(limits);
  if(plan_failed != DFP::Outcome::ok)
    std::fprintf(stderr, "warning: the local repair gives up: %s\n", DFP::to_string(plan_failed));
  if(bad.empty())
    std::fprintf(stderr, "warning: the untangling flips repaired every face: nothing is carved\n");

  std::set<const void*> flipped; // by the untangling (each flip touched two faces)
  for(std::size_t k = 2 * flipped_in_certification; k < touched.size(); ++k)
    flipped.insert(&*touched[k]);
  std::set<std::size_t> detached;
  for(const Vertex_handle v : carve.detached())
    detached.insert(v->info());
  const bool carved_any = !bad.empty() && plan_failed == DFP::Outcome::ok;
  auto is_carved = [&](Face_handle f) { return carved_any && carve.is_removed(f); };

  // 3. The figure.
  const double side = 560, margin = 20, legend_height = 78;
  const double width = side + 2 * margin, height = side + 2 * margin + legend_height;
  Svg svg(moved, side, margin);
  std::ostringstream body;
  std::size_t count_kept = 0, count_flipped = 0, count_carved = 0, count_hole_edges = 0;
  std::ostringstream edges, holes;
  body << "<g id=\"faces\" stroke=\"none\">\n";
  for(auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f) {
    const char* fill = kept_fill;
    if(is_carved(f)) {
      fill = carved_fill;
      ++count_carved;
    } else if(flipped.count(&*f)) {
      fill = untangled_fill;
      ++count_flipped;
    } else {
      ++count_kept;
    }
    body << "<polygon points=\"" << svg.xy(f->vertex(0)->point()) << ' ' << svg.xy(f->vertex(1)->point()) << ' '
         << svg.xy(f->vertex(2)->point()) << "\" fill=\"" << fill << "\"/>\n";
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      const Point& a = f->vertex(DFP::internal::ccw(i))->point();
      const Point& b = f->vertex(DFP::internal::cw(i))->point();
      const bool hole_edge = tr.is_infinite(g) ? is_carved(f) : is_carved(f) != is_carved(g);
      if(hole_edge) {
        holes << "M" << svg.xy(a) << "L" << svg.xy(b);
        ++count_hole_edges;
      }
      if(tr.is_infinite(g) || &*f < &*g)
        edges << "M" << svg.xy(a) << "L" << svg.xy(b);
    }
  }
  body << "</g>\n";
  body << "<path id=\"edges\" fill=\"none\" stroke=\"" << edge_color << "\" stroke-width=\"0.6\" d=\""
       << edges.str() << "\"/>\n";
  body << "<g id=\"inverted\" fill=\"none\" stroke=\"" << inverted_color
       << "\" stroke-width=\"1.6\" stroke-linejoin=\"round\">\n";
  for(const Triple& t : inverted)
    body << "<polygon points=\"" << svg.xy(moved[t[0]]) << ' ' << svg.xy(moved[t[1]]) << ' ' << svg.xy(moved[t[2]])
         << "\"/>\n";
  body << "</g>\n";
  body << "<path id=\"holes\" fill=\"none\" stroke=\"" << hole_color
       << "\" stroke-width=\"2.6\" stroke-linecap=\"round\" d=\"" << holes.str() << "\"/>\n";
  body << "<g id=\"vertices\">\n";
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    char buf[160];
    if(detached.count(v->info()))
      std::snprintf(buf, sizeof buf,
                    "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3.6\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.3\"/>\n",
                    svg.x(v->point()), svg.y(v->point()));
    else
      std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.4\" fill=\"#202020\"/>\n",
                    svg.x(v->point()), svg.y(v->point()));
    body << buf;
  }
  body << "</g>\n";

  // The legend, three columns of up to three entries under the drawing.
  std::ostringstream legend;
  {
    const double top = side + 2 * margin + 6, row = 22;
    const double column[3] = {0, 190, 410}; // the middle texts are the longest
    legend << "<g id=\"legend\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"13\" fill=\"#000000\">\n";
    auto at = [&](int k, double& x, double& y) {
      x = margin + column[k / 3];
      y = top + row * (k % 3);
    };
    auto swatch = [&](int k, const std::string& shape, const std::string& text) {
      double x, y;
      at(k, x, y);
      char buf[96];
      std::snprintf(buf, sizeof buf, "<g transform=\"translate(%.1f,%.1f)\">", x, y);
      legend << buf << shape << "</g>";
      std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\">", x + 28, y + 13);
      legend << buf << text << "</text>\n";
    };
    const std::string box = "<rect x=\"0\" y=\"2\" width=\"20\" height=\"13\" ";
    swatch(0, box + "fill=\"" + kept_fill + "\" stroke=\"" + edge_color + "\" stroke-width=\"0.6\"/>", "kept face");
    swatch(1, box + "fill=\"" + untangled_fill + "\" stroke=\"" + edge_color + "\" stroke-width=\"0.6\"/>",
           "flipped by untangling");
    swatch(2, box + "fill=\"" + carved_fill + "\" stroke=\"" + edge_color + "\" stroke-width=\"0.6\"/>",
           "carved face");
    swatch(3, std::string("<path d=\"M1,15 L10,2 L19,15 Z\" fill=\"none\" stroke=\"") + inverted_color +
                  "\" stroke-width=\"1.6\" stroke-linejoin=\"round\"/>",
           "inverted before untangling");
    swatch(4, std::string("<path d=\"M0,8.5 L20,8.5\" stroke=\"") + hole_color + "\" stroke-width=\"2.6\"/>",
           "boundary of a hole");
    swatch(6, "<circle cx=\"10\" cy=\"8.5\" r=\"3.6\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.3\"/>",
           "vertex to reinsert");
    swatch(7, "<circle cx=\"10\" cy=\"8.5\" r=\"1.4\" fill=\"#202020\"/>", "other vertex");
    legend << "</g>\n";
  }

  std::size_t carved_infinite = 0; // all of them once the star of a hull vertex is carved
  for(auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
    carved_infinite += tr.is_infinite(f) && is_carved(f) ? 1 : 0;
  std::ostringstream summary;
  summary << n << " points moved by sigma = " << o.sigma << " x spacing (seed " << o.seed << "): "
          << inverted.size() << " faces inverted (" << inverted_near_hull << " near the hull), "
          << flipped_in_certification << " Lawson flips during certification, "
          << untangled.size() - flipped_in_certification << " untangling flips (" << count_flipped
          << " flipped faces kept), "
          << bad.size() << " faces still inverted, " << (carved_any ? carve.faces_removed() : 0)
          << " faces carved in " << (carved_any ? carve.rounds() : 0) << " round(s), "
          << (carved_any ? carve.holes() : 0) << " hole(s)" << (carved_infinite > 0 ? " and the outer boundary" : "")
          << " (" << count_hole_edges << " boundary edges), "
          << detached.size() << " vertices to reinsert, " << count_kept << " faces kept untouched";

  std::ofstream out(o.output);
  if(!out) {
    std::fprintf(stderr, "cannot write %s\n", o.output.c_str());
    return 2;
  }
  char header[400];
  std::snprintf(header, sizeof header,
                "<?xml version=\"1.0\" encoding=\"utf-8\" standalone=\"no\"?>\n"
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.0f %.0f\">\n",
                width, height, width, height);
  out << header << "<title>A carved prediction, the holes drawn over the mesh</title>\n"
      << "<desc>figure_carved_prediction --n " << n << " --sigma " << o.sigma << " --seed " << o.seed << ": "
      << summary.str() << "</desc>\n"
      << "<rect x=\"0\" y=\"0\" width=\"" << width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n"
      << body.str() << legend.str() << "</svg>\n";
  out.close();
  if(!out) {
    std::fprintf(stderr, "cannot write %s\n", o.output.c_str());
    return 2;
  }
  std::fprintf(stderr, "%s\nwrote %s\n", summary.str().c_str(), o.output.c_str());

  // 4. make_delaunay() on the copy, checked against CGAL's triangulation of the moved points.
  const DFP::Statistics stats = DFP::make_delaunay(copy);
  std::printf("faces_carved=%zu holes_refilled=%zu points_reinserted=%zu flips=%zu fell_back=%s%s%s\n",
              stats.faces_carved, stats.holes_refilled, stats.points_reinserted, stats.flips,
              stats.fell_back ? "true" : "false", stats.fell_back ? " fallback_reason=" : "",
              stats.fell_back ? to_string(stats.outcome) : "");
  if(carved_any && !stats.fell_back &&
     (stats.faces_carved != carve.faces_removed() || stats.holes_refilled != carve.holes() ||
      stats.points_reinserted != carve.detached().size()))
    std::fprintf(stderr, "warning: make_delaunay carved otherwise than the figure shows\n");

  std::vector<std::pair<Point, std::size_t>> moved_input(n);
  for(std::size_t i = 0; i < n; ++i)
    moved_input[i] = {moved[i], i};
  DT reference;
  reference.insert(moved_input.begin(), moved_input.end());
  if(copy.number_of_vertices() != reference.number_of_vertices() || faces_of(copy) != faces_of(reference)) {
    std::fprintf(stderr, "CHECK FAILED: make_delaunay's result differs from CGAL's Delaunay triangulation\n");
    return 1;
  }
  std::fprintf(stderr, "make_delaunay's result equals CGAL's Delaunay triangulation of the moved points\n");
  return 0;
}
