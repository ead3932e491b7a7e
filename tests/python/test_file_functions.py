"""The file functions write what the command line writes, byte for byte, and return its
statistics; bad options raise ValueError with its words."""

import json
import logging
import os
import re
import shutil
import sqlite3

import pytest

import terrain_sketch
from terrain_sketch._options import keyword_message
from conftest import DATA, SAMPLE

# The sample's centre, where a panorama's viewer stands.
OBSERVER = (747300.0, 4021100.0)

# Each command with options of its own, and the outputs it writes (the first is OUTPUT).
RUNS = [
    ("silhouettes", {"azimuth": 270, "preview": "preview.svg", "stats_json": "stats.json"},
     ["strokes.geojson", "preview.svg", "stats.json"]),
    ("silhouettes", {"azimuth": 200, "filter": "fixed", "strokes": "exact", "no_diagonals": True},
     ["strokes.fgb"]),
    ("classify", {"azimuth": 0, "stats_json": "stats.json"}, ["classes.tif", "stats.json"]),
    ("row-slope", {"azimuth": 180}, ["slope.tif"]),
    ("drape", {"source": SAMPLE}, ["drape.tif"]),
    ("pstrokes", {"half_length": 3}, ["pstrokes.geojson"]),
    ("profiles", {"every": 5}, ["profiles.geojson"]),
    ("filter-plot", {"filter": "fixed"}, ["filter.html"]),
    ("panorama", {"observer": OBSERVER, "max_distance": 20000, "visibility": "seen.tif"},
     ["panorama.gpkg", "seen.tif"]),
]


def cli_arguments(options, folder):
    """The command line's spelling of the keyword options, files put in `folder`."""
    arguments = []
    for key, value in options.items():
        name = "--" + key.replace("_", "-")
        if value is True:
            arguments.append(name)
        elif isinstance(value, tuple):
            arguments += [name, ",".join(map(str, value))]
        else:
            is_file = isinstance(value, str) and "." in value and "/" not in value
            arguments += [name, os.path.join(folder, value) if is_file else str(value)]
    return arguments


def in_folder(options, folder):
    return {key: os.path.join(folder, value) if isinstance(value, str) and "." in value
            and "/" not in value else value for key, value in options.items()}


def gpkg_rows(path):
    """A GeoPackage's features, table by table (its contents table holds the time it was
    written, which two runs cannot share)."""
    with sqlite3.connect(path) as db:
        tables = [name for (name,) in db.execute(
            "SELECT table_name FROM gpkg_contents ORDER BY table_name")]
        return {table: db.execute(f'SELECT * FROM "{table}" ORDER BY fid').fetchall()
                for table in tables}


def same_file(a, b):
    if a.endswith(".gpkg"):
        return gpkg_rows(a) == gpkg_rows(b)
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


@pytest.mark.parametrize("command,options,outputs", RUNS, ids=[r[0] for r in RUNS])
def test_same_outputs_as_the_command_line(tmp_path, cli, command, options, outputs):
    by_cli, by_python = tmp_path / "cli", tmp_path / "python"
    by_cli.mkdir()
    by_python.mkdir()
    code, err = cli(command, SAMPLE, by_cli / outputs[0], *cli_arguments(options, str(by_cli)))
    assert code == 0, err
    function = getattr(terrain_sketch, command.replace("-", "_"))
    statistics = function(SAMPLE, by_python / outputs[0], **in_folder(options, str(by_python)))
    for name in outputs:
        assert same_file(str(by_cli / name), str(by_python / name)), name
    if "stats.json" in outputs:
        with open(by_cli / "stats.json") as f:
            assert statistics == json.load(f)
    assert isinstance(statistics, dict)
    assert bool(statistics) == (command in ("silhouettes", "classify", "panorama"))


def test_statistics_follow_the_options(tmp_path):
    fixed = terrain_sketch.silhouettes(SAMPLE, tmp_path / "a.gpkg", filter="fixed")
    adaptive = terrain_sketch.silhouettes(SAMPLE, tmp_path / "b.gpkg")
    assert fixed["filter"]["mode"] == "fixed"
    assert adaptive["filter"]["mode"] == "adaptive"
    assert fixed["formulated_strokes"] > 0 and fixed["factual_strokes"] > 0


@pytest.mark.parametrize("options,words", [
    ({"observer": (1, 2)}, "silhouettes() does not take observer (a keyword of panorama()); "
     "help(terrain_sketch.silhouettes) lists the keywords it takes"),
    ({"azimut": 90}, "unknown keyword 'azimut'"),
    ({"azimuth": "east"}, "azimuth needs a number, got 'east'"),
    ({"azimuth": True}, "azimuth takes DEG, not True"),
    ({"no_diagonals": 3}, "no_diagonals is a switch"),
    ({"filter": "clever"}, "filter must be 'adaptive' or 'fixed', got 'clever'"),
    ({"ve": -1}, "exaggeration"),
    ({"preview": "picture.bmp"}, "give it a .png, .svg or .pdf name"),
    ({"page_scale": 50000}, "page, page_scale and plotter shape the preview picture: give preview"),
])
def test_bad_options_raise_value_error_in_keywords(tmp_path, cli, options, words):
    with pytest.raises(ValueError) as raised:
        terrain_sketch.silhouettes(SAMPLE, tmp_path / "out.gpkg", **options)
    said = str(raised.value)
    assert words in said
    # The command line's words named its flags and its --help, which a Python caller has not.
    assert "--" not in said and "terrain-sketch" not in said
    assert not os.listdir(tmp_path)
    if not any(isinstance(value, (bool, int)) and key not in ("ve", "page_scale")
               for key, value in options.items()):
        # Spelled for the command line, the same options are refused for the same cause.
        code, err = cli("silhouettes", SAMPLE, tmp_path / "out.gpkg",
                        *cli_arguments(options, str(tmp_path)))
        assert code == 2 and err.startswith("terrain-sketch: ") and err.endswith("\n")
        assert said == keyword_message(err[len("terrain-sketch: "):-1], "silhouettes")


@pytest.mark.parametrize("options,words", [
    ({"preview": ["a.svg"]}, "preview takes one FILE, not a list: ('a.svg',)"),
    ({"preview": ("a.svg", "b.png")}, "preview takes one FILE, not a list"),
    ({"azimuth": [90]}, "azimuth takes one DEG, not a list"),
    ({"observer": (1, 2, 3)}, "observer takes X,Y, 2 numbers"),
])
def test_lists_only_for_options_of_many_numbers(tmp_path, options, words):
    # A list for an option of one value was joined with commas into one path or number.
    command = terrain_sketch.panorama if "observer" in options else terrain_sketch.silhouettes
    with pytest.raises(ValueError, match=re.escape(words)):
        command(SAMPLE, tmp_path / "out.gpkg", **options)
    assert not os.listdir(tmp_path)


def test_notes_and_run_failures_name_keywords(tmp_path, caplog):
    caplog.set_level(logging.INFO, logger="terrain_sketch")
    terrain_sketch.silhouettes(SAMPLE, tmp_path / "out.gpkg")
    notes = [record.getMessage() for record in caplog.records]
    # The command line's note reads "(--filter fixed keeps 20, 12, 8.75)".
    assert any("(filter='fixed' keeps 20, 12, 8.75)" in note for note in notes), notes
    assert not any("--" in note for note in notes), notes
    # A run refused for its DEM names the keyword that mends it, here cell_size.
    from osgeo import gdal
    heights = gdal.Open(SAMPLE).ReadAsArray()
    dem = tmp_path / "bare.tif"  # no transform, no CRS
    bare = gdal.GetDriverByName("GTiff").Create(str(dem), heights.shape[1], heights.shape[0], 1,
                                                gdal.GDT_Float32)
    bare.GetRasterBand(1).WriteArray(heights)
    bare = None  # closed: written
    with pytest.raises(terrain_sketch.Error) as refused:
        terrain_sketch.silhouettes(dem, tmp_path / "bare.gpkg")
    assert "cell_size" in str(refused.value) and "--" not in str(refused.value)


def test_paths_as_text_bytes_or_path_objects_give_one_file(tmp_path):
    # A path as bytes (os.fsencode's, a directory listing's) raised a TypeError from inside the
    # package; open() takes all three.
    for k, output in enumerate((str(tmp_path / "a.gpkg"), os.fsencode(tmp_path / "b.gpkg"),
                                tmp_path / "c.gpkg")):
        terrain_sketch.silhouettes(os.fsencode(SAMPLE) if k == 1 else SAMPLE, output,
                                   preview=os.fsencode(tmp_path / f"p{k}.svg"))
    sizes = {os.path.getsize(tmp_path / name) for name in ("a.gpkg", "b.gpkg", "c.gpkg")}
    assert len(sizes) == 1 and os.path.exists(tmp_path / "p1.svg")


def test_a_run_that_cannot_be_done_raises_an_os_error(tmp_path):
    with pytest.raises(OSError) as missing:
        terrain_sketch.silhouettes(tmp_path / "none.tif", tmp_path / "out.gpkg")
    assert "none.tif" in str(missing.value)
    assert isinstance(missing.value, terrain_sketch.Error)
    with pytest.raises(terrain_sketch.Error) as geographic:
        terrain_sketch.silhouettes(os.path.join(DATA, "jacksboro_geo.tif"), tmp_path / "out.gpkg")
    assert "geographic" in str(geographic.value)
    assert not os.listdir(tmp_path)
    dem = tmp_path / "dem.tif"
    shutil.copy(SAMPLE, dem)
    with pytest.raises(terrain_sketch.Error) as onto_input:
        terrain_sketch.row_slope(dem, dem)
    assert "choose another path" in str(onto_input.value)
    assert os.listdir(tmp_path) == ["dem.tif"]


def test_an_observer_of_three_numbers_is_told_it_takes_two(tmp_path):
    # The parser's words were "--observer needs a number, got '2,3'".
    with pytest.raises(ValueError, match=r"observer takes X,Y, 2 numbers, not \(1, 2, 3\)"):
        terrain_sketch.panorama(SAMPLE, tmp_path / "p.gpkg", observer=(1, 2, 3))
    assert not os.listdir(tmp_path)


def test_help_lists_each_commands_own_options():
    assert "azimuth (DEG)" in terrain_sketch.silhouettes.__doc__
    assert "observer" not in terrain_sketch.silhouettes.__doc__
    assert "observer (X,Y)" in terrain_sketch.panorama.__doc__
    assert "default 2.5" in terrain_sketch.silhouettes.__doc__  # ranges and defaults
    assert "preview" not in terrain_sketch.sketch.__doc__
    assert "azimuth (DEG)" in terrain_sketch.sketch.__doc__


def test_help_names_options_as_keywords():
    # The command line's help named other options by their flags: "each neighbourhood of
    # --adapt-window cells", "every --every N cells".
    for name in terrain_sketch.__all__:
        function = getattr(terrain_sketch, name)
        if callable(function) and function.__doc__:
            assert not re.search(r"--[a-z]", function.__doc__), name
            assert "stderr" not in function.__doc__, name  # --timings': the logger's here
    assert "each neighbourhood of\n        adapt_window cells" in terrain_sketch.silhouettes.__doc__
    assert "every every=N cells" in terrain_sketch.profiles.__doc__
    assert "project source=RASTER" in terrain_sketch.drape.__doc__
    assert "writing to the terrain_sketch logger" in terrain_sketch.panorama.__doc__
