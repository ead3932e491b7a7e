"""sketch() on an array gives the strokes the command line writes from the file it was read from:
the same geometries (M values too) and attributes, in the same order."""

import importlib.util
import os
import sqlite3
import struct

import numpy as np
import pytest
from osgeo import gdal

import terrain_sketch
from conftest import DATA, SAMPLE

gdal.UseExceptions()


def read_dem(path):
    dataset = gdal.Open(path)
    band = dataset.GetRasterBand(1)
    return (band.ReadAsArray(), dataset.GetGeoTransform(), band.GetNoDataValue(),
            dataset.GetProjection())


def gpkg_lines(path):
    """A GeoPackage line layer's points (x, y, m when measured) and attributes, read from its
    geometry blobs (GeoPackage header, then WKB LineString or LineString M) independently of the
    package."""
    with sqlite3.connect(path) as db:
        rows = db.execute("SELECT * FROM silhouettes ORDER BY fid").fetchall()
        names = [c[1] for c in db.execute("PRAGMA table_info(silhouettes)")]
    geometry = names.index("geom")
    lines, attributes = [], []
    for row in rows:
        blob = row[geometry]
        envelope = {0: 0, 1: 32, 2: 48, 3: 48, 4: 64}[(blob[3] >> 1) & 7]
        wkb = blob[8 + envelope:]
        kind, count = struct.unpack_from("<II", wkb, 1)
        dims = 3 if kind == 2002 else 2
        lines.append(np.array(struct.unpack_from(f"<{count * dims}d", wkb, 9)).reshape(count, dims))
        attributes.append({n: v for n, v in zip(names, row) if n not in ("fid", "geom")})
    return lines, attributes


def same_strokes(strokes, path):
    lines, attributes = gpkg_lines(path)
    assert len(strokes) == len(lines) > 0
    for k, line in enumerate(lines):
        np.testing.assert_array_equal(strokes.coordinates(k), line)
        for name, value in attributes[k].items():
            column = strokes.columns[name][k]
            assert (value is None and np.isnan(column)) or value == column, (k, name)


@pytest.mark.parametrize("options", [
    {"azimuth": 270},
    {"azimuth": 200, "filter": "fixed", "strokes": "exact"},
    {"azimuth": 35, "adapt": "local", "geometry": "oblique"},
    # Drawn for a scale that averages the 75 m sample 5 x 5 cells first.
    {"azimuth": 250, "drawn_for": 1000000},
], ids=["defaults", "exact", "local", "averaged"])
def test_array_strokes_are_the_files(tmp_path, options, caplog):
    heights, transform, nodata, crs = read_dem(SAMPLE)
    with caplog.at_level("INFO"):
        strokes = terrain_sketch.sketch(heights, transform, nodata, crs, **options)
    averaged = "the DEM was averaged 5 x 5 cells first" in caplog.text
    assert averaged == ("drawn_for" in options)
    statistics = terrain_sketch.silhouettes(SAMPLE, tmp_path / "file.gpkg", **options)
    same_strokes(strokes, str(tmp_path / "file.gpkg"))
    assert (strokes.m is None) == (options.get("strokes") == "exact")
    assert strokes.statistics == statistics


def test_integer_heights_with_nodata_and_a_masked_array(tmp_path):
    heights, transform, nodata, crs = read_dem(os.path.join(DATA, "gorillas_utm32n.tif"))
    whole = terrain_sketch.sketch(heights, transform, nodata, crs, filter="fixed")
    # Heights as whole metres with a nodata value, as an SRTM tile holds them.
    metres = np.where(np.isnan(heights) | (heights == nodata), -32768, np.round(heights))
    as_int16 = metres.astype(np.int16)
    by_int = terrain_sketch.sketch(as_int16, transform, -32768, crs, filter="fixed")
    by_float = terrain_sketch.sketch(metres.astype(np.float32), transform, -32768, crs,
                                     filter="fixed")
    np.testing.assert_array_equal(by_int.x, by_float.x)
    assert len(by_int) == len(by_float) > 0
    masked = np.ma.masked_equal(metres, -32768)
    by_mask = terrain_sketch.sketch(masked, transform, crs=crs, filter="fixed")
    np.testing.assert_array_equal(by_mask.y, by_float.y)
    assert len(whole) > 0


def test_a_transposed_view_reads_as_its_values(tmp_path):
    heights, transform, nodata, crs = read_dem(SAMPLE)
    view = np.ascontiguousarray(heights.T).T  # the same values, laid out column by column
    assert not view.flags["C_CONTIGUOUS"]
    a = terrain_sketch.sketch(view, transform, nodata, crs)
    b = terrain_sketch.sketch(heights, transform, nodata, crs)
    np.testing.assert_array_equal(a.x, b.x)


def test_rasterio_style_affine_and_crs_objects():
    heights, transform, nodata, crs = read_dem(SAMPLE)

    class Affine:  # rasterio's and rioxarray's transform
        def to_gdal(self):
            return transform

    class Crs:  # rasterio's and pyproj's
        def to_wkt(self):
            return crs

    a = terrain_sketch.sketch(heights, Affine(), nodata, Crs())
    b = terrain_sketch.sketch(heights, transform, nodata, "EPSG:32616")
    np.testing.assert_array_equal(a.x, b.x)
    assert "UTM zone 16N" in a.crs


def test_numpy_numbers_and_an_epsg_code_are_taken_as_pythons():
    heights, transform, nodata, crs = read_dem(SAMPLE)
    plain = terrain_sketch.sketch(heights, transform, nodata, "EPSG:32616", azimuth=200.5,
                                  base_slope=30)
    numpy = terrain_sketch.sketch(heights, transform, nodata, 32616, azimuth=np.float64(200.5),
                                  base_slope=np.int64(30))
    np.testing.assert_array_equal(plain.x, numpy.x)
    assert plain.crs == numpy.crs and "UTM zone 16N" in numpy.crs

    class Numpy2Float(float):  # numpy 2's np.float64, whose repr is "np.float64(200.5)"
        def __repr__(self):
            return f"np.float64({float(self)})"
    spelled = terrain_sketch.sketch(heights, transform, nodata, crs, azimuth=Numpy2Float(200.5),
                                    base_slope=30)
    np.testing.assert_array_equal(plain.x, spelled.x)
    with pytest.raises(ValueError, match="azimuth takes DEG, not True"):
        terrain_sketch.sketch(heights, transform, nodata, crs, azimuth=np.True_)


def test_an_observer_as_a_numpy_array(tmp_path):
    from test_file_functions import OBSERVER, gpkg_rows
    terrain_sketch.panorama(SAMPLE, tmp_path / "a.gpkg", observer=OBSERVER, max_distance=9000)
    terrain_sketch.panorama(SAMPLE, tmp_path / "b.gpkg", observer=np.array(OBSERVER),
                            max_distance=9000)
    assert gpkg_rows(str(tmp_path / "a.gpkg")) == gpkg_rows(str(tmp_path / "b.gpkg"))
    with pytest.raises(ValueError, match="observer takes X,Y, 2 numbers"):
        terrain_sketch.panorama(SAMPLE, tmp_path / "c.gpkg", observer=np.zeros(3))


def test_bad_arrays_and_options():
    heights, transform, nodata, crs = read_dem(SAMPLE)
    with pytest.raises(ValueError, match="2-D"):
        terrain_sketch.sketch(heights[0], transform, nodata, crs)
    with pytest.raises(ValueError, match="a row and a column at least, got 0 x 414"):
        terrain_sketch.sketch(heights[:0], transform, nodata, crs)
    for not_heights in (heights > 300, heights.astype(complex), heights.astype(str)):
        with pytest.raises(ValueError, match="heights must be real numbers, got an array of"):
            terrain_sketch.sketch(not_heights, transform, nodata, crs)
    with pytest.raises(ValueError, match="neither reads nor writes files: preview"):
        terrain_sketch.sketch(heights, transform, nodata, crs, preview="p.svg")
    with pytest.raises(ValueError, match=r"sketch\(\) does not take observer \(a keyword of "
                       r"panorama\(\)\); help\(terrain_sketch.sketch\)"):
        terrain_sketch.sketch(heights, transform, nodata, crs, observer=(1, 2))
    with pytest.raises(ValueError, match="6 numbers"):
        terrain_sketch.sketch(heights, transform[:4], nodata, crs)
    with pytest.raises(terrain_sketch.Error, match="geographic"):
        terrain_sketch.sketch(heights, (-97.0, 0.001, 0, 33.0, 0, -0.001), nodata, "EPSG:4326")
    # Text in no form of CRS gets no reason from GDAL: the message says the forms taken.
    with pytest.raises(terrain_sketch.Error, match="CRS 'no such CRS'.*give it as WKT"):
        terrain_sketch.sketch(heights, transform, nodata, "no such CRS")
    with pytest.raises(terrain_sketch.Error, match="CRS 'EPSG:999999'.*crs not found"):
        terrain_sketch.sketch(heights, transform, nodata, "EPSG:999999")


def test_a_grid_without_georeferencing_takes_a_cell_size():
    heights, transform, nodata, _ = read_dem(SAMPLE)
    strokes = terrain_sketch.sketch(heights, None, nodata, cell_size=75)
    assert len(strokes) > 0 and strokes.crs == ""
    with pytest.raises(terrain_sketch.Error, match="give it with cell_size"):
        terrain_sketch.sketch(heights, None, nodata)


def test_strokes_are_indexed_as_a_list_is():
    heights, transform, nodata, crs = read_dem(SAMPLE)
    strokes = terrain_sketch.sketch(heights, transform, nodata, crs)
    n = len(strokes)
    last = np.column_stack([strokes.x[strokes.offsets[n - 1]:], strokes.y[strokes.offsets[n - 1]:],
                            strokes.m[strokes.offsets[n - 1]:]])
    assert len(last) >= 2
    # -1 read the offsets from the last to the first: an empty stroke.
    np.testing.assert_array_equal(strokes.coordinates(-1), last)
    np.testing.assert_array_equal(strokes.coordinates(-n), strokes.coordinates(0))
    np.testing.assert_array_equal(strokes.coordinates(np.int64(n - 1)), last)
    for beyond in (n, -n - 1):
        with pytest.raises(IndexError, match=f"stroke {beyond} is none of the {n} strokes"):
            strokes.coordinates(beyond)
    with pytest.raises(TypeError):
        strokes.coordinates(1.5)
    # Subscripts and iteration give the same arrays.
    np.testing.assert_array_equal(strokes[-1], last)
    with pytest.raises(IndexError):
        strokes[n]
    walked = list(strokes)
    assert len(walked) == n
    for k in (0, n // 2, n - 1):
        np.testing.assert_array_equal(walked[k], strokes.coordinates(k))


def test_geodataframe():
    geopandas = pytest.importorskip("geopandas")
    heights, transform, nodata, crs = read_dem(SAMPLE)
    strokes = terrain_sketch.sketch(heights, transform, nodata, crs)
    frame = strokes.to_geodataframe()
    assert isinstance(frame, geopandas.GeoDataFrame)
    assert len(frame) == len(strokes)
    assert frame.crs.to_epsg() == 32616
    first = np.asarray(frame.geometry.iloc[0].coords)
    np.testing.assert_array_equal(first, strokes.coordinates(0)[:, :2])
    np.testing.assert_array_equal(frame["weights"].iloc[0], strokes.coordinates(0)[:, 2])
    assert list(frame.columns[:3]) == ["class", "cells", "length"]


def test_a_run_that_draws_nothing_warns_why(caplog):
    # A flat DEM: nothing hidden and no slope seen edge-on, so no stroke, and a warning that says so
    # (logged as a warning, not among the notes).
    heights = np.full((40, 40), 100.0, dtype=np.float32)
    with caplog.at_level("INFO", logger="terrain_sketch"):
        strokes = terrain_sketch.sketch(heights, (500000, 10, 0, 4000000, 0, -10), None,
                                        "EPSG:32616")
    assert len(strokes) == 0
    # No stroke is still Strokes: shown, walked and framed as any, its class column text.
    assert repr(strokes) == "<Strokes: 0 factual, 0 formulated>"
    assert strokes.columns["class"].dtype.kind == "U" and list(strokes) == []
    if importlib.util.find_spec("geopandas"):
        frame = strokes.to_geodataframe()
        assert len(frame) == 0 and list(frame.columns[:2]) == ["class", "cells"]
    warnings = [r.getMessage() for r in caplog.records if r.levelname == "WARNING"]
    assert any(w.startswith("warning: no strokes: no cell of the DEM is hidden") for w in warnings)
    # The sample draws strokes, and warns of nothing.
    caplog.clear()
    with caplog.at_level("INFO", logger="terrain_sketch"):
        assert len(terrain_sketch.sketch(*read_dem(SAMPLE))) > 0
    assert not [r for r in caplog.records if r.levelname == "WARNING"]


def test_notes_on_an_array_name_its_keywords_not_gdal_tools(caplog):
    # An array has no file to correct with gdal_edit.py: its notes name sketch()'s keywords.
    heights, transform, nodata, crs = read_dem(SAMPLE)
    heights = np.where(heights == nodata, np.nan, heights).astype(np.float32)

    def told(*args, **options):
        caplog.clear()
        with caplog.at_level("INFO", logger="terrain_sketch"):
            strokes = terrain_sketch.sketch(*args, **options)
        return strokes, " ".join(r.getMessage() for r in caplog.records)

    filled = heights.copy()
    filled[:, :6] = -9999
    _, said = told(filled, transform, None, crs)
    assert "nodata=-9999" in said and "gdal_edit" not in said
    # Float's fill value is taken as nodata: the strokes of the strip given as NaN.
    filled[:, :6] = np.float32(3.4028235e38)
    taken, said = told(filled, transform, None, crs)
    assert "taken as nodata" in said and "gdal_edit" not in said
    nan_strip = heights.copy()
    nan_strip[:, :6] = np.nan
    oracle, _ = told(nan_strip, transform, None, crs)
    assert len(taken) == len(oracle) > 0
    for k in range(len(oracle)):
        np.testing.assert_array_equal(taken.coordinates(k), oracle.coordinates(k))
    _, said = told(heights * 1000, transform, None, crs)
    assert "divide them by 1000" in said and "gdal_edit" not in said
    _, said = told(np.full((30, 30), np.nan), transform, None, crs)
    assert "every height of the array is nodata" in said and "--band" not in said
    _, said = told(heights, None, None, None, cell_size=75)
    assert "no transform" in said and "crs=" in said


def test_grids_from_the_south_or_east_are_read_flipped():
    # netCDF and xarray often hold rows from the south (a positive row step): the same ground,
    # so the same strokes as the grid from the north, point for point.
    heights, transform, nodata, crs = read_dem(SAMPLE)
    rows, cols = heights.shape
    x0, dx, _, y0, _, dy = transform
    north_up = terrain_sketch.sketch(heights, transform, nodata, crs)
    views = {
        "rows from the south": (heights[::-1], (x0, dx, 0, y0 + rows * dy, 0, -dy)),
        "columns from the east": (heights[:, ::-1], (x0 + cols * dx, -dx, 0, y0, 0, dy)),
        "both": (heights[::-1, ::-1], (x0 + cols * dx, -dx, 0, y0 + rows * dy, 0, -dy)),
    }
    for name, (view, numbers) in views.items():
        flipped = terrain_sketch.sketch(view, numbers, nodata, crs)
        assert len(flipped) == len(north_up) > 0, name
        np.testing.assert_array_equal(flipped.x, north_up.x, err_msg=name)
        np.testing.assert_array_equal(flipped.y, north_up.y, err_msg=name)


def test_a_transform_that_places_no_cell_is_refused():
    heights, transform, nodata, crs = read_dem(SAMPLE)
    x0, dx, _, y0, _, dy = transform
    # Not finite: a run drew nothing and blamed the chains for being short.
    for bad in (np.nan, np.inf):
        with pytest.raises(ValueError, match="must be finite"):
            terrain_sketch.sketch(heights, (bad, dx, 0, y0, 0, dy), nodata, crs)
    with pytest.raises(ValueError, match="rotated or sheared"):
        terrain_sketch.sketch(heights, (x0, dx, 5, y0, 5, dy), nodata, crs)
    with pytest.raises(ValueError, match="no width or height"):
        terrain_sketch.sketch(heights, (x0, 0, 0, y0, 0, dy), nodata, crs)
    # So far out that doubles cannot tell the cells apart: strokes collapsed onto a few points.
    for far in ((1e308, dx, 0, y0, 0, dy), (x0, 1e-300, 0, y0, 0, -1e-300)):
        with pytest.raises(terrain_sketch.Error, match="too far for coordinates") as refused:
            terrain_sketch.sketch(heights, far, nodata, crs)
        assert "transform=" in str(refused.value) and "gdal_edit" not in str(refused.value)
    # Cells so large that a corner is beyond any number.
    with pytest.raises(terrain_sketch.Error, match="not a finite number"):
        terrain_sketch.sketch(heights, (x0, 1e306, 0, y0, 0, -1e306), nodata, crs)
    # A geographic array is told of the UTM zone, not of gdalwarp.
    with pytest.raises(terrain_sketch.Error, match="EPSG:32616") as refused:
        terrain_sketch.sketch(heights, (-87.0, 0.001, 0, 36.3, 0, -0.001), nodata, "EPSG:4326")
    assert "gdalwarp" not in str(refused.value)
