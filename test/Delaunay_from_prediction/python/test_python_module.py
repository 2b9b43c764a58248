# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Tests of the Python module delaunay_from_prediction (ctest: python_module; by hand:
# PYTHONPATH=build/python /usr/bin/python3 -m pytest -q test/Delaunay_from_prediction/python).
# General-position inputs are checked against scipy.spatial.Delaunay (qhull); degenerate ones
# (co-circular, collinear, duplicate, extreme coordinates), where qhull's choice may differ
# from CGAL's symbolic perturbation, against dfp.delaunay_triangulation (CGAL's own build).
# The proximity graphs are checked against scipy's minimum spanning tree and brute force.

import concurrent.futures
import math
import zlib

import numpy as np
import pytest
import scipy.sparse
import scipy.sparse.csgraph
import scipy.spatial

import delaunay_from_prediction as dfp
from triangle_util import oriented, uniform

# ----------------------------------------------------------------------------------------------
# Helpers



def unoriented(triangles):
    """The triangles as a sorted array of sorted triples (orientation ignored)."""
    t = np.sort(np.asarray(triangles, dtype=np.int64).reshape(-1, 3), axis=1)
    return t[np.lexsort(t.T[::-1])]


def assert_same(triangles, reference):
    assert triangles.dtype == np.int64 and triangles.ndim == 2 and triangles.shape[1] == 3
    np.testing.assert_array_equal(oriented(triangles), oriented(reference))


def assert_ccw(points, triangles):
    a, b, c = (points[triangles[:, j]] for j in range(3))
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert np.all(cross > 0)


def scipy_delaunay(points):
    return scipy.spatial.Delaunay(points).simplices.astype(np.int64)


def assert_equals_scipy(points, triangles):
    """Same triangle set as qhull's, and every triangle counterclockwise (qhull's are not all)."""
    np.testing.assert_array_equal(unoriented(triangles), unoriented(scipy_delaunay(points)))
    assert_ccw(points, triangles)


def shuffled_faces(faces, rng):
    """The faces in a random order, each with its corners in a random order (so in either
    orientation)."""
    faces = faces[rng.permutation(len(faces))]
    return np.take_along_axis(faces, np.argsort(rng.random(faces.shape), axis=1), axis=1)


def edges_of(triangles):
    e = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    return np.unique(np.sort(e, axis=1), axis=0)



def assert_sorted_pairs(pairs):
    assert pairs.dtype == np.int64 and pairs.ndim == 2 and pairs.shape[1] == 2
    assert np.all(pairs[:, 0] < pairs[:, 1])
    np.testing.assert_array_equal(pairs, np.unique(pairs, axis=0))


# ----------------------------------------------------------------------------------------------
# General position, against scipy


@pytest.mark.parametrize("n, seed", [(10, 1), (1000, 2), (20000, 3)])
def test_general_position_against_scipy(n, seed):
    rng = np.random.default_rng(100 + seed)
    points = uniform(n, seed)
    reference = scipy_delaunay(points)
    moved = points + rng.normal(scale=0.3 / math.sqrt(n), size=points.shape)
    garbage = np.array([rng.choice(n, 3, replace=False) for _ in range(2 * n)]) if n <= 1000 else \
        np.stack([rng.integers(0, n, 2 * n) for _ in range(3)], axis=1)
    garbage = garbage[(garbage[:, 0] != garbage[:, 1]) & (garbage[:, 1] != garbage[:, 2]) &
                      (garbage[:, 0] != garbage[:, 2])]
    predictions = {
        "none": None,
        "empty": np.empty((0, 3), dtype=np.int64),
        "scipy shuffled": shuffled_faces(reference, rng),
        "half of scipy": shuffled_faces(reference, rng)[: len(reference) // 2],
        "DT of moved points": scipy_delaunay(moved),
        "random garbage": garbage,
    }
    for name, faces in predictions.items():
        triangles, stats = dfp.delaunay_from_prediction(points, faces)
        assert_equals_scipy(points, triangles)
        assert stats["faces_in"] == (0 if faces is None else len(faces)), name
    # The correct triangulation, as given: certified as it is.
    triangles, stats = dfp.delaunay_from_prediction(points, reference)
    assert_equals_scipy(points, triangles)
    assert not stats["fell_back"] and stats["flips"] == 0
    assert stats["faces_certified"] == len(reference)
    # CGAL's own build agrees too.
    assert_equals_scipy(points, dfp.delaunay_triangulation(points))


def test_stats_dict():
    points = uniform(500, 4)
    _, stats = dfp.delaunay_from_prediction(points, scipy_delaunay(points))
    expected = {"faces_in", "faces_certified", "flips", "points_reinserted", "fell_back", "edges_tested",
                "edges_not_locally_delaunay", "points_unused", "duplicate_points", "input_reordered",
                "faces_carved", "holes_refilled", "carve_rounds", "regions", "bad_regions",
                "boundary_vertices", "edges_in", "points_located", "faces_visited", "walk_fallbacks",
                "insertion_rounds", "conflict_list_entries", "largest_conflict_list", "points_relocated",
                "exceptional_cells", "supercells", "bad_supercells", "walls", "chain_edges", "cells_computed",
                "regions_per_level", "boundary_crossings", "regions_keeping_prediction", "d_cross_guesses",
                "fallback_reason"}
    assert set(stats) == expected
    assert isinstance(stats["fallback_reason"], str) and stats["fallback_reason"] == ""
    assert isinstance(stats["fell_back"], bool) and isinstance(stats["flips"], int)
    assert stats["regions_per_level"] == []
    _, stats = dfp.delaunay_from_prediction(points, None)
    assert stats["fell_back"] and stats["fallback_reason"] != ""


def test_input_conversions():
    """Any integer dtype for faces, non-contiguous or non-float64 points, lists: same result."""
    points = uniform(100, 5)
    faces = scipy_delaunay(points)
    expected, _ = dfp.delaunay_from_prediction(points, faces)
    for dtype in (np.int8, np.uint8, np.int16, np.uint16, np.int32, np.uint32, np.uint64, np.intp):
        triangles, _ = dfp.delaunay_from_prediction(points, faces.astype(dtype))
        np.testing.assert_array_equal(triangles, expected)
    fortran = np.asfortranarray(points)
    strided = np.repeat(points, 2, axis=0)[::2]
    for p in (fortran, strided, points.tolist(), points.astype(np.float32).astype(np.float64)):
        triangles, _ = dfp.delaunay_from_prediction(p, faces.tolist())
        assert_same(triangles, expected)
    triangles, _ = dfp.delaunay_from_prediction(points, [])
    assert_same(triangles, expected)
    # Integer coordinates are converted to float64.
    grid = np.array([(x, y) for x in range(5) for y in range(5)], dtype=np.int32)
    assert_same(dfp.delaunay_from_prediction(grid)[0], dfp.delaunay_triangulation(grid.astype(float)))


# ----------------------------------------------------------------------------------------------
# Degenerate inputs, against CGAL's own build


def circle_points():
    """Every integer point on the circle of radius 5525 (exactly co-circular)."""
    r = 5525
    pts = set()
    for x in range(0, r + 1):
        y = math.isqrt(r * r - x * x)
        if x * x + y * y == r * r:
            pts.update({(x, y), (-x, y), (x, -y), (-x, -y)})
    return np.array(sorted(pts), dtype=float)


def degenerate_inputs():
    rng = np.random.default_rng(7)
    grid = np.array([(x, y) for x in range(30) for y in range(30)], dtype=float)
    circle = circle_points()
    circle_and_centre = np.vstack([circle, [[0.0, 0.0]], circle[:10] / 2])
    base = uniform(300, 8)
    duplicates = np.vstack([base, base[rng.integers(0, 300, 200)]])[rng.permutation(500)]
    grid_duplicates = np.vstack([grid, grid[::7]])
    return {
        "grid": grid,
        "grid shuffled": grid[rng.permutation(len(grid))],
        "circle": circle,
        "circle and centre": circle_and_centre,
        "duplicates": duplicates,
        "grid with duplicates": grid_duplicates,
        "huge": uniform(1000, 9) * 1e300,
        "huge grid": grid * 1e300,
        "tiny": uniform(1000, 10) * 1e-300,
        "tiny grid": grid * 1e-300,
        "mixed scales": np.vstack([uniform(200, 11) * 1e-300, uniform(200, 12), uniform(200, 13) * 1e200]),
    }


@pytest.mark.parametrize("name", list(degenerate_inputs()))
def test_degenerate_against_cgal(name):
    points = degenerate_inputs()[name]
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    reference = dfp.delaunay_triangulation(points)
    assert len(reference) > 0
    other = scipy_delaunay(points / np.abs(points).max()) if "grid" in name else None
    predictions = [None, shuffled_faces(reference, rng), reference[: len(reference) // 3]]
    if other is not None:
        predictions.append(other)  # qhull's tie breaks: a different triangulation of the grid
    for faces in predictions:
        for parallel in (False, True):
            triangles, _ = dfp.delaunay_from_prediction(points, faces, parallel=parallel)
            assert_same(triangles, reference)
    if name == "grid":  # the other diagonal of every square: every edge to flip
        n = 30
        flipped = []
        for x in range(n - 1):
            for y in range(n - 1):
                a, b, c, d = x * n + y, (x + 1) * n + y, (x + 1) * n + y + 1, x * n + y + 1
                flipped += [(a, b, d), (b, c, d)] if (x + y) % 2 else [(a, b, c), (a, c, d)]
        assert_same(dfp.delaunay_from_prediction(points, np.array(flipped))[0], reference)


def test_duplicates_use_smallest_index():
    points = np.array([[0, 0], [1, 0], [0, 1], [1, 0], [1, 1], [0, 0]], dtype=float)
    triangles, stats = dfp.delaunay_from_prediction(points)
    assert stats["duplicate_points"] == 2
    used = set(triangles.ravel())
    assert used == {0, 1, 2, 4}
    assert_same(triangles, dfp.delaunay_triangulation(points))
    # A prediction naming the larger duplicates gives the same result.
    triangles, _ = dfp.delaunay_from_prediction(points, [[5, 3, 2], [3, 4, 2]])
    assert_same(triangles, dfp.delaunay_triangulation(points))


@pytest.mark.parametrize("points", [
    np.array([[i, 2.0 * i] for i in range(20)]),
    np.array([[1.0, 1.0]] * 5),
    np.array([[3.0, 4.0]]),
    np.empty((0, 2)),
], ids=["collinear", "one point repeated", "one point", "empty"])
def test_no_triangles(points):
    for faces in (None, np.array([[0, 1, 2]]) if len(points) >= 3 else None):
        triangles, _ = dfp.delaunay_from_prediction(points, faces)
        assert triangles.shape == (0, 3) and triangles.dtype == np.int64
    assert dfp.delaunay_triangulation(points).shape == (0, 3)
    assert dfp.Triangulation(points).triangles.shape == (0, 3)


# ----------------------------------------------------------------------------------------------
# The kinetic Triangulation


def test_triangulation_moves():
    rng = np.random.default_rng(20)
    n = 3000
    points = uniform(n, 21)
    t = dfp.Triangulation(points)
    assert t.number_of_points == n
    assert_same(t.triangles, dfp.delaunay_triangulation(points))
    np.testing.assert_array_equal(t.points, points)
    spacing = 1 / math.sqrt(n)
    for step, scale in enumerate([0.01, 0.05, 0.2, 1.0, 3.0, 10.0, 0.01]):
        points = points + rng.normal(scale=scale * spacing, size=points.shape)
        stats = t.move(points, parallel=step % 2 == 1)
        assert stats["rebuilt"] is False
        assert_same(t.triangles, dfp.delaunay_triangulation(points))
        assert_ccw(points, t.triangles)
        np.testing.assert_array_equal(t.points, points)
    # Every point somewhere else: the previous triangulation is a useless prediction.
    points = uniform(n, 22)
    t.move(points)
    assert_same(t.triangles, dfp.delaunay_triangulation(points))


def test_triangulation_errors_leave_it_unchanged():
    points = uniform(200, 23)
    t = dfp.Triangulation(points)
    before = t.triangles
    with pytest.raises(ValueError, match="200"):
        t.move(points[:-1])
    with pytest.raises(ValueError, match=r"\(200, 3\)"):
        t.move(np.zeros((200, 3)))
    bad = points + 0.001
    bad[17, 1] = np.nan
    with pytest.raises(dfp.InvalidPrediction, match="point 17"):
        t.move(bad)
    bad[17, 1] = np.inf
    with pytest.raises(dfp.InvalidPrediction, match="point 17"):
        t.move(bad)
    np.testing.assert_array_equal(t.triangles, before)
    np.testing.assert_array_equal(t.points, points)
    with pytest.raises(dfp.InvalidPrediction):
        dfp.Triangulation(bad)


def test_triangulation_duplicates_made_and_split():
    rng = np.random.default_rng(24)
    n = 500
    points = uniform(n, 25)
    t = dfp.Triangulation(points)
    # Moves that put points onto others: rebuilt, the duplicates share a vertex.
    moved = points + rng.normal(scale=1e-3, size=points.shape)
    moved[[3, 40, 41]] = moved[10]
    moved[99] = moved[7]
    stats = t.move(moved)
    assert stats["rebuilt"] is True and stats["duplicate_points"] == 4
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))
    np.testing.assert_array_equal(t.points, moved)
    # Duplicates that stay together: in place.
    moved = moved + 1e-4
    stats = t.move(moved)
    assert stats["rebuilt"] is False
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))
    # Split apart again: rebuilt.
    moved = moved + rng.normal(scale=1e-3, size=points.shape)
    stats = t.move(moved)
    assert stats["rebuilt"] is True and stats["duplicate_points"] == 0
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))
    # And then in place again.
    moved = moved + rng.normal(scale=1e-3, size=points.shape)
    assert t.move(moved)["rebuilt"] is False
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))


def test_triangulation_constructed_with_duplicates():
    base = uniform(100, 26)
    points = np.vstack([base, base[:30]])
    t = dfp.Triangulation(points)
    assert t.number_of_points == 130
    assert_same(t.triangles, dfp.delaunay_triangulation(points))
    np.testing.assert_array_equal(t.points, points)
    moved = points * 2  # the duplicates stay equal
    assert t.move(moved)["rebuilt"] is False
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))
    moved[100:] += 1e-3  # split them
    assert t.move(moved)["rebuilt"] is True
    assert_same(t.triangles, dfp.delaunay_triangulation(moved))


def test_triangulation_dimension_changes():
    line = np.array([[i, 0.0] for i in range(10)])
    t = dfp.Triangulation(line)
    assert t.triangles.shape == (0, 3)
    off = line.copy()
    off[::2, 1] = 1.0
    t.move(off)
    assert_same(t.triangles, dfp.delaunay_triangulation(off))
    assert len(t.triangles) > 0
    t.move(line[::-1].copy())
    assert t.triangles.shape == (0, 3)
    t.move(off + 5)
    assert_same(t.triangles, dfp.delaunay_triangulation(off + 5))


# ----------------------------------------------------------------------------------------------
# Errors


def test_malformed_faces():
    points = uniform(10, 30)
    with pytest.raises(dfp.InvalidPrediction, match=r"face 1 has index 10 .*\[0, 10\)"):
        dfp.delaunay_from_prediction(points, [[0, 1, 2], [3, 4, 10]])
    with pytest.raises(dfp.InvalidPrediction, match="face 0 has index -1"):
        dfp.delaunay_from_prediction(points, [[0, -1, 2]])
    with pytest.raises(dfp.InvalidPrediction, match="face 2 repeats index 5"):
        dfp.delaunay_from_prediction(points, [[0, 1, 2], [1, 2, 3], [5, 6, 5]])
    with pytest.raises(dfp.InvalidPrediction, match="face 0 has index 18446744073709551615"):
        dfp.delaunay_from_prediction(points, np.array([[0, 1, 2**64 - 1]], dtype=np.uint64))
    bad = points.copy()
    bad[3, 0] = np.nan
    with pytest.raises(dfp.InvalidPrediction, match="point 3 has a non-finite coordinate"):
        dfp.delaunay_from_prediction(bad, None)
    with pytest.raises(dfp.InvalidPrediction, match="point 3"):
        dfp.delaunay_triangulation(bad)
    # A ValueError too, and the C++ message.
    with pytest.raises(ValueError, match="Delaunay_from_prediction: face"):
        dfp.delaunay_from_prediction(points, [[0, 1, 99]])


def test_wrong_shapes_and_types():
    points = uniform(10, 31)
    with pytest.raises(ValueError, match=r"points .*\(10, 3\)"):
        dfp.delaunay_from_prediction(np.zeros((10, 3)), None)
    with pytest.raises(ValueError, match=r"points .*\(20,\)"):
        dfp.delaunay_from_prediction(np.zeros(20), None)
    with pytest.raises(ValueError, match=r"faces .*\(2, 4\)"):
        dfp.delaunay_from_prediction(points, np.zeros((2, 4), dtype=int))
    with pytest.raises(ValueError, match=r"faces .*\(3,\)"):
        dfp.delaunay_from_prediction(points, np.array([0, 1, 2]))
    with pytest.raises(TypeError, match="faces .*float64"):
        dfp.delaunay_from_prediction(points, np.zeros((2, 3)))
    with pytest.raises(TypeError, match="faces .*bool"):
        dfp.delaunay_from_prediction(points, np.zeros((2, 3), dtype=bool))
    with pytest.raises(TypeError, match="points"):
        dfp.delaunay_from_prediction([["a", "b"]], None)
    with pytest.raises(TypeError, match="points"):
        dfp.delaunay_from_prediction(None, None)
    with pytest.raises(ValueError, match=r"edges .*\(4, 3\)"):
        dfp.gabriel_graph(points, np.zeros((4, 3), dtype=int))
    with pytest.raises(ValueError, match="exactly one"):
        dfp.euclidean_minimum_spanning_tree(points)
    with pytest.raises(ValueError, match="exactly one"):
        dfp.euclidean_minimum_spanning_tree(points, faces=[[0, 1, 2]], edges=[[0, 1]])
    with pytest.raises(dfp.InvalidPrediction, match="edge 1 joins index 4 to itself"):
        dfp.relative_neighborhood_graph(points, [[0, 1], [4, 4]])
    with pytest.raises(dfp.InvalidPrediction, match="edge 0 has index 12"):
        dfp.euclidean_minimum_spanning_tree(points, edges=[[0, 12]])


# ----------------------------------------------------------------------------------------------
# EMST, RNG, Gabriel


def scipy_emst(points):
    """scipy's minimum spanning tree of the Delaunay edges, weighted by length: (edges, total)."""
    e = edges_of(scipy_delaunay(points))
    w = np.linalg.norm(points[e[:, 0]] - points[e[:, 1]], axis=1)
    n = len(points)
    tree = scipy.sparse.csgraph.minimum_spanning_tree(scipy.sparse.coo_matrix((w, (e[:, 0], e[:, 1])), shape=(n, n)))
    tree = tree.tocoo()
    pairs = np.sort(np.stack([tree.row, tree.col], axis=1), axis=1).astype(np.int64)
    return pairs[np.lexsort(pairs.T[::-1])], tree.sum()


def total_length(points, pairs):
    return np.linalg.norm(points[pairs[:, 0]] - points[pairs[:, 1]], axis=1).sum()


@pytest.mark.parametrize("n, seed", [(50, 40), (5000, 41)])
def test_emst_against_scipy(n, seed):
    rng = np.random.default_rng(seed)
    points = uniform(n, seed)
    expected, length = scipy_emst(points)
    dt = scipy_delaunay(points)
    random_tree = np.stack([np.arange(1, n), rng.integers(0, np.arange(1, n))], axis=1)
    for kwargs in ({"faces": dt}, {"faces": shuffled_faces(dt, rng)[: len(dt) // 2]}, {"faces": []},
                   {"edges": expected}, {"edges": random_tree}, {"edges": edges_of(dt)},
                   {"edges": np.empty((0, 2), dtype=np.int32)}):
        tree = dfp.euclidean_minimum_spanning_tree(points, **kwargs)
        assert_sorted_pairs(tree)
        assert len(tree) == n - 1
        assert math.isclose(total_length(points, tree), length, rel_tol=1e-12)
        np.testing.assert_array_equal(tree, expected)  # lengths are distinct: the tree is unique


def test_emst_duplicates_span_every_index():
    points = np.array([[0, 0], [1, 0], [0, 0], [2, 0], [1, 0]], dtype=float)
    tree = dfp.euclidean_minimum_spanning_tree(points, faces=[])
    assert len(tree) == 4
    assert {(0, 2), (1, 4)} <= set(map(tuple, tree.tolist()))


def brute_force_rng(points):
    d = np.linalg.norm(points[:, None, :] - points[None, :, :], axis=2)
    n = len(points)
    edges = []
    for i in range(n):
        # blocked[j]: some r has max(|ir|, |jr|) < |ij| (r = i or j never does).
        blocked = np.any(np.maximum(d[i][None, :], d) < d[i][:, None], axis=1)
        edges += [(i, j) for j in range(i + 1, n) if not blocked[j]]
    return np.array(edges, dtype=np.int64)


def brute_force_gabriel(points):
    d2 = ((points[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
    n = len(points)
    edges = []
    for i in range(n):
        # r in the closed disk with diameter ij iff |ir|^2 + |jr|^2 <= |ij|^2; r = i, j excluded.
        inside = d2[i][None, :] + d2 <= d2[i][:, None]
        inside[:, i] = False
        np.fill_diagonal(inside, False)
        blocked = inside.any(axis=1)
        edges += [(i, j) for j in range(i + 1, n) if not blocked[j]]
    return np.array(edges, dtype=np.int64)


def test_rng_and_gabriel_against_brute_force():
    rng = np.random.default_rng(50)
    points = uniform(200, 51)
    dt_edges = edges_of(scipy_delaunay(points))
    rng_expected = brute_force_rng(points)
    gabriel_expected = brute_force_gabriel(points)
    for edges in (dt_edges, dt_edges[rng.permutation(len(dt_edges))[: len(dt_edges) // 2]], rng_expected,
                  dfp.euclidean_minimum_spanning_tree(points, faces=[]), None, np.empty((0, 2), dtype=int)):
        graph = dfp.relative_neighborhood_graph(points, edges)
        assert_sorted_pairs(graph)
        np.testing.assert_array_equal(graph, rng_expected)
        graph = dfp.gabriel_graph(points, edges)
        assert_sorted_pairs(graph)
        np.testing.assert_array_equal(graph, gabriel_expected)
    # EMST within RNG within Gabriel within Delaunay.
    emst = set(map(tuple, dfp.euclidean_minimum_spanning_tree(points, faces=[]).tolist()))
    rng_set = set(map(tuple, rng_expected.tolist()))
    gabriel_set = set(map(tuple, gabriel_expected.tolist()))
    assert emst <= rng_set <= gabriel_set <= set(map(tuple, dt_edges.tolist()))


# ----------------------------------------------------------------------------------------------
# Parallel and threads


def test_parallel_gives_identical_triangles():
    rng = np.random.default_rng(60)
    points = uniform(200000, 61)
    reference = dfp.delaunay_triangulation(points)
    moved = points + rng.normal(scale=0.01 / math.sqrt(len(points)), size=points.shape)
    for faces in (None, shuffled_faces(reference, rng)):
        sequential, _ = dfp.delaunay_from_prediction(points, faces)
        parallel, _ = dfp.delaunay_from_prediction(points, faces, parallel=True)
        assert_same(sequential, reference)
        assert_same(parallel, reference)
    a, b = dfp.Triangulation(points), dfp.Triangulation(points, parallel=True)
    a.move(moved)
    b.move(moved, parallel=True)
    assert_same(a.triangles, b.triangles)
    assert_same(b.triangles, dfp.delaunay_triangulation(moved))


def test_calls_from_several_threads():
    """The GIL is released during the C++ work: concurrent calls give the same results."""
    inputs = [uniform(20000, 70 + k) for k in range(4)]
    expected = [dfp.delaunay_triangulation(p) for p in inputs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(lambda p: dfp.delaunay_from_prediction(p, None)[0], inputs))
    for got, want in zip(results, expected):
        assert_same(got, want)
