"""The DEMs the measured goals are held out on (issue 31, item 7): every projected DEM in
../shared/data (a geographic one is refused), as it is and averaged to coarser cells."""
import os

from osgeo import gdal

SHARED = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "..",
                      "shared", "data")
AZIMUTHS = (0, 90, 200, 315)


def average(src, factor, dst):
    """`src` averaged to `factor` times its cells, written to `dst`; returns `dst`."""
    ds = gdal.Open(src)
    gt = ds.GetGeoTransform()
    gdal.Warp(dst, src, xRes=gt[1] * factor, yRes=-gt[5] * factor, resampleAlg="average")
    return dst


def projected_dems():
    """(name, path) of each projected DEM in ../shared/data, by name."""
    for file in sorted(os.listdir(SHARED)):
        path = os.path.join(SHARED, file)
        if not file.endswith(".tif"):
            continue
        srs = gdal.Open(path).GetSpatialRef()
        if srs is None or not srs.IsGeographic():
            yield file[:-4], path


def coarsened(name, path, work, factors=(2, 4)):
    """The DEM as it is, then averaged to each of `factors` (files in `work`)."""
    return [path] + [average(path, k, os.path.join(work, f"{name}_x{k}.tif")) for k in factors]
