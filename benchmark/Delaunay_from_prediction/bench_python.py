#!/usr/bin/env python3
# Copyright (c) 2026 Delaunay_from_prediction contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Benchmark of the Python module delaunay_from_prediction (dfp) against what its users compare it
# with: scipy.spatial.Delaunay (qhull) and, where installed, matplotlib.tri.Triangulation (qhull
# too; an optional peer: its rows are skipped, and the output says so, without matplotlib).
# n uniform random points in the unit square; three phases, each a few rows:
#   build         scipy.spatial.Delaunay(points), dfp.Delaunay(points) (the drop-in for scipy's),
#                 dfp.Delaunay(points, prediction=<the previous frame's simplices>), and
#                 matplotlib.tri.Triangulation(x, y); each with its triangles and neighbours read
#                 (.simplices/.neighbors, .triangles/.neighbors): dfp computes them on first read,
#                 scipy and matplotlib in the constructor.
#   find_simplex  10^6 query points, uniform in the points' bounding box grown by 1% per side (some
#                 outside the hull), on the object built in the same repetition (untimed here):
#                 scipy's find_simplex, dfp.Delaunay.find_simplex, matplotlib's
#                 Triangulation.get_trifinder()(x, y) (the trapezoid map's set-up included).
#   move          points moved by gaussian steps of --moves x the mean spacing 1/sqrt(n) (default
#                 1% and 30%): dfp.Delaunay.move(new) then .simplices/.neighbors,
#                 dfp.Triangulation.move(new) then .triangles (each on an object built, untimed,
#                 at the old points in the same repetition, its triangles read once as a frame loop
#                 does), against rebuilding: scipy.spatial.Delaunay(new) (scipy has no move) and
#                 matplotlib.tri.Triangulation(new x, new y).
# The "previous frame" of the predicted build is points - step: the frames points - step, points,
# points + step move at a constant velocity.
# Every repetition runs every row once, phase by phase, the rows of a phase in an order that
# rotates from one repetition to the next (the machine is noisy: interleaving lets the rows
# share its slow spells); medians over the repetitions; ratio = median over the repetitions of
# scipy's time / the row's time, scipy's row of the same phase (and move scale). Times are wall
# clock around the Python calls (numpy conversions in and out included).
# scipy's find_simplex of 10^6 random queries takes minutes at 10^6 points (each query walks from
# the previous answer): --find-reps bounds the repetitions of the find_simplex phase (default:
# all of them below 10^6 points, 1 from 10^6 on).
# The first repetition checks every result (untimed): every triangulation equals CGAL's
# (dfp.delaunay_triangulation) of its points, and dfp's find_simplex answers are compared with
# scipy's and matplotlib's (the same triangle as a vertex set, -1 the same).
# Allocator: glibc's malloc with its default settings, unless --tuned-malloc, which tells it to
# keep freed memory for the whole process (mallopt(M_MMAP_MAX, 0), mallopt(M_TRIM_THRESHOLD, -1)),
# scipy and matplotlib included.
#
# Usage (the module on PYTHONPATH, Debian's python3 for numpy, scipy and matplotlib):
#   PYTHONPATH=build/python /usr/bin/python3 benchmark/Delaunay_from_prediction/bench_python.py \
#       --n 1e5 --reps 5 --out benchmark/Delaunay_from_prediction/results/python_vs_scipy_1e5.txt

import argparse
import ctypes
import datetime
import math
import os
import platform
import shlex
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
    return f"nproc {os.cpu_count()}, CPU {cpu}, RAM {ram}"


def loadavg():
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def canonical(triangles):
    """The triangle set, each rotated to start at its smallest index (orientation kept)."""
    t = np.asarray(triangles, dtype=np.int64)
    first = np.argmin(t, axis=1)
    t = np.take_along_axis(t, (first[:, None] + np.arange(3)) % 3, axis=1)
    return t[np.lexsort(t.T[::-1])]


def unoriented(triangles):
    t = np.sort(np.asarray(triangles, dtype=np.int64), axis=1)
    return t[np.lexsort(t.T[::-1])]


def find_disagreements(simplices_a, found_a, simplices_b, found_b):
    """(queries inside for one and outside for the other, queries in different triangles)."""
    out_a, out_b = found_a < 0, found_b < 0
    both = ~out_a & ~out_b
    a = np.sort(np.asarray(simplices_a)[found_a[both]], axis=1)
    b = np.sort(np.asarray(simplices_b)[found_b[both]], axis=1)
    return int(np.count_nonzero(out_a != out_b)), int(np.count_nonzero(np.any(a != b, axis=1)))


def snake_order(q):
    """An order of the queries along strips of height 1/sqrt(m), alternately left to right and
    right to left: consecutive queries are close (what scipy's walk needs)."""
    lo, hi = q.min(axis=0), q.max(axis=0)
    strips = max(1, int(math.sqrt(len(q))))
    s = np.minimum(((q[:, 1] - lo[1]) / (hi[1] - lo[1]) * strips).astype(np.int64), strips - 1)
    x = np.where(s % 2 == 0, q[:, 0], -q[:, 0])
    return np.lexsort((x, s))


def timed(f):
    start = time.perf_counter()
    result = f()
    return time.perf_counter() - start, result


def path(stats):
    if stats is None:
        return ""
    if stats.get("rebuilt"):
        return f"rebuilt, flips {stats['flips']}"
    if stats["fell_back"]:
        return "built from scratch (no prediction)" if stats["faces_in"] == 0 else "fell back to a build from scratch: " + stats["fallback_reason"]
    return f"predict, flips {stats['flips']}"


def main():
    parser = argparse.ArgumentParser(description="Python module delaunay_from_prediction vs scipy.spatial.Delaunay "
                                     "(and matplotlib.tri where installed)")
    parser.add_argument("--n", type=float, default=1e5, help="number of points (1e5, 1e6, ...)")
    parser.add_argument("--reps", type=int, default=5, help="repetitions (median reported)")
    parser.add_argument("--find-reps", type=int, default=None,
                        help="repetitions of the find_simplex phase (default: --reps below 1e6 points, 1 from 1e6 on)")
    parser.add_argument("--queries", type=float, default=1e6, help="find_simplex queries (default 1e6)")
    parser.add_argument("--moves", default="0.01,0.3",
                        help="move scales, in mean spacings, comma separated (default 0.01,0.3)")
    parser.add_argument("--seed", type=int, default=20260101)
    parser.add_argument("--no-check", action="store_true", help="skip the (untimed) checks of the first repetition")
    parser.add_argument("--no-matplotlib", action="store_true", help="skip matplotlib's rows even where installed")
    parser.add_argument("--tuned-malloc", action="store_true",
                        help="mallopt(M_MMAP_MAX, 0) and mallopt(M_TRIM_THRESHOLD, -1): glibc keeps freed memory")
    parser.add_argument("--default-malloc", action="store_true",
                        help="glibc's default malloc settings: the default; accepted for old command lines")
    parser.add_argument("--out", help="also write the output to this file")
    args = parser.parse_args()
    n = int(args.n)
    m = int(args.queries)
    scales = [float(s) for s in args.moves.split(",") if s]
    find_reps = args.find_reps if args.find_reps is not None else (args.reps if n < 1000000 else 1)
    find_reps = max(1, min(find_reps, args.reps))
    if args.tuned_malloc and args.default_malloc:
        parser.error("--tuned-malloc and --default-malloc exclude each other")

    malloc = "glibc's malloc, default settings (no mallopt)"
    if args.tuned_malloc:
        malloc = "glibc's malloc, mallopt failed: default settings"
        try:
            libc = ctypes.CDLL("libc.so.6")
            M_TRIM_THRESHOLD, M_MMAP_MAX = -1, -4
            if libc.mallopt(M_MMAP_MAX, 0) == 1 and libc.mallopt(M_TRIM_THRESHOLD, -1) == 1:
                malloc = ("glibc's malloc tuned (--tuned-malloc): mallopt(M_MMAP_MAX, 0) + mallopt(M_TRIM_THRESHOLD, -1), "
                          "no mmap'd blocks, freed memory kept and reused, for the whole process")
        except OSError:
            pass

    mtri, mpl_line = None, ""
    if args.no_matplotlib:
        mpl_line = "matplotlib: skipped (--no-matplotlib), its rows left out"
    else:
        try:
            import matplotlib
            import matplotlib.tri
            mtri = matplotlib.tri
            mpl_line = f"matplotlib {matplotlib.__version__}"
        except ImportError as e:
            mpl_line = f"matplotlib: not installed ({e}), its rows skipped"

    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC")
    load_before = loadavg()
    run_start = time.perf_counter()

    # Inputs, prepared once, untimed.
    rng = np.random.default_rng(args.seed)
    points = rng.random((n, 2))
    spacing = 1 / math.sqrt(n)
    steps = {s: rng.normal(scale=s * spacing, size=points.shape) for s in scales}
    moved = {s: points + steps[s] for s in scales}
    previous = {s: points - steps[s] for s in scales}
    prediction = {s: dfp.Delaunay(previous[s]).simplices.copy() for s in scales}
    lo, hi = points.min(axis=0), points.max(axis=0)
    margin = 0.01 * (hi - lo)
    queries = rng.uniform(lo - margin, hi + margin, size=(m, 2))
    qx, qy = np.ascontiguousarray(queries[:, 0]), np.ascontiguousarray(queries[:, 1])
    xy = {None: (np.ascontiguousarray(points[:, 0]), np.ascontiguousarray(points[:, 1]))}
    for s in scales:
        xy[s] = (np.ascontiguousarray(moved[s][:, 0]), np.ascontiguousarray(moved[s][:, 1]))
    reference = {}
    if not args.no_check:
        reference[None] = dfp.delaunay_triangulation(points)
        for s in scales:
            reference[s] = dfp.delaunay_triangulation(moved[s])

    # Rows: phase -> list of (key, description, function(state) -> (seconds, result, note)).
    # state: the objects built in the build phase of the current repetition.
    def delaunay_build(delaunay_class, *args):
        """scipy's or the module's Delaunay(*args), its simplices and neighbors read."""
        def f():
            d = delaunay_class(*args)
            d.simplices, d.neighbors
            return d
        return f

    def scipy_build(p):
        return delaunay_build(scipy.spatial.Delaunay, p)

    def dfp_build(p, pred=None):
        return delaunay_build(dfp.Delaunay, p, pred)

    def mpl_build(x, y):
        def f():
            t = mtri.Triangulation(x, y)
            t.triangles, t.neighbors
            return t
        return f

    def row_build(key, make):
        def run(state):
            seconds, obj = timed(make)
            state[key] = obj
            return seconds, obj, path(getattr(obj, "statistics", None))
        return run

    def scipy_find(state):
        d = state["scipy"]
        seconds, found = timed(lambda: d.find_simplex(queries))
        return seconds, found, ""

    def scipy_find_sorted(state):
        d = state["scipy"]

        def f():
            order = snake_order(queries)
            found = np.empty(m, dtype=np.intc)
            found[order] = d.find_simplex(queries[order])
            return found
        seconds, found = timed(f)
        return seconds, found, "sort + find + unsort timed"

    def dfp_find(state):
        d = state["dfp"]
        seconds, found = timed(lambda: d.find_simplex(queries))
        return seconds, found, ""

    def mpl_find(state):
        t = state["mpl"]
        setup, finder = timed(t.get_trifinder)
        query, found = timed(lambda: finder(qx, qy))
        return setup + query, found, f"trapezoid map set-up {setup:.3f} s + queries {query:.3f} s"

    def scipy_move(s):
        def run(state):
            seconds, d = timed(scipy_build(moved[s]))
            return seconds, d, ""
        return run

    def mpl_move(s):
        def run(state):
            seconds, t = timed(mpl_build(*xy[s]))
            return seconds, t, ""
        return run

    def dfp_move(s):
        def run(state):
            d = dfp.Delaunay(points)
            d.simplices, d.neighbors
            start = time.perf_counter()
            stats = d.move(moved[s])
            middle = time.perf_counter()
            d.simplices, d.neighbors
            end = time.perf_counter()
            return end - start, d, f"{path(stats)}; move() {middle - start:.4f} s"
        return run

    def triangulation_move(s):
        def run(state):
            t = dfp.Triangulation(points)
            t.triangles
            start = time.perf_counter()
            stats = t.move(moved[s])
            middle = time.perf_counter()
            triangles = t.triangles
            end = time.perf_counter()
            return end - start, triangles, f"{path(stats)}; move() {middle - start:.4f} s"
        return run

    def pct(s):
        return f"{100 * s:g}%"

    phases = []
    build = [("scipy", "scipy.spatial.Delaunay(points)", row_build("scipy", scipy_build(points))),
             ("dfp", "dfp.Delaunay(points)", row_build("dfp", dfp_build(points)))]
    for s in scales:
        build.append((f"dfp-pred-{s}", f"dfp.Delaunay(points, prediction=prev) {pct(s)}",
                      row_build(f"dfp-pred-{s}", dfp_build(points, prediction[s]))))
    if mtri:
        build.append(("mpl", "matplotlib.tri.Triangulation(x, y)", row_build("mpl", mpl_build(*xy[None]))))
    phases.append(("build", "build (+ simplices and neighbors read)", build))
    find = [("scipy", "scipy Delaunay.find_simplex(q)", scipy_find),
            ("dfp", "dfp.Delaunay.find_simplex(q)", dfp_find)]
    if mtri:
        find.append(("mpl", "matplotlib get_trifinder()(qx, qy)", mpl_find))
    find.append(("scipy-sorted", "(extra) scipy find_simplex, q snake-sorted", scipy_find_sorted))
    phases.append(("find", f"find_simplex of {m} queries (on the object built in the build phase)", find))
    for s in scales:
        move = [("scipy", "scipy.spatial.Delaunay(new) (rebuild)", scipy_move(s)),
                ("dfp", "dfp.Delaunay.move(new) + read", dfp_move(s)),
                ("tri", "dfp.Triangulation.move(new) + .triangles", triangulation_move(s))]
        if mtri:
            move.append(("mpl", "matplotlib Triangulation(new) (rebuild)", mpl_move(s)))
        phases.append((f"move {pct(s)}", f"move: gaussian steps of {s:g} x mean spacing", move))

    times = {(phase, key): [] for phase, _, rows in phases for key, _, _ in rows}
    notes = {}
    checks = []
    for rep in range(args.reps):
        state = {}
        print(f"bench_python: repetition {rep + 1}/{args.reps}, loadavg {loadavg()}, "
              f"{time.perf_counter() - run_start:.0f} s so far", file=sys.stderr, flush=True)
        for phase, _, rows in phases:
            if phase == "find" and rep >= find_reps:
                continue
            k = rep % len(rows)
            order = rows[k:] + rows[:k]
            results = {}
            for key, description, run in order:
                seconds, result, note = run(state)
                times[(phase, key)].append(seconds)
                notes[(phase, key)] = note
                if rep == 0 and not args.no_check:
                    results[key] = result
            if rep > 0 or args.no_check:
                continue
            # Checks of the first repetition (untimed).
            if phase == "build" or phase.startswith("move"):
                scale = None if phase == "build" else scales[[f"move {pct(s)}" for s in scales].index(phase)]
                expected = reference[scale]
                for key, result in results.items():
                    if key == "scipy":
                        ok = np.array_equal(unoriented(result.simplices), unoriented(expected))
                    elif key == "mpl":
                        ok = np.array_equal(unoriented(result.triangles), unoriented(expected))
                    elif key == "tri":
                        ok = np.array_equal(canonical(result), canonical(expected))
                    else:
                        ok = np.array_equal(canonical(result.simplices), canonical(expected))
                    if not ok:
                        sys.exit(f"bench_python: {phase} {key} differs from CGAL's triangulation")
                checks.append(f"{phase}: the {len(results)} triangulations equal CGAL's of the same points")
            elif phase == "find":
                d = state["dfp"]
                outside = int(np.count_nonzero(results["dfp"] < 0))
                checks.append(f"find_simplex: dfp finds {m - outside} queries inside, {outside} outside (-1); "
                              "disagreements with dfp's answers (inside/outside, another triangle):")
                for key, simplices in (("scipy", state["scipy"].simplices), ("scipy-sorted", state["scipy"].simplices),
                                       ("mpl", state["mpl"].triangles if "mpl" in state else None)):
                    if key in results:
                        io, tri = find_disagreements(d.simplices, results["dfp"], simplices, results[key])
                        checks.append(f"  {key}: {io} inside/outside, {tri} another triangle")
            del results
        del state
    elapsed = time.perf_counter() - run_start

    lines = []
    lines.append(f"Delaunay_from_prediction Python benchmark, {now}")
    lines.append(f"command:  {shlex.join([sys.executable] + sys.argv)}")
    lines.append(f"machine:  {machine()}")
    lines.append(f"load:     loadavg {load_before} before the run, {loadavg()} after it; run time {elapsed:.0f} s")
    lines.append(f"python:   {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, {mpl_line}")
    lines.append(f"module:   {dfp.__file__}")
    lines.append(f"malloc:   {malloc}")
    lines.append(f"setup:    n = {n} uniform points in the unit square, seed {args.seed}; mean spacing 1/sqrt(n);")
    lines.append(f"          {m} queries uniform in the bounding box grown by 1% per side;")
    lines.append(f"          moves: gaussian steps of {', '.join(f'{s:g}' for s in scales)} x the mean spacing; "
                 "prev = points - step (the previous frame)")
    lines.append(f"          median of {args.reps} repetitions ({find_reps} for find_simplex), every row once per repetition,")
    lines.append("          phase by phase, the rows of a phase in an order rotating with the repetition;")
    lines.append("          wall clock of the Python calls (numpy in and out included); build and move rows read the")
    lines.append("          triangles and neighbours (dfp computes them on first read; scipy, matplotlib in the constructor);")
    lines.append("          move rows of dfp: on an object built (untimed) at the old points, triangles already read")
    lines.append("notes:    of the last repetition: the path dfp took (stats), the parts of a time")
    lines.append("ratio:    median over repetitions of scipy's time / the row's time, scipy's row of the same phase")
    lines.append("          (> 1: faster than scipy); the extra row shows scipy with the queries sorted first")
    if args.no_check:
        lines.append("check:    skipped (--no-check)")
    else:
        lines.append("check:    first repetition, untimed:")
        lines.extend(f"          {c}" for c in checks)
    lines.append("")
    lines.append(f"{'phase':9} {'row':44} {'median[s]':>10} {'reps':>4} {'ratio':>8}  note")
    lines.append("-" * 120)
    for phase, title, rows in phases:
        reference_times = times[(phase, "scipy")]
        for key, description, _ in rows:
            t = times[(phase, key)]
            ratio = statistics.median(r / x for r, x in zip(reference_times, t))
            lines.append(f"{phase:9} {description:44} {statistics.median(t):10.4f} {len(t):4d} {ratio:8.2f}  "
                         f"{notes[(phase, key)]}")
    if mtri is None:
        lines.append(f"(matplotlib rows: none; {mpl_line})")
    lines.append("")
    text = "\n".join(lines)
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
