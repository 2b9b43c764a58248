# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The Python classes on the torus: Triangulation(points, domain=...) and Delaunay(points,
# domain=...). The reference is independent of CGAL: scipy's (qhull's) Delaunay triangulation
# of the points tiled k x k times, whose triangles touching the middle tile, translated to least
# offset 0, are the periodic triangles (points in general position). Moves, errors that leave
# the triangulation as it was, scipy's attributes on the torus (neighbors, find_simplex, ...).

import math

import numpy as np
import pytest
import scipy.spatial

import delaunay_from_prediction as dfp
from triangle_util import uniform


def wrap(points, low=0.0, period=1.0):
    """The points wrapped into [low, low + period) (rounding up to the upper side wraps to low)."""
    w = points - period * np.floor((points - low) / period)
    w[w >= low + period] = low
    return np.maximum(w, low)


def canonical(triangles, offsets):
    """The periodic triangles as a sorted list of ((i, ox, oy), ...) corners: offsets translated
    to least value 0 in each coordinate, each triangle rotated to start at its least corner."""
    out = []
    for t, o in zip(np.asarray(triangles), np.asarray(offsets)):
        o = o - o.min(axis=0)
        corners = [(int(t[j]), int(o[j, 0]), int(o[j, 1])) for j in range(3)]
        k = corners.index(min(corners))
        out.append(tuple(corners[k:] + corners[:k]))
    return sorted(out)


def tiled_reference(points, low=0.0, period=1.0, tiles=3):
    """The periodic Delaunay triangles from qhull's triangulation of the points tiled
    tiles x tiles times (each copy's offset from -(tiles // 2) to tiles // 2), keeping the
    triangles that touch the middle copy, each counterclockwise."""
    n = len(points)
    half = tiles // 2
    shifts = [(dx, dy) for dx in range(-half, half + 1) for dy in range(-half, half + 1)]
    tiled = np.concatenate([points + period * np.array(s, dtype=float) for s in shifts])
    shift_of = np.repeat(np.array(shifts), n, axis=0)
    simplices = scipy.spatial.Delaunay(tiled).simplices
    middle = shifts.index((0, 0))
    keep = np.any(simplices // n == middle, axis=1)
    simplices = simplices[keep]
    a, b, c = (tiled[simplices[:, j]] for j in range(3))
    cw = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]) < 0
    simplices[cw] = simplices[cw][:, [0, 2, 1]]
    return sorted(set(canonical(simplices % n, shift_of[simplices])))


def corners(points, triangles, offsets, period=1.0):
    return [points[triangles[:, j]] + period * offsets[:, j] for j in range(3)]


def assert_ccw(points, triangles, offsets, period=1.0):
    a, b, c = corners(points, triangles, offsets, period)
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert np.all(cross > 0)


@pytest.mark.parametrize("n, seed", [(300, 1), (2000, 2)])
def test_triangulation_against_tiled_scipy(n, seed):
    points = uniform(n, seed)
    t = dfp.Triangulation(points, domain=(0, 0, 1, 1))
    assert t.domain == (0.0, 0.0, 1.0, 1.0)
    triangles, offsets = t.triangles, t.offsets
    assert triangles.dtype == np.int64 and triangles.shape == (2 * n, 3)
    assert offsets.dtype == np.int64 and offsets.shape == (2 * n, 3, 2)
    assert offsets.min() == 0 and offsets.max() == 1
    assert np.all(offsets.min(axis=1) == 0)
    assert canonical(triangles, offsets) == tiled_reference(points)
    assert_ccw(points, triangles, offsets)
    # The plane: no offsets, no domain.
    plane = dfp.Triangulation(points)
    assert plane.offsets is None and plane.domain is None


def test_other_domain_and_few_points():
    # [-2, 6)^2: the unit-square points scaled give the same triangles.
    points = uniform(1000, 3)
    t = dfp.Triangulation(8 * points - 2, domain=(-2, -2, 6, 6))
    unit = dfp.Triangulation(points, domain=(0, 0, 1, 1))
    assert canonical(t.triangles, t.offsets) == canonical(unit.triangles, unit.offsets)
    assert_ccw(8 * points - 2, t.triangles, t.offsets, period=8.0)
    # Few points: CGAL's covering is 9-sheeted; each periodic triangle is listed once.
    for n, seed in [(10, 4), (25, 5)]:
        few = uniform(n, seed)
        t = dfp.Triangulation(few, domain=(0, 0, 1, 1))
        assert len(t.triangles) == 2 * n
        assert canonical(t.triangles, t.offsets) == tiled_reference(few, tiles=5)
        d = dfp.Delaunay(few, domain=(0, 0, 1, 1))
        assert canonical(d.simplices, d.offsets) == canonical(t.triangles, t.offsets)
        assert np.all(d.neighbors >= 0)


def test_triangulation_moves_across_the_sides():
    rng = np.random.default_rng(6)
    n = 2000
    points = uniform(n, 7)
    t = dfp.Triangulation(points, domain=(0, 0, 1, 1))
    spacing = 1 / math.sqrt(n)
    for step, scale in enumerate([0.01, 0.05, 0.3, 0.01]):
        points = wrap(points + rng.normal(scale=scale * spacing, size=points.shape))
        stats = t.move(points, parallel=step % 2 == 1)
        if scale <= 0.01:
            assert stats["rebuilt"] is False and stats["fell_back"] is False
        assert canonical(t.triangles, t.offsets) == tiled_reference(points)
        np.testing.assert_array_equal(t.points, points)
    # Two points meet (rebuilt, they share a vertex), then part (rebuilt).
    moved = points.copy()
    moved[5] = moved[9]
    stats = t.move(moved)
    assert stats["rebuilt"] is True and stats["duplicate_points"] == 1
    assert len(t.triangles) == 2 * (n - 1)
    t.move(points)
    assert canonical(t.triangles, t.offsets) == tiled_reference(points)


def test_errors_leave_it_unchanged():
    points = uniform(500, 8)
    with pytest.raises(ValueError, match="square"):
        dfp.Triangulation(points, domain=(0, 0, 1, 2))
    with pytest.raises(ValueError, match="four numbers"):
        dfp.Triangulation(points, domain=(0, 0, 1))
    with pytest.raises(ValueError, match="xmin < xmax"):
        dfp.Delaunay(points, domain=(1, 1, 0, 0))
    outside = points.copy()
    outside[12] = (1.0, 0.5)
    with pytest.raises(dfp.InvalidPrediction, match="point 12 .* outside the periodic domain"):
        dfp.Triangulation(outside, domain=(0, 0, 1, 1))
    t = dfp.Triangulation(points, domain=(0, 0, 1, 1))
    before = canonical(t.triangles, t.offsets)
    with pytest.raises(dfp.InvalidPrediction, match="point 12"):
        t.move(outside)
    outside[12] = (0.5, np.nan)
    with pytest.raises(dfp.InvalidPrediction, match="point 12"):
        t.move(outside)
    assert canonical(t.triangles, t.offsets) == before
    np.testing.assert_array_equal(t.points, points)


def test_delaunay_attributes_on_the_torus():
    n = 1500
    points = uniform(n, 9)
    d = dfp.Delaunay(points, domain=(0, 0, 1, 1))
    t = dfp.Triangulation(points, domain=(0, 0, 1, 1))
    simplices, neighbors, offsets = d.simplices, d.neighbors, d.offsets
    assert simplices.dtype == np.intc and offsets.shape == (2 * n, 3, 2) and d.nsimplex == 2 * n
    assert canonical(simplices, offsets) == canonical(t.triangles, t.offsets)
    assert d.domain == (0.0, 0.0, 1.0, 1.0) and d.convex_hull.shape == (0, 2)
    # neighbors[i, j] is across the edge opposite corner j: it holds that edge's two points,
    # and the relation is symmetric.
    assert np.all(neighbors >= 0)
    for i in range(0, 2 * n, 7):
        for j in range(3):
            k = neighbors[i, j]
            edge = {simplices[i, (j + 1) % 3], simplices[i, (j + 2) % 3]}
            assert edge <= set(simplices[k]) and i in neighbors[k]
    # vertex_neighbor_vertices: every edge twice (3n edges on the torus), symmetric.
    indptr, indices = d.vertex_neighbor_vertices
    assert indptr[-1] == 6 * n
    for k in range(0, n, 11):
        for m in indices[indptr[k]:indptr[k + 1]]:
            assert k in indices[indptr[m]:indptr[m + 1]]
    vts = d.vertex_to_simplex
    assert all(k in simplices[vts[k]] for k in range(n))
    # find_simplex: the query lies in a translate of the triangle found, wherever it is in the plane.
    rng = np.random.default_rng(10)
    queries = rng.random((400, 2))
    found = d.find_simplex(queries)
    assert found.shape == (400,) and np.all(found >= 0)
    np.testing.assert_array_equal(d.find_simplex(queries + np.array([3.0, -2.0])), found)
    a, b, c = corners(points, simplices[found], offsets[found])
    for q, pa, pb, pc in zip(queries, a, b, c):
        inside = False
        for s in [(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]:
            p = q + np.array(s, dtype=float)
            m = np.array([pb - pa, pc - pa]).T
            u, v = np.linalg.solve(m, p - pa)
            inside = inside or (u >= -1e-9 and v >= -1e-9 and u + v <= 1 + 1e-9)
        assert inside
    assert d.find_simplex(np.array([[np.nan, 0.5]]))[0] == -1
    # move(), and a previous Delaunay as the prediction.
    moved = wrap(points + np.random.default_rng(11).normal(scale=0.002, size=points.shape))
    stats = d.move(moved)
    assert stats["rebuilt"] is False
    assert canonical(d.simplices, d.offsets) == tiled_reference(moved)
    e = dfp.Delaunay(moved, prediction=d, domain=(0, 0, 1, 1))
    assert e.statistics["fell_back"] is False and e.statistics["faces_certified"] == 2 * n
    assert canonical(e.simplices, e.offsets) == canonical(d.simplices, d.offsets)
    assert dfp.Delaunay(points).offsets is None
