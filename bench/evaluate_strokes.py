#!/usr/bin/python3
"""Prints the measured goals of drawn strokes (docs/DRAWN_STROKES.md) against SPEC's exact ones,
on the sample DEM and the real DEMs in tests/data.

Usage: bench/evaluate_strokes.py BUILD_DIR [WORK_DIR] [--speed DEM8000.tif [RUNS]] [--held-out]
Needs GDAL's Python bindings (python3-gdal) and numpy. TSK_STROKE_OPTIONS adds options to the
drawn runs (to try other settings: TSK_STROKE_OPTIONS="--smooth 2").

- smoothness: total absolute turning angle over total length of the factual strokes, exact over
  drawn (the goal: at least 3);
- accuracy: the share of drawn vertices (both classes) within one cell of an exact stroke of
  their class (the goal: at least 99 %);
- clutter: the share of strokes shorter than 5 cells before grouping (drawn, --join-gap 0) and
  after (drawn), and the total length after over before;
- speed: wall time of the 8000 x 8000 benchmark DEM, drawn over exact (the goal: at most 1.15),
  the best of RUNS runs of each, taken in turns.
- --held-out: the accuracy on every projected DEM in ../shared/data, as it is and averaged to 2x
  and 4x its cells (while 20 cells or more a side), from four azimuths; against the exact
  strokes, and against the exact chains of two cells or more (--min-cells 2): the drawn strokes
  keep the pieces that join, which SPEC's generalisation drops.
"""
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from osgeo import gdal, ogr

from held_out_dems import AZIMUTHS, coarsened, projected_dems

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(REPO, "tests", "data")
DEMS = [("sample (jacksboro, 75 m)", "jacksboro_utm16n.tif", 90),
        ("gorillas (30 m)", "gorillas_utm32n.tif", 270),
        ("bei (5 m lidar)", "bei_5m_local.tif", 180)]


def run(cli, dem, out, strokes, azimuth, extra=()):
    if strokes == "drawn":
        extra = [*os.environ.get("TSK_STROKE_OPTIONS", "").split(), *extra]
    subprocess.run([cli, "silhouettes", dem, out, "--strokes", strokes, "--azimuth", str(azimuth),
                    *extra], check=True, capture_output=True)


def lines(path):
    """(class, N x 2 array of points) of every stroke."""
    ds = ogr.Open(path)
    layer = ds.GetLayer(0)
    found = []
    for feature in layer:
        geometry = feature.GetGeometryRef()
        points = np.array([geometry.GetPoint_2D(k) for k in range(geometry.GetPointCount())])
        found.append((feature.GetField("class"), points))
    return found


def turning_per_length(strokes):
    turn = length = 0.0
    for _, p in strokes:
        d = np.diff(p, axis=0)
        seg = np.hypot(d[:, 0], d[:, 1])
        d = d[seg > 0]
        length += seg.sum()
        if len(d) < 2:
            continue
        heading = np.arctan2(d[:, 1], d[:, 0])
        turn += np.abs(np.angle(np.exp(1j * np.diff(heading)))).sum()
    return turn / length


def segment_distances(points, segments):
    """Distance from each point to the nearest of the segments (K x 4: x0 y0 x1 y1)."""
    a, b = segments[:, 0:2], segments[:, 2:4]
    ab = b - a
    denom = np.maximum((ab * ab).sum(axis=1), 1e-300)
    best = np.full(len(points), np.inf)
    for start in range(0, len(points), 256):
        p = points[start:start + 256, None, :]
        t = np.clip(((p - a) * ab).sum(axis=2) / denom, 0.0, 1.0)
        nearest = a + t[:, :, None] * ab
        best[start:start + 256] = np.sqrt(((p - nearest) ** 2).sum(axis=2)).min(axis=1)
    return best


def within_one_cell(drawn, exact, cell):
    """Share of the drawn vertices within a cell of an exact stroke of their class, found in
    tiles of 50 cells with the exact segments that reach into each tile's surroundings."""
    near = total = 0
    for cls in ("factual", "formulated"):
        segs = [np.hstack([p[:-1], p[1:]]) for c, p in exact if c == cls and len(p) > 1]
        singles = [np.hstack([p, p]) for c, p in exact if c == cls and len(p) == 1]
        segs = np.vstack(segs + singles) if segs or singles else np.zeros((0, 4))
        pts = np.vstack([p for c, p in drawn if c == cls]) if any(c == cls for c, _ in drawn) \
            else np.zeros((0, 2))
        total += len(pts)
        if len(pts) == 0 or len(segs) == 0:
            continue
        tile = 50 * cell
        lo = np.minimum(segs[:, 0:2], segs[:, 2:4])
        hi = np.maximum(segs[:, 0:2], segs[:, 2:4])
        keys = np.floor(pts / tile).astype(np.int64)
        for key in np.unique(keys, axis=0):
            inside = (keys == key).all(axis=1)
            x0, y0 = key * tile - 2 * cell
            x1, y1 = (key + 1) * tile + 2 * cell
            reach = (hi[:, 0] >= x0) & (lo[:, 0] <= x1) & (hi[:, 1] >= y0) & (lo[:, 1] <= y1)
            if not reach.any():
                continue
            d = segment_distances(pts[inside], segs[reach])
            near += int((d <= cell * (1 + 1e-9)).sum())
    return near / total if total else float("nan")


def clutter(strokes, cell):
    lengths = [float(np.hypot(*np.diff(p, axis=0).T).sum()) if len(p) > 1 else 0.0
               for _, p in strokes]
    short = sum(1 for s in lengths if s < 5 * cell)
    return short / len(lengths), sum(lengths), len(lengths)


def run_variants(cli, work, dem, azimuth, variants):
    """The strokes of each (name, strokes mode, extra options) run of `dem`, by name."""
    found = {}
    for name, strokes, extra in variants:
        path = os.path.join(work, name + ".gpkg")
        run(cli, dem, path, strokes, azimuth, extra)
        found[name] = lines(path)
    return found


def evaluate(cli, work, name, file, azimuth):
    dem = os.path.join(DATA, file)
    cell = abs(gdal.Open(dem).GetGeoTransform()[1])
    out = run_variants(cli, work, dem, azimuth,
                       (("exact", "exact", ()), ("drawn", "drawn", ()),
                        ("ungrouped", "drawn", ("--join-gap", "0"))))
    factual = {k: [s for s in v if s[0] == "factual"] for k, v in out.items()}
    smooth = turning_per_length(factual["exact"]) / turning_per_length(factual["drawn"])
    accuracy = within_one_cell(out["drawn"], out["exact"], cell)
    short_e, length_e, n_e = clutter(out["ungrouped"], cell)
    short_d, length_d, n_d = clutter(out["drawn"], cell)
    print("%-26s %8.2fx %9.2f %% %8d %5.1f %% %8d %5.1f %% %9.3f" % (
        name, smooth, 100 * accuracy, n_e, 100 * short_e, n_d, 100 * short_d,
        length_d / length_e))


def speed(cli, work, dem, runs):
    best = {}
    for _ in range(runs):
        for strokes in ("exact", "drawn"):
            start = time.perf_counter()
            run(cli, dem, os.path.join(work, "speed.gpkg"), strokes, 90)
            best[strokes] = min(best.get(strokes, math.inf), time.perf_counter() - start)
    print("\n8000 x 8000 DEM, best of %d: exact %.2f s, drawn %.2f s, drawn / exact %.3f "
          "(goal: at most 1.15)" % (runs, best["exact"], best["drawn"],
                                     best["drawn"] / best["exact"]))


def held_out(cli, work):
    print("\nHeld out: drawn vertices within a cell of the exact strokes / of the exact chains "
          "of 2 or more cells (goal 99 %)")
    worst = [100.0, 100.0]
    for name, src in projected_dems():
        for factor, dem in zip((1, 2, 4), coarsened(name, src, work)):
            ds = gdal.Open(dem)
            if min(ds.RasterXSize, ds.RasterYSize) < 20:
                continue
            cell = abs(ds.GetGeoTransform()[1])
            row = []
            for azimuth in AZIMUTHS:
                found = run_variants(cli, work, dem, azimuth,
                                     (("exact", "exact", ()), ("drawn", "drawn", ()),
                                      ("chains", "exact", ("--min-cells", "2"))))
                pair = [100 * within_one_cell(found["drawn"], found[ref], cell)
                        for ref in ("exact", "chains")]
                worst = [min(w, p) for w, p in zip(worst, pair)]
                row.append("%6.2f / %6.2f" % tuple(pair))
            print("%-24s %dx  %s" % (name, factor, "   ".join(row)), flush=True)
    print("least: %.2f %% of the exact strokes, %.2f %% of the exact chains" % tuple(worst))


def main():
    args = sys.argv[1:]
    if not args:
        print(__doc__)
        return 2
    speed_dem, runs = None, 5
    with_held_out = "--held-out" in args
    args = [a for a in args if a != "--held-out"]
    if "--speed" in args:
        k = args.index("--speed")
        speed_dem = args[k + 1]
        if len(args) > k + 2 and args[k + 2].isdigit():
            runs = int(args[k + 2])
            del args[k + 2]
        del args[k:k + 2]
    cli = os.path.join(args[0], "cli", "terrain-sketch")
    work = args[1] if len(args) > 1 else tempfile.mkdtemp(prefix="tsk-strokes-")
    os.makedirs(work, exist_ok=True)
    print("%-26s %9s %11s %8s %7s %8s %7s %9s" % (
        "DEM", "smoother", "within 1 cell", "before", "<5 cells", "after", "<5 cells",
        "length"))
    print("%-26s %9s %11s %8s %7s %8s %7s %9s" % (
        "", "(goal 3x)", "(goal 99 %)", "grouping", "", "grouping", "", "after/before"))
    for name, file, azimuth in DEMS:
        evaluate(cli, work, name, file, azimuth)
    if with_held_out:
        held_out(cli, work)
    if speed_dem:
        speed(cli, work, speed_dem, runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
