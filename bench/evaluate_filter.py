#!/usr/bin/python3
"""Prints the measured goals of the adaptive slope filter (docs/ADAPTIVE_FILTER.md) against the
thesis's fixed filter, on the DEMs in tests/data and DEMs made from them.

Usage: bench/evaluate_filter.py BUILD_DIR [WORK_DIR] [--speed DEM8000.tif] [--held-out]
--held-out adds the coarsening goal on every projected DEM in ../shared/data, from four azimuths.
Needs GDAL's Python bindings (python3-gdal) and gdalwarp.
"""
import json
import math
import os
import sqlite3
import statistics
import subprocess
import sys
import time

import numpy as np
from osgeo import gdal

from held_out_dems import AZIMUTHS, average, coarsened, projected_dems

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(REPO, "tests", "data")
SAMPLE = os.path.join(DATA, "jacksboro_utm16n.tif")


class Tool:
    def __init__(self, build, work):
        self.cli = os.path.join(build, "cli", "terrain-sketch")
        self.work = work

    def run(self, command, dem, filt, azimuth=90, extra=()):
        out = os.path.join(self.work, "out.gpkg" if command == "silhouettes" else "out.tif")
        stats = os.path.join(self.work, "stats.json")
        subprocess.run([self.cli, command, dem, out, "--filter", filt, "--azimuth", str(azimuth),
                        "--stats-json", stats, *extra], check=True, capture_output=True)
        with open(stats) as f:
            return out, json.load(f)

    def formulated(self, dem, filt, azimuth=90):
        """Formulated stroke length (ground units and cells) and the run's statistics."""
        out, stats = self.run("silhouettes", dem, filt, azimuth)
        db = sqlite3.connect(out)
        table = db.execute("select table_name from gpkg_contents").fetchone()[0]
        length, cells = db.execute(
            f'select coalesce(sum(length), 0), coalesce(sum(cells), 0) from "{table}" '
            "where class = 'formulated'").fetchone()
        db.close()
        return length, cells, stats

    def fset_cells(self, dem, filt):
        """The DEM cells in the f-set (f-set or t-set in the classification), as a mask."""
        out, stats = self.run("classify", dem, filt)
        names = gdal.Info(out, format="json")["bands"][0]["categories"]
        codes = [names.index("f-set"), names.index("t-set")]
        ds = gdal.Open(out)  # held: a band outliving its dataset crashes the bindings
        return np.isin(ds.GetRasterBand(1).ReadAsArray(), codes), stats


def integer_heights(src, dst):
    """The sample with its heights rounded to whole metres: flat plateaus and steps."""
    ds = gdal.Open(src)
    band = ds.GetRasterBand(1)
    z = band.ReadAsArray()
    nodata = band.GetNoDataValue()
    out = gdal.GetDriverByName("GTiff").CreateCopy(dst, ds)
    out.GetRasterBand(1).WriteArray(np.where(z == nodata, nodata, np.round(z)))
    out = None
    return dst


def lidar_like(dst, size=600, seed=7):
    """Fractal terrain at 1 m cells (spectral synthesis, 40 m of relief) with 5 cm of noise,
    as a lidar DEM of rolling ground has."""
    rng = np.random.default_rng(seed)
    fy = np.fft.fftfreq(size)[:, None]
    fx = np.fft.fftfreq(size)[None, :]
    f = np.hypot(fx, fy)
    f[0, 0] = 1
    spectrum = (rng.normal(size=(size, size)) + 1j * rng.normal(size=(size, size))) / f ** 2.1
    spectrum[0, 0] = 0
    z = np.real(np.fft.ifft2(spectrum))
    z = (z - z.min()) / (z.max() - z.min()) * 40 + 100 + rng.normal(0, 0.05, (size, size))
    ds = gdal.GetDriverByName("GTiff").Create(dst, size, size, 1, gdal.GDT_Float32)
    ds.SetGeoTransform([500000, 1, 0, 4000000, 0, -1])
    ds.SetProjection("EPSG:32616")
    ds.GetRasterBand(1).WriteArray(z.astype(np.float32))
    ds = None
    return dst


def coarsening(tool, work):
    print("Coarsening: formulated stroke length (km) of a real DEM averaged to 2x and 4x its cells")
    print("  goal: adaptive keeps >= 50 % at each step")
    for name in ("jacksboro_utm16n", "gorillas_utm32n"):
        src = os.path.join(DATA, name + ".tif")
        dems = coarsened(name, src, work)
        for filt in ("fixed", "adaptive"):
            lengths = [tool.formulated(d, filt)[0] for d in dems]
            steps = [100 * b / a if a else float("nan") for a, b in zip(lengths, lengths[1:])]
            print(f"  {name:18s} {filt:8s} 1x {lengths[0] / 1000:7.1f}  2x {lengths[1] / 1000:7.1f}"
                  f"  4x {lengths[2] / 1000:7.1f}  kept at each step: {steps[0]:5.1f} %, "
                  f"{steps[1]:5.1f} % (4x of 1x: {100 * lengths[2] / lengths[0]:5.1f} %)")


def thinned_length(stats, dem):
    """What the t-set would draw if every thinned cell lay in a stroke: its cells times the cell
    side, the most any chaining or generalisation could keep of the run's formulated length."""
    gt = gdal.Open(dem).GetGeoTransform()
    return stats["valid_cells"] * stats["tset_pct"] / 100 * math.sqrt(abs(gt[1] * gt[5]))


def held_out_coarsening(tool, work):
    print("Held out: formulated length kept at each step of averaging to 2x and 4x, adaptive, "
          "every projected DEM in ../shared/data from azimuths 0, 90, 200, 315 (goal >= 50 %);\n"
          "  in brackets the 4x length over the 1x length (the issue's own measure: a 90 m DEM "
          "averaged to 360 m),\n  then the same for the t-set's length (its cells times the cell "
          "side): the most that chaining and generalisation could keep")
    least, least_whole, least_thinned = math.inf, math.inf, (math.inf, "")
    for name, src in projected_dems():
        dems = coarsened(name, src, work)
        size = gdal.Open(dems[2])
        row = []
        for azimuth in AZIMUTHS:
            runs = [tool.formulated(d, "adaptive", azimuth) for d in dems]
            lengths = [run[0] for run in runs]
            thinned = [thinned_length(run[2], d) for run, d in zip(runs, dems)]
            steps = [100 * b / a if a else float("nan") for a, b in zip(lengths, lengths[1:])]
            whole = 100 * lengths[2] / lengths[0] if lengths[0] else float("nan")
            bound = 100 * thinned[2] / thinned[0] if thinned[0] else float("nan")
            least = min([least] + [x for x in steps if x == x])
            least_whole = min([least_whole] + [whole] * (whole == whole))
            if bound < least_thinned[0]:
                least_thinned = (bound, f"{name} from {azimuth}")
            row.append(f"{steps[0]:4.0f} %, {steps[1]:4.0f} % ({whole:3.0f} %, t-set {bound:3.0f} %)")
        print(f"  {name:18s} (4x: {size.RasterXSize} x {size.RasterYSize}) " + "   ".join(row))
    print(f"  least step: {least:.0f} %; least 4x of 1x: {least_whole:.0f} %; the t-set's least "
          f"4x of 1x: {least_thinned[0]:.0f} % ({least_thinned[1]})")


def coarse(tool, work):
    print("Coarse DEMs: share of the c-set that passes the filter (f-set / c-set)")
    print("  goal: adaptive >= 10 % on cells of 1 km or more")
    dems = [(os.path.join(DATA, "topobathy_3857.tif"), "topobathy, ~2.4 km"),
            (average(SAMPLE, 16, os.path.join(work, "jacksboro_x16.tif")), "sample at 1.2 km")]
    for dem, label in dems:
        row = []
        for filt in ("fixed", "adaptive"):
            _, _, s = tool.formulated(dem, filt)
            row.append(f"{filt} {100 * s['fset_pct'] / s['cset_pct']:5.1f} %")
        print(f"  {label:20s} " + ", ".join(row))


def thesis_scale(tool):
    print("The thesis's scale: the sample DEM's fixed-filter f-set cells the adaptive f-set keeps")
    print("  goal: >= 90 %")
    fixed, _ = tool.fset_cells(SAMPLE, "fixed")
    adaptive, stats = tool.fset_cells(SAMPLE, "adaptive")
    kept = 100 * np.count_nonzero(fixed & adaptive) / np.count_nonzero(fixed)
    print(f"  kept {kept:.1f} % of {np.count_nonzero(fixed)} cells (scale "
          f"{stats['filter']['scale']:.3f})")


def per_thousand(tool, dem, filt):
    _, cells, s = tool.formulated(dem, filt)
    return 1000 * cells / s["valid_cells"]


def fine(tool, work):
    print("Fine DEMs: formulated stroke cells per 1000 valid cells, against the sample's")
    print("  goal: adaptive within 2x of the sample's")
    reference = {f: per_thousand(tool, SAMPLE, f) for f in ("fixed", "adaptive")}
    print(f"  {'sample (75 m)':24s} fixed {reference['fixed']:6.1f}   adaptive "
          f"{reference['adaptive']:6.1f}")
    dems = [(os.path.join(DATA, "bei_5m_local.tif"), "bei (5 m, low relief)"),
            (lidar_like(os.path.join(work, "lidar_1m.tif")), "fractal + noise (1 m)")]
    for dem, label in dems:
        v = {f: per_thousand(tool, dem, f) for f in ("fixed", "adaptive")}
        print(f"  {label:24s} fixed {v['fixed']:6.1f}   adaptive {v['adaptive']:6.1f}  "
              f"({v['adaptive'] / reference['adaptive']:.2f} x the sample's)")


def turning(tool, work):
    print("Turning the view: largest difference of a stage share (points) between azimuth 90 and")
    print("90.000001, and 0 and 0.000001   goal: adaptive <= 0.5")
    warped = os.path.join(work, "jacksboro_geo_utm_integer.tif")
    gdal.Warp(warped, os.path.join(DATA, "jacksboro_geo.tif"), dstSRS="EPSG:32616",
              xRes=75, yRes=75, resampleAlg="near", dstNodata=-9999)
    dems = sorted(os.path.join(DATA, f) for f in os.listdir(DATA)
                  if f.endswith(".tif") and f != "jacksboro_geo.tif")
    dems += [warped, integer_heights(SAMPLE, os.path.join(work, "sample_integer.tif"))]
    keys = ("hidden_pct", "occluding_pct", "cset_pct", "fset_pct", "tset_pct", "gset_pct")
    for dem in dems:
        row = []
        for filt in ("fixed", "adaptive"):
            worst = 0.0
            for a, b in ((90, 90.000001), (0, 0.000001)):
                sa = tool.run("classify", dem, filt, a)[1]
                sb = tool.run("classify", dem, filt, b)[1]
                worst = max([worst] + [abs(sa[k] - sb[k]) for k in keys if k in sa])
            row.append(f"{filt} {worst:5.2f}")
        print(f"  {os.path.basename(dem):32s} " + "   ".join(row))
    print("  and a tenth of a degree off (89.9 against 90), where the resampling moves every "
          "height:")
    for dem in dems[-2:]:
        row = []
        for filt in ("fixed", "adaptive"):
            sa = tool.run("classify", dem, filt, 90)[1]
            sb = tool.run("classify", dem, filt, 89.9)[1]
            row.append(f"{filt} c-set {abs(sa['cset_pct'] - sb['cset_pct']):5.2f}")
        print(f"  {os.path.basename(dem):32s} " + "   ".join(row))


def speed(tool, dem):
    print("Speed: wall time of `silhouettes` on the 8000^2 benchmark DEM, medians of 5 runs "
          "alternated")
    print("  goal: adaptive adds <= 10 %")
    times = {"fixed": [], "adaptive": []}
    for _ in range(5):
        for filt in times:
            start = time.perf_counter()
            tool.run("silhouettes", dem, filt)
            times[filt].append(time.perf_counter() - start)
    fixed, adaptive = (statistics.median(times[f]) for f in ("fixed", "adaptive"))
    print(f"  fixed {fixed:.2f} s, adaptive {adaptive:.2f} s: "
          f"{100 * (adaptive / fixed - 1):+.1f} %")


def main():
    args = sys.argv[1:]
    speed_dem = None
    with_held_out = "--held-out" in args
    args = [a for a in args if a != "--held-out"]
    if "--speed" in args:
        k = args.index("--speed")
        speed_dem = args[k + 1]
        del args[k:k + 2]
    if not args:
        sys.exit(__doc__)
    work = args[1] if len(args) > 1 else "/tmp/tsk-evaluate-filter"
    os.makedirs(work, exist_ok=True)
    gdal.UseExceptions()
    tool = Tool(os.path.abspath(args[0]), work)
    coarsening(tool, work)
    if with_held_out:
        held_out_coarsening(tool, work)
    coarse(tool, work)
    thesis_scale(tool)
    fine(tool, work)
    turning(tool, work)
    if speed_dem:
        speed(tool, speed_dem)


if __name__ == "__main__":
    main()
