"""The distributed issue's benchmark: terrain_sketch.dask with single-threaded worker processes
against the command line with as many threads, on the same DEM (exact strokes), and what a band
costs: its sketch, its bytes, its edges, and the client's stitching.

    [RUNS=3] [STROKES=exact|drawn] /usr/bin/python3 bench/dask_bands.py BUILD_DIR DEM [WORKERS=2]
        [BAND_PROFILES|default ...]

Prints for each band width: the Dask run's wall time (cluster started beforehand, as a user
keeps one) and the CLI's, each Dask run in turn with a CLI run, the median of the pairs' ratios,
the bands sketched again, and per band the median sketch time on a worker, bytes, pieces
crossing its edges and the stitching time on the client. Figures, not a test.
"""
import os
import statistics
import subprocess
import sys
import time

build, dem = os.path.abspath(sys.argv[1]), sys.argv[2]
workers = int(sys.argv[3]) if len(sys.argv) > 3 else 2
# "default": the package's own cut (about four bands a worker, narrower at both ends).
widths = [None if w == "default" else int(w) for w in sys.argv[4:]] or [None, 250, 500, 1000,
                                                                        2000, 4000]
sys.path.insert(0, os.path.join(build, "python"))

import distributed  # noqa: E402

import terrain_sketch  # noqa: E402
import terrain_sketch.dask as tsd  # noqa: E402
from terrain_sketch import _native, _options  # noqa: E402

OUT = "/tmp/tsk-dask-bench"
RUNS = int(os.environ.get("RUNS", "3"))  # runs of each kind, their median printed
STROKES = os.environ.get("STROKES", "exact")  # or drawn


def cli_seconds():
    start = time.monotonic()
    subprocess.run([os.path.join(build, "cli", "terrain-sketch"), "silhouettes", dem,
                    f"{OUT}/cli.gpkg", "--strokes", STROKES, "--threads", str(workers)],
                   check=True, capture_output=True)
    return time.monotonic() - start


def timed_band(arguments, filter_report, first, count):
    """The band's sketch time and its bytes (copied after the timing: Dask pickles the pair, and
    a memoryview does not pickle)."""
    start = time.monotonic()
    band = _native.sketch_band(dem, arguments, filter_report, 0.0, first, count, tsd.HALO, b"")
    return time.monotonic() - start, bytes(memoryview(band))


def band_figures(client, width):
    """Per-band figures: sketch seconds on a worker, bytes, and the client's stitching."""
    arguments = _options.to_arguments({"strokes": STROKES})
    plan = _native.plan_bands(dem, f"{OUT}/b.gpkg", arguments, _options.hooks(None))
    profiles, filter_report = plan["profiles"], tsd._filter(client, dem, arguments, plan)
    bands = tsd._bands(profiles, width or tsd._band_width(profiles, workers), width is None)
    results = client.gather([client.submit(timed_band, arguments, filter_report, f, c, pure=False)
                             for f, c in bands])
    start, again = time.monotonic(), 0
    sketches = iter(results)

    def next_band():
        return next(sketches, (0, b""))[1]

    def sketch_again(first, count, order):
        nonlocal again
        again += 1
        return memoryview(_native.sketch_band(dem, arguments, filter_report, 0.0, first, count, 0,
                                              order))

    _native.stitch_bands(dem, f"{OUT}/b.gpkg", arguments, filter_report, 0.0, profiles,
                         next_band, sketch_again, _native.RunHooks(None, None, False))
    stitch = time.monotonic() - start
    sizes = [len(b) for _, b in results]
    edges = [_native.band_summary(b) for _, b in results]
    edge_bytes = statistics.median(e["piece_bytes"] for e in edges)
    pieces = statistics.median(e["pieces"] for e in edges)
    return (statistics.median(s for s, _ in results), statistics.median(sizes), stitch, again,
            len(bands), pieces, edge_bytes)


def main():
    os.makedirs(OUT, exist_ok=True)
    print(f"CLI, {workers} threads, {STROKES} strokes; each Dask run in turn with a CLI run")
    # The cluster a run without a client makes, kept for all the runs, as a user keeps one.
    with tsd.local_cluster(workers) as cluster, distributed.Client(cluster) as client:
        client.run(lambda: __import__("terrain_sketch"))
        for width in widths:
            pairs = []
            for _ in range(RUNS):
                cli = cli_seconds()
                start = time.monotonic()
                tsd.silhouettes(dem, f"{OUT}/dask.gpkg", client, width, strokes=STROKES)
                pairs.append((time.monotonic() - start, cli))
            wall = statistics.median(d for d, _ in pairs)
            cli = statistics.median(c for _, c in pairs)
            ratio = statistics.median(d / c for d, c in pairs)
            band_s, band_bytes, stitch_s, again, count, pieces, edge_bytes = band_figures(
                client, width)
            print(f"bands of {width or 'default':>7} profiles ({count:3d} bands): {wall:.2f} s "
                  f"against the CLI's {cli:.2f} s, {ratio:.2f}x (pairs "
                  f"{' '.join(f'{d / c:.2f}' for d, c in pairs)}); per band {band_s:.3f} s on a "
                  f"worker, {band_bytes / 1e6:.2f} MB; stitching and writing {stitch_s:.2f} s on "
                  f"the client ({stitch_s / count * 1000:.1f} ms a band); sketched again "
                  f"{again}; {pieces:.0f} pieces cross a band's edges, {edge_bytes / 1e3:.0f} kB")


if __name__ == "__main__":
    main()
