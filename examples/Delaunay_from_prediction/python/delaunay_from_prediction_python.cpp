// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction contributors
//
// The Python module `delaunay_from_prediction` (pybind11): the package's functions on numpy
// arrays, in and out.
//
//   import delaunay_from_prediction as dfp
//   triangles, stats = dfp.delaunay_from_prediction(points, faces)  # (n,2) float64, (m,3) ints
//   t = dfp.Triangulation(points); t.move(new_points); t.triangles
//
// Inputs are read straight from the numpy buffers into C++ vectors (no Python object per
// point), then the GIL is released for the C++ work; outputs are numpy arrays that take over
// the C++ vectors (no copy). Kernel: Exact_predicates_inexact_constructions_kernel; the
// vertices carry the index of their point as info().

// Python.h first: it defines feature macros the standard headers must see.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace DFP = CGAL::Delaunay_from_prediction;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using Vertex_handle = DT::Vertex_handle;
using Face = std::array<std::int64_t, 3>;
using Edge = std::array<std::int64_t, 2>;
using Index_pairs = std::vector<std::pair<std::size_t, std::size_t>>;

// ---------------------------------------------------------------------------------------------
// Reading the inputs

std::string shape_of(const py::array& a)
{
  std::ostringstream s;
  s << "(";
  for(py::ssize_t d = 0; d < a.ndim(); ++d)
    s << (d ? ", " : "") << a.shape(d);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

// (n, 2) coordinates, converted to C-contiguous float64 when they are not.
std::vector<Point> read_points(const py::handle& obj, const char* name)
{
  if(obj.is_none())
    throw py::type_error(std::string(name) + " must be an (n, 2) float64 array, got None");
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if(!a)
    throw py::type_error(std::string(name) + " must be an (n, 2) array of numbers, got an object of type " +
                         std::string(py::str(py::type::of(obj).attr("__name__"))) + " that numpy cannot convert to float64");
  if(a.ndim() != 2 || a.shape(1) != 2)
    throw py::value_error(std::string(name) + " must be an (n, 2) array, got shape " + shape_of(a));
  const std::size_t n = std::size_t(a.shape(0));
  const double* xy = a.data();
  std::vector<Point> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(xy[2 * i], xy[2 * i + 1]);
  return points;
}

// (m, C) integer indices (faces: C = 3, edges: C = 2), of any integer dtype, into n points.
// None or an empty array: no indices. Range checks are the C++ functions' (they name the face
// or edge), except for uint64 values above the int64 range, which are caught here, in the
// same words, because they are read as int64.
template <std::size_t C>
std::vector<std::array<std::int64_t, C>> read_indices(const py::handle& obj, const char* name, std::size_t n)
{
  std::vector<std::array<std::int64_t, C>> rows;
  if(obj.is_none())
    return rows;
  const char* item = C == 3 ? "face" : "edge";
  const char* shape = C == 3 ? "(m, 3)" : "(m, 2)";
  const py::array a = py::array::ensure(obj);
  if(!a)
    throw py::type_error(std::string(name) + " must be an " + shape + " integer array, got an object of type " +
                         std::string(py::str(py::type::of(obj).attr("__name__"))) + " that numpy cannot convert");
  // An empty list converts to an empty float64 array: accepted as "no prediction".
  if(a.size() == 0 && (a.ndim() == 1 || (a.ndim() == 2 && a.shape(1) == py::ssize_t(C))))
    return rows;
  const char kind = a.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must be an " + shape + " integer array, got dtype " +
                         std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || a.shape(1) != py::ssize_t(C))
    throw py::value_error(std::string(name) + " must be an " + shape + " integer array, got shape " + shape_of(a));
  const std::size_t m = std::size_t(a.shape(0));
  if(kind == 'u' && a.itemsize() == 8) {
    const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    const std::uint64_t* v = u.data();
    for(std::size_t k = 0; k < m * C; ++k)
      if(v[k] > std::uint64_t((std::numeric_limits<std::int64_t>::max)())) {
        std::ostringstream msg;
        msg << "Delaunay_from_prediction: " << item << " " << k / C << " has index " << v[k] << " ("
            << (C == 3 ? "position " : "end ") << k % C << "), outside the point range [0, " << n << ")";
        throw DFP::Invalid_prediction(msg.str());
      }
  }
  const auto s = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
  if(!s)
    throw py::type_error(std::string(name) + ": cannot convert dtype " + std::string(py::str(a.dtype())) + " to int64");
  const std::int64_t* v = s.data();
  rows.resize(m);
  for(std::size_t k = 0; k < m; ++k)
    for(std::size_t j = 0; j < C; ++j)
      rows[k][j] = v[C * k + j];
  return rows;
}

// The same check as the C++ functions make, with the same words, for `Triangulation.move()`,
// which must refuse before it touches anything.
void check_finite(const std::vector<Point>& points)
{
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      std::ostringstream msg;
      msg << "Delaunay_from_prediction: point " << i << " has a non-finite coordinate (" << points[i].x() << ", "
          << points[i].y() << ")";
      throw DFP::Invalid_prediction(msg.str());
    }
}

// ---------------------------------------------------------------------------------------------
// Writing the outputs

// An (rows, cols) int64 array that owns `values` (moved, not copied): a capsule deletes them.
py::array_t<std::int64_t> as_array(std::vector<std::int64_t>&& values, std::size_t cols)
{
  auto owned = std::make_unique<std::vector<std::int64_t>>(std::move(values));
  const std::size_t rows = owned->size() / cols;
  std::int64_t* data = owned->data();
  py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<std::int64_t>*>(p); });
  owned.release(); // the capsule owns it now
  return py::array_t<std::int64_t>({py::ssize_t(rows), py::ssize_t(cols)},
                                   {py::ssize_t(cols * sizeof(std::int64_t)), py::ssize_t(sizeof(std::int64_t))},
                                   data, owner);
}

std::vector<std::int64_t> flatten(const Index_pairs& pairs)
{
  std::vector<std::int64_t> flat;
  flat.reserve(2 * pairs.size());
  for(const auto& e : pairs) {
    flat.push_back(std::int64_t(e.first));
    flat.push_back(std::int64_t(e.second));
  }
  return flat;
}

// The finite faces as point-index triples, counterclockwise (CGAL's faces are); none below
// dimension 2.
std::vector<std::int64_t> triangles_of(const DT& dt)
{
  std::vector<std::int64_t> t;
  if(dt.dimension() < 2)
    return t;
  t.reserve(3 * dt.number_of_faces());
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for(int j = 0; j < 3; ++j)
      t.push_back(std::int64_t(f->vertex(j)->info()));
  return t;
}

py::dict stats_dict(const DFP::Statistics& s)
{
  py::dict d;
  d["faces_in"] = s.faces_in;
  d["faces_certified"] = s.faces_certified;
  d["flips"] = s.flips;
  d["points_reinserted"] = s.points_reinserted;
  d["fell_back"] = s.fell_back;
  d["edges_tested"] = s.edges_tested;
  d["edges_not_locally_delaunay"] = s.edges_not_locally_delaunay;
  d["points_unused"] = s.points_unused;
  d["duplicate_points"] = s.duplicate_points;
  d["input_reordered"] = s.input_reordered;
  d["faces_carved"] = s.faces_carved;
  d["holes_refilled"] = s.holes_refilled;
  d["carve_rounds"] = s.carve_rounds;
  d["regions"] = s.regions;
  d["bad_regions"] = s.bad_regions;
  d["boundary_vertices"] = s.boundary_vertices;
  d["edges_in"] = s.edges_in;
  d["points_located"] = s.points_located;
  d["faces_visited"] = s.faces_visited;
  d["walk_fallbacks"] = s.walk_fallbacks;
  d["insertion_rounds"] = s.insertion_rounds;
  d["fallback_reason"] = std::string(DFP::to_string(s.outcome));
  return d;
}

// ---------------------------------------------------------------------------------------------
// The work

// Calls `f(tag)` with the concurrency tag asked for: both instantiations are compiled once here.
template <class F>
auto with_tag(bool parallel, F f)
{
  if(parallel)
    return f(CGAL::Parallel_if_available_tag());
  return f(CGAL::Sequential_tag());
}

// representative[i]: the smallest index of a point equal to point i (the vertex info the
// package gives duplicates). A sort, done only when there are duplicates.
std::vector<std::size_t> smallest_equal_index(const std::vector<Point>& points)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const Point &p = points[a], &q = points[b];
    return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y() || (p.y() == q.y() && a < b)));
  });
  std::vector<std::size_t> representative(points.size());
  for(std::size_t k = 0; k < order.size(); ++k)
    representative[order[k]] = k > 0 && points[order[k]] == points[order[k - 1]] ? representative[order[k - 1]] : order[k];
  return representative;
}

// CGAL's own build from scratch (range insertion, spatial sort): the reference and baseline.
// CGAL keeps, for duplicates, the info of whichever came last in its spatial order: set to
// the smallest index, as the package does, so that the results compare.
std::vector<std::int64_t> cgal_delaunay(const std::vector<Point>& points)
{
  check_finite(points);
  std::vector<std::pair<Point, std::size_t>> with_index;
  with_index.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    with_index.emplace_back(points[i], i);
  DT dt;
  dt.insert(with_index.begin(), with_index.end());
  if(dt.number_of_vertices() < points.size()) {
    const std::vector<std::size_t> representative = smallest_equal_index(points);
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      v->info() = representative[v->info()];
  }
  return triangles_of(dt);
}

// A Delaunay triangulation kept for points that move: vertex handles per point index,
// repaired in place by make_delaunay() when the points move.
class Triangulation
{
public:
  Triangulation(const std::vector<Point>& points, bool parallel) : n_(points.size())
  {
    build(points, std::vector<Face>(), parallel);
  }

  std::size_t number_of_points() const { return n_; }

  struct Move_result
  {
    DFP::Statistics stats;
    bool rebuilt = false;
  };

  Move_result move(const std::vector<Point>& points, bool parallel)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    check_finite(points); // before anything changes
    // Indices that share a vertex (equal points) can stay in place only if they still coincide.
    bool in_place = true;
    if(shares_vertices_)
      for(std::size_t i = 0; i < n_ && in_place; ++i)
        in_place = points[i] == points[vertex_of_[i]->info()];
    if(in_place) {
      for(auto v = dt_->finite_vertices_begin(); v != dt_->finite_vertices_end(); ++v)
        v->set_point(points[v->info()]);
      try {
        return {with_tag(parallel, [&](auto tag) { return DFP::make_delaunay<decltype(tag)>(*dt_); }), false};
      } catch(const DFP::Invalid_prediction&) {
        // Two vertices moved onto one point: make_delaunay() left the connectivity as it was,
        // which is still a good prediction for the rebuild below.
      }
    }
    Move_result result;
    result.stats = build(points, DFP::internal::faces_of(*dt_), parallel);
    result.rebuilt = true;
    return result;
  }

  std::vector<std::int64_t> triangles() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return triangles_of(*dt_);
  }

  std::size_t number_of_triangles() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return dt_->dimension() == 2 ? dt_->number_of_faces() : 0;
  }

  std::vector<double> coordinates() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<double> xy(2 * n_);
    for(std::size_t i = 0; i < n_; ++i) {
      xy[2 * i] = vertex_of_[i]->point().x();
      xy[2 * i + 1] = vertex_of_[i]->point().y();
    }
    return xy;
  }

private:
  // Builds aside, then takes the result (a throw leaves *this as it was).
  template <class FaceRange>
  DFP::Statistics build(const std::vector<Point>& points, const FaceRange& faces, bool parallel)
  {
    auto dt = std::make_unique<DT>();
    const DFP::Statistics stats = with_tag(
        parallel, [&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, *dt); });
    std::vector<Vertex_handle> vertex_of(n_);
    for(auto v = dt->finite_vertices_begin(); v != dt->finite_vertices_end(); ++v)
      vertex_of[v->info()] = v;
    if(stats.duplicate_points > 0) {
      const std::vector<std::size_t> representative = smallest_equal_index(points);
      for(std::size_t i = 0; i < n_; ++i)
        vertex_of[i] = vertex_of[representative[i]];
    }
    dt_ = std::move(dt);
    vertex_of_ = std::move(vertex_of);
    shares_vertices_ = stats.duplicate_points > 0;
    return stats;
  }

  std::size_t n_;
  std::unique_ptr<DT> dt_;
  std::vector<Vertex_handle> vertex_of_; // by point index
  bool shares_vertices_ = false;         // some indices share a vertex (equal points)
  mutable std::mutex mutex_;             // the GIL is released while the C++ works
};

// ---------------------------------------------------------------------------------------------
// Docstrings

const char* const module_doc = R"doc(Delaunay triangulations from predictions (CGAL package Delaunay_from_prediction).

Every function takes points as an (n, 2) array of float64 (anything numpy converts is
accepted and converted) and indices as integer arrays (any integer dtype); results are numpy
int64 arrays of point indices. The exact predicates of CGAL's
Exact_predicates_inexact_constructions_kernel decide everything, so the results are exact:
a Delaunay triangulation is the one CGAL's Delaunay_triangulation_2 builds from the same
points (co-circular ties broken by CGAL's symbolic perturbation), whatever the prediction.
Equal points are represented by the smallest of their indices. Malformed input raises
InvalidPrediction (a ValueError); wrong shapes ValueError, wrong types TypeError. The GIL is
released while the C++ code runs.

    import delaunay_from_prediction as dfp
    triangles, stats = dfp.delaunay_from_prediction(points, faces)
    t = dfp.Triangulation(points)
    t.move(new_points)          # repaired in place
    t.triangles                 # (k, 3) int64, counterclockwise
)doc";

const char* const invalid_prediction_doc =
    R"doc(Malformed input (C++: CGAL::Delaunay_from_prediction::Invalid_prediction): an index outside
[0, n) (a negative one included), a face repeating an index, an edge joining a point to itself,
or a non-finite coordinate in any point. The message names the face, edge, index or point.
Nothing was changed when it is raised. Derives from ValueError.)doc";

const char* const delaunay_from_prediction_doc = R"doc(The Delaunay triangulation of `points`, using `faces` as a prediction of it.

points: (n, 2) array of coordinates (converted to C-contiguous float64 if needed).
faces:  (m, 3) integer array (any integer dtype) of point indices, in any orientation; it need
        not be a triangulation: wrong, missing, repeated, crossing or inverted faces only cost
        time. None or an empty array: no prediction (a build from scratch).
parallel: use CGAL::Parallel_if_available_tag (TBB's threads when the module is linked with
        TBB); the result is the same.

Returns (triangles, stats): triangles an (k, 3) int64 array of point indices, each
counterclockwise, exactly the faces of CGAL's Delaunay triangulation of the points (k = 0 when
all points are collinear); a duplicate point is represented by the smallest of its indices.
stats: a dict of the C++ Statistics members (faces_in, faces_certified, flips,
points_reinserted, fell_back, ..., fallback_reason as a str).

Raises InvalidPrediction (a ValueError) for an index out of range or negative, a face
repeating an index, or a non-finite coordinate; ValueError for wrong shapes; TypeError for
non-numeric points or non-integer faces.)doc";

const char* const delaunay_triangulation_doc = R"doc(CGAL's own Delaunay triangulation of `points`, built from scratch (range insertion into
Delaunay_triangulation_2, with a spatial sort): the reference the package's results equal, and
the baseline of the benchmarks. Returns an (k, 3) int64 array of point indices, each
counterclockwise; a duplicate point is represented by the smallest of its indices. Raises
InvalidPrediction for a non-finite coordinate.)doc";

const char* const triangulation_doc = R"doc(Triangulation(points, *, parallel=False)

The Delaunay triangulation of points that move (a kinetic triangulation). The constructor
builds the Delaunay triangulation of `points` ((n, 2) array) with delaunay_from_prediction()
and no prediction, and keeps one vertex per point index (indices of equal points share one).
move(new_points) repairs it in place; .triangles gives its faces.)doc";

const char* const move_doc = R"doc(Moves point i to new_points[i] for every i and makes the triangulation the Delaunay
triangulation of the new points. new_points must have the same number of points (ValueError
otherwise).

- Usual case: each vertex's point is set (vertex->set_point()) and make_delaunay() repairs the
  triangulation in place, whatever the moves (inverted faces, a change of dimension): the
  previous triangulation is its prediction, and vertex handles survive.
- Two points moved onto the same position: make_delaunay() refuses (two vertices at one
  point), and the triangulation is rebuilt with delaunay_from_prediction(new_points, current
  triangles); the indices of the equal points then share one vertex.
- Points that were equal (sharing a vertex since the constructor or an earlier move) and no
  longer are: a vertex cannot be split in place, so the triangulation is rebuilt the same way.
  While equal points stay equal, the move is in place.
- A non-finite new coordinate: raises InvalidPrediction before anything is changed (the
  points and triangles stay those before the call).

parallel: CGAL::Parallel_if_available_tag for make_delaunay() or the rebuild; same result.
Returns the stats dict of the C++ call (as delaunay_from_prediction()), plus 'rebuilt': True
when the triangulation was rebuilt instead of repaired in place.)doc";

const char* const emst_doc = R"doc(The Euclidean minimum spanning tree of `points`, read off their Delaunay triangulation, which
is built from a prediction: exactly one of
  faces: (m, 3) integer array, a predicted triangulation (any faces, as for
         delaunay_from_prediction(); C++ euclidean_minimum_spanning_tree_from_predicted_faces), or
  edges: (e, 2) integer array, a predicted spanning tree, or any graph on the points (edges may
         cross, repeat, or be wrong; C++ euclidean_minimum_spanning_tree_from_prediction).
An empty array means no prediction.

Returns an (n - 1, 2) int64 array (for n >= 1) of pairs (i, j), i < j, in increasing
lexicographic order. Ties: edges are ordered by exact length, then by their pair of indices;
the tree is the unique minimum for that order. Equal points are joined by zero-length edges to
the smallest index among them, so the tree spans every index.
Raises ValueError unless exactly one of faces and edges is given; InvalidPrediction (a
ValueError) for an index out of range, a repeated index in a face, an edge joining a point to
itself, or a non-finite coordinate.)doc";

const char* const rng_doc = R"doc(The relative neighbourhood graph of `points`: p q is an edge iff no point r has both
|pr| < |pq| and |qr| < |pq| (the open lune is empty). Built from a predicted graph on the
points, `edges` ((e, 2) integer array; a connected graph close to the result, e.g. a guess of
it, is fastest; any graph is accepted, None or empty: no prediction), as the C++
relative_neighborhood_graph_from_prediction(). Equal points count as one, the smallest of
their indices. Returns an (e', 2) int64 array of pairs (i, j), i < j, in increasing
lexicographic order. Raises InvalidPrediction (a ValueError) for an end out of range, an edge
joining a point to itself, or a non-finite coordinate.)doc";

const char* const gabriel_doc = R"doc(The Gabriel graph of `points`: p q is an edge iff the closed disk with diameter p q holds no
other point (a point on its circle removes the edge). Built from a predicted graph on the
points, `edges` ((e, 2) integer array; any graph is accepted, a connected one close to the
result is fastest; None or empty: no prediction), as the C++ gabriel_graph_from_prediction().
Equal points count as one, the smallest of their indices. Returns an (e', 2) int64 array of
pairs (i, j), i < j, in increasing lexicographic order. Raises InvalidPrediction (a ValueError)
for an end out of range, an edge joining a point to itself, or a non-finite coordinate.)doc";

} // namespace

PYBIND11_MODULE(delaunay_from_prediction, m)
{
  m.doc() = module_doc;
  // Invalid_prediction derives from std::invalid_argument, which pybind11 already turns into
  // ValueError; this more specific translator is registered later, so it is tried first.
  auto invalid_prediction = py::register_exception<DFP::Invalid_prediction>(m, "InvalidPrediction", PyExc_ValueError);
  invalid_prediction.attr("__doc__") = invalid_prediction_doc;

  m.def(
      "delaunay_from_prediction",
      [](const py::object& points_in, const py::object& faces_in, bool parallel) {
        const std::vector<Point> points = read_points(points_in, "points");
        const std::vector<Face> faces = read_indices<3>(faces_in, "faces", points.size());
        DFP::Statistics stats;
        std::vector<std::int64_t> triangles;
        {
          py::gil_scoped_release nogil;
          DT dt;
          stats = with_tag(parallel,
                           [&](auto tag) { return DFP::delaunay_from_prediction<decltype(tag)>(points, faces, dt); });
          triangles = triangles_of(dt);
        }
        return py::make_tuple(as_array(std::move(triangles), 3), stats_dict(stats));
      },
      py::arg("points"), py::arg("faces") = py::none(), py::kw_only(), py::arg("parallel") = false,
      delaunay_from_prediction_doc);

  m.def(
      "delaunay_triangulation",
      [](const py::object& points_in) {
        const std::vector<Point> points = read_points(points_in, "points");
        std::vector<std::int64_t> triangles;
        {
          py::gil_scoped_release nogil;
          triangles = cgal_delaunay(points);
        }
        return as_array(std::move(triangles), 3);
      },
      py::arg("points"), delaunay_triangulation_doc);

  py::class_<Triangulation>(m, "Triangulation", triangulation_doc)
      .def(py::init([](const py::object& points_in, bool parallel) {
             const std::vector<Point> points = read_points(points_in, "points");
             py::gil_scoped_release nogil;
             return std::make_unique<Triangulation>(points, parallel);
           }),
           py::arg("points"), py::kw_only(), py::arg("parallel") = false,
           "Builds the Delaunay triangulation of points, an (n, 2) array (see the class documentation).")
      .def(
          "move",
          [](Triangulation& t, const py::object& points_in, bool parallel) {
            const std::vector<Point> points = read_points(points_in, "new_points");
            if(points.size() != t.number_of_points())
              throw py::value_error("new_points must have the triangulation's " + std::to_string(t.number_of_points()) +
                                    " points, got " + std::to_string(points.size()));
            Triangulation::Move_result result;
            {
              py::gil_scoped_release nogil;
              result = t.move(points, parallel);
            }
            py::dict stats = stats_dict(result.stats);
            stats["rebuilt"] = result.rebuilt;
            return stats;
          },
          py::arg("new_points"), py::kw_only(), py::arg("parallel") = false, move_doc)
      .def_property_readonly(
          "triangles",
          [](const Triangulation& t) {
            std::vector<std::int64_t> triangles;
            {
              py::gil_scoped_release nogil;
              triangles = t.triangles();
            }
            return as_array(std::move(triangles), 3);
          },
          "(k, 3) int64 array of point indices, each face counterclockwise (a new array each time; "
          "equal points: the smallest of their indices).")
      .def_property_readonly(
          "points",
          [](const Triangulation& t) {
            std::vector<double> xy = t.coordinates();
            py::array_t<double> a({py::ssize_t(t.number_of_points()), py::ssize_t(2)});
            std::copy(xy.begin(), xy.end(), a.mutable_data());
            return a;
          },
          "(n, 2) float64 array: a copy of the current points, by index.")
      .def_property_readonly("number_of_points", &Triangulation::number_of_points, "n, the number of point indices.")
      .def("__repr__", [](const Triangulation& t) {
        return "<delaunay_from_prediction.Triangulation of " + std::to_string(t.number_of_points()) + " points, " +
               std::to_string(t.number_of_triangles()) + " triangles>";
      });

  m.def(
      "euclidean_minimum_spanning_tree",
      [](const py::object& points_in, const py::object& faces_in, const py::object& edges_in) {
        if(faces_in.is_none() == edges_in.is_none())
          throw py::value_error("euclidean_minimum_spanning_tree(): give exactly one of faces= (a predicted "
                                "triangulation) and edges= (a predicted spanning tree or graph)");
        const std::vector<Point> points = read_points(points_in, "points");
        Index_pairs tree;
        if(!faces_in.is_none()) {
          const std::vector<Face> faces = read_indices<3>(faces_in, "faces", points.size());
          py::gil_scoped_release nogil;
          DFP::euclidean_minimum_spanning_tree_from_predicted_faces(points, faces, std::back_inserter(tree));
        } else {
          const std::vector<Edge> edges = read_indices<2>(edges_in, "edges", points.size());
          py::gil_scoped_release nogil;
          DFP::euclidean_minimum_spanning_tree_from_prediction(points, edges, std::back_inserter(tree));
        }
        return as_array(flatten(tree), 2);
      },
      py::arg("points"), py::kw_only(), py::arg("faces") = py::none(), py::arg("edges") = py::none(), emst_doc);

  m.def(
      "relative_neighborhood_graph",
      [](const py::object& points_in, const py::object& edges_in) {
        const std::vector<Point> points = read_points(points_in, "points");
        const std::vector<Edge> edges = read_indices<2>(edges_in, "edges", points.size());
        Index_pairs graph;
        {
          py::gil_scoped_release nogil;
          DFP::relative_neighborhood_graph_from_prediction(points, edges, std::back_inserter(graph));
        }
        return as_array(flatten(graph), 2);
      },
      py::arg("points"), py::arg("edges") = py::none(), rng_doc);

  m.def(
      "gabriel_graph",
      [](const py::object& points_in, const py::object& edges_in) {
        const std::vector<Point> points = read_points(points_in, "points");
        const std::vector<Edge> edges = read_indices<2>(edges_in, "edges", points.size());
        Index_pairs graph;
        {
          py::gil_scoped_release nogil;
          DFP::gabriel_graph_from_prediction(points, edges, std::back_inserter(graph));
        }
        return as_array(flatten(graph), 2);
      },
      py::arg("points"), py::arg("edges") = py::none(), gabriel_doc);
}
