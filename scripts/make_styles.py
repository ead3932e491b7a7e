"""Regenerates resources/styles/*.qml with QGIS itself, so they load without warnings.

Run with Debian's Python that has the qgis module:
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_styles.py
"""
import os
import sys

from qgis.core import (QgsApplication, QgsLineSymbol, QgsProperty, QgsSingleSymbolRenderer,
                       QgsSymbolLayer, QgsVectorLayer)

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "styles")

FIELDS = ("field=class:string&field=cells:integer&field=length:double&field=mean_slope:double"
          "&field=mean_row_slope:double&field=mean_depth:double&field=max_depth:double"
          "&field=mean_dist:double&field=mean_z:double")

# (file, colour, width expression): widths in millimetres, data-defined so designers can restyle.
STYLES = [
    ("factual", "17,17,17",
     'coalesce(scale_linear("mean_depth", 0, 150, 0.45, 1.4), 0.6)'),
    ("formulated", "120,120,120",
     'coalesce(scale_linear("mean_slope", 0, 40, 0.2, 0.55), 0.3)'),
]


def main():
    app = QgsApplication([], False)
    app.initQgis()
    os.makedirs(OUT, exist_ok=True)
    for name, colour, width in STYLES:
        layer = QgsVectorLayer("LineString?crs=EPSG:32616&" + FIELDS, name, "memory")
        symbol = QgsLineSymbol.createSimple({"line_color": colour, "line_width": "0.5",
                                             "line_width_unit": "MM", "capstyle": "round",
                                             "joinstyle": "round"})
        symbol.symbolLayer(0).setDataDefinedProperty(QgsSymbolLayer.PropertyStrokeWidth,
                                                     QgsProperty.fromExpression(width))
        layer.setRenderer(QgsSingleSymbolRenderer(symbol))
        path = os.path.join(OUT, name + ".qml")
        message, ok = layer.saveNamedStyle(path)
        if not ok:
            print("failed:", path, message, file=sys.stderr)
            return 1
        print("wrote", os.path.normpath(path))
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
