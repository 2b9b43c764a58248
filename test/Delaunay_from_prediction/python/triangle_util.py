# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Helpers shared by the Python tests (pytest puts this folder on sys.path).

import numpy as np


def uniform(n, seed):
    """n points uniform in the unit square, from a seeded generator."""
    return np.random.default_rng(seed).random((n, 2))


def oriented(triangles):
    """The triangles as a sorted array, each rotated to start at its smallest index (so that
    the orientation is kept and compared)."""
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    first = np.argmin(t, axis=1)
    t = np.take_along_axis(t, (first[:, None] + np.arange(3)) % 3, axis=1)
    return t[np.lexsort(t.T[::-1])]
