"""Silhouettes of DEMs beyond one machine, on a Dask cluster.

The view's profiles are cut into bands. Each task reads its own band of the DEM from the file
(a GeoTIFF, COG or VRT on storage every worker sees; no DEM goes through the scheduler), sketches
it and returns its strokes and the chains that run across its edges. The client stitches the
bands in order into one output, written whole, with the same strokes as one machine's run, exact
or drawn, in another order in the file (see docs/DISTRIBUTED.md)::

    from dask.distributed import Client
    import terrain_sketch.dask
    stats = terrain_sketch.dask.silhouettes("dem.vrt", "strokes.gpkg", Client("tcp://host:8786"),
                                            azimuth=270)

From a shell, with the command line's options:
``python3 -m terrain_sketch.dask dem.vrt strokes.gpkg --scheduler tcp://host:8786 --azimuth 270``.
"""

import itertools
import json
import math
import numbers
import os
import uuid

from . import _errors, _native, _options

# Profiles linked before a band's first to guess the order of the chains open there: long enough
# that a band seldom has to be sketched again from the true order.
HALO = 64


def _sketch_band(input, arguments, filter_report, z_ref, first, count, halo, order):
    """One task: a band of profiles sketched from the DEM's file, as a memoryview of its bytes,
    which Dask sends without a copy. On one thread: a worker runs a task on each of its threads,
    and more threads a task would only contend."""
    return memoryview(_native.sketch_band(input, arguments + ["--threads", "1"], filter_report,
                                          z_ref, first, count, halo, order or b""))


def _lowest_height_of_rows(input, arguments, first_row, rows):
    """One task: the lowest height of some of the DEM's rows (+inf when none has data)."""
    return _native.lowest_height(input, arguments, first_row, rows)


def _lowest_height(client, input_path, arguments, plan):
    """The DEM's lowest height, which plan-oblique geometry keeps in place: the least of its
    parts' lowest, read by the workers (as one machine finds it, exactly)."""
    rows = plan["dem_rows"]
    step = max(1, math.ceil(rows / max(1, 4 * len(client.scheduler_info()["workers"]))))
    parts = client.gather([client.submit(_lowest_height_of_rows, input_path, arguments, first,
                                         min(step, rows - first), pure=False)
                           for first in range(0, rows, step)])
    lowest = min(parts)
    return lowest if math.isfinite(lowest) else 0.0


def _survey_heights(input, arguments, windows):
    """One task: the step of the heights in some of the survey's windows, as bytes."""
    return _native.survey_heights(input, arguments, windows)


def _survey_slopes(input, arguments, windows, heights):
    """One task: the slopes in some of the survey's windows, as bytes."""
    return _native.survey_slopes(input, arguments, windows, heights)


def _filter(client, input_path, arguments, plan):
    """The filter's report for every band: a fixed filter as planned, or an adaptive one from the
    DEM's survey as a reduction over the workers (each reads some of its windows: first the
    heights' step, then the slopes measured with it), summed by the client into the report one
    machine's survey makes."""
    if not plan["survey"]:
        return plan["filter"]
    windows = _native.survey_windows(input_path, arguments)
    parts = max(1, min(len(windows), len(client.scheduler_info()["workers"])))
    shares = [windows[k::parts] for k in range(parts)]

    def each(task, *extra):
        return client.gather([client.submit(task, input_path, arguments, share, *extra,
                                            pure=False) for share in shares])

    heights = _native.merge_heights(each(_survey_heights))
    return _native.survey_filter(arguments, heights, each(_survey_slopes, heights))


def _band_width(profiles, workers):
    """About four bands a worker, so that the client starts while the workers are busy and a slow
    band holds up little, while each band's halo and fixed cost stay small (on the 8000^2
    benchmark, four a worker was as fast as eight or faster in every round measured in turns,
    docs/DISTRIBUTED.md), and none narrower than four halos, so that guessing costs little."""
    return max(4 * HALO, math.ceil(profiles / max(1, 4 * workers)))


def _bands(profiles, width, taper=False):
    """The bands as (first profile, profiles), of `width` profiles each but the last. Tapered
    (where there are four widths or more), the two bands at each end are a quarter as wide and the
    one next to them half as wide, so that the client starts stitching early and has little left to
    stitch once the workers are done (on the 8000^2 benchmark, drawn strokes, 1.37x the CLI's time
    against 1.51x with even bands, in turns; for exact strokes the rounds went either way,
    docs/DISTRIBUTED.md)."""
    if not taper or profiles < 4 * width:
        sizes = [min(width, profiles - first) for first in range(0, profiles, width)]
    else:
        ends = [max(1, width // 4), max(1, width // 4), max(1, width // 2)]
        middle = profiles - 2 * sum(ends)
        count = max(1, round(middle / width))
        sizes = ends + [middle // count + (k < middle % count) for k in range(count)] + ends[::-1]
    return list(zip(itertools.accumulate([0] + sizes[:-1]), sizes))


class KeepFreedMemory:
    """A Dask worker plugin that sets glibc's thresholds in the worker's process: blocks below
    32 MiB (the most glibc allows) come from the heap, and up to 256 MiB of freed heap is kept
    for the next band. local_cluster() starts its workers with it.

    Dask starts workers with MALLOC_TRIM_THRESHOLD_=65536, which also fixes glibc's threshold for
    taking blocks straight from the system at 128 kB: every larger block is handed back as it is
    freed, and a band's grids and strokes fault their pages in afresh, band after band (about
    1.5 s of processor time in a drawn run on the 8000^2 benchmark, docs/DISTRIBUTED.md). Elsewhere
    than glibc, it does nothing."""

    name = "terrain-sketch-keep-freed-memory"
    MMAP_THRESHOLD = 32 << 20
    TRIM_THRESHOLD = 256 << 20

    def setup(self, worker=None):
        import ctypes

        try:
            mallopt = ctypes.CDLL(None).mallopt
        except (AttributeError, OSError, TypeError):  # not glibc, or no C library to open
            return
        m_trim_threshold, m_mmap_threshold = -1, -3  # glibc's <malloc.h>
        mallopt(m_mmap_threshold, self.MMAP_THRESHOLD)
        mallopt(m_trim_threshold, self.TRIM_THRESHOLD)


def dask_setup(worker):
    """Dask's preload hook: ``dask worker ... --preload terrain_sketch.dask`` starts workers that
    keep freed memory for the next band, as local_cluster()'s do (KeepFreedMemory)."""
    KeepFreedMemory().setup(worker)


def local_cluster(workers=None):
    """local_cluster(workers=None)

    A dask.distributed.LocalCluster for runs on this machine, as silhouettes() makes one when
    given no client: `workers` single-threaded worker processes (None: one a core) that send what
    they return uncompressed, and keep freed memory for the next band (KeepFreedMemory). Keep one
    for several runs with
    ``with local_cluster() as cluster, Client(cluster) as client: ...``.

    Bands cross the loopback here, where Dask's lz4 (used wherever lz4 is installed) costs more
    than it saves: about 0.1 s of a worker's time for each 50 MB band, to save a quarter of its
    bytes (docs/DISTRIBUTED.md).
    """
    from dask.distributed import LocalCluster

    # A worker and the scheduler that disagree on compression send uncompressed; a flat key, as
    # the nanny merges this over the whole configuration one level deep. The nanny hands the
    # plugin to each worker it starts, again after a restart.
    return LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                        processes=True, dashboard_address=":0",
                        config={"distributed.comm.compression": False},
                        plugins=(KeepFreedMemory(),))


def silhouettes(input, output, client=None, band_profiles=None, *, progress=None, **options):
    """silhouettes(input, output, client=None, band_profiles=None, *, progress=None, **options)

    The silhouettes command on a Dask cluster: `client` (a dask.distributed.Client, or a
    scheduler's address such as "tcp://scheduler:8786"; None makes local_cluster() for the run),
    bands of `band_profiles` profiles (a whole number from 1; None: about four a worker, narrower
    at both ends), and the options of terrain_sketch.silhouettes() but those that need
    the whole DEM on one machine: the filter fixed or adapted to the whole DEM (surveyed once, by
    the workers), not locally, and no files beyond OUTPUT. Drawn strokes are drawn by the bands,
    those near a band's edges by the client (plan-oblique ones all by the client, which reads the
    DEM's lowest height on the workers). Returns the stage statistics as a dict. Raises
    ValueError on bad options, terrain_sketch.Error when the run cannot be done (a worker that
    cannot read the DEM ends it with its message); a worker lost mid-run has its band sketched
    again by another. OUTPUT is written whole at the end, or not at all.
    """
    input_path, output_path = _options.path_argument(input), _options.path_argument(output)
    with _options.keyword_errors("dask.silhouettes"):
        return _run(input_path, output_path, client, band_profiles,
                    _options.to_arguments(options), progress, "dask.silhouettes")


def _checked_band_profiles(band_profiles):
    """None, or a whole number of profiles from 1 (0 was taken as None, "x" raised a TypeError)."""
    if band_profiles is None:
        return None
    if (isinstance(band_profiles, bool) or not isinstance(band_profiles, numbers.Integral)
            or band_profiles < 1):
        raise ValueError("band_profiles must be a whole number of profiles, at least 1 (None: "
                         f"chosen for the cluster), got {band_profiles!r}")
    return int(band_profiles)


def _run(input_path, output_path, client, band_profiles, arguments, progress, function=None):
    """silhouettes() with the command line's arguments; `client` a Client, a scheduler's address,
    or None; the notes in the words of `function` (None: the command line's)."""
    from dask.distributed import Client

    band_profiles = _checked_band_profiles(band_profiles)
    hooks = _options.hooks(progress, function)
    plan = _native.plan_bands(input_path, output_path, arguments, hooks)
    cluster, own_client = None, client is None or isinstance(client, str)
    if client is None:
        cluster = local_cluster()
        client = Client(cluster)
    elif isinstance(client, str):
        client = Client(client)
    try:
        profiles = plan["profiles"]
        workers = len(client.scheduler_info()["workers"])
        width = band_profiles if band_profiles is not None else _band_width(profiles, workers)
        bands = _bands(profiles, width, taper=band_profiles is None)
        statistics = _stitch(client, input_path, output_path, arguments, plan, bands, progress,
                             function)
    finally:
        if own_client:
            client.close()
        if cluster is not None:
            cluster.close()
    return json.loads(statistics)


def _stitch(client, input_path, output_path, arguments, plan, bands, progress, function):
    """Submits every band, then stitches them as they come back, in order, writing each stroke
    as soon as it is whole; a band whose guess of the chains' order was wrong is sketched again
    from the true order."""
    profiles = plan["profiles"]
    filter_report = _filter(client, input_path, arguments, plan)
    z_ref = _lowest_height(client, input_path, arguments, plan) if plan["oblique"] else 0.0
    token = uuid.uuid4().hex
    futures = [client.submit(_sketch_band, input_path, arguments, filter_report, z_ref, first,
                             count, HALO, None, key=f"terrain-sketch-band-{first}-{token}",
                             pure=False)
               for first, count in bands]
    done = 0

    def next_band():
        nonlocal done
        if done == len(futures):
            return b""
        band = futures[done].result()
        futures[done].release()
        done += 1
        if progress is not None and progress(done / len(futures)) is False:
            client.cancel(futures[done:])
            raise _errors.Cancelled("the progress callable asked to stop; no output written")
        return band

    def again(first, count, order):
        return client.submit(_sketch_band, input_path, arguments, filter_report, z_ref, first,
                             count, 0, order, pure=False).result()

    try:
        # Ctrl-C reaches Python's own handler while the client waits for a band.
        hooks = _native.RunHooks(None, _options.notes_of(function), False)
        return _native.stitch_bands(input_path, output_path, arguments, filter_report, z_ref,
                                    profiles, next_band, again, hooks)
    finally:
        client.cancel([f for f in futures[done:]])


_USAGE = ("usage: python3 -m terrain_sketch.dask INPUT OUTPUT [--scheduler ADDRESS] "
          "[--band-profiles N] [OPTIONS]")
_HELP = """
The silhouettes command on a Dask cluster, with the same strokes and statistics as one machine.

  --scheduler ADDRESS  the cluster's scheduler (tcp://HOST:8786); without it, a LocalCluster of
                       one single-threaded worker process a core
  --band-profiles N    profiles a band (default: about four bands a worker, narrower
                       at both ends)
  OPTIONS              those of `terrain-sketch silhouettes --help`, but those that need the
                       whole DEM on one machine (a locally adaptive filter) and the outputs
                       beyond OUTPUT (--preview, --stats-json, --timings)

Exits 0 when OUTPUT is written whole, 1 when the run cannot be done, 2 on bad options."""


def main(argv=None):
    """The run on a Dask cluster from a shell: INPUT and OUTPUT, the scheduler's address (none: a
    LocalCluster of a worker process a core), the width of a band, and the silhouettes command's
    options as `terrain-sketch silhouettes` takes them. Exits 0, 1 when the run cannot be done,
    2 on bad options, 130 on Ctrl-C."""
    import logging
    import sys
    args = list(sys.argv[1:] if argv is None else argv)
    # The notes on the DEM and the filter on stderr, as the command line tells them.
    notes = logging.StreamHandler(sys.stderr)
    notes.setFormatter(logging.Formatter("%(message)s"))
    logging.getLogger("terrain_sketch").addHandler(notes)
    logging.getLogger("terrain_sketch").setLevel(logging.INFO)
    if any(a in ("-h", "--help") for a in args):
        print(_USAGE + "\n" + _HELP)
        return 0
    chosen, rest = {"--scheduler": None, "--band-profiles": None}, []
    while args:
        arg = args.pop(0)
        if arg in chosen:
            if not args:
                print(f"terrain_sketch.dask: {arg} needs a value\n{_USAGE}", file=sys.stderr)
                return 2
            chosen[arg] = args.pop(0)
        else:
            rest.append(arg)
    if len(rest) < 2 or any(a.startswith("-") for a in rest[:2]):
        print(f"terrain_sketch.dask: INPUT and OUTPUT come first\n{_USAGE}", file=sys.stderr)
        return 2
    try:
        band_profiles = chosen["--band-profiles"]
        if band_profiles is not None:
            if not band_profiles.isdigit():
                raise ValueError(f"--band-profiles takes a whole number, not {band_profiles!r}")
            band_profiles = int(band_profiles)
        stats = _run(rest[0], rest[1], chosen["--scheduler"], band_profiles, rest[2:], None)
    except ValueError as error:
        print(f"terrain_sketch.dask: {error}", file=sys.stderr)
        return 2
    except (_errors.Error, OSError) as error:
        print(f"terrain_sketch.dask: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        return 130
    print(f"{rest[1]}: {stats['factual_strokes']} factual and {stats['formulated_strokes']} "
          "formulated strokes")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
