# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Tests that delaunay_from_prediction.Delaunay is a drop-in for scipy.spatial.Delaunay in 2D (by
# hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest -q test/Delaunay_from_prediction/python).
# In general position every attribute is checked against scipy's (qhull), modulo the order of the
# simplices; degenerate inputs (lattices, duplicates, (near-)collinear points), where qhull's choice
# may differ from CGAL's symbolic perturbation or qhull may fail, are checked in exact arithmetic
# (the doubles scaled to Python integers) and against dfp.delaunay_triangulation (CGAL's own build).

import collections
import math

import numpy as np
import pytest
import scipy.spatial

import delaunay_from_prediction as dfp
from triangle_util import oriented, uniform

INTC = np.dtype(np.intc)

# ----------------------------------------------------------------------------------------------
# Helpers




def edge_set(edges):
    """Unordered edges as a set of sorted pairs."""
    return set(map(tuple, np.sort(np.asarray(edges, dtype=np.int64).reshape(-1, 2), axis=1).tolist()))


def triangle_keys(simplices, n):
    t = np.sort(np.asarray(simplices, dtype=np.int64), axis=1)
    return (t[:, 0] * n + t[:, 1]) * n + t[:, 2]


def row_map(simplices, reference, n):
    """rows with reference[rows[i]] the triangle simplices[i] (as a vertex set); fails if the
    two are not the same set of triangles."""
    ours, theirs = triangle_keys(simplices, n), triangle_keys(reference, n)
    assert len(ours) == len(theirs)
    order = np.argsort(theirs)
    pos = np.clip(np.searchsorted(theirs[order], ours), 0, max(len(theirs) - 1, 0))
    assert np.array_equal(theirs[order][pos], ours), "not the same triangles"
    return order[pos]


def neighbour_sets(tri):
    indptr, indices = tri.vertex_neighbor_vertices
    return [set(indices[indptr[k]:indptr[k + 1]].tolist()) for k in range(len(indptr) - 1)]


def assert_contains(simplices, rows, vertices):
    """simplices[rows[i]] holds vertices[i], for every i."""
    rows = np.asarray(rows)
    assert np.all(rows >= 0) and np.all(rows < len(simplices))
    assert np.all(np.any(simplices[rows] == np.asarray(vertices)[:, None], axis=1))


def assert_own_invariants(tri):
    """neighbors[i, j] is the simplex sharing the edge of simplices[i] without simplices[i, j]
    (and it has i as neighbour across that edge), -1 exactly on the hull edges; each
    vertex_to_simplex entry holds its point's vertex; every simplex counterclockwise."""
    s, nb = tri.simplices.astype(np.int64), tri.neighbors.astype(np.int64)
    k = len(s)
    hull = edge_set(tri.convex_hull)
    boundary = set()
    for j in range(3):
        a, b = s[:, (j + 1) % 3], s[:, (j + 2) % 3]
        m = nb[:, j]
        inner = m >= 0
        assert np.all(m < k)
        other = s[m[inner]]
        assert np.all(np.any(other == a[inner, None], axis=1))
        assert np.all(np.any(other == b[inner, None], axis=1))
        assert not np.any(np.any(other == s[inner, j, None], axis=1))
        # The neighbour's entry opposite its third vertex points back.
        third = np.argmax((other != a[inner, None]) & (other != b[inner, None]), axis=1)
        np.testing.assert_array_equal(nb[m[inner], third], np.nonzero(inner)[0])
        boundary |= edge_set(np.stack([a[~inner], b[~inner]], axis=1))
    assert boundary == hull
    p = tri.points
    a, b, c = (p[s[:, j]] for j in range(3))
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    unsure = np.nonzero(cross <= 0)[0]  # nearly flat: decided exactly
    if len(unsure):
        z = exact_integers(p)
        assert all(v > 0 for v in orient(*(z[s[unsure, j]] for j in range(3))))
    vts = tri.vertex_to_simplex
    used = np.unique(s)
    assert_contains(s, vts[used], used)


def assert_same_types(ours, theirs, xi_shapes=((2,), (7, 2), (3, 4, 2))):
    """Every attribute (and find_simplex's output) with scipy's dtype, shape and ndim."""
    for name in ("points", "simplices", "neighbors", "convex_hull", "coplanar", "vertex_to_simplex",
                 "min_bound", "max_bound"):
        a, b = getattr(ours, name), getattr(theirs, name)
        assert isinstance(a, np.ndarray), name
        assert (a.dtype, a.shape, a.ndim) == (b.dtype, b.shape, b.ndim), name
    for a, b in zip(ours.vertex_neighbor_vertices, theirs.vertex_neighbor_vertices):
        assert isinstance(a, np.ndarray)
        assert (a.dtype, a.shape, a.ndim) == (b.dtype, b.shape, b.ndim)
    assert len(ours.vertex_neighbor_vertices) == 2
    assert ours.ndim == theirs.ndim == 2
    assert (ours.npoints, ours.nsimplex) == (theirs.npoints, theirs.nsimplex)
    assert isinstance(ours.npoints, int) and isinstance(ours.nsimplex, int)
    rng = np.random.default_rng(1)
    for shape in xi_shapes:
        xi = rng.random(shape)
        a, b = ours.find_simplex(xi), theirs.find_simplex(xi)
        assert isinstance(a, np.ndarray)
        assert (a.dtype, a.shape, a.ndim) == (b.dtype, b.shape, b.ndim) == (INTC, shape[:-1], len(shape) - 1)


def assert_same_delaunay(ours, reference, compare_coplanar=True):
    """ours and reference (scipy's, or another Delaunay) are the same triangulation, attribute by
    attribute, modulo the order of the simplices (and of the rotation of each simplex)."""
    n = ours.npoints
    np.testing.assert_array_equal(ours.points, reference.points)
    assert (ours.npoints, ours.nsimplex, ours.ndim) == (reference.npoints, reference.nsimplex, reference.ndim)
    np.testing.assert_array_equal(ours.min_bound, reference.min_bound)
    np.testing.assert_array_equal(ours.max_bound, reference.max_bound)
    for name in ("simplices", "neighbors", "convex_hull", "coplanar", "vertex_to_simplex"):
        assert getattr(ours, name).dtype == INTC, name
    np.testing.assert_array_equal(oriented(ours.simplices), oriented(reference.simplices))
    # neighbors, after mapping our rows onto the reference's.
    rows = row_map(ours.simplices, reference.simplices, n)
    inverse = np.empty(len(rows), dtype=np.int64)
    inverse[rows] = np.arange(len(rows))
    theirs, their_nb = reference.simplices[rows], reference.neighbors[rows]
    everywhere = np.arange(len(rows))
    for j in range(3):
        col = np.argmax(theirs == ours.simplices[:, j, None], axis=1)
        np.testing.assert_array_equal(theirs[everywhere, col], ours.simplices[:, j])
        expected = their_nb[everywhere, col]
        expected = np.where(expected >= 0, inverse[np.maximum(expected, 0)], -1)
        np.testing.assert_array_equal(ours.neighbors[:, j], expected)
    assert edge_set(ours.convex_hull) == edge_set(reference.convex_hull)
    assert len(ours.convex_hull) == len(reference.convex_hull)
    indptr, _ = ours.vertex_neighbor_vertices
    np.testing.assert_array_equal(indptr, reference.vertex_neighbor_vertices[0])
    assert neighbour_sets(ours) == neighbour_sets(reference)
    used = np.unique(ours.simplices)
    assert_contains(ours.simplices, ours.vertex_to_simplex[used], used)
    assert_contains(reference.simplices, reference.vertex_to_simplex[used], used)
    if compare_coplanar:
        assert ours.coplanar.shape == reference.coplanar.shape
        np.testing.assert_array_equal(ours.coplanar[:, [0, 2]], reference.coplanar[:, [0, 2]])
    assert_own_invariants(ours)


# Exact arithmetic: the doubles scaled by a common power of two to Python integers.


def exact_integers(points):
    """The coordinates as an object array of Python integers: every double times one common
    power of two (Fraction(float) is exact, and so is this)."""
    ratios = [float(v).as_integer_ratio() for v in np.asarray(points, dtype=float).ravel()]
    scale = max([d for _, d in ratios], default=1)  # a power of two
    return np.array([num * (scale // d) for num, d in ratios] or np.zeros(0), dtype=object).reshape(
        np.shape(points))


def orient(a, b, c):
    return (b[..., 0] - a[..., 0]) * (c[..., 1] - a[..., 1]) - (b[..., 1] - a[..., 1]) * (c[..., 0] - a[..., 0])


def in_circle(a, b, c, d):
    """> 0 iff d is strictly inside the circle through the counterclockwise a, b, c."""
    ad, bd, cd = a - d, b - d, c - d
    lift = [(v[..., 0] * v[..., 0] + v[..., 1] * v[..., 1]) for v in (ad, bd, cd)]
    return (lift[0] * (bd[..., 0] * cd[..., 1] - cd[..., 0] * bd[..., 1])
            + lift[1] * (cd[..., 0] * ad[..., 1] - ad[..., 0] * cd[..., 1])
            + lift[2] * (ad[..., 0] * bd[..., 1] - bd[..., 0] * ad[..., 1]))


def assert_exact_delaunay(points, simplices):
    """In exact arithmetic: simplices triangulate the convex hull of the points with every
    distinct point a vertex, and no point is strictly inside a triangle's circumcircle."""
    z = exact_integers(points)
    s = np.asarray(simplices, dtype=np.int64)
    assert len(s) > 0
    a, b, c = (z[s[:, j]] for j in range(3))
    assert all(v > 0 for v in orient(a, b, c)), "a triangle is not counterclockwise"
    # Each directed edge at most once; the edges without their reverse are the boundary.
    directed = collections.Counter(map(tuple, np.concatenate([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]]).tolist()))
    assert max(directed.values()) == 1
    boundary = [e for e in directed if (e[1], e[0]) not in directed]
    # The boundary is one cycle with every point on its left: the convex hull.
    nxt = dict(boundary)
    assert len(nxt) == len(boundary)
    start, k, cycle = boundary[0][0], boundary[0][0], 0
    while True:
        k = nxt[k]
        cycle += 1
        if k == start:
            break
    assert cycle == len(boundary)
    e = np.array(boundary)
    for i in range(len(z)):
        assert all(v >= 0 for v in orient(z[e[:, 0]], z[e[:, 1]], z[i][None, :]))
    # A disk (V - E + F = 1) whose vertices are all the distinct points.
    vertices = set(s.ravel().tolist())
    edges = edge_set(np.array(list(directed)))
    assert len(vertices) - len(edges) + len(s) == 1
    distinct = {tuple(r) for r in z.tolist()}
    assert {tuple(z[v]) for v in vertices} == distinct and len(vertices) == len(distinct)
    # Empty circumcircles: every (triangle, point) pair.
    for i in range(len(z)):
        d = z[i][None, :]
        assert all(v <= 0 for v in in_circle(a, b, c, d)), f"point {i} is inside a circumcircle"


def is_exact_delaunay(points, simplices):
    try:
        assert_exact_delaunay(points, simplices)
        return True
    except AssertionError:
        return False


def canonical_indices(points):
    """For each point, the smallest index of a point equal to it."""
    _, first, inverse = np.unique(points, axis=0, return_index=True, return_inverse=True)
    return first[inverse.ravel()]


# ----------------------------------------------------------------------------------------------
# 1. General position: every attribute as scipy's


@pytest.mark.parametrize("n", [3, 4, 10, 1000, 20000])
def test_attributes_equal_scipy(n):
    points = uniform(n, 10 + n)
    ours = dfp.Delaunay(points)
    theirs = scipy.spatial.Delaunay(points)
    assert_same_types(ours, theirs)
    # Simplices: the same oriented triangles (both counterclockwise).
    np.testing.assert_array_equal(oriented(ours.simplices), oriented(theirs.simplices))
    assert_same_delaunay(ours, theirs)
    assert ours.coplanar.shape == (0, 3)
    np.testing.assert_array_equal(ours.min_bound, points.min(axis=0))
    np.testing.assert_array_equal(ours.max_bound, points.max(axis=0))
    assert ours.nsimplex == len(ours.simplices) == 2 * n - 2 - len(ours.convex_hull)
    # Each vertex's neighbours are those of scipy, vertex by vertex.
    assert neighbour_sets(ours) == neighbour_sets(theirs)
    assert all(len(v) >= 2 for v in neighbour_sets(ours))
    assert isinstance(ours.statistics, dict) and "flips" in ours.statistics
    # qhull_options accepted and ignored.
    np.testing.assert_array_equal(dfp.Delaunay(points, qhull_options="Qbb Qc Qz Q12").simplices, ours.simplices)


def test_convex_hull_is_counterclockwise():
    """The docstring: the hull's edges counterclockwise around the hull, each from one hull vertex
    to the next (scipy gives no order; this is the module's own promise)."""
    for points in (np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]), uniform(500, 2)):
        h = dfp.Delaunay(points).convex_hull
        np.testing.assert_array_equal(h[:, 1], np.roll(h[:, 0], -1))  # a cycle, one edge to the next
        a, b = points[h[:, 0]], points[h[:, 1]]
        side = (b[:, 0] - a[:, 0])[:, None] * (points[None, :, 1] - a[:, None, 1]) - \
            (b[:, 1] - a[:, 1])[:, None] * (points[None, :, 0] - a[:, None, 0])
        assert np.all(side >= 0), "a point is to the right of a hull edge"


def test_unsupported_options_raise():
    points = uniform(20, 1)
    with pytest.raises(ValueError):
        dfp.Delaunay(points, furthest_site=True)
    with pytest.raises(ValueError):
        dfp.Delaunay(points, incremental=True)
    dfp.Delaunay(points, furthest_site=False, incremental=False, qhull_options=None)


# ----------------------------------------------------------------------------------------------
# 2. find_simplex


def test_find_simplex_random_queries_equal_scipy():
    rng = np.random.default_rng(20)
    points = uniform(1000, 21)
    ours, theirs = dfp.Delaunay(points), scipy.spatial.Delaunay(points)
    queries = rng.uniform(-0.2, 1.2, (10000, 2))
    expected = theirs.find_simplex(queries)
    # Keep the queries away from every edge (1e-9), where qhull's tolerance could decide.
    inside = expected >= 0
    t = theirs.transform[expected[inside]]
    bary = np.einsum("kij,kj->ki", t[:, :2], queries[inside] - t[:, 2])
    bary = np.concatenate([bary, 1 - bary.sum(axis=1, keepdims=True)], axis=1)
    far = np.ones(len(queries), dtype=bool)
    far[inside] = bary.min(axis=1) > 1e-9
    h = theirs.convex_hull
    a, b = points[h[:, 0]], points[h[:, 1]]
    ab = b - a
    t = np.clip(np.einsum("qhk,hk->qh", queries[:, None, :] - a[None], ab) / (ab * ab).sum(axis=1), 0, 1)
    distance = np.linalg.norm(queries[:, None, :] - (a[None] + t[..., None] * ab[None]), axis=2).min(axis=1)
    far &= distance > 1e-9
    assert far.sum() > 9900 and (~inside[far]).sum() > 2000
    queries, expected = queries[far], expected[far]
    got = ours.find_simplex(queries)
    assert got.dtype == INTC and got.shape == (len(queries),)
    rows = row_map(ours.simplices, theirs.simplices, len(points))
    mapped = np.where(got >= 0, rows[np.maximum(got, 0)], -1)
    np.testing.assert_array_equal(mapped, expected)
    # Same answers for any shape of xi, and for a list; bruteforce and tol are accepted.
    np.testing.assert_array_equal(ours.find_simplex(queries[:9000].reshape(30, 300, 2)), got[:9000].reshape(30, 300))
    np.testing.assert_array_equal(ours.find_simplex(queries[:50].tolist()), got[:50])
    np.testing.assert_array_equal(ours.find_simplex(queries[:50], bruteforce=True, tol=1e-3), got[:50])
    single = ours.find_simplex(queries[0])
    assert single.shape == () and single == got[0]


def integer_points(kind):
    if kind == "lattice":
        return np.array([(x, y) for x in range(9) for y in range(7)], dtype=float)
    rng = np.random.default_rng(22)
    return np.unique(rng.integers(0, 1000, (300, 2)), axis=0)[rng.permutation(300)[:280]].astype(float)


@pytest.mark.parametrize("kind", ["lattice", "random integers"])
def test_find_simplex_on_vertices_and_edges(kind):
    points = integer_points(kind)
    tri = dfp.Delaunay(points)
    s = tri.simplices.astype(np.int64)
    e = np.array(sorted(edge_set(np.concatenate([s[:, [0, 1]], s[:, [1, 2]], s[:, [2, 0]]]))))
    midpoints = (points[e[:, 0]] + points[e[:, 1]]) / 2  # exact: half-integers
    queries = np.vstack([points, midpoints])
    got = tri.find_simplex(queries).astype(np.int64)
    assert np.all(got >= 0)
    # Closed containment, with integer cross products on the doubled coordinates.
    q = np.rint(2 * queries).astype(np.int64)
    z = np.rint(2 * points).astype(np.int64)
    corners = s[got]
    for j in range(3):
        a, b = z[corners[:, j]], z[corners[:, (j + 1) % 3]]
        assert np.all(orient(a, b, q) >= 0)
    # A query on a vertex gets a simplex having it as a corner.
    assert np.all(np.any(corners[: len(points)] == np.arange(len(points))[:, None], axis=1))
    # Hull edges' midpoints nudged outward by 2^-30 (exactly) are outside, inward inside.
    h = tri.convex_hull.astype(np.int64)
    a, b = points[h[:, 0]], points[h[:, 1]]
    # The left normal, flipped where the hull is to the left (whatever the edges' orientation).
    normal = np.stack([-(b - a)[:, 1], (b - a)[:, 0]], axis=1) * 2.0**-30
    centre = points.mean(axis=0)
    normal[orient(a, b, centre[None, :]) > 0] *= -1
    mid = (a + b) / 2
    for sign, outside in ((1, True), (-1, False)):
        nudged = mid + sign * normal
        exact = exact_integers(np.vstack([points, nudged, [centre]]))  # one common scale
        zpts, zn, zc = exact[: len(points)], exact[len(points): -1], exact[-1:]
        # Exactly strictly beyond (or before) the hull edge, so out of (in) the hull.
        assert all((v * w < 0) == outside and v != 0
                   for v, w in zip(orient(zpts[h[:, 0]], zpts[h[:, 1]], zn), orient(zpts[h[:, 0]], zpts[h[:, 1]], zc)))
        found = tri.find_simplex(nudged)
        if outside:
            np.testing.assert_array_equal(found, -1)
        else:
            assert np.all(found >= 0)
            corners = s[found]
            for j in range(3):
                assert all(v >= 0 for v in orient(zpts[corners[:, j]], zpts[corners[:, (j + 1) % 3]], zn))


def test_find_simplex_outside_and_non_finite():
    tri = dfp.Delaunay(integer_points("random integers"))
    lo, hi = tri.min_bound, tri.max_bound
    xi = np.array([[lo[0] - 0.5, lo[1]], [hi[0] + 1e-9, hi[1]], [lo[0], lo[1] - 1e-3], [1e300, 0], [-1e300, -1e300],
                   [np.nan, 500], [500, np.nan], [np.nan, np.nan], [np.inf, 500], [-np.inf, 500], [500, np.inf],
                   [np.inf, -np.inf]])
    got = tri.find_simplex(xi)
    assert got.dtype == INTC
    np.testing.assert_array_equal(got, -1)
    # Non-finite entries among finite ones do not disturb the others.
    mixed = np.array([[500.0, 500.0], [np.nan, 1.0], [400.0, 600.0]])
    got = tri.find_simplex(mixed)
    assert got[1] == -1 and got[0] >= 0 and got[2] >= 0
    np.testing.assert_array_equal(got[[0, 2]], tri.find_simplex(mixed[[0, 2]]))


# ----------------------------------------------------------------------------------------------
# 3. The integer lattice: co-circular everywhere


@pytest.mark.parametrize("shuffle", [False, True])
def test_lattice(shuffle):
    points = np.array([(x, y) for x in range(12) for y in range(10)], dtype=float)
    if shuffle:
        points = points[np.random.default_rng(30).permutation(len(points))]
    ours = dfp.Delaunay(points)
    theirs = scipy.spatial.Delaunay(points)
    assert_same_types(ours, theirs)
    assert ours.nsimplex == theirs.nsimplex == 2 * 11 * 9
    assert_exact_delaunay(points, ours.simplices)
    assert edge_set(ours.convex_hull) == edge_set(theirs.convex_hull)
    assert len(ours.convex_hull) == 2 * (11 + 9)
    np.testing.assert_array_equal(oriented(ours.simplices), oriented(dfp.delaunay_triangulation(points)))
    assert_own_invariants(ours)
    # Each unit square is split by one diagonal: 2 triangles per square, every edge of length 1
    # or sqrt(2).
    lengths = {round(float(np.linalg.norm(points[a] - points[b])) ** 2) for a, b in edge_set(
        np.concatenate([ours.simplices[:, [0, 1]], ours.simplices[:, [1, 2]]]))}
    assert lengths == {1, 2}


# ----------------------------------------------------------------------------------------------
# 4. Duplicates


def test_duplicates():
    rng = np.random.default_rng(40)
    base = uniform(300, 41)
    points = np.vstack([base, base[rng.integers(0, 300, 80)], base[:5], base[:5]])[rng.permutation(390)]
    n = len(points)
    ours, theirs = dfp.Delaunay(points), scipy.spatial.Delaunay(points)
    canonical = canonical_indices(points)
    duplicates = np.nonzero(canonical != np.arange(n))[0]
    assert len(duplicates) == n - len(np.unique(points, axis=0)) > 80
    # coplanar: exactly the non-smallest indices, each with its smallest and a simplex holding it.
    cop = ours.coplanar
    assert cop.dtype == INTC and cop.shape == (len(duplicates), 3)
    np.testing.assert_array_equal(np.sort(cop[:, 0]), duplicates)
    np.testing.assert_array_equal(cop[:, 2], canonical[cop[:, 0]])
    assert_contains(ours.simplices, cop[:, 1], cop[:, 2])
    assert cop.shape == theirs.coplanar.shape
    # Only the smallest indices are vertices; as coordinate triangles the simplices are scipy's.
    used = np.unique(ours.simplices)
    np.testing.assert_array_equal(used, np.unique(canonical))
    np.testing.assert_array_equal(oriented(ours.simplices), oriented(canonical[theirs.simplices]))
    np.testing.assert_array_equal(oriented(ours.simplices), oriented(dfp.delaunay_triangulation(points)))
    # No neighbours for the duplicates; the others' are scipy's, modulo the representative.
    sets = neighbour_sets(ours)
    assert all(not sets[k] for k in duplicates)
    # (qhull may have kept another index of a group as the vertex: merge the groups.)
    their_sets = collections.defaultdict(set)
    for k, around in enumerate(neighbour_sets(theirs)):
        their_sets[int(canonical[k])] |= {int(canonical[v]) for v in around}
    assert {k: sets[k] for k in used.tolist()} == dict(their_sets)
    assert_own_invariants(ours)
    # vertex_to_simplex of a duplicate: a simplex holding its vertex.
    assert_contains(ours.simplices, ours.vertex_to_simplex, canonical)
    # find_simplex on a duplicate: a simplex holding the point.
    assert_contains(ours.simplices, ours.find_simplex(points[duplicates]), canonical[duplicates])
    assert_same_types(ours, theirs)


# ----------------------------------------------------------------------------------------------
# 5. Collinear, too few points, near-collinear


@pytest.mark.parametrize("points", [
    np.empty((0, 2)),
    np.array([[0.5, 0.25]]),
    np.array([[0.5, 0.25], [1.0, 3.0]]),
    np.array([[0.5, 0.25], [0.5, 0.25]]),
    np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
    np.array([[i, 2.0 * i] for i in range(20)])[np.random.default_rng(50).permutation(20)],
    np.array([[3.0, 4.0]] * 5),
    np.array([[1.0, 0.0], [0.0, 1.0], [1.0, 0.0], [0.5, 0.5], [0.0, 1.0]]),
], ids=["empty", "one", "two", "two equal", "three collinear", "twenty collinear", "five equal",
        "collinear with duplicates"])
def test_no_triangles(points):
    with pytest.raises(Exception):
        scipy.spatial.Delaunay(points)
    tri = dfp.Delaunay(points)
    n = len(points)
    assert tri.simplices.shape == (0, 3) and tri.simplices.dtype == INTC
    assert tri.neighbors.shape == (0, 3) and tri.neighbors.dtype == INTC
    assert tri.convex_hull.shape == (0, 2) and tri.convex_hull.dtype == INTC
    assert tri.nsimplex == 0 and tri.npoints == n and tri.ndim == 2
    assert tri.points.shape == (n, 2) and tri.points.dtype == np.float64
    assert tri.vertex_to_simplex.shape == (n,) and tri.vertex_to_simplex.dtype == INTC
    np.testing.assert_array_equal(tri.vertex_to_simplex, -1)
    assert tri.coplanar.dtype == INTC and tri.coplanar.shape[1] == 3
    if n:
        canonical = canonical_indices(points)
        duplicates = np.nonzero(canonical != np.arange(n))[0]
        np.testing.assert_array_equal(np.sort(tri.coplanar[:, 0]), duplicates)
        np.testing.assert_array_equal(tri.coplanar[:, 2], canonical[tri.coplanar[:, 0]])
        np.testing.assert_array_equal(tri.coplanar[:, 1], -1)
        np.testing.assert_array_equal(tri.min_bound, points.min(axis=0))
        np.testing.assert_array_equal(tri.max_bound, points.max(axis=0))
    queries = np.vstack([points, (points[:1] + points[-1:]) / 2, [[0.5, 0.5]]]) if n else np.array([[0.5, 0.5]])
    got = tri.find_simplex(queries)
    assert got.dtype == INTC and got.shape == (len(queries),)
    np.testing.assert_array_equal(got, -1)
    assert tri.find_simplex(np.zeros((2, 3, 2))).shape == (2, 3)


def near_collinear_inputs():
    rng = np.random.default_rng(51)
    x = np.sort(rng.random(30))
    base = np.array([[float(i), 0.0] for i in range(11)])
    return {
        "y = x + 1e-12 noise": np.stack([x, x + 1e-12 * rng.random(30)], axis=1),
        "y = 0.1 x (rounded)": np.stack([x, 0.1 * x], axis=1),
        "y = x, one ulp off": np.vstack([np.stack([x, x], axis=1), [[0.5, np.nextafter(0.5, 1.0)]]]),
        "flat fan": np.vstack([base, [[5.0, 1e-9]]]),
        "flat fans both sides": np.vstack([base, [[5.5, -1e-12], [2.25, 1e-13]]]),
        "fan at 1e-300": np.vstack([base, [[3.0, 1e-300]]]),
        "near-collinear shuffled": np.stack([x, 1 - x + 1e-14 * rng.normal(size=30)], axis=1)[rng.permutation(30)],
    }


@pytest.mark.parametrize("name", list(near_collinear_inputs()))
def test_near_collinear(name):
    points = near_collinear_inputs()[name]
    tri = dfp.Delaunay(points)
    assert_exact_delaunay(points, tri.simplices)
    np.testing.assert_array_equal(oriented(tri.simplices), oriented(dfp.delaunay_triangulation(points)))
    assert_own_invariants(tri)
    try:
        theirs = scipy.spatial.Delaunay(points)
    except Exception:  # qhull gives up on some of these
        return
    # Where qhull's answer is a true Delaunay triangulation of every point, it is ours (no
    # co-circular ties here). qhull 2019.1 (scipy 1.10) answers "y = x + 1e-12 noise" and "flat
    # fan" so; its answers for "flat fans both sides" (17 triangles, not Delaunay) and
    # "near-collinear shuffled" (4 points dropped as coplanar) are not.
    if len(theirs.coplanar) == 0 and is_exact_delaunay(points, theirs.simplices):
        assert_same_delaunay(tri, theirs)


# ----------------------------------------------------------------------------------------------
# 6. move()


def read_all(tri):
    """Reads every attribute, so that a cache would be filled before a move()."""
    return [tri.points, tri.simplices, tri.neighbors, tri.convex_hull, tri.coplanar, tri.vertex_to_simplex,
            tri.vertex_neighbor_vertices, tri.min_bound, tri.max_bound, tri.npoints, tri.nsimplex, tri.statistics]


def test_move():
    rng = np.random.default_rng(60)
    n = 1000
    points = uniform(n, 61)
    tri = dfp.Delaunay(points)
    jittered = points + rng.normal(scale=1e-3, size=points.shape)
    merged = jittered[rng.permutation(n)]
    merged[[5, 700]] = merged[321]
    split = merged + rng.normal(scale=1e-4, size=points.shape)
    steps = [("small jitter", jittered, False), ("large permutation", jittered[rng.permutation(n)], False),
             ("two points merged onto one", merged, True), ("split", split, True),
             ("jitter again", split + rng.normal(scale=1e-4, size=points.shape), False)]
    for name, new, rebuilt in steps:
        returned = read_all(tri)
        kept = [np.copy(a) if isinstance(a, np.ndarray) else a for a in returned[:7]]
        stats = tri.move(new)
        # The arrays returned before the move are the caller's: not written over by it.
        for a, b in zip(returned[:7], kept):
            for u, v in zip(a, b) if isinstance(a, tuple) else [(a, b)]:
                np.testing.assert_array_equal(u, v)
        assert isinstance(stats, dict) and stats["rebuilt"] is rebuilt, name
        assert tri.statistics == stats, name
        np.testing.assert_array_equal(tri.points, new)
        fresh = dfp.Delaunay(new)
        assert_same_delaunay(tri, fresh)
        np.testing.assert_array_equal(tri.find_simplex(new[:100]) >= 0, True)
        if name == "two points merged onto one":
            np.testing.assert_array_equal(tri.coplanar[:, [0, 2]], [[321, 5], [700, 5]])
            assert_contains(tri.simplices, tri.coplanar[:, 1], [5, 5])
        else:
            assert tri.coplanar.shape == (0, 3)
            theirs = scipy.spatial.Delaunay(new)
            assert_same_delaunay(tri, theirs)
            assert_same_types(tri, theirs)


def test_move_errors_leave_it_unchanged():
    points = uniform(300, 62)
    tri = dfp.Delaunay(points)
    before = [np.copy(a) for a in (tri.simplices, tri.neighbors, tri.points)]
    assert issubclass(dfp.InvalidPrediction, ValueError)
    for value in (np.nan, np.inf, -np.inf):
        bad = points + 0.01
        bad[17, 1] = value
        with pytest.raises(dfp.InvalidPrediction):
            tri.move(bad)
    with pytest.raises(ValueError):
        tri.move(points[:-1])
    with pytest.raises(ValueError):
        tri.move(np.vstack([points, [[0.5, 0.5]]]))
    with pytest.raises(ValueError):
        tri.move(np.zeros((300, 3)))
    for a, b in zip(before, (tri.simplices, tri.neighbors, tri.points)):
        np.testing.assert_array_equal(a, b)
    assert_same_delaunay(tri, scipy.spatial.Delaunay(points))
    # And it still moves afterwards.
    assert tri.move(points + 0.01)["rebuilt"] is False
    assert_same_delaunay(tri, scipy.spatial.Delaunay(points + 0.01))


# ----------------------------------------------------------------------------------------------
# 7. Predictions


def test_predictions_do_not_change_the_result():
    rng = np.random.default_rng(70)
    n = 2000
    points = uniform(n, 71)
    moved = points + rng.normal(scale=2e-3, size=points.shape)
    expected = dfp.Delaunay(points)
    reference = scipy.spatial.Delaunay(points)
    garbage = rng.integers(0, n, (3 * n, 3))
    garbage = garbage[(garbage[:, 0] != garbage[:, 1]) & (garbage[:, 1] != garbage[:, 2]) &
                      (garbage[:, 0] != garbage[:, 2])]
    predictions = {
        "previous Delaunay": dfp.Delaunay(moved),
        "scipy Delaunay of moved points": scipy.spatial.Delaunay(moved),
        "scipy Delaunay": reference,
        "scipy simplices": reference.simplices,
        "int64 list": reference.simplices.astype(np.int64).tolist(),
        "Delaunay of a prefix": dfp.Delaunay(points[: n // 2]),
        "garbage": garbage,
        "empty": np.empty((0, 3), dtype=np.intc),
    }
    for name, prediction in predictions.items():
        tri = dfp.Delaunay(points, prediction)
        assert_same_delaunay(tri, expected)
        assert tri.statistics["faces_in"] == len(getattr(prediction, "simplices", prediction)), name
    assert dfp.Delaunay(points, reference).statistics["flips"] == 0
    for bad in ([[0, 1, n]], [[0, -1, 2]], np.array([[0, 1, 2], [3, 4, n + 5]]), dfp.Delaunay(uniform(n + 10, 72))):
        with pytest.raises(dfp.InvalidPrediction):
            dfp.Delaunay(points, bad)


# ----------------------------------------------------------------------------------------------
# 8. scipy code runs with only the import changed


def interpolate(delaunay_class, points, values, xi):
    """Piecewise-linear interpolation, NaN outside the hull (as written for scipy)."""
    tri = delaunay_class(points)
    simplex = tri.find_simplex(xi)
    corners = tri.simplices[simplex]
    a, b, c = (tri.points[corners[:, j]] for j in range(3))
    det = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    lb = ((b[:, 0] - xi[:, 0]) * (c[:, 1] - xi[:, 1]) - (b[:, 1] - xi[:, 1]) * (c[:, 0] - xi[:, 0])) / det
    lc = ((a[:, 0] - xi[:, 0]) * (b[:, 1] - xi[:, 1]) - (a[:, 1] - xi[:, 1]) * (b[:, 0] - xi[:, 0])) / det
    la = 1 - lb - lc
    result = lb * values[corners[:, 0]] + lc * values[corners[:, 2]] + la * values[corners[:, 1]]
    return np.where(simplex >= 0, result, np.nan)


def hop_distances(delaunay_class, points, source):
    """Breadth-first search over vertex_neighbor_vertices."""
    indptr, indices = delaunay_class(points).vertex_neighbor_vertices
    distance = np.full(len(points), -1)
    distance[source] = 0
    frontier = collections.deque([source])
    while frontier:
        k = frontier.popleft()
        for m in indices[indptr[k]:indptr[k + 1]]:
            if distance[m] < 0:
                distance[m] = distance[k] + 1
                frontier.append(m)
    return distance


def hull_perimeter_and_area(delaunay_class, points):
    tri = delaunay_class(points)
    e = tri.points[tri.convex_hull]
    perimeter = np.linalg.norm(e[:, 1] - e[:, 0], axis=1).sum()
    s = tri.points[tri.simplices]
    area = 0.5 * np.abs(np.cross(s[:, 1] - s[:, 0], s[:, 2] - s[:, 0])).sum()
    return perimeter, area


def walk(delaunay_class, points, targets):
    """Point location by walking across neighbors from simplex 0: the corners of the triangle
    holding each target, as a sorted tuple (None outside)."""
    tri = delaunay_class(points)
    found = []
    for x in targets:
        s = 0
        for _ in range(10 * tri.nsimplex):
            p = tri.points[tri.simplices[s]]
            for j in range(3):
                a, b = p[(j + 1) % 3], p[(j + 2) % 3]
                # x beyond the edge opposite corner j (on the other side from corner j).
                if np.cross(b - a, x - a) * np.cross(b - a, p[j] - a) < 0:
                    s = tri.neighbors[s, j]
                    break
            else:
                break
            if s < 0:
                break
        found.append(None if s < 0 else tuple(sorted(tri.simplices[s].tolist())))
    return found


def test_scipy_code_with_only_the_import_changed():
    rng = np.random.default_rng(80)
    points = uniform(500, 81)
    values = np.sin(3 * points[:, 0]) + points[:, 1] ** 2
    xi = rng.uniform(-0.1, 1.1, (2000, 2))
    got, want = interpolate(dfp.Delaunay, points, values, xi), interpolate(scipy.spatial.Delaunay, points, values, xi)
    np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
    assert np.isnan(want).sum() > 100 and (~np.isnan(want)).sum() > 1000
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(hop_distances(dfp.Delaunay, points, 0),
                                  hop_distances(scipy.spatial.Delaunay, points, 0))
    np.testing.assert_allclose(hull_perimeter_and_area(dfp.Delaunay, points),
                               hull_perimeter_and_area(scipy.spatial.Delaunay, points), rtol=1e-12)
    targets = xi[:60]
    assert walk(dfp.Delaunay, points, targets) == walk(scipy.spatial.Delaunay, points, targets)


# ----------------------------------------------------------------------------------------------
# 9. parallel


def test_parallel_gives_identical_arrays():
    rng = np.random.default_rng(90)
    points = uniform(20000, 91)
    a, b = dfp.Delaunay(points), dfp.Delaunay(points, parallel=True)
    for x, y in zip(read_all(a)[:-1], read_all(b)[:-1]):
        if isinstance(x, tuple):
            for u, v in zip(x, y):
                np.testing.assert_array_equal(u, v)
        else:
            np.testing.assert_array_equal(x, y)
    xi = rng.random((5000, 2))
    np.testing.assert_array_equal(a.find_simplex(xi), b.find_simplex(xi))
    # A parallel move is the same triangulation as a sequential one.
    moved = points + rng.normal(scale=1e-3 / math.sqrt(20), size=points.shape)
    a.move(moved)
    b.move(moved)
    assert_same_delaunay(b, a)
    a.move(points, parallel=True)
    assert_same_delaunay(a, dfp.Delaunay(points))
