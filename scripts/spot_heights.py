#!/usr/bin/python3
"""Writes a DEM's spot heights as a GeoJSON of points named by their height: every cell that is
the highest of the WINDOW x WINDOW cells around it and higher than MIN metres. For trying
`terrain-sketch panorama --peaks` where no gazetteer of summits is at hand.

Usage: scripts/spot_heights.py DEM OUT.geojson [WINDOW (15)] [MIN (700)]
Needs GDAL's Python bindings (python3-gdal) and numpy.
"""
import sys

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view
from osgeo import gdal, ogr, osr


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    window = int(sys.argv[3]) if len(sys.argv) > 3 else 15
    lowest = float(sys.argv[4]) if len(sys.argv) > 4 else 700.0
    ds = gdal.Open(sys.argv[1])
    band = ds.GetRasterBand(1)
    z = band.ReadAsArray().astype(float)
    if band.GetNoDataValue() is not None:
        z[z == band.GetNoDataValue()] = np.nan
    half = window // 2
    padded = np.pad(z, half, constant_values=-np.inf)
    highest = np.nanmax(sliding_window_view(padded, (window, window)), axis=(2, 3))
    rows, cols = np.nonzero((z == highest) & (z > lowest))
    gt = ds.GetGeoTransform()
    srs = osr.SpatialReference(wkt=ds.GetProjection())
    out = ogr.GetDriverByName("GeoJSON").CreateDataSource(sys.argv[2])
    layer = out.CreateLayer("spot_heights", srs, ogr.wkbPoint)
    layer.CreateField(ogr.FieldDefn("name", ogr.OFTString))
    for r, c in zip(rows, cols):
        feature = ogr.Feature(layer.GetLayerDefn())
        feature.SetField("name", "%d m" % round(z[r, c]))
        point = ogr.Geometry(ogr.wkbPoint)
        point.AddPoint_2D(gt[0] + (c + 0.5) * gt[1], gt[3] + (r + 0.5) * gt[5])
        feature.SetGeometry(point)
        layer.CreateFeature(feature)
    print(f"{len(rows)} spot heights written to {sys.argv[2]}")


if __name__ == "__main__":
    main()
