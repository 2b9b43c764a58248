#!/usr/bin/env python3
# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Benchmark of the Python module delaunay_from_prediction against scipy.spatial.Delaunay
# (qhull), on n uniform random points in the unit square:
#   (a) dfp.delaunay_triangulation(points): CGAL's own build from scratch
#   (b) dfp.delaunay_from_prediction(points, the correct triangles shuffled)
#   (c) dfp.delaunay_from_prediction(moved points, the triangles before the move)
#   (d) Triangulation.move(moved points): make_delaunay() in place (the move only is timed)
#   (e) (d) with parallel=True (CGAL::Parallel_if_available_tag: TBB's threads)
# The moves are gaussian, of scale --move times the mean spacing 1/sqrt(n). Every repetition
# runs scipy and every case once, in a rotating order (the machine is noisy: interleaving
# lets the cases share its slow spells); medians over the repetitions. Times are wall clock
# around the Python call: numpy conversion in and out included. As in the C++ benchmarks,
# glibc's malloc is told to keep freed memory (no mmap'd blocks, no trimming; --default-malloc
# to leave it be): on this VM, the page faults of memory handed back and forth to the kernel
# can double a call's time, and vary from run to run (see the last table of the results).
#
# Usage (the module on PYTHONPATH, Debian's python3 for numpy and scipy):
#   PYTHONPATH=build/python /usr/bin/python3 benchmark/Delaunay_from_prediction/bench_python.py --n 1e5 --reps 5

import argparse
import ctypes
import datetime
import math
import os
import platform
import statistics
import sys
import time

import numpy as np
import scipy
import scipy.spatial

import delaunay_from_prediction as dfp


def machine():
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    ram = "?"
    try:
        with open("/proc/meminfo") as f:
            ram = next(line.split(":", 1)[1].strip() for line in f if line.startswith("MemTotal"))
    except (OSError, StopIteration):
        pass
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    return f"nproc {os.cpu_count()}, CPU {cpu}, RAM {ram}, loadavg {load}"


def canonical(triangles):
    """The triangle set, each rotated to start at its smallest index (orientation kept)."""
    t = np.asarray(triangles, dtype=np.int64)
    first = np.argmin(t, axis=1)
    t = np.take_along_axis(t, (first[:, None] + np.arange(3)) % 3, axis=1)
    return t[np.lexsort(t.T[::-1])]


def unoriented(triangles):
    t = np.sort(np.asarray(triangles, dtype=np.int64), axis=1)
    return t[np.lexsort(t.T[::-1])]


def timed(f):
    start = time.perf_counter()
    result = f()
    return time.perf_counter() - start, result


def main():
    parser = argparse.ArgumentParser(description="Python module delaunay_from_prediction vs scipy.spatial.Delaunay")
    parser.add_argument("--n", type=float, default=1e5, help="number of points (1e5, 1e6, ...)")
    parser.add_argument("--reps", type=int, default=5, help="repetitions (median reported)")
    parser.add_argument("--move", type=float, default=0.01, help="move scale, in mean spacings (default 0.01)")
    parser.add_argument("--seed", type=int, default=20260101)
    parser.add_argument("--no-check", action="store_true", help="skip the (untimed) check of every result")
    parser.add_argument("--default-malloc", action="store_true", help="leave glibc's malloc settings as they are")
    args = parser.parse_args()
    n = int(args.n)
    malloc = "glibc defaults"
    if not args.default_malloc:
        try:
            libc = ctypes.CDLL("libc.so.6")
            M_TRIM_THRESHOLD, M_MMAP_MAX = -1, -4
            if libc.mallopt(M_MMAP_MAX, 0) == 1 and libc.mallopt(M_TRIM_THRESHOLD, -1) == 1:
                malloc = ("mallopt(M_MMAP_MAX, 0) + mallopt(M_TRIM_THRESHOLD, -1): no mmap'd blocks, freed memory "
                          "is kept and reused")
        except OSError:
            pass

    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC")
    machine_line = machine()  # the load before the run
    rng = np.random.default_rng(args.seed)
    points = rng.random((n, 2))
    moved = points + rng.normal(scale=args.move / math.sqrt(n), size=points.shape)
    # Inputs of the predicted cases, prepared once, untimed.
    triangles = dfp.delaunay_triangulation(points)
    shuffled = triangles[rng.permutation(len(triangles))]
    shuffled = np.take_along_axis(shuffled, np.argsort(rng.random(shuffled.shape), axis=1), axis=1)

    kinetic = {}  # the Triangulation objects of the current repetition, built untimed

    def move(parallel):
        t = kinetic.pop(parallel)
        seconds, stats = timed(lambda: t.move(moved, parallel=parallel))
        return seconds, (t.triangles, stats)

    cases = {
        "scipy": lambda: timed(lambda: (scipy.spatial.Delaunay(points).simplices, None)),
        "(a)": lambda: timed(lambda: (dfp.delaunay_triangulation(points), None)),
        "(b)": lambda: timed(lambda: dfp.delaunay_from_prediction(points, shuffled)),
        "(c)": lambda: timed(lambda: dfp.delaunay_from_prediction(moved, triangles)),
        "(d)": lambda: move(False),
        "(e)": lambda: move(True),
    }
    descriptions = {
        "scipy": "scipy.spatial.Delaunay(points).simplices",
        "(a)": "dfp.delaunay_triangulation(points) [CGAL, scratch]",
        "(b)": "dfp.delaunay_from_prediction(points, DT shuffled)",
        "(c)": "dfp.delaunay_from_prediction(moved, DT before)",
        "(d)": "Triangulation.move(moved)",
        "(e)": "Triangulation.move(moved, parallel=True)",
    }
    names = list(cases)
    times = {name: [] for name in names}
    last_stats = {}
    for rep in range(args.reps):
        kinetic[False] = dfp.Triangulation(points)
        kinetic[True] = dfp.Triangulation(points)
        order = names[rep % len(names):] + names[:rep % len(names)]
        for name in order:
            seconds, (result, stats) = cases[name]()
            times[name].append(seconds)
            last_stats[name] = stats
            if rep == 0 and not args.no_check:
                expected = triangles if name in ("scipy", "(a)", "(b)") else dfp.delaunay_triangulation(moved)
                if name == "scipy":
                    ok = np.array_equal(unoriented(result), unoriented(expected))
                else:
                    ok = np.array_equal(canonical(result), canonical(expected))
                if not ok:
                    sys.exit(f"bench_python: {name} differs from CGAL's triangulation")

    ratios = {name: statistics.median(s / o for s, o in zip(times["scipy"], times[name])) for name in names}
    print(f"Delaunay_from_prediction Python benchmark, {now}")
    print(f"command:  {' '.join([sys.executable] + sys.argv)}")
    print(f"machine:  {machine_line}")
    print(f"python:   {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, "
          f"module {dfp.__file__}")
    print(f"setup:    n = {n} uniform points in the unit square, seed {args.seed}; moves: gaussian of scale "
          f"{args.move} x mean spacing 1/sqrt(n);")
    print(f"          median of {args.reps} repetitions, every case once per repetition in a rotating order;")
    print("          wall clock of the Python call (numpy in and out included); (d), (e): the move only,")
    print("          on a Triangulation built (untimed) at the old points in the same repetition;")
    print(f"          (e): TBB's default number of threads ({os.cpu_count()} CPUs here)")
    print(f"malloc:   {malloc}")
    print("ratio:    median over repetitions of scipy's time / the case's time (> 1: faster than scipy)")
    print("check:    every result of the first repetition equals CGAL's triangulation (untimed)"
          if not args.no_check else "check:    skipped (--no-check)")
    print()
    print(f"{'case':5} {'call':52} {'median[s]':>10} {'ratio':>7}  path")
    print("-" * 100)
    for name in names:
        stats = last_stats[name]
        if stats is None:
            path = ""
        else:
            path = "FALLBACK" if stats["fell_back"] else "predict"
            if stats.get("rebuilt"):
                path = "rebuilt"
            path += f", flips {stats['flips']}"
        print(f"{name:5} {descriptions[name]:52} {statistics.median(times[name]):10.4f} {ratios[name]:7.2f}  {path}")
    print()


if __name__ == "__main__":
    main()
