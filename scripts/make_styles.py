"""Regenerates resources/styles/*.qml with QGIS itself, so they load without warnings.

Run with Debian's Python that has the qgis module:
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_styles.py
"""
import os
import sys

from osgeo import gdal
from qgis.core import (QgsApplication, QgsContrastEnhancement, QgsLineSymbol,
                       QgsPalettedRasterRenderer, QgsProperty, QgsRasterLayer,
                       QgsSingleBandGrayRenderer, QgsSingleSymbolRenderer, QgsSymbolLayer,
                       QgsVectorLayer)
from qgis.PyQt.QtGui import QColor

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "styles")

FIELDS = ("field=class:string&field=cells:integer&field=length:double&field=mean_slope:double"
          "&field=mean_row_slope:double&field=mean_depth:double&field=max_depth:double"
          "&field=mean_dist:double&field=mean_z:double")

# (file, colour, width expression): widths in millimetres, data-defined so designers can restyle.
# The widths follow each layer's own spread (its mean and standard deviation), not fixed depths
# and slopes: a 1 m lidar DEM's hidden zones are centimetres deep, a 90 m DEM's hundreds of
# metres. Formulated strokes are a dark sepia, so they stay visible over a grey hillshade while
# the black factual strokes lead.
STYLES = [
    ("factual", "17,17,17",
     'coalesce(scale_linear("mean_depth", 0, mean("mean_depth") + 2 * stdev("mean_depth"), '
     '0.45, 1.4), 0.6)'),
    ("formulated", "110,62,28",
     'coalesce(scale_linear("mean_slope", minimum("mean_slope"), '
     'mean("mean_slope") + 2 * stdev("mean_slope"), 0.3, 0.65), 0.4)'),
    ("profiles", "60,60,60", "0.25"),
    ("pstrokes", "150,70,20", "0.3"),
]

# Stage classes as in the thesis's map views (same colours as the CLI's colour table).
CLASSES = [(1, "visible", "#ffffff"), (2, "hidden", "#bed2eb"), (3, "occluding", "#dc1e1e"),
           (4, "c-set", "#d7d7d7"), (5, "f-set", "#787878"), (6, "t-set", "#141414")]


def save(layer, name):
    path = os.path.join(OUT, name + ".qml")
    message, ok = layer.saveNamedStyle(path)
    if not ok:
        raise RuntimeError("failed: %s %s" % (path, message))
    print("wrote", os.path.normpath(path))


def raster_styles(tmp):
    path = os.path.join(tmp, "r.tif")
    ds = gdal.GetDriverByName("GTiff").Create(path, 4, 4, 1, gdal.GDT_Byte)
    ds.SetGeoTransform([0, 1, 0, 4, 0, -1])
    ds = None
    layer = QgsRasterLayer(path, "classes")
    classes = [QgsPalettedRasterRenderer.Class(v, QColor(c), label) for v, label, c in CLASSES]
    layer.setRenderer(QgsPalettedRasterRenderer(layer.dataProvider(), 1, classes))
    save(layer, "classification")
    # Row slope: white where flat across the view, black from 60 %.
    gray = QgsSingleBandGrayRenderer(layer.dataProvider(), 1)
    gray.setGradient(QgsSingleBandGrayRenderer.WhiteToBlack)
    enhancement = QgsContrastEnhancement(layer.dataProvider().dataType(1))
    enhancement.setContrastEnhancementAlgorithm(QgsContrastEnhancement.StretchToMinimumMaximum)
    enhancement.setMinimumValue(0)
    enhancement.setMaximumValue(60)
    gray.setContrastEnhancement(enhancement)
    layer.setRenderer(gray)
    save(layer, "row_slope")


def main():
    app = QgsApplication([], False)
    app.initQgis()
    os.makedirs(OUT, exist_ok=True)
    for name, colour, width in STYLES:
        layer = QgsVectorLayer("LineString?crs=EPSG:32616&" + FIELDS, name, "memory")
        symbol = QgsLineSymbol.createSimple({"line_color": colour, "line_width": "0.5",
                                             "line_width_unit": "MM", "capstyle": "round",
                                             "joinstyle": "round"})
        if name not in ("profiles", "pstrokes"):
            symbol.symbolLayer(0).setDataDefinedProperty(QgsSymbolLayer.PropertyStrokeWidth,
                                                         QgsProperty.fromExpression(width))
        else:
            symbol.setWidth(float(width))
        layer.setRenderer(QgsSingleSymbolRenderer(symbol))
        save(layer, name)
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        raster_styles(tmp)
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
