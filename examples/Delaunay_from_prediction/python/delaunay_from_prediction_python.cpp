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
//   d = dfp.Delaunay(points)    # a drop-in for scipy.spatial.Delaunay in 2D
//   t = dfp.Triangulation(points, domain=(0, 0, 1, 1))  # periodic: t.triangles, t.offsets
//
// Inputs are read straight from the numpy buffers into C++ vectors (no Python object per
// point), then the GIL is released for the C++ work; outputs are numpy arrays that take over
// the C++ vectors (no copy). Kernel: Exact_predicates_inexact_constructions_kernel; the
// vertices carry the index of their point as info().

// Python.h first: it defines feature macros the standard headers must see.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <CGAL/Delaunay_from_prediction_2.h>
#include <CGAL/Delaunay_from_prediction/Kinetic_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_from_prediction/Statistics.h>
#include <CGAL/Delaunay_from_prediction/periodic_2.h>
#include <CGAL/Delaunay_from_prediction/proximity_graphs.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_2.h>
#include <CGAL/Periodic_2_Delaunay_triangulation_traits_2.h>
#include <CGAL/Periodic_2_triangulation_face_base_2.h>
#include <CGAL/Periodic_2_triangulation_vertex_base_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;
namespace DFP = CGAL::Delaunay_from_prediction;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K>; // the simplex index (Delaunay)
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
using Vertex_handle = DT::Vertex_handle;
using Face = std::array<std::int64_t, 3>;
using Edge = std::array<std::int64_t, 2>;
using Index_pairs = std::vector<std::pair<std::size_t, std::size_t>>;
// domain=(xmin, ymin, xmax, ymax): CGAL's periodic Delaunay triangulation (the flat torus), the
// same vertex and face infos.
using Periodic_traits = CGAL::Periodic_2_Delaunay_triangulation_traits_2<K>;
using Periodic_vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Periodic_traits,
                                                                CGAL::Periodic_2_triangulation_vertex_base_2<Periodic_traits>>;
using Periodic_fb = CGAL::Triangulation_face_base_with_info_2<int, Periodic_traits,
                                                              CGAL::Periodic_2_triangulation_face_base_2<Periodic_traits>>;
using Periodic_DT =
    CGAL::Periodic_2_Delaunay_triangulation_2<Periodic_traits, CGAL::Triangulation_data_structure_2<Periodic_vb, Periodic_fb>>;

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

// domain=None or (xmin, ymin, xmax, ymax), a square of finite numbers: the periodic domain.
std::optional<std::array<double, 4>> read_domain(const py::object& obj)
{
  if(obj.is_none())
    return std::nullopt;
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if(!a || a.ndim() != 1 || a.shape(0) != 4)
    throw py::value_error("domain must be (xmin, ymin, xmax, ymax), four numbers");
  const std::array<double, 4> d = {a.data()[0], a.data()[1], a.data()[2], a.data()[3]};
  const double width = d[2] - d[0], height = d[3] - d[1];
  if(!(width > 0) || !(height > 0) || !std::isfinite(width) || !std::isfinite(height))
    throw py::value_error("domain=(xmin, ymin, xmax, ymax) needs finite numbers, xmin < xmax and ymin < ymax");
  if(width != height)
    throw py::value_error("domain must be a square (xmax - xmin == ymax - ymin): CGAL's periodic triangulation has "
                          "one period");
  return d;
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
  d["conflict_list_entries"] = s.conflict_list_entries;
  d["largest_conflict_list"] = s.largest_conflict_list;
  d["points_relocated"] = s.points_relocated;
  d["exceptional_cells"] = s.exceptional_cells;
  d["supercells"] = s.supercells;
  d["bad_supercells"] = s.bad_supercells;
  d["walls"] = s.walls;
  d["chain_edges"] = s.chain_edges;
  d["cells_computed"] = s.cells_computed;
  py::list regions_per_level;
  for(const std::size_t r : s.regions_per_level)
    regions_per_level.append(r);
  d["regions_per_level"] = regions_per_level;
  d["boundary_crossings"] = s.boundary_crossings;
  d["regions_keeping_prediction"] = s.regions_keeping_prediction;
  d["d_cross_guesses"] = s.d_cross_guesses;
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

// The package's Kinetic_Delaunay_triangulation_2 behind a mutex (the GIL is released while the
// C++ works, so two Python threads may call one object), with the finite faces numbered in
// their info() for the scipy-style attributes: face k is simplex k, infinite faces -1.
using Kinetic = DFP::Kinetic_Delaunay_triangulation_2<DT>;
using Periodic_kinetic = DFP::Kinetic_Delaunay_triangulation_2<Periodic_DT>;

// Numbers the triangles in their info(): finite faces 0, 1, ..., infinite ones -1.
void number_faces(const DT& dt)
{
  std::int32_t k = 0;
  for(auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f)
    f->info() = dt.is_infinite(f) ? -1 : k++;
}

// A periodic triangle as (point index, x offset, y offset) corners, offsets translated to least
// value 0, rotated to its least corner: the same for every copy of it in a 9-sheeted covering.
using Periodic_key = std::array<std::tuple<std::size_t, int, int>, 3>;
Periodic_key key_of(const Periodic_DT& t, Periodic_DT::Face_handle f)
{
  const auto pt = t.periodic_triangle(f);
  const int low_x = (std::min)({pt[0].second.x(), pt[1].second.x(), pt[2].second.x()});
  const int low_y = (std::min)({pt[0].second.y(), pt[1].second.y(), pt[2].second.y()});
  Periodic_key key;
  for(int k = 0; k < 3; ++k)
    key[k] = {t.get_original_vertex(f->vertex(k))->info(), pt[k].second.x() - low_x, pt[k].second.y() - low_y};
  std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
  return key;
}

// Numbers the periodic triangles in the order of DFP::indexed_periodic_triangles() (CGAL's
// UNIQUE order); the copies of a 9-sheeted covering get the number of their triangle.
void number_faces(const Periodic_DT& t)
{
  std::int32_t k = 0;
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f)
    f->info() = -1;
  for(auto it = t.periodic_triangles_begin(Periodic_DT::UNIQUE); it != t.periodic_triangles_end(Periodic_DT::UNIQUE); ++it)
    it.get_face()->info() = k++;
  if(t.is_1_cover())
    return;
  std::map<Periodic_key, std::int32_t> number;
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f)
    if(f->info() >= 0)
      number.emplace(key_of(t, f), f->info());
  for(auto f = t.faces_begin(); f != t.faces_end(); ++f)
    if(f->info() < 0) {
      const auto found = number.find(key_of(t, f));
      f->info() = found == number.end() ? -1 : found->second;
    }
}

template <class KineticTriangulation>
class Kinetic_points
{
public:
  using Triangulation = typename KineticTriangulation::Triangulation;

  Kinetic_points(const std::vector<Point>& points, const std::vector<Face>& faces, bool parallel,
                 const Triangulation& empty)
      : kinetic_(empty)
  {
    stats_ = with_tag(parallel, [&](auto tag) { return kinetic_.template build<decltype(tag)>(points, faces); });
  }

  std::size_t number_of_points() const { return kinetic_.number_of_points(); }

  // Moves the points by the class's rule (in place, or rebuilt when points merge or split).
  std::pair<DFP::Statistics, bool> move(const std::vector<Point>& points, bool parallel)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const DFP::Statistics stats =
        with_tag(parallel, [&](auto tag) { return kinetic_.template move<decltype(tag)>(points); });
    faces_numbered_ = false;
    return {stats, kinetic_.last_move_rebuilt()};
  }

  const DFP::Statistics& build_statistics() const { return stats_; }

  // Calls f(kinetic triangulation) under the lock, the finite faces numbered first when
  // `numbered`.
  template <class F>
  auto read(F f, bool numbered = false) const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if(numbered && !faces_numbered_) {
      number_faces(kinetic_.triangulation());
      faces_numbered_ = true;
    }
    return f(kinetic_);
  }

private:
  KineticTriangulation kinetic_;
  DFP::Statistics stats_;
  mutable bool faces_numbered_ = false;
  mutable std::mutex mutex_;
};

// The triangulation of a Python object: in the plane, or on the torus of `domain`.
class Core
{
public:
  Core(const std::vector<Point>& points, const std::vector<Face>& faces, bool parallel,
       const std::optional<std::array<double, 4>>& domain)
      : domain_(domain)
  {
    if(domain)
      torus_ = std::make_unique<Kinetic_points<Periodic_kinetic>>(
          points, faces, parallel, Periodic_DT(Periodic_DT::Iso_rectangle((*domain)[0], (*domain)[1], (*domain)[2], (*domain)[3])));
    else
      plane_ = std::make_unique<Kinetic_points<Kinetic>>(points, faces, parallel, DT());
  }

  // f(the Kinetic_points held): f takes either.
  template <class F>
  decltype(auto) visit(F f) const
  {
    return torus_ ? f(*torus_) : f(*plane_);
  }
  template <class F>
  decltype(auto) visit(F f)
  {
    return torus_ ? f(*torus_) : f(*plane_);
  }
  // f(the kinetic triangulation), under the lock, the faces numbered first when `numbered`.
  template <class F>
  auto read(F f, bool numbered = false) const
  {
    return visit([&](const auto& core) { return core.read(f, numbered); });
  }

  std::size_t number_of_points() const
  {
    return visit([](const auto& core) { return core.number_of_points(); });
  }
  const DFP::Statistics& build_statistics() const
  {
    return visit([](const auto& core) -> const DFP::Statistics& { return core.build_statistics(); });
  }
  std::pair<DFP::Statistics, bool> move(const std::vector<Point>& points, bool parallel)
  {
    return visit([&](auto& core) { return core.move(points, parallel); });
  }
  const std::optional<std::array<double, 4>>& domain() const { return domain_; }

private:
  std::optional<std::array<double, 4>> domain_;
  std::unique_ptr<Kinetic_points<Kinetic>> plane_;
  std::unique_ptr<Kinetic_points<Periodic_kinetic>> torus_;
};

py::object domain_tuple(const Core& core)
{
  if(!core.domain())
    return py::none();
  const auto& d = *core.domain();
  return py::make_tuple(d[0], d[1], d[2], d[3]);
}

// The periodic triangles as point-index triples (k, 3) and each corner's offset in periods
// (k, 3, 2, flattened), in the order of their numbers.
std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>> triangles_and_offsets(const Periodic_DT& t)
{
  std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>> out;
  for(const DFP::Indexed_periodic_triangle& triangle : DFP::indexed_periodic_triangles(t))
    for(int k = 0; k < 3; ++k) {
      out.first.push_back(std::int64_t(triangle.vertices[k]));
      out.second.push_back(triangle.offsets[k][0]);
      out.second.push_back(triangle.offsets[k][1]);
    }
  return out;
}

std::vector<std::int64_t> triangles_of(const Periodic_DT& t)
{
  std::vector<std::int64_t> triangles;
  for(const DFP::Indexed_periodic_triangle& triangle : DFP::indexed_periodic_triangles(t))
    triangles.insert(triangles.end(), triangle.vertices.begin(), triangle.vertices.end());
  return triangles;
}

// ---------------------------------------------------------------------------------------------
// scipy.spatial.Delaunay's attributes, read off the triangulation (dimension 2; below it there
// is no simplex). Arrays of np.intc, as scipy's.

using Intc = int; // np.intc

py::array_t<Intc> intc_array(std::vector<Intc>&& values, std::size_t cols)
{
  auto owned = std::make_unique<std::vector<Intc>>(std::move(values));
  const std::size_t rows = cols ? owned->size() / cols : owned->size();
  Intc* data = owned->data();
  py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<Intc>*>(p); });
  owned.release();
  if(cols == 0)
    return py::array_t<Intc>({py::ssize_t(rows)}, {py::ssize_t(sizeof(Intc))}, data, owner);
  return py::array_t<Intc>({py::ssize_t(rows), py::ssize_t(cols)},
                           {py::ssize_t(cols * sizeof(Intc)), py::ssize_t(sizeof(Intc))}, data, owner);
}

Intc index_of(Vertex_handle v) { return Intc(v->info()); }

// A finite face incident to v (-1: none, below dimension 2).
Intc simplex_at(const DT& dt, Vertex_handle v)
{
  if(dt.dimension() < 2)
    return -1;
  auto f = dt.incident_faces(v), done = f;
  do {
    if(!dt.is_infinite(f))
      return f->info();
  } while(++f != done);
  return -1;
}

// On the torus every face is a simplex (copies numbered as their triangle).
Intc simplex_at(const Periodic_DT&, Periodic_DT::Vertex_handle v) { return v->face()->info(); }

// simplices (k, 3), each counterclockwise, and neighbors (k, 3): neighbors[i][j] is the simplex
// opposite simplices[i][j], -1 on the hull.
std::pair<std::vector<Intc>, std::vector<Intc>> simplices_and_neighbors_of(const DT& dt)
{
  std::vector<Intc> simplices, neighbors;
  if(dt.dimension() == 2) {
    simplices.reserve(3 * dt.number_of_faces());
    neighbors.reserve(3 * dt.number_of_faces());
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      for(int j = 0; j < 3; ++j) {
        simplices.push_back(index_of(f->vertex(j)));
        neighbors.push_back(f->neighbor(j)->info());
      }
  }
  return {std::move(simplices), std::move(neighbors)};
}

// The hull's edges (h, 2), counterclockwise around the hull, each from one hull vertex to the
// next.
std::vector<Intc> convex_hull_edges(const DT& dt)
{
  std::vector<Intc> edges;
  if(dt.dimension() < 2)
    return edges;
  // The infinite faces circle the infinite vertex counterclockwise, which walks the hull
  // clockwise, and each holds its hull edge in the clockwise direction: both reversed.
  auto f = dt.incident_faces(dt.infinite_vertex()), done = f;
  do {
    const int i = f->index(dt.infinite_vertex());
    edges.push_back(index_of(f->vertex(dt.ccw(i))));
    edges.push_back(index_of(f->vertex(dt.cw(i))));
  } while(++f != done);
  std::reverse(edges.begin(), edges.end());
  return edges;
}

// The lists `around` packed as (indptr, indices): list k is indices[indptr[k]:indptr[k+1]].
std::pair<std::vector<Intc>, std::vector<Intc>> as_csr(const std::vector<std::vector<Intc>>& around)
{
  std::vector<Intc> indptr(around.size() + 1, 0), indices;
  for(std::size_t k = 0; k < around.size(); ++k)
    indptr[k + 1] = indptr[k] + Intc(around[k].size());
  indices.reserve(std::size_t(indptr.back()));
  for(const auto& a : around)
    indices.insert(indices.end(), a.begin(), a.end());
  return {std::move(indptr), std::move(indices)};
}

// (indptr, indices): the neighbours of point k are indices[indptr[k]:indptr[k+1]], counter-
// clockwise; none for a point that is not a vertex (a duplicate). Dimension 1 included.
std::pair<std::vector<Intc>, std::vector<Intc>> vertex_neighbor_vertices(const DT& dt, std::size_t n)
{
  std::vector<std::vector<Intc>> around(n);
  if(dt.dimension() >= 1)
    for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      std::vector<Intc>& out = around[v->info()];
      auto w = dt.incident_vertices(v), done = w;
      do {
        if(!dt.is_infinite(w))
          out.push_back(index_of(w));
      } while(++w != done);
    }
  return as_csr(around);
}

// coplanar (c, 3): the points that are no vertex (duplicates of a smaller index), each with a
// simplex holding its vertex (-1 below dimension 2) and that vertex's point index.
template <class KineticTriangulation>
std::vector<Intc> coplanar_points(const KineticTriangulation& k)
{
  std::vector<Intc> rows;
  for(std::size_t i = 0; i < k.number_of_points(); ++i)
    if(k.vertex(i)->info() != i) {
      rows.push_back(Intc(i));
      rows.push_back(simplex_at(k.triangulation(), k.vertex(i)));
      rows.push_back(Intc(k.vertex(i)->info()));
    }
  return rows;
}

// vertex_to_simplex (n,): a simplex holding each point's vertex, -1 below dimension 2.
template <class KineticTriangulation>
std::vector<Intc> vertex_to_simplex(const KineticTriangulation& k)
{
  std::vector<Intc> simplex(k.number_of_points());
  for(std::size_t i = 0; i < simplex.size(); ++i)
    simplex[i] = simplex_at(k.triangulation(), k.vertex(i));
  return simplex;
}

// The simplex holding each query point (closed triangles; -1 outside the hull, for a
// non-finite query and below dimension 2). The queries are visited in Hilbert order and each
// located by CGAL's exact walk from the previous answer.
std::vector<Intc> find_simplices(const DT& dt, const std::vector<Point>& queries)
{
  std::vector<Intc> found(queries.size(), -1);
  if(dt.dimension() < 2)
    return found;
  std::vector<std::size_t> order;
  order.reserve(queries.size());
  for(std::size_t i = 0; i < queries.size(); ++i)
    if(std::isfinite(queries[i].x()) && std::isfinite(queries[i].y()))
      order.push_back(i);
  using Pmap = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Spatial_sort_traits_adapter_2<K, Pmap>;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(queries)));
  DT::Face_handle hint;
  for(const std::size_t i : order) {
    DT::Locate_type lt;
    int li;
    DT::Face_handle f = dt.locate(queries[i], lt, li, hint);
    if(lt == DT::OUTSIDE_CONVEX_HULL || lt == DT::OUTSIDE_AFFINE_HULL)
      continue;
    hint = f;
    // On a hull edge or vertex, locate() may answer an infinite face: the finite face across
    // its finite edge holds the query too.
    if(dt.is_infinite(f))
      f = f->neighbor(f->index(dt.infinite_vertex()));
    found[i] = f->info();
  }
  return found;
}

// The same attributes on the torus: every simplex has three neighbours, there is no hull.

std::pair<std::vector<Intc>, std::vector<Intc>> simplices_and_neighbors_of(const Periodic_DT& t)
{
  std::vector<Intc> simplices, neighbors;
  for(auto it = t.periodic_triangles_begin(Periodic_DT::UNIQUE); it != t.periodic_triangles_end(Periodic_DT::UNIQUE); ++it) {
    const auto f = it.get_face();
    for(int j = 0; j < 3; ++j) {
      simplices.push_back(Intc(t.get_original_vertex(f->vertex(j))->info()));
      neighbors.push_back(f->neighbor(j)->info());
    }
  }
  return {std::move(simplices), std::move(neighbors)};
}

std::vector<Intc> convex_hull_edges(const Periodic_DT&) { return {}; }

// The neighbours of each point, counterclockwise, one per edge at its vertex (in a 9-sheeted
// covering a point may be its own neighbour, or another's twice, across different sides).
std::pair<std::vector<Intc>, std::vector<Intc>> vertex_neighbor_vertices(const Periodic_DT& t, std::size_t n)
{
  std::vector<std::vector<Intc>> around(n);
  for(auto v = t.unique_vertices_begin(); v != t.unique_vertices_end(); ++v) {
    std::vector<Intc>& out = around[v->info()];
    auto w = t.adjacent_vertices(v), done = w;
    if(w != nullptr)
      do
        out.push_back(Intc(t.get_original_vertex(w)->info()));
      while(++w != done);
  }
  return as_csr(around);
}

// `x` wrapped into [low, low + period) (a double computation; the side stays closed below).
double wrap(double x, double low, double period)
{
  double y = x - period * std::floor((x - low) / period);
  if(!(y < low + period))
    y = low;
  return y < low ? low : y;
}

// The simplex holding each query point, wrapped into the domain first (every point of the
// plane is in some translate of a triangle); -1 for a non-finite query.
std::vector<Intc> find_simplices(const Periodic_DT& t, const std::vector<Point>& queries)
{
  std::vector<Intc> found(queries.size(), -1);
  const auto& d = t.domain();
  const double period = d.xmax() - d.xmin();
  std::vector<Point> wrapped;
  std::vector<std::size_t> order;
  wrapped.reserve(queries.size());
  for(std::size_t i = 0; i < queries.size(); ++i) {
    const bool finite = std::isfinite(queries[i].x()) && std::isfinite(queries[i].y());
    wrapped.emplace_back(finite ? wrap(queries[i].x(), d.xmin(), period) : d.xmin(),
                         finite ? wrap(queries[i].y(), d.ymin(), period) : d.ymin());
    if(finite)
      order.push_back(i);
  }
  if(t.number_of_vertices() == 0)
    return found;
  using Pmap = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Spatial_sort_traits_adapter_2<K, Pmap>;
  const std::vector<Point>& sorted_by = wrapped;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(sorted_by)));
  Periodic_DT::Face_handle hint;
  for(const std::size_t i : order) {
    Periodic_DT::Locate_type lt;
    int li;
    hint = t.locate(wrapped[i], lt, li, hint);
    found[i] = hint->info();
  }
  return found;
}

// (n, 2) float64 array of the points.
py::array_t<double> xy_array(const std::vector<Point>& points)
{
  py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(2)});
  double* xy = a.mutable_data();
  for(std::size_t i = 0; i < points.size(); ++i) {
    xy[2 * i] = points[i].x();
    xy[2 * i + 1] = points[i].y();
  }
  return a;
}

// The current points, by index.
py::array_t<double> coordinates(const Core& core)
{
  return xy_array(core.read([](const auto& k) {
    std::vector<Point> points;
    points.reserve(k.number_of_points());
    for(std::size_t i = 0; i < k.number_of_points(); ++i)
      points.push_back(k.point(i));
    return points;
  }));
}

// move(new_points) of both classes: the stats dict of the call, plus 'rebuilt'.
py::dict move_points(Core& core, const py::object& points_in, bool parallel)
{
  const std::vector<Point> points = read_points(points_in, "new_points");
  if(points.size() != core.number_of_points())
    throw py::value_error("new_points must have the triangulation's " + std::to_string(core.number_of_points()) +
                          " points, got " + std::to_string(points.size()));
  std::pair<DFP::Statistics, bool> result;
  {
    py::gil_scoped_release nogil;
    result = core.move(points, parallel);
  }
  py::dict stats = stats_dict(result.first);
  stats["rebuilt"] = result.second;
  return stats;
}

// The Python class Triangulation.
struct Triangulation
{
  Triangulation(const std::vector<Point>& points, const std::vector<Face>& faces, bool parallel,
                const std::optional<std::array<double, 4>>& domain)
      : core(points, faces, parallel, domain)
  {}
  Core core;
};

// The Python class Delaunay: scipy.spatial.Delaunay's attributes, each computed when first read
// and kept until the next move().
struct Delaunay
{
  Delaunay(const std::vector<Point>& points, const std::vector<Face>& faces, bool parallel,
           const std::optional<std::array<double, 4>>& domain)
      : core(points, faces, parallel, domain), parallel(parallel)
  {}

  // py::object members are null until set: the object is made while the GIL is released.
  Core core;
  bool parallel;
  py::object points;     // (n, 2) float64 array
  py::object statistics; // dict
  py::object simplices_cache, neighbors_cache, offsets_cache, convex_hull_cache, vertex_neighbor_vertices_cache,
      coplanar_cache, vertex_to_simplex_cache;

  void forget()
  {
    for(py::object* o : {&simplices_cache, &neighbors_cache, &offsets_cache, &convex_hull_cache,
                         &vertex_neighbor_vertices_cache, &coplanar_cache, &vertex_to_simplex_cache})
      *o = py::object();
  }

  // slot, made by make(kinetic triangulation) with the faces numbered, if it is not yet.
  template <class Make>
  py::object cached(py::object& slot, Make make)
  {
    if(!slot) {
      py::object value = core.read([&](const auto& k) { return py::object(make(k)); }, true);
      slot = value;
    }
    return slot;
  }

  std::pair<py::object, py::object> simplices_and_neighbors()
  {
    if(!simplices_cache) {
      std::pair<std::vector<Intc>, std::vector<Intc>> both;
      {
        py::gil_scoped_release nogil;
        both = core.read([](const auto& k) { return simplices_and_neighbors_of(k.triangulation()); }, true);
      }
      simplices_cache = intc_array(std::move(both.first), 3);
      neighbors_cache = intc_array(std::move(both.second), 3);
    }
    return {simplices_cache, neighbors_cache};
  }

  py::array_t<Intc> find_simplex(const py::object& xi_in, bool /*bruteforce*/, const py::object& /*tol*/)
  {
    const auto xi = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(xi_in);
    if(!xi)
      throw py::type_error("xi must be an array of points of shape (..., 2)");
    if(xi.ndim() < 1 || xi.shape(xi.ndim() - 1) != 2)
      throw py::value_error("xi must be an array of shape (..., 2), got " + shape_of(xi));
    std::vector<py::ssize_t> shape(xi.shape(), xi.shape() + xi.ndim() - 1);
    const std::size_t count = std::size_t(xi.size() / 2);
    std::vector<Point> queries;
    queries.reserve(count);
    for(std::size_t i = 0; i < count; ++i)
      queries.emplace_back(xi.data()[2 * i], xi.data()[2 * i + 1]);
    std::vector<Intc> found;
    {
      py::gil_scoped_release nogil;
      found = core.read([&](const auto& k) { return find_simplices(k.triangulation(), queries); }, true);
    }
    py::array_t<Intc> out(shape);
    std::copy(found.begin(), found.end(), out.mutable_data());
    return out;
  }
};

// ---------------------------------------------------------------------------------------------
// Docstrings

const char* const module_doc = R"doc(Delaunay triangulations from predictions (CGAL package Delaunay_from_prediction).

Every function takes points as an (n, 2) array of float64 (anything numpy converts is
accepted and converted) and indices as integer arrays (any integer dtype). The functions and
Triangulation return numpy int64 arrays of point indices; Delaunay's arrays (simplices,
neighbors, offsets, convex_hull, vertex_neighbor_vertices, coplanar, vertex_to_simplex and
find_simplex's result) are np.intc, as scipy.spatial.Delaunay's. The exact predicates of CGAL's
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
    d = dfp.Delaunay(points)    # scipy.spatial.Delaunay's attributes, np.intc: d.simplices, d.neighbors, ...
    d.find_simplex(xi); d.move(new_points)
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

const char* const triangulation_doc = R"doc(Triangulation(points, *, parallel=False, domain=None)

The Delaunay triangulation of points that move (a kinetic triangulation), on the C++ class
Kinetic_Delaunay_triangulation_2. The constructor builds the Delaunay triangulation of
`points` ((n, 2) array) with delaunay_from_prediction() and no prediction, and keeps one vertex
per point index (indices of equal points share one). move(new_points) repairs it in place;
.triangles gives its faces. Delaunay is the same with scipy's attributes.

domain: None (the plane), or (xmin, ymin, xmax, ymax), a square: the triangulation is periodic
        in it (the flat torus), exactly CGAL's Periodic_2_Delaunay_triangulation_2 of the points
        (periodic_2.h). Every point, and every point given to move(), must lie in
        [xmin, xmax) x [ymin, ymax) (the caller wraps them): InvalidPrediction otherwise.
        .triangles then lists each periodic triangle once and .offsets each corner's offset in
        periods. With few or clustered points CGAL's covering is 9-sheeted; the triangles are
        still listed once each.)doc";

const char* const move_doc = R"doc(Moves point i to new_points[i] for every i and makes the triangulation the Delaunay
triangulation of the new points. new_points must have the same number of points (ValueError
otherwise). The rule is the C++ Kinetic_Delaunay_triangulation_2::move()'s:

- Usual case: each vertex's point is set (vertex->set_point()) and make_delaunay() repairs the
  triangulation in place, whatever the moves (inverted faces, a change of dimension): the
  previous triangulation is its prediction, and vertex handles survive.
- Two points moved onto the same position: make_delaunay() refuses (two vertices at one
  point), and the triangulation is rebuilt with delaunay_from_prediction(new_points, current
  triangles); the indices of the equal points then share one vertex.
- Points that were equal (sharing a vertex since the constructor or an earlier move) and no
  longer are: a vertex cannot be split in place, so the triangulation is rebuilt the same way.
  While equal points stay equal, the move is in place.
- A non-finite new coordinate, or with a domain a point outside it: raises InvalidPrediction
  before anything is changed (the points and triangles stay those before the call).
- With a domain, a move that leaves CGAL's covering 9-sheeted (before or after) rebuilds it
  ('rebuilt' is True): the vertices are new.

parallel: CGAL::Parallel_if_available_tag for make_delaunay() or the rebuild; same result.
Returns the stats dict of the C++ call (as delaunay_from_prediction()), plus 'rebuilt': True
when the triangulation was rebuilt instead of repaired in place.)doc";

const char* const delaunay_doc = R"doc(Delaunay(points, prediction=None, *, parallel=False, domain=None)

A drop-in for scipy.spatial.Delaunay in 2D: the same attributes with the same conventions and
dtypes, computed exactly (CGAL's exact predicates; co-circular ties broken by CGAL's symbolic
perturbation, so the triangles are those of CGAL's Delaunay_triangulation_2 of the points).

points:     (n, 2) array of coordinates.
prediction: None, an (m, 3) integer array of predicted triangles (any faces: wrong ones only
            cost time), or an object with .simplices (a previous Delaunay, scipy's included).
parallel:   use TBB's threads when the module has them (same result).
furthest_site, incremental: only False (ValueError otherwise); qhull_options: accepted and
            ignored (the triangulation is always the exact one).
domain:     None (the plane), or (xmin, ymin, xmax, ymax), a square holding every point
            (half-open): the periodic Delaunay triangulation (CGAL's
            Periodic_2_Delaunay_triangulation_2 of the points). Then simplices lists each
            periodic triangle once, offsets[i, j] (an extra attribute, (nsimplex, 3, 2)) is the
            offset in periods of corner j of simplex i, every simplex has three neighbors,
            convex_hull is empty, and find_simplex wraps the query points into the domain.

Attributes (computed when first read, kept until move()): points, simplices (each
counterclockwise), neighbors (neighbors[i, j] opposite simplices[i, j], -1 on the hull),
convex_hull, vertex_neighbor_vertices, coplanar (here: the duplicate points, which are no
vertex), vertex_to_simplex, npoints, nsimplex, ndim, min_bound, max_bound, and statistics (the
C++ call's stats). Methods: find_simplex(xi), move(new_points).

Differences from scipy: fewer than three points, or all points collinear, give an empty
simplices array instead of an exception (QhullError); for equal points the smallest index is
the vertex and the others are in coplanar. transform, equations, plane_distance, lift_points,
add_points and the furthest-site triangulation are not provided.)doc";

const char* const find_simplex_doc = R"doc(find_simplex(xi, bruteforce=False, tol=None)

The simplex holding each point of xi (an array of shape (..., 2)), as an intc array of shape
xi.shape[:-1]; -1 outside the convex hull (and for non-finite points). Exact: triangles are
closed, a point on an edge or a vertex gets one of the triangles holding it. The points are
visited in Hilbert order, each located by CGAL's walk from the previous answer.
bruteforce and tol are accepted for scipy's code and ignored. With a domain, each point is
first wrapped into it (in floating point: x - period * floor((x - xmin) / period)), then
located exactly; only non-finite points get -1.)doc";

const char* const delaunay_move_doc = R"doc(move(new_points, *, parallel=None)

Moves point i to new_points[i] for every i (the same number of points) and makes the
triangulation the Delaunay triangulation of the new points: repaired in place by
make_delaunay(), or rebuilt with the current triangles as the prediction when points merge or
split (the rule of Triangulation.move and of the C++ Kinetic_Delaunay_triangulation_2). The
attributes are those of the new points afterwards. parallel: None uses the constructor's.
Returns the stats dict, with 'rebuilt'. A non-finite coordinate raises InvalidPrediction and
changes nothing.)doc";

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
      .def(py::init([](const py::object& points_in, bool parallel, const py::object& domain_in) {
             const std::vector<Point> points = read_points(points_in, "points");
             const auto domain = read_domain(domain_in);
             py::gil_scoped_release nogil;
             return std::make_unique<Triangulation>(points, std::vector<Face>(), parallel, domain);
           }),
           py::arg("points"), py::kw_only(), py::arg("parallel") = false, py::arg("domain") = py::none(),
           "Builds the Delaunay triangulation of points, an (n, 2) array, periodic in domain when one is "
           "given (see the class documentation).")
      .def(
          "move",
          [](Triangulation& t, const py::object& points_in, bool parallel) {
            return move_points(t.core, points_in, parallel);
          },
          py::arg("new_points"), py::kw_only(), py::arg("parallel") = false, move_doc)
      .def_property_readonly(
          "triangles",
          [](const Triangulation& t) {
            std::vector<std::int64_t> triangles;
            {
              py::gil_scoped_release nogil;
              triangles = t.core.read([](const auto& k) { return triangles_of(k.triangulation()); });
            }
            return as_array(std::move(triangles), 3);
          },
          "(k, 3) int64 array of point indices, each face counterclockwise (a new array each time; "
          "equal points: the smallest of their indices). With a domain: each periodic triangle once, "
          "its corners translated by .offsets.")
      .def_property_readonly(
          "offsets",
          [](const Triangulation& t) -> py::object {
            if(!t.core.domain())
              return py::none();
            std::vector<std::int64_t> offsets;
            {
              py::gil_scoped_release nogil;
              offsets = t.core.read([](const auto& k) {
                if constexpr(std::is_same_v<std::decay_t<decltype(k.triangulation())>, Periodic_DT>)
                  return triangles_and_offsets(k.triangulation()).second;
                else
                  return std::vector<std::int64_t>();
              });
            }
            const py::ssize_t rows = py::ssize_t(offsets.size() / 6);
            return as_array(std::move(offsets), 6).attr("reshape")(rows, 3, 2);
          },
          "With a domain: (k, 3, 2) int64 array, offsets[i, j] the offset in periods (x, y) of corner j of "
          "triangle i: the corner is points[triangles[i, j]] + offsets[i, j] * (xmax - xmin). Least value 0 in "
          "each coordinate of a triangle. None without a domain.")
      .def_property_readonly(
          "domain", [](const Triangulation& t) { return domain_tuple(t.core); },
          "(xmin, ymin, xmax, ymax), the periodic domain; None in the plane.")
      .def_property_readonly(
          "points", [](const Triangulation& t) { return coordinates(t.core); },
          "(n, 2) float64 array: a copy of the current points, by index.")
      .def_property_readonly(
          "number_of_points", [](const Triangulation& t) { return t.core.number_of_points(); },
          "n, the number of point indices.")
      .def("__repr__", [](const Triangulation& t) {
        const std::size_t triangles = t.core.read(
            [](const auto& k) { return triangles_of(k.triangulation()).size() / 3; });
        return "<delaunay_from_prediction.Triangulation of " + std::to_string(t.core.number_of_points()) + " points, " +
               std::to_string(triangles) + " triangles>";
      });

  py::class_<Delaunay>(m, "Delaunay", delaunay_doc)
      .def(py::init([](const py::object& points_in, const py::object& prediction, bool parallel, bool furthest_site,
                       bool incremental, const py::object& qhull_options, const py::object& domain_in) {
             if(furthest_site)
               throw py::value_error("Delaunay(furthest_site=True): the furthest-site triangulation is not provided");
             if(incremental)
               throw py::value_error("Delaunay(incremental=True): add_points() is not provided; build a new "
                                     "Delaunay, or move() the points");
             (void)qhull_options; // accepted for scipy's code; the result is always the exact DT
             const std::vector<Point> points = read_points(points_in, "points");
             const py::object faces_in =
                 !prediction.is_none() && py::hasattr(prediction, "simplices") ? prediction.attr("simplices") : prediction;
             const std::vector<Face> faces = read_indices<3>(faces_in, "prediction", points.size());
             const auto domain = read_domain(domain_in);
             std::unique_ptr<Delaunay> d;
             {
               py::gil_scoped_release nogil;
               d = std::make_unique<Delaunay>(points, faces, parallel, domain);
             }
             d->points = xy_array(points);
             py::dict stats = stats_dict(d->core.build_statistics());
             stats["rebuilt"] = false;
             d->statistics = stats;
             return d;
           }),
           py::arg("points"), py::arg("prediction") = py::none(), py::kw_only(), py::arg("parallel") = false,
           py::arg("furthest_site") = false, py::arg("incremental") = false, py::arg("qhull_options") = py::none(),
           py::arg("domain") = py::none())
      .def_readonly("points", &Delaunay::points, "(n, 2) float64 array: the points (after move(), the new ones).")
      .def_property_readonly(
          "simplices", [](Delaunay& d) { return d.simplices_and_neighbors().first; },
          "(nsimplex, 3) intc array: the triangles' point indices, each counterclockwise.")
      .def_property_readonly(
          "neighbors", [](Delaunay& d) { return d.simplices_and_neighbors().second; },
          "(nsimplex, 3) intc array: neighbors[i, j] is the simplex opposite simplices[i, j], -1 on the hull.")
      .def_property_readonly(
          "offsets",
          [](Delaunay& d) -> py::object {
            if(!d.core.domain())
              return py::none();
            return d.cached(d.offsets_cache, [](const auto& k) -> py::object {
              if constexpr(std::is_same_v<std::decay_t<decltype(k.triangulation())>, Periodic_DT>) {
                std::vector<std::int64_t> offsets = triangles_and_offsets(k.triangulation()).second;
                std::vector<Intc> values(offsets.begin(), offsets.end());
                const py::ssize_t rows = py::ssize_t(values.size() / 6);
                return intc_array(std::move(values), 6).attr("reshape")(rows, 3, 2);
              } else
                return py::none();
            });
          },
          "With a domain: (nsimplex, 3, 2) intc array, the offset in periods (x, y) of each corner of each "
          "simplex (the corner is points[simplices[i, j]] + offsets[i, j] * (xmax - xmin)); None in the plane.")
      .def_property_readonly(
          "domain", [](const Delaunay& d) { return domain_tuple(d.core); },
          "(xmin, ymin, xmax, ymax), the periodic domain; None in the plane.")
      .def_property_readonly(
          "convex_hull",
          [](Delaunay& d) {
            return d.cached(d.convex_hull_cache, [](const auto& k) {
              return intc_array(convex_hull_edges(k.triangulation()), 2);
            });
          },
          "(h, 2) intc array: the hull's edges, counterclockwise around the hull (empty below dimension 2, and "
          "on the torus, which has no hull).")
      .def_property_readonly(
          "vertex_neighbor_vertices",
          [](Delaunay& d) {
            return d.cached(d.vertex_neighbor_vertices_cache, [&](const auto& k) {
              auto csr = vertex_neighbor_vertices(k.triangulation(), k.number_of_points());
              return py::object(py::make_tuple(intc_array(std::move(csr.first), 0), intc_array(std::move(csr.second), 0)));
            });
          },
          "(indptr, indices), intc arrays: the neighbours of point k are indices[indptr[k]:indptr[k+1]].")
      .def_property_readonly(
          "coplanar",
          [](Delaunay& d) {
            return d.cached(d.coplanar_cache, [](const auto& k) { return intc_array(coplanar_points(k), 3); });
          },
          "(c, 3) intc array: each point that is no vertex (a duplicate of a smaller index), a simplex holding its "
          "vertex (-1 below dimension 2), and that vertex's point index.")
      .def_property_readonly(
          "vertex_to_simplex",
          [](Delaunay& d) {
            return d.cached(d.vertex_to_simplex_cache, [](const auto& k) { return intc_array(vertex_to_simplex(k), 0); });
          },
          "(n,) intc array: a simplex holding each point's vertex (-1 below dimension 2).")
      .def_property_readonly("npoints", [](const Delaunay& d) { return d.core.number_of_points(); }, "n.")
      .def_property_readonly(
          "nsimplex", [](Delaunay& d) { return py::len(d.simplices_and_neighbors().first); }, "The number of simplices.")
      .def_property_readonly("ndim", [](const Delaunay&) { return 2; }, "2.")
      .def_property_readonly(
          "min_bound", [](const Delaunay& d) { return d.points.attr("min")(py::arg("axis") = 0); },
          "(2,) float64: the smallest coordinates.")
      .def_property_readonly(
          "max_bound", [](const Delaunay& d) { return d.points.attr("max")(py::arg("axis") = 0); },
          "(2,) float64: the largest coordinates.")
      .def_readonly("statistics", &Delaunay::statistics, "The stats dict of the constructor's or last move()'s call.")
      .def("find_simplex", &Delaunay::find_simplex, py::arg("xi"), py::arg("bruteforce") = false,
           py::arg("tol") = py::none(), find_simplex_doc)
      .def(
          "move",
          [](Delaunay& d, const py::object& points_in, const py::object& parallel) {
            py::dict stats = move_points(d.core, points_in, parallel.is_none() ? d.parallel : parallel.cast<bool>());
            d.points = coordinates(d.core);
            d.forget();
            d.statistics = stats;
            return stats;
          },
          py::arg("new_points"), py::kw_only(), py::arg("parallel") = py::none(), delaunay_move_doc)
      .def("__repr__", [](Delaunay& d) {
        return "<delaunay_from_prediction.Delaunay of " + std::to_string(d.core.number_of_points()) + " points, " +
               std::to_string(py::len(d.simplices_and_neighbors().first)) + " simplices>";
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
