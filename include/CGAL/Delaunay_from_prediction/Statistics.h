// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_STATISTICS_H
#define CGAL_DELAUNAY_FROM_PREDICTION_STATISTICS_H

#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
Exception thrown for structurally malformed input: an index out of range (a negative signed
index included), a face repeating an index, a non-finite point coordinate, or, for
`make_delaunay()`, two vertices at the same point. `what()` names the offending face, index,
point or vertices. When it is thrown, the caller's containers and triangulation are unchanged.
*/
class Invalid_prediction : public std::invalid_argument
{
public:
  /// constructs the exception with the message `what`.
  /// \param what the message, returned by `what()`.
  explicit Invalid_prediction(const std::string& what) : std::invalid_argument(what) {}
};

/*!
\ingroup PkgDelaunayFromPredictionRef
Reports what a call of `delaunay_from_prediction()`, `make_delaunay()`,
`delaunay_from_predicted_edges()`, `delaunay_from_spanning_graph()`,
`Imprecise_points_2::triangulate()`, `split_delaunay()` or `brio_dc_delaunay()` did. Every member is
filled at negligible cost; members a call has no use for stay 0.
*/
struct Statistics
{
  /// number of predicted faces read (`make_delaunay()`: finite faces before the call).
  std::size_t faces_in = 0;
  /// number of predicted faces that are faces of the result and were never modified.
  std::size_t faces_certified = 0;
  /// number of edge flips performed.
  std::size_t flips = 0;
  /// number of points (re)inserted by incremental insertion: points used by no face, vertices
  /// of carved faces, or every point when the call built from scratch.
  std::size_t points_reinserted = 0;
  /// `true` if the call gave up on the prediction and built the triangulation from scratch.
  /// The counts of the stages that ran before (edges tested, faces carved, holes refilled,
  /// carve rounds, regions, flips) are kept: they tell how far the call went.
  bool fell_back = false;

  /// number of interior edges of the prediction checked by the in-circle test.
  std::size_t edges_tested = 0;
  /// number of those edges found not locally Delaunay (the measure \f$D_{local}\f$ of the
  /// paper when the prediction is a triangulation). `make_delaunay()` flips during its
  /// certification pass: it counts the edges the pass found failing before a flip reached
  /// them, between 1 and \f$D_{local}\f$ (0 exactly when \f$D_{local} = 0\f$); with
  /// `CGAL::Parallel_tag` (TBB linked), whose pass only reads, it counts them all.
  std::size_t edges_not_locally_delaunay = 0;
  /// number of points used by no predicted face that was kept (a point used only by
  /// degenerate faces counts); they are inserted afterwards, or merged as duplicates.
  /// `Strategy::regions`: the points used by no predicted face.
  std::size_t points_unused = 0;
  /// number of points equal to a point of smaller index (they share its vertex).
  std::size_t duplicate_points = 0;
  /// `true` if the points were renumbered or the faces sorted into a spatial order before the
  /// import (done for large inputs that come in no spatial order; it never changes the result).
  bool input_reordered = false;
  /// number of predicted faces removed by the local repair (carved): inverted or flat faces
  /// and the faces around their vertices, faces lying on the same side of an edge as another
  /// (repeated or overlapping), and whatever the repair had to clear around holes that were
  /// not simple polygons. Vertices left without a face are reinserted (`points_reinserted`).
  std::size_t faces_carved = 0;
  /// number of holes (boundary cycles of the kept faces other than the outer one) that the
  /// local repair retriangulated.
  std::size_t holes_refilled = 0;
  /// number of rounds of the local repair: each round traces the holes and widens those that
  /// cannot be retriangulated as they are (0 when the local repair did not run; it may run
  /// without carving anything, only to fill holes). In `delaunay_from_prediction()`, the
  /// small holes the import fills itself count as the first round.
  std::size_t carve_rounds = 0;
  /// `Strategy::t_division` and `Strategy::regions`: number of regions the faces were divided
  /// into (0 otherwise).
  std::size_t regions = 0;
  /// `Strategy::t_division`: number of bad regions, whose faces were replaced.
  std::size_t bad_regions = 0;
  /// `Strategy::t_division`: number of vertices on region boundaries (\f$|V_B|\f$), whose
  /// Delaunay triangulation was built. `Strategy::regions`: number of points triangulated
  /// again for the seams between regions.
  std::size_t boundary_vertices = 0;
  /// `delaunay_from_spanning_graph()` and the functions built on it: number of edges read.
  std::size_t edges_in = 0;
  /// number of points located by a walk from a vertex already inserted (the spanning-tree
  /// insertion of Section 3 of the paper; the hints of `Imprecise_points_2`; the neighbours of
  /// `split_delaunay()` and `brio_dc_delaunay()`).
  std::size_t points_located = 0;
  /// number of faces those walks entered, fallback walks included: divided by
  /// `points_located`, the mean cost of a location.
  std::size_t faces_visited = 0;
  /// number of those walks that passed their cap (about \f$\log_2 n + 8\f$ faces) and
  /// started again from a vertex inserted near the point (a wrong edge of the tree, or a point
  /// far from its disk, mostly).
  std::size_t walk_fallbacks = 0;
  /// number of rounds of the gradation (random samples) that inserted the points (BrioDC: the
  /// number of samples).
  std::size_t insertion_rounds = 0;
  /// why the prediction was not used as it is: empty when it was a triangulation of the
  /// points; otherwise a static string such as `"a face is degenerate"`.
  const char* fallback_reason = "";
};

/*!
\ingroup PkgDelaunayFromPredictionRef
writes `s` to `out`, one `name: value` line per member, named as the members are: always
`faces_in`, `faces_certified`, `flips`, `points_reinserted` and `fell_back` (`true` or
`false`), then every other count that is not 0, the flag `input_reordered` when set, and
`fallback_reason` when the prediction was not used as it is.
\param out the stream.
\param s the statistics.
\returns `out`.
*/
inline std::ostream& operator<<(std::ostream& out, const Statistics& s)
{
  out << "faces_in: " << s.faces_in << "\nfaces_certified: " << s.faces_certified << "\nflips: " << s.flips
      << "\npoints_reinserted: " << s.points_reinserted << "\nfell_back: " << (s.fell_back ? "true" : "false") << "\n";
  const std::pair<const char*, std::size_t> counts[] = {
      {"edges_tested", s.edges_tested},         {"edges_not_locally_delaunay", s.edges_not_locally_delaunay},
      {"points_unused", s.points_unused},       {"duplicate_points", s.duplicate_points},
      {"faces_carved", s.faces_carved},         {"holes_refilled", s.holes_refilled},
      {"carve_rounds", s.carve_rounds},         {"regions", s.regions},
      {"bad_regions", s.bad_regions},           {"boundary_vertices", s.boundary_vertices},
      {"edges_in", s.edges_in},                 {"points_located", s.points_located},
      {"faces_visited", s.faces_visited},       {"walk_fallbacks", s.walk_fallbacks},
      {"insertion_rounds", s.insertion_rounds}};
  for(const auto& c : counts)
    if(c.second != 0)
      out << c.first << ": " << c.second << "\n";
  if(s.input_reordered)
    out << "input_reordered: true\n";
  if(s.fallback_reason != nullptr && s.fallback_reason[0] != '\0')
    out << "fallback_reason: " << s.fallback_reason << "\n";
  return out;
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_STATISTICS_H
