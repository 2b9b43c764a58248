// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// dfp: the package's command-line tool. `dfp triangulate` reads points and, optionally, a
// prediction of their Delaunay triangulation from files, computes the triangulation with
// delaunay_from_prediction() and writes it; `dfp kinetic` keeps one triangulation through a
// sequence of point frames with Kinetic_Delaunay_triangulation_2 (make_delaunay() in place, a
// rebuild when points merge or split). With `--periodic XMIN YMIN XMAX YMAX` both work on the
// flat torus (CGAL's Periodic_2_Delaunay_triangulation_2, periodic_2.h) and write each triangle
// with its corners' offsets. `dfp --help` tells the rest.
//
// Exit status: 0 on success, 1 for an input or output error (the message names the file and
// the line), 2 for a wrong command line, 3 when --check finds a difference with CGAL's build.

#include <CGAL/Delaunay_from_predicted_edges_2.h>
#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_from_prediction/file_io.h>
#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/periodic_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <thread>
#endif

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
// --periodic: CGAL's periodic Delaunay triangulation, vertices with the point index as info().
using Periodic_traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
using Periodic_vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Periodic_traits,
                                                                CGAL::Periodic_2_triangulation_vertex_base_2<Periodic_traits>>;
using Periodic_fb = CGAL::Periodic_2_triangulation_face_base_2<Periodic_traits>;
using Periodic_DT = CGAL::Periodic_2_Delaunay_triangulation_2<Periodic_traits, CGAL::Triangulation_data_structure_2<Periodic_vb, Periodic_fb>>;
namespace DFP = CGAL::Delaunay_from_prediction;
namespace IO = CGAL::Delaunay_from_prediction::IO;

const char* const usage_text =
    "usage: dfp triangulate POINTS [--prediction FACES] -o OUT [options]\n"
    "       dfp kinetic FRAME... [--prediction FACES] [-o OUT] [options]\n"
    "       dfp --help | --version\n"
    "\n"
    "triangulate  computes the Delaunay triangulation of POINTS, using FACES (if given) as a\n"
    "             prediction of it, and writes it to OUT.\n"
    "kinetic      triangulates the first frame (using FACES if given), then moves its vertices\n"
    "             to each next frame's points and repairs the triangulation in place (rebuilt\n"
    "             when points merge or split: Kinetic_Delaunay_triangulation_2). Every\n"
    "             frame has the same number of points, the same point in the same place.\n"
    "             OUT with '{}' writes every frame ('{}' becomes the frame number, from 0);\n"
    "             without, the last frame only.\n"
    "\n"
    "POINTS, FRAME  Triangle .node (numbered from 0 or 1), .off (z ignored), or plain text\n"
    "               (any other extension, e.g. .xyz): one 'x y' or 'x y z' per line.\n"
    "FACES          .ele or .off faces (a polygon is read as a fan of triangles), or a .edge\n"
    "               edge list (Triangle's formats; the indices numbered as the file's items).\n"
    "OUT            by extension: .ele (numbered as the .node, else from 0), .off, or .edge\n"
    "               (the edges: the only output that holds collinear points' triangulation).\n"
    "In every file, '#' starts a comment and commas count as blanks.\n"
    "\n"
    "options:\n"
    "  --stats            print what the call did (the package's Statistics) and the times,\n"
    "                     of each stage of the call too (read with a visitor: DFP::Stage)\n"
    "  --check            compare the result with CGAL's Delaunay_triangulation_2 built from\n"
    "                     scratch; exit status 3 if they differ\n"
    "  --threads N        run on N threads (0: all cores; default 1); the result is the same\n"
    "  --strategy NAME    automatic (default), flips, carve, t_division, regions, rebuild,\n"
    "                     spanning_tree, section_3, theorem_4_1, theorem_5_4: see the\n"
    "                     manual\n"
    "  --cgal             ignore the prediction and build with CGAL's Delaunay_triangulation_2\n"
    "                     (range insertion), for comparisons; kinetic: every frame so\n"
    "  --periodic XMIN YMIN XMAX YMAX\n"
    "                     triangulate on the flat torus [XMIN, XMAX) x [YMIN, YMAX) (a square:\n"
    "                     CGAL's Periodic_2_Delaunay_triangulation_2), every point inside it;\n"
    "                     FACES are index triples, OUT a .ele file whose triangles carry six\n"
    "                     attributes, each corner's offset in periods (x, y); --check and --cgal\n"
    "                     use CGAL's periodic triangulation\n"
    "  --quiet            no progress lines on stderr (printed for files over 64 MiB)\n";

struct Usage_error
{
  std::string message;
};

struct Options
{
  std::string command;
  std::vector<std::string> inputs;
  std::string prediction;
  std::string output;
  bool stats = false;
  bool check = false;
  bool cgal = false;
  bool quiet = false;
  long threads = 1;
  DFP::Strategy strategy = DFP::Strategy::automatic;
  bool periodic = false;
  std::array<double, 4> domain = {0, 0, 1, 1}; // --periodic XMIN YMIN XMAX YMAX
};

double number_named(const std::string& option, const std::string& value)
{
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  if(value.empty() || *end != '\0' || !std::isfinite(x))
    throw Usage_error{option + " needs finite numbers, not '" + value + "'"};
  return x;
}

DFP::Strategy strategy_named(const std::string& name)
{
  const std::pair<const char*, DFP::Strategy> names[] = {
      {"automatic", DFP::Strategy::automatic}, {"flips", DFP::Strategy::flips},
      {"carve", DFP::Strategy::carve},         {"t_division", DFP::Strategy::t_division},
      {"regions", DFP::Strategy::regions},     {"rebuild", DFP::Strategy::rebuild},
      {"spanning_tree", DFP::Strategy::spanning_tree}, {"section_3", DFP::Strategy::section_3},
      {"theorem_4_1", DFP::Strategy::theorem_4_1},     {"theorem_5_4", DFP::Strategy::theorem_5_4}};
  for(const auto& n : names)
    if(name == n.first)
      return n.second;
  throw Usage_error{"unknown strategy '" + name + "'"};
}

Options parse_command_line(int argc, char** argv)
{
  Options o;
  if(argc < 2)
    throw Usage_error{"no command"};
  o.command = argv[1];
  if(o.command != "triangulate" && o.command != "kinetic")
    throw Usage_error{"unknown command '" + o.command + "'"};
  for(int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
        throw Usage_error{a + " needs a value"};
      return argv[++i];
    };
    if(a == "--prediction")
      o.prediction = value();
    else if(a == "-o" || a == "--output")
      o.output = value();
    else if(a == "--stats")
      o.stats = true;
    else if(a == "--check")
      o.check = true;
    else if(a == "--cgal")
      o.cgal = true;
    else if(a == "--quiet")
      o.quiet = true;
    else if(a == "--strategy")
      o.strategy = strategy_named(value());
    else if(a == "--periodic") {
      o.periodic = true;
      for(double& bound : o.domain)
        bound = number_named(a, value());
    }
    else if(a == "--threads") {
      const std::string v = value();
      char* end = nullptr;
      o.threads = std::strtol(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || o.threads < 0)
        throw Usage_error{"--threads needs a non-negative integer, not '" + v + "'"};
    } else if(a.size() > 1 && a[0] == '-')
      throw Usage_error{"unknown option '" + a + "'"};
    else
      o.inputs.push_back(a);
  }
  if(o.command == "triangulate") {
    if(o.inputs.size() != 1)
      throw Usage_error{"triangulate takes one POINTS file"};
    if(o.output.empty())
      throw Usage_error{"triangulate needs -o OUT"};
  } else if(o.inputs.empty())
    throw Usage_error{"kinetic needs at least one FRAME file"};
  if(o.periodic) {
    const double width = o.domain[2] - o.domain[0], height = o.domain[3] - o.domain[1];
    if(!(width > 0) || !(height > 0) || !std::isfinite(width) || !std::isfinite(height))
      throw Usage_error{"--periodic XMIN YMIN XMAX YMAX needs XMIN < XMAX and YMIN < YMAX"};
    if(width != height)
      throw Usage_error{"--periodic: the domain must be a square (XMAX - XMIN = YMAX - YMIN): CGAL's "
                        "periodic triangulation has one period"};
    if(!o.prediction.empty() && IO::file_format(o.prediction) == IO::File_format::edge)
      throw Usage_error{"--periodic takes a prediction of faces (.ele or .off), not edges"};
    if(!o.output.empty() && IO::file_format(o.output) != IO::File_format::ele)
      throw Usage_error{"--periodic writes a .ele file (the offsets as attributes), not '" + o.output + "'"};
  }
  if(!o.output.empty() && IO::file_format(o.output) == IO::File_format::node)
    throw Usage_error{"OUT is a .ele, .off or .edge file, not '" + o.output + "'"};
  if(!o.output.empty() && IO::file_format(o.output) == IO::File_format::xyz)
    throw Usage_error{"OUT is a .ele, .off or .edge file (by its extension), not '" + o.output + "'"};
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Progress lines on stderr, only for large files (over 64 MiB of points: several seconds).
struct Progress
{
  bool on = false;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void say(const std::string& what) const
  {
    if(on)
      std::fprintf(stderr, "dfp: %7.1f s  %s\n", seconds_since(start), what.c_str());
  }
};

long long file_size(const std::string& file)
{
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  return in ? static_cast<long long>(in.tellg()) : -1;
}

// A prediction read from a file: triangles, or edges for a .edge file.
struct Prediction
{
  std::vector<std::array<std::size_t, 3>> faces;
  std::vector<std::array<std::size_t, 2>> edges;
  bool has_edges = false;
};

Prediction read_prediction(const std::string& file, std::size_t n)
{
  Prediction p;
  if(file.empty())
    return p;
  if(IO::file_format(file) == IO::File_format::edge) {
    p.edges = IO::read_edges(file, n);
    p.has_edges = true;
  } else if(IO::file_format(file) == IO::File_format::ele || IO::file_format(file) == IO::File_format::off)
    p.faces = IO::read_faces(file, n);
  else
    throw IO::File_error(file, 0, "a prediction is a .ele, .off or .edge file");
  return p;
}

// CGAL's own build from scratch (range insertion, plane or torus): the reference of --check,
// and what --cgal runs.
template <class Triangulation>
void build_with_cgal(const std::vector<Point>& points, Triangulation& dt)
{
  std::vector<std::pair<Point, std::size_t>> indexed;
  indexed.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    indexed.emplace_back(points[i], i);
  dt.clear();
  dt.insert(indexed.begin(), indexed.end());
}

// The faces and edges of `dt` by the coordinates of their points, in a canonical order (a
// face starts at its smallest point, which keeps its orientation): two triangulations of the
// same points are the same iff these are equal, whichever index represents duplicate points.
using Coordinates = std::pair<double, double>;
std::pair<std::vector<std::array<Coordinates, 3>>, std::vector<std::array<Coordinates, 2>>> geometry_of(const DT& dt)
{
  auto at = [](DT::Vertex_handle v) { return Coordinates(v->point().x(), v->point().y()); };
  std::vector<std::array<Coordinates, 3>> faces;
  if(dt.dimension() == 2)
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
      std::array<Coordinates, 3> t = {at(f->vertex(0)), at(f->vertex(1)), at(f->vertex(2))};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      faces.push_back(t);
    }
  std::vector<std::array<Coordinates, 2>> edges;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    std::array<Coordinates, 2> s = {at(e->first->vertex(dt.cw(e->second))), at(e->first->vertex(dt.ccw(e->second)))};
    if(s[1] < s[0])
      std::swap(s[0], s[1]);
    edges.push_back(s);
  }
  std::sort(faces.begin(), faces.end());
  std::sort(edges.begin(), edges.end());
  return {faces, edges};
}

// True if `dt` is CGAL's Delaunay triangulation of `points`.
bool equals_cgal_build(const std::vector<Point>& points, const DT& dt)
{
  DT reference;
  build_with_cgal(points, reference);
  return geometry_of(dt) == geometry_of(reference);
}

// The periodic counterparts, for --periodic: the comparison as faces of (point, offset)
// corners, and the .ele output with the offsets.
// Each triangle as its corners (x, y, x offset, y offset), rotated to start at its least corner.
using Periodic_corner = std::array<double, 4>;
std::vector<std::array<Periodic_corner, 3>> geometry_of(const Periodic_DT& t)
{
  std::vector<std::array<Periodic_corner, 3>> faces;
  for(auto it = t.periodic_triangles_begin(Periodic_DT::UNIQUE); it != t.periodic_triangles_end(Periodic_DT::UNIQUE); ++it) {
    const int low_x = (std::min)({(*it)[0].second.x(), (*it)[1].second.x(), (*it)[2].second.x()});
    const int low_y = (std::min)({(*it)[0].second.y(), (*it)[1].second.y(), (*it)[2].second.y()});
    std::array<Periodic_corner, 3> f;
    for(int k = 0; k < 3; ++k)
      f[k] = {(*it)[k].first.x(), (*it)[k].first.y(), double((*it)[k].second.x() - low_x), double((*it)[k].second.y() - low_y)};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

bool equals_cgal_build(const std::vector<Point>& points, const Periodic_DT& t)
{
  Periodic_DT reference(t.domain());
  build_with_cgal(points, reference);
  return reference.is_1_cover() == t.is_1_cover() && geometry_of(t) == geometry_of(reference);
}

void write_triangulation(const std::string& file, const std::vector<Point>& points, const DT& dt, std::size_t first_index)
{
  IO::write_triangulation(file, points, dt, first_index);
}

void write_triangulation(const std::string& file, const std::vector<Point>&, const Periodic_DT& t, std::size_t first_index)
{
  IO::write_periodic_ele(file, DFP::indexed_periodic_triangles(t), first_index);
}

std::size_t number_of_triangles(const DT& dt) { return dt.dimension() == 2 ? dt.number_of_faces() : 0; }
std::size_t number_of_triangles(const Periodic_DT& t) { return DFP::indexed_periodic_triangles(t).size(); }

// What --check compares with, and what it found.
const char* name_of(const DT&) { return "CGAL's Delaunay_triangulation_2"; }
const char* name_of(const Periodic_DT&) { return "CGAL's Periodic_2_Delaunay_triangulation_2"; }
const char* result_name(const DT&) { return "CGAL's Delaunay triangulation"; }
const char* result_name(const Periodic_DT&) { return "CGAL's periodic Delaunay triangulation"; }

// A visitor of the package's calls (DFP::parameters::visitor) that times their stages, for --stats.
struct Stage_times
{
  std::vector<std::pair<DFP::Stage, double>> seconds; // each stage as it ended
  std::chrono::steady_clock::time_point began;
  void stage_begin(DFP::Stage) { began = std::chrono::steady_clock::now(); }
  void stage_end(DFP::Stage stage) { seconds.emplace_back(stage, seconds_since(began)); }
};

template <class Triangulation>
void print_statistics(const DFP::Statistics& s, double read_s, double triangulate_s, double write_s,
                      const Stage_times& stages, const Triangulation& dt, std::size_t n)
{
  std::cout << "points: " << n << "\nvertices: " << dt.number_of_vertices()
            << "\ntriangles: " << number_of_triangles(dt) << "\n";
  if constexpr(std::is_same_v<Triangulation, Periodic_DT>)
    std::cout << "covering: " << (dt.is_1_cover() ? "1-sheeted" : "9-sheeted") << "\n";
  std::cout << s << "time_read_s: " << read_s << "\ntime_triangulate_s: " << triangulate_s << "\n";
  for(const auto& stage : stages.seconds)
    std::cout << "time_stage_" << DFP::to_string(stage.first) << "_s: " << stage.second << "\n";
  std::cout << "time_write_s: " << write_s << "\n";
}

// The stage times of `stages` on one line: " stages_s check=0.01 certify=0.02 ...".
std::string stage_list(const Stage_times& stages)
{
  std::ostringstream out;
  out << " stages_s";
  for(const auto& stage : stages.seconds)
    out << " " << DFP::to_string(stage.first) << "=" << stage.second;
  return out.str();
}

// `pattern` with its "{}" replaced by `frame`; `pattern` itself when it has none.
std::string frame_file(const std::string& pattern, std::size_t frame)
{
  const std::size_t at = pattern.find("{}");
  if(at == std::string::npos)
    return pattern;
  return pattern.substr(0, at) + std::to_string(frame) + pattern.substr(at + 2);
}

template <class Tag, class Triangulation>
DFP::Statistics triangulate(const std::vector<Point>& points, const Prediction& prediction, Triangulation& dt,
                            const Options& o, Stage_times& stages)
{
  if(o.cgal) {
    build_with_cgal(points, dt);
    DFP::Statistics s;
    s.points_reinserted = points.size();
    s.fell_back = true;
    s.outcome = DFP::Outcome::rebuild_requested; // --cgal: CGAL's own build
    return s;
  }
  const auto np = DFP::parameters::strategy(o.strategy).visitor(std::ref(stages));
  if constexpr(std::is_same_v<Triangulation, DT>) // --periodic takes no edges (parse_command_line)
    if(prediction.has_edges)
      return DFP::delaunay_from_predicted_edges<Tag>(points, prediction.edges, dt, np);
  return DFP::delaunay_from_prediction<Tag>(points, prediction.faces, dt, np);
}

template <class Tag, class Triangulation>
int run_triangulate(const Options& o, Triangulation dt)
{
  Progress progress;
  progress.on = !o.quiet && file_size(o.inputs[0]) > (64ll << 20);
  const auto start = std::chrono::steady_clock::now();
  progress.say("reading " + o.inputs[0]);
  std::vector<Point> points;
  const std::size_t first_index = IO::read_points(o.inputs[0], points);
  if(!o.prediction.empty())
    progress.say("reading " + o.prediction);
  const Prediction prediction = read_prediction(o.prediction, points.size());
  const double read_s = seconds_since(start);

  progress.say("triangulating " + std::to_string(points.size()) + " points");
  const auto built = std::chrono::steady_clock::now();
  Stage_times stages;
  const DFP::Statistics s = triangulate<Tag>(points, prediction, dt, o, stages);
  const double triangulate_s = seconds_since(built);

  progress.say("writing " + o.output);
  const auto written = std::chrono::steady_clock::now();
  write_triangulation(o.output, points, dt, first_index);
  const double write_s = seconds_since(written);
  progress.say("done");

  if(o.stats)
    print_statistics(s, read_s, triangulate_s, write_s, stages, dt, points.size());
  if(o.check) {
    if(!equals_cgal_build(points, dt)) {
      std::cerr << "dfp: --check: the result differs from " << name_of(dt) << "\n";
      return 3;
    }
    std::cerr << "dfp: --check: the result is " << result_name(dt) << "\n";
  }
  return 0;
}

template <class Tag, class Triangulation>
int run_kinetic(const Options& o, Triangulation built)
{
  std::vector<Point> points;
  const std::size_t first_index = IO::read_points(o.inputs[0], points);
  const std::size_t n = points.size();
  Stage_times stages;
  DFP::Statistics s = triangulate<Tag>(points, read_prediction(o.prediction, n), built, o, stages);
  // The package's kinetic triangulation moves the vertices frame by frame (in place, or
  // rebuilt when points merge or split); --cgal builds every frame with CGAL instead.
  DFP::Kinetic_Delaunay_triangulation_2<Triangulation> kinetic(built);
  if(!o.cgal)
    kinetic.assign(built, points);
  const Triangulation& dt = o.cgal ? built : kinetic.triangulation();

  int status = 0;
  for(std::size_t frame = 0; frame < o.inputs.size(); ++frame) {
    const auto start = std::chrono::steady_clock::now();
    double read_s = 0;
    if(frame > 0) {
      std::vector<Point> next;
      IO::read_points(o.inputs[frame], next);
      if(next.size() != n)
        throw IO::File_error(o.inputs[frame], 0,
                             "the frame has " + std::to_string(next.size()) + " points, the first frame " +
                                 std::to_string(n));
      points.swap(next);
      read_s = seconds_since(start);
      const auto repair = std::chrono::steady_clock::now();
      stages.seconds.clear();
      if(o.cgal)
        s = triangulate<Tag>(points, Prediction(), built, o, stages);
      else
        s = kinetic.template move<Tag>(points, DFP::parameters::strategy(o.strategy).visitor(std::ref(stages)));
      const bool rebuilt = !o.cgal && kinetic.last_move_rebuilt();
      if(o.stats)
        std::cout << "frame " << frame << ": read_s " << read_s << " repair_s " << seconds_since(repair)
                  << " flips " << s.flips << " faces_certified " << s.faces_certified << "/" << s.faces_in
                  << " points_reinserted " << s.points_reinserted << (rebuilt ? " rebuilt" : "")
                  << (s.fell_back ? " fell_back" : "") << stage_list(stages) << "\n";
    } else if(o.stats)
      std::cout << "frame 0: built, faces_certified " << s.faces_certified << "/" << s.faces_in << " flips "
                << s.flips << " points_reinserted " << s.points_reinserted << (s.fell_back ? " fell_back" : "")
                << stage_list(stages) << "\n";
    if(!o.output.empty() && (o.output.find("{}") != std::string::npos || frame + 1 == o.inputs.size()))
      write_triangulation(frame_file(o.output, frame), points, dt, first_index);
    if(o.check && !equals_cgal_build(points, dt)) {
      std::cerr << "dfp: --check: frame " << frame << " (" << o.inputs[frame] << ") differs from " << name_of(dt)
                << "\n";
      status = 3;
    }
  }
  if(o.check && status == 0)
    std::cerr << "dfp: --check: every frame is " << result_name(dt) << "\n";
  return status;
}

template <class Tag, class Triangulation>
int run(const Options& o, Triangulation empty)
{
  return o.command == "triangulate" ? run_triangulate<Tag>(o, empty) : run_kinetic<Tag>(o, empty);
}

template <class Tag>
int run(const Options& o)
{
  if(o.periodic)
    return run<Tag>(o, Periodic_DT(Periodic_DT::Iso_rectangle(o.domain[0], o.domain[1], o.domain[2], o.domain[3])));
  return run<Tag>(o, DT());
}

// The first touch of a 4 KiB page costs a page fault, and a triangulation of 10^6 points
// touches some 87,000 of them: on the virtual machine measured, huge pages (about 7,000 faults)
// took the D = 0 run from 3.0 s to under 2 s (results/dfp_cli_end_to_end.txt). glibc (2.35 on) backs its large blocks with transparent huge
// pages (2 MiB, where the kernel allows them on request: Debian's default) when the tunable
// glibc.malloc.hugetlb=1 is set, which is read only when a program starts: so dfp starts
// itself again once with it. DFP_NO_HUGE_PAGES=1 keeps the process as it is.
void restart_with_huge_pages(char** argv)
{
#if defined(__linux__) && defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if(std::getenv("DFP_NO_HUGE_PAGES") != nullptr ||
     (tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr))
    return;
  const std::string value =
      tunables != nullptr && tunables[0] != '\0' ? std::string(tunables) + ":glibc.malloc.hugetlb=1" : "glibc.malloc.hugetlb=1";
  if(setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
    execv("/proc/self/exe", argv); // returns only if it failed: then go on as we are
#else
  (void)argv;
#endif
}

} // namespace

int main(int argc, char** argv)
{
  restart_with_huge_pages(argv);
  if(argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" ||
                   std::string(argv[1]) == "help")) {
    std::cout << usage_text;
    return 0;
  }
  if(argc >= 2 && std::string(argv[1]) == "--version") {
    std::cout << "dfp (Delaunay_from_prediction) 1.0.0\n";
    return 0;
  }
  try {
    const Options o = parse_command_line(argc, argv);
    if(o.threads == 1)
      return run<CGAL::Sequential_tag>(o);
#ifdef CGAL_LINKED_WITH_TBB
    const std::size_t threads = o.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : std::size_t(o.threads);
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return run<CGAL::Parallel_tag>(o);
#else
    std::cerr << "dfp: built without TBB: --threads is ignored, running on one thread\n";
    return run<CGAL::Sequential_tag>(o);
#endif
  } catch(const Usage_error& e) {
    std::cerr << "dfp: " << e.message << "\n\n" << usage_text;
    return 2;
  } catch(const IO::File_error& e) {
    std::cerr << "dfp: " << e.what() << "\n";
    return 1;
  } catch(const DFP::Invalid_prediction& e) {
    std::cerr << "dfp: " << e.what() << "\n";
    return 1;
  } catch(const std::bad_alloc&) {
    std::cerr << "dfp: out of memory\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "dfp: " << e.what() << "\n";
    return 1;
  }
}
