"""The QGIS Silhouettes algorithm against the command line on the same DEM, both writing
GeoPackages. Prints figures; never a test.

Usage (QGIS's Python): /usr/bin/python3 bench/qgis_vs_cli.py BUILD_DIR DEM [RUNS [AZIMUTH]]
BUILD_DIR is a build with -DTSK_BUILD_PLUGIN=ON. The algorithm runs in one QGIS process (as in the
desktop, where QGIS is already up); the command line runs as a new process each time, as a script
would run it. Runs alternate so that both see the same machine.
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

build, dem = sys.argv[1], sys.argv[2]
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
azimuth = float(sys.argv[4]) if len(sys.argv) > 4 else 90.0
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "e2e"))
import headless_qgis  # noqa: E402

app = headless_qgis.start(build)
from qgis import processing  # noqa: E402

cli = os.path.join(build, "cli", "terrain-sketch")

qgis_times, cli_times = [], []
with tempfile.TemporaryDirectory() as out:
    for run in range(runs):
        start = time.perf_counter()
        processing.run("terrainsketch:silhouettes", {
            "INPUT": dem, "BAND": 1, "AZIMUTH": azimuth,
            "FACTUAL": os.path.join(out, f"factual{run}.gpkg"),
            "FORMULATED": os.path.join(out, f"formulated{run}.gpkg")})
        qgis_times.append(time.perf_counter() - start)
        start = time.perf_counter()
        subprocess.run([cli, "silhouettes", dem, os.path.join(out, f"cli{run}.gpkg"),
                        "--azimuth", str(azimuth)],
                       check=True, stdout=subprocess.DEVNULL)
        cli_times.append(time.perf_counter() - start)

show = " ".join
print(f"QGIS algorithm (in QGIS): median {statistics.median(qgis_times):.2f} s; runs "
      + show(f"{t:.2f}" for t in qgis_times))
print(f"command line (new process): median {statistics.median(cli_times):.2f} s; runs "
      + show(f"{t:.2f}" for t in cli_times))
print(f"ratio QGIS / command line: "
      f"{statistics.median(qgis_times) / statistics.median(cli_times):.2f}")
