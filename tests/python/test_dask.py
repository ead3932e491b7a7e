"""terrain_sketch.dask against the run on one machine: the same strokes, exact and drawn
(compared as sets of rows: geometry with M values, and attributes; drawn ones also in one run's
order within each class) and statistics (the filter's report among them), on the sample and a
4000^2 DEM made of it, bands down to a few profiles, the adaptive filter's survey made by the
workers, a worker killed mid-run, and the refusals."""

import importlib.util
import os
import platform
import shutil
import sqlite3

import numpy as np
import pytest
from osgeo import gdal

import terrain_sketch
import terrain_sketch.dask
from conftest import SAMPLE

distributed = pytest.importorskip("distributed")
dask = pytest.importorskip("dask")
gdal.UseExceptions()


def cluster(**options):
    return distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                    dashboard_address=":0", **options)


@pytest.fixture(scope="module")
def client():
    with cluster() as local, distributed.Client(local) as c:
        yield c


def rows(path):
    """The strokes as a sorted list of rows: geometry blob and attributes, without the fid."""
    with sqlite3.connect(path) as db:
        return sorted(row[1:] for row in db.execute("SELECT * FROM silhouettes"))


def rows_of_class(path, cls):
    """One class's strokes in the file's order: geometry blob and attributes, without the fid."""
    with sqlite3.connect(path) as db:
        return [row[1:] for row in
                db.execute("SELECT * FROM silhouettes WHERE class = ? ORDER BY fid", (cls,))]


def same_run(tmp_path, client, dem, band_profiles, **options):
    single = terrain_sketch.silhouettes(dem, tmp_path / "one.gpkg", **options)
    spread = terrain_sketch.dask.silhouettes(dem, tmp_path / "bands.gpkg", client, band_profiles,
                                             **options)
    assert spread == single
    one, bands = rows(tmp_path / "one.gpkg"), rows(tmp_path / "bands.gpkg")
    assert len(one) == single["factual_strokes"] + single["formulated_strokes"] > 0
    assert bands == one
    # Drawn strokes come in one run's order within each class (docs/DISTRIBUTED.md); exact ones
    # in the order the bands complete them.
    if options.get("strokes") != "exact":
        for cls in ("factual", "formulated"):
            assert (rows_of_class(tmp_path / "bands.gpkg", cls) ==
                    rows_of_class(tmp_path / "one.gpkg", cls))
    return spread


@pytest.mark.parametrize("band_profiles", [3, 50, None])
@pytest.mark.parametrize("options", [{"azimuth": 90, "filter": "fixed", "strokes": "exact"},
                                     {"azimuth": 200, "strokes": "exact"},
                                     {"azimuth": 0, "geometry": "oblique", "subcell": True,
                                      "strokes": "exact"},
                                     {},  # the defaults: adaptive filter, drawn strokes
                                     {"azimuth": 135, "geometry": "oblique", "join_gap": 4},
                                     # the 75 m sample averaged 5 x 5 cells at every task
                                     {"azimuth": 250, "drawn_for": 1000000}],
                         ids=["exact-fixed-90", "exact-200", "exact-oblique-0", "defaults",
                              "drawn-oblique-135", "drawn-for-averaged"])
def test_bands_give_the_strokes_of_one_machine(tmp_path, client, band_profiles, options):
    same_run(tmp_path, client, SAMPLE, band_profiles, **options)


def test_a_dem_of_4000_squared(tmp_path, client):
    # The sample mirrored into 10 x 10 copies: 4140 x 4360 cells of continuous terrain.
    source = gdal.Open(SAMPLE)
    tile = source.GetRasterBand(1).ReadAsArray()
    row = np.hstack([tile if k % 2 == 0 else tile[:, ::-1] for k in range(10)])
    heights = np.vstack([row if k % 2 == 0 else row[::-1, :] for k in range(10)])
    path = str(tmp_path / "large.tif")
    large = gdal.GetDriverByName("GTiff").Create(path, heights.shape[1], heights.shape[0], 1,
                                                  gdal.GDT_Float32, ["TILED=YES"])
    large.SetGeoTransform(source.GetGeoTransform())
    large.SetProjection(source.GetProjection())
    large.GetRasterBand(1).SetNoDataValue(-9999)
    large.GetRasterBand(1).WriteArray(heights)
    large = None
    same_run(tmp_path, client, path, 700, azimuth=270, strokes="exact")
    # The adaptive filter's survey (64 windows here) is a reduction over the workers: the heights'
    # step, then the slopes, a share of the windows each; the same filter as one machine's.
    # Bands of the default width, narrower at both ends.
    with distributed.get_task_stream(client) as tasks:
        same_run(tmp_path, client, path, None, azimuth=90)
    survey = [t for t in tasks.data if str(t["key"]).startswith(("_survey_heights",
                                                                 "_survey_slopes"))]
    assert len({t["worker"] for t in survey}) == 2 and len(survey) == 4
    firsts = sorted({int(str(t["key"]).split("-")[3]) for t in tasks.data
                     if str(t["key"]).startswith("terrain-sketch-band-")})
    widths = np.diff(firsts)
    assert len(firsts) > 8 and widths[0] == widths[1] == widths[2] // 2 < widths[3] // 3


@pytest.mark.parametrize("profiles,width", [(8000, 1000), (4001, 1000), (4000, 256), (3999, 1000),
                                            (9, 1), (1, 5)])
def test_bands_cover_every_profile_once(profiles, width):
    for taper in (False, True):
        bands = terrain_sketch.dask._bands(profiles, width, taper)
        assert [first for first, _ in bands] == [0] + list(np.cumsum([c for _, c in bands]))[:-1]
        assert sum(count for _, count in bands) == profiles and min(c for _, c in bands) >= 1
        counts = [count for _, count in bands]
        if taper and profiles >= 4 * width:  # a quarter, a quarter and a half at both ends
            ends = [max(1, width // 4), max(1, width // 4), max(1, width // 2)]
            assert counts[:3] == ends and counts[-3:] == ends[::-1]
            assert all(abs(c - width) <= width // 2 for c in counts[3:-3])
        else:  # as asked, but the last
            assert all(c == width for c in counts[:-1]) and counts[-1] <= width


def test_from_a_shell(tmp_path, client, cli):
    # python3 -m terrain_sketch.dask: the command line's options, the scheduler's address.
    import subprocess
    import sys

    def run(*args):
        return subprocess.run([sys.executable, "-m", "terrain_sketch.dask", *map(str, args)],
                              capture_output=True, text=True, env=os.environ.copy())

    single = terrain_sketch.silhouettes(SAMPLE, tmp_path / "one.gpkg", azimuth=200)
    done = run(SAMPLE, tmp_path / "bands.gpkg", "--azimuth", "200", "--scheduler",
               client.scheduler.address, "--band-profiles", "40")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == (f"{tmp_path / 'bands.gpkg'}: {single['factual_strokes']} "
                                   f"factual and {single['formulated_strokes']} formulated strokes")
    assert rows(tmp_path / "bands.gpkg") == rows(tmp_path / "one.gpkg")
    # The notes on stderr, as the command line's.
    code, said = cli("silhouettes", SAMPLE, tmp_path / "cli.gpkg", "--azimuth", "200")
    assert code == 0
    cli_notes = [line for line in said.splitlines() if line.startswith("note:")]
    assert cli_notes and [line for line in done.stderr.splitlines()
                          if line.startswith("note:")] == cli_notes
    refused = run(SAMPLE, tmp_path / "no.gpkg", "--observer", "1,2", "--scheduler",
                  client.scheduler.address)
    assert refused.returncode == 2
    assert "silhouettes does not take --observer" in refused.stderr
    assert run(SAMPLE, tmp_path / "no.gpkg", "--band-profiles", "many").returncode == 2
    assert run("--azimuth", "90").returncode == 2
    assert not (tmp_path / "no.gpkg").exists()


class KillFirstBand(distributed.WorkerPlugin):
    """Ends its worker's process outright as the first band of a run begins there."""

    def __init__(self, marker):
        self.marker = marker

    def transition(self, key, start, finish, **kwargs):
        if (finish == "executing" and str(key).startswith("terrain-sketch-band")
                and not os.path.exists(self.marker)):
            open(self.marker, "w").close()
            os._exit(1)


def test_a_worker_killed_mid_run(tmp_path):
    marker = str(tmp_path / "killed")
    with cluster() as local, distributed.Client(local) as c:
        register(c, KillFirstBand(marker))
        same_run(tmp_path, c, SAMPLE, 40, azimuth=0)
    assert os.path.exists(marker)


def watch_compressions():
    """On a worker: records the compression Dask chooses for each frame it may compress (10 kB
    or more) that it sends from now on."""
    import distributed.protocol.core as core
    chosen = core.maybe_compress
    core.terrain_sketch_chosen = []

    def watched(payload, **options):
        compression, sent = chosen(payload, **options)
        if memoryview(payload).nbytes >= 10_000:
            core.terrain_sketch_chosen.append(compression)
        return compression, sent

    core.maybe_compress, core.terrain_sketch_unwatched = watched, chosen


def compressions_chosen():
    """On a worker: what watch_compressions() recorded, Dask's own choice put back."""
    import distributed.protocol.core as core
    core.maybe_compress = core.terrain_sketch_unwatched
    return core.terrain_sketch_chosen


def band_compressions(folder, client):
    folder.mkdir()
    client.run(watch_compressions)
    same_run(folder, client, SAMPLE, 100, azimuth=90)
    return [c for chosen in client.run(compressions_chosen).values() for c in chosen]


def test_the_local_cluster_sends_bands_uncompressed(tmp_path, client):
    with terrain_sketch.dask.local_cluster(2) as local, distributed.Client(local) as c:
        chosen = band_compressions(tmp_path / "local", c)
    assert chosen and all(c is None for c in chosen)
    # A cluster as Dask 2022.12 makes it compresses them where lz4 is installed; Dask 2024.12
    # (Debian 13) no longer compresses by default.
    if (dask.config.get("distributed.comm.compression") == "auto"
            and importlib.util.find_spec("lz4")):
        assert "lz4" in band_compressions(tmp_path / "plain", client)


def heap_probe():
    """On a worker: of 64 blocks of 1 MiB, how many glibc takes from the heap, and how many MiB
    the heap still spans once they are freed."""
    import ctypes

    libc = ctypes.CDLL(None)
    libc.malloc.restype = ctypes.c_void_p
    libc.free.argtypes = [ctypes.c_void_p]

    def heap():
        for line in open("/proc/self/maps"):
            if line.rstrip().endswith("[heap]"):
                return [int(end, 16) for end in line.split()[0].split("-")]
        return [0, 0]

    blocks = [libc.malloc(1 << 20) for _ in range(64)]
    low, high = heap()
    inside = sum(low <= block < high for block in blocks)
    for block in reversed(blocks):
        libc.free(block)
    return inside, (heap()[1] - low) >> 20


@pytest.mark.skipif(platform.libc_ver()[0] != "glibc", reason="glibc's thresholds")
def test_the_local_cluster_keeps_freed_memory_for_the_next_band(client):
    with terrain_sketch.dask.local_cluster(2) as local, distributed.Client(local) as c:
        probes = list(c.run(heap_probe).values())
    assert len(probes) == 2
    for inside, spanned in probes:
        assert inside == 64 and spanned >= 64
    # A real cluster's workers, started with `--preload terrain_sketch.dask`, do the same.
    with cluster(preload=["terrain_sketch.dask"]) as preloaded, \
            distributed.Client(preloaded) as c:
        assert [inside for inside, _ in c.run(heap_probe).values()] == [64, 64]
    # The control: Dask's own workers, started with MALLOC_TRIM_THRESHOLD_=65536, map each block
    # apart and hand it back.
    if set(client.run(os.environ.get, "MALLOC_TRIM_THRESHOLD_").values()) == {"65536"}:
        assert all(inside == 0 for inside, _ in client.run(heap_probe).values())


def test_options_a_run_in_bands_cannot_take(tmp_path, client):
    out = tmp_path / "out.gpkg"
    for options, words in [({"strokes": "exact", "adapt": "local"}, "not locally"),
                           ({"strokes": "exact", "preview": "p.svg"}, "OUTPUT only"),
                           ({"strokes": "exact", "observer": (1, 2)},
                            r"dask.silhouettes\(\) does not take observer")]:
        with pytest.raises(ValueError, match=words) as refused:
            terrain_sketch.dask.silhouettes(SAMPLE, out, client, **options)
        assert "--" not in str(refused.value)  # keywords, not the command line's flags
    with pytest.raises(terrain_sketch.Error, match="no.tif"):
        terrain_sketch.dask.silhouettes(tmp_path / "no.tif", out, client, strokes="exact")
    # 0 was taken as "chosen for the cluster"; text and fractions raised a TypeError from inside.
    for width in (0, -1, "x", 2.5, True):
        with pytest.raises(ValueError, match="band_profiles must be a whole number"):
            terrain_sketch.dask.silhouettes(SAMPLE, out, client, width, strokes="exact")
    assert not os.listdir(tmp_path)


def test_a_scheduler_named_by_its_address(tmp_path, client):
    # A client's address, as `dask worker` and the shell's --scheduler take it: it raised an
    # AttributeError.
    address = client.scheduler.address
    by_address = terrain_sketch.dask.silhouettes(SAMPLE, tmp_path / "a.gpkg", address, 40,
                                                 strokes="exact")
    by_client = terrain_sketch.dask.silhouettes(SAMPLE, tmp_path / "c.gpkg", client, 40,
                                                strokes="exact")
    assert by_address == by_client
    assert rows(tmp_path / "a.gpkg") == rows(tmp_path / "c.gpkg")
    assert client.status == "running"  # the run closed only the client it made


class WorkInFolder(distributed.WorkerPlugin):
    """Moves its worker into another folder, where a relative path names nothing."""

    def __init__(self, folder):
        self.folder = folder

    def setup(self, worker):
        os.chdir(self.folder)


def register(client, plugin):
    # register_plugin from distributed 2023.9 on; register_worker_plugin before.
    (getattr(client, "register_plugin", None) or client.register_worker_plugin)(plugin)


def test_a_worker_that_cannot_read_the_dem_ends_the_run_with_its_message(tmp_path, monkeypatch):
    here, elsewhere = tmp_path / "client", tmp_path / "workers"
    here.mkdir()
    elsewhere.mkdir()
    shutil.copy(SAMPLE, here / "dem.tif")
    monkeypatch.chdir(here)
    with cluster() as local, distributed.Client(local) as c:
        register(c, WorkInFolder(str(elsewhere)))
        with pytest.raises(terrain_sketch.Error, match="dem.tif"):
            terrain_sketch.dask.silhouettes("dem.tif", "out.gpkg", c)
    assert os.listdir(here) == ["dem.tif"]


def test_the_notes_on_the_dem_and_filter_are_told_as_one_machine_tells_them(tmp_path, client,
                                                                          caplog):
    # A DEM without a CRS whose corner holds a common fill value: the run goes on, with notes,
    # and the adaptive filter's cut-offs.
    heights = gdal.Open(str(SAMPLE)).ReadAsArray().astype(np.float32)
    heights[:20, :20] = -9999
    dem = gdal.GetDriverByName("GTiff").Create(str(tmp_path / "dem.tif"), heights.shape[1],
                                               heights.shape[0], 1, gdal.GDT_Float32)
    dem.SetGeoTransform(gdal.Open(str(SAMPLE)).GetGeoTransform())
    dem.GetRasterBand(1).WriteArray(heights)
    dem = None

    def notes(run):
        caplog.clear()
        with caplog.at_level("INFO", logger="terrain_sketch"):
            run()
        return [r.getMessage() for r in caplog.records if r.getMessage().startswith("note:")]

    one = notes(lambda: terrain_sketch.silhouettes(tmp_path / "dem.tif", tmp_path / "one.gpkg",
                                                   strokes="exact"))
    spread = notes(lambda: terrain_sketch.dask.silhouettes(
        tmp_path / "dem.tif", tmp_path / "bands.gpkg", client, strokes="exact"))
    assert any("CRS" in note for note in one) and any("-9999" in note for note in one), one
    assert any("adaptive slope filter" in note for note in one), one
    assert spread == one
    # Drawn for a scale far coarser than the DEM: the averaging is told too.
    one = notes(lambda: terrain_sketch.silhouettes(SAMPLE, tmp_path / "one.gpkg",
                                                   drawn_for=1000000))
    spread = notes(lambda: terrain_sketch.dask.silhouettes(SAMPLE, tmp_path / "bands.gpkg",
                                                           client, drawn_for=1000000))
    assert any("averaged 5 x 5 cells first" in note for note in one), one
    assert spread == one
