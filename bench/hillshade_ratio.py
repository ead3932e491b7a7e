"""The speed issue's benchmark: the command line against GDAL's own tools on the same file, in
turns, on a low-relief fBm DEM like the one the issue measured (25 m cells, median slope 6.6 % as
the adaptive filter's survey measures it, about 8 000 factual and 800 000 formulated strokes at
8000 x 8000 with the defaults).

    /usr/bin/python3 bench/hillshade_ratio.py BUILD_DIR [SIZE=8000] [PAIRS=5]

Prints, for each run kind, the median wall time and peak memory over PAIRS runs, each run
alternated with `gdaldem hillshade` (or `gdal_viewshed` for the panorama, or the same run with
exact strokes for the drawn ones), the median of the per-pair ratios, the defaults' --timings and
the stroke counts, and the panorama's --timings with a visibility raster. The DEM is made once and
kept in /tmp. Figures, not a test: nothing here passes or fails.
"""
import json
import os
import re
import statistics
import subprocess
import sys

import numpy as np
from osgeo import gdal, osr

build = os.path.abspath(sys.argv[1])
size = int(sys.argv[2]) if len(sys.argv) > 2 else 8000
pairs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
cli = os.path.join(build, "cli", "terrain-sketch")
work = "/tmp/tsk-hillshade-ratio"
os.makedirs(work, exist_ok=True)
# The terrain: a median slope of 6.6 % as the adaptive filter's survey measures it (the
# slopes between neighbouring 25 m cells). The file's name says so: an earlier DEM, scaled to
# 6.6 % between cells 100 m apart, measured 11.4 % at 25 m and gave 27 times the factual
# strokes.
MEDIAN_SLOPE_PCT = 6.6
dem = os.path.join(work, "fbm%d_slope6.6.tif" % size)


def surveyed_median_slope(path):
    """The median slope (%) the adaptive filter's survey finds on the DEM at `path`."""
    stats = os.path.join(work, "survey.json")
    subprocess.run([cli, "silhouettes", path, os.path.join(work, "survey.gpkg"), "--strokes",
                    "exact", "--stats-json", stats], check=True, capture_output=True)
    with open(stats) as f:
        return json.load(f)["filter"]["median_slope_pct"]


def write_dem(z):
    ds = gdal.GetDriverByName("GTiff").Create(dem, size, size, 1, gdal.GDT_Float32,
                                              ["TILED=YES", "COMPRESS=DEFLATE"])
    ds.SetGeoTransform([500000, 25, 0, 5000000, 0, -25])
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(32632)
    ds.SetProjection(srs.ExportToWkt())
    ds.GetRasterBand(1).WriteArray(z)


def make_dem():
    """Spectral fBm (power falling as f^-3.4), its heights scaled so that the survey's median
    slope is MEDIAN_SLOPE_PCT (slopes scale with the heights)."""
    rng = np.random.default_rng(7)
    fx = np.fft.fftfreq(size)[:, None]
    fy = np.fft.rfftfreq(size)[None, :]
    f = np.sqrt(fx * fx + fy * fy)
    f[0, 0] = 1
    amplitude = f ** -1.7
    amplitude[0, 0] = 0
    spectrum = amplitude * (rng.standard_normal(amplitude.shape) +
                            1j * rng.standard_normal(amplitude.shape))
    z = np.fft.irfft2(spectrum, s=(size, size)).astype(np.float32)
    del spectrum, amplitude, f
    z -= z.min()
    z *= 100.0 / z.max()
    write_dem(z + 100)
    z *= MEDIAN_SLOPE_PCT / surveyed_median_slope(dem)
    write_dem(z + 100)
    print("DEM made: median slope %.2f %% as surveyed" % surveyed_median_slope(dem))


def timed(command):
    """Wall seconds and peak memory (MB) of `command`, and what it said."""
    run = subprocess.run(["/usr/bin/time", "-f", "TIME %e %M"] + command, capture_output=True,
                         text=True, check=True)
    wall, kb = re.search(r"TIME ([0-9.]+) ([0-9]+)", run.stderr).groups()
    return float(wall), int(kb) / 1024, run.stdout + run.stderr


def compare(name, command, anchor_name, anchor):
    ours, theirs, ratios, memory, anchor_memory = [], [], [], [], []
    for _ in range(pairs):
        a_wall, a_mb, _ = timed(anchor)
        wall, mb, said = timed(command)
        theirs.append(a_wall), anchor_memory.append(a_mb)
        ours.append(wall), memory.append(mb)
        ratios.append(wall / a_wall)
    print("%-34s %6.2f s %6.0f MB | %-18s %6.2f s %6.0f MB | ratio %.2f (pairs %s)" % (
        name, statistics.median(ours), statistics.median(memory), anchor_name,
        statistics.median(theirs), statistics.median(anchor_memory), statistics.median(ratios),
        " ".join("%.2f" % r for r in ratios)), flush=True)
    return said


if not os.path.exists(dem):
    make_dem()
out = os.path.join(work, "out.gpkg")
shade = ["gdaldem", "hillshade", "-q", dem, os.path.join(work, "hs.tif")]
sketch = [cli, "silhouettes", dem, out, "--azimuth", "90"]
print("DEM %s: %d x %d cells, %d pairs in turns" % (dem, size, size, pairs))
said = compare("defaults (adaptive, drawn)", sketch + ["--timings"], "gdaldem hillshade", shade)
print("  " + "\n  ".join(line for line in said.splitlines() if not line.startswith("TIME")))
# Another azimuth: the DEM read in bands of slanting rows, resampled (hillshade has no azimuth
# that changes how it reads).
compare("defaults from 45 degrees", [cli, "silhouettes", dem, out, "--azimuth", "45"],
        "gdaldem hillshade", shade)
compare("exact (--filter fixed --strokes exact)",
        sketch + ["--filter", "fixed", "--strokes", "exact"], "gdaldem hillshade", shade)
# The goal that drawn strokes cost at most 15 % more than exact ones, with each filter.
compare("drawn, against exact (adaptive)", sketch, "--strokes exact",
        sketch + ["--strokes", "exact"])
compare("drawn, against exact (fixed)", sketch + ["--filter", "fixed"], "--strokes exact",
        sketch + ["--filter", "fixed", "--strokes", "exact"])
centre = (500000 + 25 * size / 2, 5000000 - 25 * size / 2)
panorama = [cli, "panorama", dem, os.path.join(work, "p.gpkg"), "--observer", "%f,%f" % centre,
            "--observer-height", "2"]
viewshed = ["gdal_viewshed", "-q", "-ox", str(centre[0]), "-oy", str(centre[1]), "-oz", "2", dem,
            os.path.join(work, "vs.tif")]
compare("panorama, full circle at 2 m", panorama, "gdal_viewshed", viewshed)
# Like for like: gdal_viewshed's output is a visibility raster, which the panorama writes too.
said = compare("panorama with --visibility", panorama + [
    "--visibility", os.path.join(work, "seen.tif"), "--timings"], "gdal_viewshed", viewshed)
print("  " + "\n  ".join(line for line in said.splitlines() if line.startswith("timings")))
