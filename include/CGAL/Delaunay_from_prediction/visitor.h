// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Instrumentation of delaunay_from_prediction() and make_delaunay(): the stages of their
// pipeline, told to a visitor (named parameter `visitor`) as they begin and end, as \cgal's
// Polygon Mesh Processing tells its visitors. The default visitor does nothing and compiles away.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_VISITOR_H
#define CGAL_DELAUNAY_FROM_PREDICTION_VISITOR_H

namespace CGAL {
namespace Delaunay_from_prediction {

/*!
\ingroup PkgDelaunayFromPredictionRef
A stage of the pipeline of `delaunay_from_prediction()` and `make_delaunay()` (in the plane and
on the torus, `periodic_2.h`), told to the visitor (named parameter `visitor`) as it begins and
ends. A call runs some of them, each at most once, one after the other (never nested); a stage
that throws `Invalid_prediction` gets no `stage_end()`.
*/
enum class Stage {
  /// the input checked: coordinates finite; for `delaunay_from_prediction()`, the faces read
  /// and validated into index triples.
  check,
  /// In the plane, the screens that may reject a prediction before any repair:
  /// `delaunay_from_prediction()` before the import (sampled faces against sampled points,
  /// failing edges estimated, missing faces counted), `make_delaunay()` before the certificate
  /// (too many inverted faces foreseen from a sample).
  screen,
  /// `delaunay_from_prediction()`: the spatial reordering of the points and faces, with the
  /// copy of the points.
  order,
  /// `delaunay_from_prediction()`: the import of the faces with their certificate
  /// (orientation, pairing of edges, in-circle tests). On the torus, both entry points: the
  /// faces read into flat arrays with their offsets (the in-circle tests are `certify`).
  import,
  /// `make_delaunay()`: the certification of the faces (sequentially, with Lawson's flips of
  /// the failing edges as they are found). On the torus, both entry points: the in-circle test
  /// of every edge.
  certify,
  /// `make_delaunay()`, and both entry points on the torus: the flips (on the torus, also the
  /// reinsertions) that make inverted faces counterclockwise.
  untangle,
  /// the local repair: faces carved, holes filled, the vertices left without a face reinserted.
  carve,
  /// `Strategy::t_division`: the bad regions replaced and their inner vertices reinserted.
  t_division,
  /// `Strategy::regions`: the build by regions of the prediction.
  regions,
  /// Lawson's flips of the edges that fail the in-circle test (`make_delaunay()`: with the
  /// hull made convex first, where it is not).
  flips,
  /// `delaunay_from_prediction()`: the insertion of the points that no face uses.
  insert,
  /// the build from scratch: a fallback, `Strategy::rebuild` or `Strategy::spanning_tree`
  /// (with `CGAL::Parallel_tag`, in spatial blocks on TBB's threads).
  rebuild,
  /// `Strategy::theorem_4_1`: Theorem 4.1's computation of the faces (the rounds, the cells,
  /// the supercells, their walls and good test, the cells of the bad supercells), before the
  /// import certifies them.
  supercells,
  /// `Strategy::theorem_5_4`: Theorem 5.4's recursion over the prediction's regions and its
  /// guesses of \f$d_{cross}\f$, which compute the completion \f$G'\f$ that the import, the
  /// local repair and the flips then make Delaunay (the proof's step 6).
  region_recursion
};

/*!
\ingroup PkgDelaunayFromPredictionRef
The name of a stage, as it is spelled in `Stage` (for example `"t_division"`).
\param stage the stage.
\returns its name, a string literal.
*/
inline const char* to_string(Stage stage)
{
  constexpr const char* names[] = {"check", "screen",     "order",   "import", "certify", "untangle",
                                   "carve", "t_division", "regions", "flips",  "insert",  "rebuild",
                                   "supercells", "region_recursion"};
  return names[static_cast<int>(stage)];
}

/*!
\ingroup PkgDelaunayFromPredictionRef
The visitor of `delaunay_from_prediction()` and `make_delaunay()` when none is given (named
parameter `visitor`): its members do nothing, so that the calls compile away. A visitor is
any class with these two members; both are called on the calling thread only, never from TBB's
tasks, between the stages (so a visitor need not be thread-safe, and may read a clock).

The named parameter holds a copy of the visitor; pass `std::ref(v)` to have `v` itself called.
*/
struct Default_visitor
{
  /// called when `stage` begins.
  /// \param stage the stage.
  void stage_begin(Stage stage) { (void)stage; }
  /// called when `stage` ends, unless it threw.
  /// \param stage the stage.
  void stage_end(Stage stage) { (void)stage; }
};

} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_VISITOR_H
