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
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
Exception thrown for structurally malformed input: an index out of range (a negative signed
index included), a face repeating an index, an edge joining a point to itself, a non-finite point
coordinate, or, for `make_delaunay()`, two vertices at the same point. Also: for
`Kinetic_Delaunay_triangulation_2::move()`, another number of points than the triangulation
has; for the periodic overloads (`periodic_2.h`), a point outside the domain or, with a
floating-point number type (`Epick`), a period outside \f$[2^{-500}, 2^{500}]\f$; for
`Imprecise_points_2`, radii and centres of different counts, a negative or non-finite radius, an
instance of another size; and inputs too large for the 32-bit indices of
`delaunay_from_spanning_graph()`, the proximity graphs, `brio_dc_delaunay()`,
`Imprecise_points_2` and `prediction_measures()` (the user manual, "Limitations", lists the
limits). `what()` names the offending face, index, point or vertices. When it is thrown, the
caller's containers and triangulation are unchanged.
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
What a call made of its prediction: `Outcome::ok` when the prediction was used (certified,
repaired or flipped), otherwise why the call built from scratch instead
(`Statistics::fell_back`). `to_string()` gives the sentence a user reads for each.
*/
enum class Outcome {
  ok, ///< the prediction was used (certified, repaired or flipped): the call did not fall back
  // Chosen by the caller or the traits.
  rebuild_requested, ///< the rebuild strategy was chosen
  spanning_tree_requested, ///< the spanning_tree strategy was chosen
  section_3_requested, ///< the section_3 strategy was chosen
  inexact_predicates, ///< the traits' predicates are not exact: the faces are decided by exact predicates on double coordinates
  // The prediction, as the import reads it.
  too_many_indices, ///< too many points or faces for 32-bit indices
  no_faces, ///< there are no faces
  screen_rejected, ///< most sampled faces have sampled points inside their circumcircles
  too_many_holes, ///< too many holes for a local repair
  holes_or_not_a_triangulation, ///< the faces leave holes, or do not form a triangulation of their vertices
  degenerate_face, ///< a face is degenerate (its points are collinear or equal)
  too_many_degenerate_faces, ///< too many faces are degenerate
  overlapping_faces, ///< two faces lie on the same side of an edge (overlapping or repeated faces)
  too_many_overlapping_faces, ///< too many faces lie on the same side of an edge as others
  boundary_pinched, ///< the boundary of the faces pinches at a vertex (not a single polygon)
  boundary_not_closed, ///< the boundary of the faces is not closed
  boundary_with_holes, ///< the boundary of the faces has several components (holes)
  boundary_not_convex, ///< the boundary of the faces is not a convex polygon wound once
  // A CGAL triangulation (make_delaunay).
  dimension_below_2, ///< the triangulation has dimension below 2
  inverted_face, ///< a face is inverted or flat
  too_many_inverted_faces, ///< too many faces are inverted or flat for a local repair
  hull_not_convex, ///< the hull is not a convex polygon wound once, and no flip of hull edges makes it one
  // The local repair (carve).
  damage_over_budget, ///< the damage exceeds the budget of the local repair
  holes_kept_growing, ///< holes kept growing past the budget of the local repair
  hole_over_budget, ///< a hole is larger than the budget of the local repair
  outer_boundary_not_ccw, ///< the outer boundary of the kept faces is not counterclockwise
  carve_not_a_triangulation, ///< the kept faces and the filled holes do not form a triangulation
  duplicate_points, ///< two vertices are at the same point
  // The t-division repair.
  t_division_over_budget, ///< the damage would make the t-division cost more than a rebuild
  bad_regions_too_large, ///< the bad regions of the t-division are too large for a local repair
  boundary_vertices_collinear, ///< the boundary vertices of the t-division are collinear
  every_region_bad, ///< every region of the t-division is bad
  kept_faces_repeated, ///< two kept faces have the same vertices
  kept_faces_do_not_fit, ///< the kept faces do not fit the triangulation of the boundary vertices
  // The build by the prediction's regions.
  too_few_regions, ///< the prediction is too small to be divided into regions
  regions_interleave, ///< the prediction's regions interleave too much to be triangulated apart
  regions_do_not_fit, ///< the triangulations of the prediction's regions do not fit together
  // Flips.
  flip_budget_exhausted, ///< the flip budget was exhausted
  too_many_failing_edges, ///< the edges failing the in-circle test would need more flips than the budget
  // The spanning-tree engine.
  graph_too_many_components, ///< the graph has too many components to guide the insertion
  tree_walks_missing, ///< the walks along the spanning tree kept missing
  graph_edges_too_long, ///< the graph's edges are far longer than the spacing of the points
  // Periodic domains (periodic_2.h).
  faces_do_not_close, ///< a face's edges, each taken as its shortest periodic image, do not close, or two faces do not fit along their edge
  faces_do_not_tile_domain, ///< the faces do not cover the periodic domain exactly once
  point_without_face, ///< a point is a vertex of no face
  not_1_sheeted, ///< the points may be too few or too clustered for a 1-sheeted periodic covering: built as CGAL builds them
  count_ ///< the number of outcomes (not an outcome)
};

/*!
\ingroup PkgDelaunayFromPredictionRef
returns the sentence that explains `outcome`: empty for `Outcome::ok`, for example `"a face is
degenerate (its points are collinear or equal)"` for `Outcome::degenerate_face`.
\param outcome the outcome.
\returns the sentence, a string literal.
*/
inline const char* to_string(Outcome outcome)
{
  static constexpr const char* sentences[] = {
      "",
      "the rebuild strategy was chosen",
      "the spanning_tree strategy was chosen",
      "the section_3 strategy was chosen",
      "the traits' predicates are not exact: the faces are decided by exact predicates on double coordinates",
      "too many points or faces for 32-bit indices",
      "there are no faces",
      "most sampled faces have sampled points inside their circumcircles",
      "too many holes for a local repair",
      "the faces leave holes, or do not form a triangulation of their vertices",
      "a face is degenerate (its points are collinear or equal)",
      "too many faces are degenerate",
      "two faces lie on the same side of an edge (overlapping or repeated faces)",
      "too many faces lie on the same side of an edge as others",
      "the boundary of the faces pinches at a vertex (not a single polygon)",
      "the boundary of the faces is not closed",
      "the boundary of the faces has several components (holes)",
      "the boundary of the faces is not a convex polygon wound once",
      "the triangulation has dimension below 2",
      "a face is inverted or flat",
      "too many faces are inverted or flat for a local repair",
      "the hull is not a convex polygon wound once, and no flip of hull edges makes it one",
      "the damage exceeds the budget of the local repair",
      "holes kept growing past the budget of the local repair",
      "a hole is larger than the budget of the local repair",
      "the outer boundary of the kept faces is not counterclockwise",
      "the kept faces and the filled holes do not form a triangulation",
      "two vertices are at the same point",
      "the damage would make the t-division cost more than a rebuild",
      "the bad regions of the t-division are too large for a local repair",
      "the boundary vertices of the t-division are collinear",
      "every region of the t-division is bad",
      "two kept faces have the same vertices",
      "the kept faces do not fit the triangulation of the boundary vertices",
      "the prediction is too small to be divided into regions",
      "the prediction's regions interleave too much to be triangulated apart",
      "the triangulations of the prediction's regions do not fit together",
      "the flip budget was exhausted",
      "the edges failing the in-circle test would need more flips than the budget",
      "the graph has too many components to guide the insertion",
      "the walks along the spanning tree kept missing",
      "the graph's edges are far longer than the spacing of the points",
      "a face's edges, each taken as its shortest periodic image, do not close, or two faces do not fit along their edge",
      "the faces do not cover the periodic domain exactly once",
      "a point is a vertex of no face",
      "the points may be too few or too clustered for a 1-sheeted periodic covering: built as CGAL builds them",
  };
  static_assert(sizeof(sentences) / sizeof(sentences[0]) == std::size_t(Outcome::count_), "one sentence per outcome");
  const std::size_t i = std::size_t(outcome);
  return i < std::size_t(Outcome::count_) ? sentences[i] : "";
}

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
  /// number of predicted faces that are faces of the result and were never modified
  /// (`Strategy::theorem_4_1`: those its good supercells kept, less any the certificate's
  /// repair changed).
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
  /// number of samples; `Strategy::section_3`: the samples \f$R_1, \dots, R_\ell\f$ of
  /// Theorem 3.3; `Strategy::theorem_4_1`: 3, the rounds up to \f$R_3\f$).
  std::size_t insertion_rounds = 0;
  /// `Strategy::section_3` and `Strategy::theorem_4_1`: the total size of the conflict lists
  /// Lemma 3.2 computed, over all rounds (for each point outside the round's sample, the
  /// number of faces of the sample's Delaunay triangulation whose circumcircle holds it).
  std::size_t conflict_list_entries = 0;
  /// `Strategy::section_3` and `Strategy::theorem_4_1`: the longest conflict list of a face,
  /// over all rounds.
  std::size_t largest_conflict_list = 0;
  /// `Strategy::section_3` and `Strategy::theorem_4_1`: the number of times a point waiting for its round's insertion was
  /// moved to another face because an insertion changed the face holding it (the work of the
  /// randomized incremental construction with conflict lists).
  std::size_t points_relocated = 0;
  /// `Strategy::theorem_4_1`: the cells (Voronoi cells of the last sample \f$R_3\f$) whose
  /// conflict list was longer than the threshold (\f$6 b s_3\f$ with \f$b = s_3\f$) and whose
  /// triangles were computed first, as the paper's exceptional cells.
  std::size_t exceptional_cells = 0;
  /// `Strategy::theorem_4_1`: the supercells (groups of about \f$t = s_3^4\f$ cells).
  std::size_t supercells = 0;
  /// `Strategy::theorem_4_1`: the supercells that failed the good test against the
  /// prediction, whose cells were computed one by one.
  std::size_t bad_supercells = 0;
  /// `Strategy::theorem_4_1`: the walls (Voronoi edges of \f$R_3\f$ between two supercells)
  /// along which a chain of Delaunay edges was traced.
  std::size_t walls = 0;
  /// `Strategy::theorem_4_1`: the Delaunay edges found on the walls (the chains' lengths).
  std::size_t chain_edges = 0;
  /// `Strategy::theorem_4_1`: the cells whose Delaunay triangles were computed from their
  /// conflict lists (the exceptional cells and the cells of bad supercells).
  std::size_t cells_computed = 0;
  /// `Strategy::theorem_5_4`: the regions of the t-divisions at each level of the recursion
  /// (level 0 divides the prediction), in the run of the last guess of \f$d_{cross}\f$; empty
  /// when that run was the base case (a build from scratch).
  std::vector<std::size_t> regions_per_level;
  /// `Strategy::theorem_5_4`: the edges of the regions' triangulations \f$DT(V_\gamma)\f$ that
  /// cross their region's boundary (\f$|X_\gamma|\f$ summed over every region of every level).
  std::size_t boundary_crossings = 0;
  /// `Strategy::theorem_5_4`: the regions whose triangulation could not be walked (collinear
  /// points, a duplicate point on the boundary), which kept the prediction's own faces.
  std::size_t regions_keeping_prediction = 0;
  /// `Strategy::theorem_5_4`: the guesses \f$b = 2^{2^j}\f$ of \f$d_{cross}\f$ made (the last
  /// one's run finished within its cap).
  std::size_t d_cross_guesses = 0;
  /// what the call made of the prediction: `Outcome::ok` when it was used, otherwise why the
  /// call built from scratch (`to_string(outcome)` says it in a sentence).
  Outcome outcome = Outcome::ok;
};

/*!
\ingroup PkgDelaunayFromPredictionRef
writes `s` to `out`, one `name: value` line per member, named as the members are: always
`faces_in`, `faces_certified`, `flips`, `points_reinserted` and `fell_back` (`true` or
`false`), then every other count that is not 0, `regions_per_level` (its values on one line)
when it is not empty, the flag `input_reordered` when set, and
`outcome` (`to_string()`'s sentence) when it is not `Outcome::ok`.
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
      {"insertion_rounds", s.insertion_rounds}, {"conflict_list_entries", s.conflict_list_entries},
      {"largest_conflict_list", s.largest_conflict_list}, {"points_relocated", s.points_relocated},
      {"exceptional_cells", s.exceptional_cells}, {"supercells", s.supercells},
      {"bad_supercells", s.bad_supercells},     {"walls", s.walls},
      {"chain_edges", s.chain_edges},           {"cells_computed", s.cells_computed},
      {"boundary_crossings", s.boundary_crossings}, {"regions_keeping_prediction", s.regions_keeping_prediction},
      {"d_cross_guesses", s.d_cross_guesses}};
  for(const auto& c : counts)
    if(c.second != 0)
      out << c.first << ": " << c.second << "\n";
  if(!s.regions_per_level.empty()) {
    out << "regions_per_level:";
    for(const std::size_t r : s.regions_per_level)
      out << " " << r;
    out << "\n";
  }
  if(s.input_reordered)
    out << "input_reordered: true\n";
  if(s.outcome != Outcome::ok)
    out << "outcome: " << to_string(s.outcome) << "\n";
  return out;
}

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_STATISTICS_H
