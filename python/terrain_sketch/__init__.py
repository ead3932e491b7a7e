"""Terrain Sketch: the silhouettes of a DEM seen obliquely from above, as vector strokes.

The functions run the command line's commands in-process, with the same options (as keywords:
``azimuth=90``, ``filter="fixed"``, ``strokes="exact"``), defaults, checks and messages, and
write the same files::

    import terrain_sketch
    stats = terrain_sketch.silhouettes("dem.tif", "strokes.gpkg", azimuth=270)

``sketch`` takes a 2-D numpy array (``rasterio``'s ``ds.read(1)`` with ``ds.transform``) and
returns the strokes as numpy columns, with ``to_geodataframe()``.

Every function releases the GIL while it works, reports ``progress(fraction)`` (return False to
stop: ``Cancelled``), stops on Ctrl-C with ``KeyboardInterrupt``, and writes its outputs whole or
not at all. Bad options raise ValueError with the command line's message, its options named as
keywords; a run that cannot be done raises ``terrain_sketch.Error``, an OSError. Notes on the DEM
go to the ``terrain_sketch`` logger.
"""

import json
from numbers import Integral

from . import _native, _options
from ._errors import Cancelled, Error
from ._strokes import Strokes

__version__ = _native.version
__all__ = ["silhouettes", "panorama", "classify", "row_slope", "drape", "pstrokes", "profiles",
           "filter_plot", "sketch", "Strokes", "Error", "Cancelled"]

_RETURNS = """
Returns the run's stage statistics as a dict (as stats_json= writes them), or an empty dict for
a command that counts none. Raises ValueError on bad options, terrain_sketch.Error (an OSError)
when the run cannot be done, KeyboardInterrupt on Ctrl-C and terrain_sketch.Cancelled when
progress returns False; nothing is written then.
"""


def _command_function(command):
    name = command.replace("-", "_")

    def run(input, output, *, progress=None, **options):
        arguments = [_options.path_argument(input), _options.path_argument(output)]
        arguments += _options.to_arguments(options)
        with _options.keyword_errors(name):
            _said, statistics = _native.run_command(command, arguments,
                                                    _options.hooks(progress, name))
        return json.loads(statistics) if statistics else {}

    run.__name__ = run.__qualname__ = name
    run.__doc__ = (f"{run.__name__}(input, output, *, progress=None, **options)\n\n"
                   f"{_options.summary(command)} (terrain-sketch {command}).\n\n"
                   f"Options:\n{_options.options_help(command)}\n"
                   f"    progress (callable): called with the share done, 0 to 1; False stops\n"
                   f"{_RETURNS}")
    return run


silhouettes = _command_function("silhouettes")
panorama = _command_function("panorama")
classify = _command_function("classify")
row_slope = _command_function("row-slope")
drape = _command_function("drape")
pstrokes = _command_function("pstrokes")
profiles = _command_function("profiles")
filter_plot = _command_function("filter-plot")

# The silhouettes' options that name or shape files, which sketch() neither reads nor writes.
_FILE_OPTIONS = ("band", "format", "stats_json", "preview", "page", "page_scale", "plotter",
                 "timings")


def _heights_array(heights, nodata):
    """The heights as an array GDAL can hold in place, and their nodata value."""
    import numpy as np

    if isinstance(heights, np.ma.MaskedArray):
        heights = heights.astype(np.float64).filled(np.nan)
    array = np.asarray(heights)
    # Booleans, complex numbers, text and times are no heights: cast, a mask of True and False
    # gave strokes round it without a word.
    if array.dtype.kind in "bcmMSUV":
        raise ValueError(f"heights must be real numbers, got an array of {array.dtype}")
    if nodata is None:
        nodata = getattr(heights, "attrs", {}).get("_FillValue")  # xarray's
    held = {"f4", "f8", "i2", "i4", "u1", "u2", "u4"}
    if f"{array.dtype.kind}{array.dtype.itemsize}" not in held or not array.dtype.isnative:
        array = array.astype(np.float64)
    if array.ndim == 2 and (array.strides[0] <= 0 or array.strides[1] <= 0):
        array = np.ascontiguousarray(array)
    return array, nodata


def _transform_numbers(transform):
    """GDAL's six numbers from an affine.Affine (rasterio's, rioxarray's) or six numbers."""
    if transform is None:
        return None
    if hasattr(transform, "to_gdal"):
        return tuple(transform.to_gdal())
    return tuple(float(v) for v in transform)


def _north_up(array, numbers):
    """A grid whose rows run from the south (a positive row step: netCDF's and xarray's order
    often) or whose columns run from the east, as the same grid from the north-west: flipped, a
    copy, with its transform's numbers to match."""
    import numpy as np

    if numbers is None or len(numbers) != 6 or array.ndim != 2 or numbers[2] or numbers[4]:
        return array, numbers
    x0, dx, _, y0, _, dy = numbers
    if not (dy > 0 or dx < 0):
        return array, numbers
    rows, cols = array.shape
    if dy > 0:
        array, y0, dy = array[::-1], y0 + rows * dy, -dy
    if dx < 0:
        array, x0, dx = array[:, ::-1], x0 + cols * dx, -dx
    return np.ascontiguousarray(array), (x0, dx, 0.0, y0, 0.0, dy)


def sketch(heights, transform=None, nodata=None, crs=None, *, progress=None, **options):
    heights_array, nodata = _heights_array(heights, nodata)
    heights_array, numbers = _north_up(heights_array, _transform_numbers(transform))
    for key in options:
        if key in _FILE_OPTIONS:
            raise ValueError(f"sketch() neither reads nor writes files: {key} is an option of "
                             "silhouettes(), which does")
    crs_text = "" if crs is None else crs.to_wkt() if hasattr(crs, "to_wkt") else str(crs)
    if isinstance(crs, Integral) and not isinstance(crs, bool):
        crs_text = f"EPSG:{int(crs)}"  # an EPSG code alone, as pyproj takes it
    with _options.keyword_errors("sketch"):
        native = _native.sketch(heights_array, numbers, crs_text,
                                None if nodata is None else float(nodata),
                                _options.to_arguments(options), _options.hooks(progress, "sketch"))
    return Strokes(native)


sketch.__doc__ = f"""sketch(heights, transform=None, nodata=None, crs=None, *, progress=None, **options)

The silhouettes of a DEM held as a 2-D array (heights in metres), returned
as Strokes: coordinates and M values as numpy arrays, attributes as columns, and
to_geodataframe(). The same recipe and options as silhouettes(), on the array in place.

    heights: a 2-D array of any numeric type (a masked array's mask is nodata; NaN is nodata)
    transform: GDAL's six numbers or an affine.Affine (rasterio's ds.transform); None for a grid
        without georeferencing (then give cell_size). Rows from the south (a positive row step,
        netCDF's order) or columns from the east are read as a flipped copy
    nodata: the value that marks no data, if any
    crs: the CRS, as WKT, "EPSG:N", an EPSG code (32616) or an object with to_wkt() (rasterio's,
        pyproj's)

Options:
{_options.options_help("silhouettes", _FILE_OPTIONS)}
    progress (callable): called with the share done, 0 to 1; False stops

Raises ValueError on bad options, terrain_sketch.Error when the array cannot be sketched,
KeyboardInterrupt on Ctrl-C and terrain_sketch.Cancelled when progress returns False.
"""
