"""Times QGIS drawing drawn strokes (LineString M) with the candidate styles for taper and depth.

    QT_QPA_PLATFORM=offscreen /usr/bin/python3 bench/render_styles.py STROKES.gpkg [SIZE_PX] \
        [PLUGIN_DIR]

STROKES.gpkg: the command line's default output (e.g. of the 8000 x 8000 benchmark DEM, about
100 000 strokes). Each style draws the whole layer at SIZE_PX (default 1600) square; the figure is
the best of three renderings (one for buffer_by_m, which takes minutes). The plain line is the
reference: it draws no taper. The drawn style is timed twice: without the plugin (its stepped
stand-ins draw) and with the plugin from PLUGIN_DIR (default
build/qgis-plugin/terrain_sketch_plugin) loaded (its tapered line layer draws).
"""
import ctypes
import os
import sys
import time

from qgis.core import (Qgis, QgsApplication, QgsExpressionContext, QgsExpressionContextUtils,
                       QgsFillSymbol, QgsGeometryGeneratorSymbolLayer, QgsLineSymbol,
                       QgsMapRendererSequentialJob, QgsMapSettings, QgsSingleSymbolRenderer,
                       QgsVectorLayer, QgsVectorSimplifyMethod)
from qgis.PyQt.QtCore import QSize
from qgis.PyQt.QtGui import QColor

FULL_MM = 0.9
SCALE_M = "affine_transform($geometry, 0, 0, 0, 1, 1, 0, 0, 1, %g * @map_scale / 1000)" % FULL_MM
HERE = os.path.dirname(os.path.abspath(__file__))
STYLE = os.path.join(HERE, "..", "resources", "styles", "factual_drawn.qml")
# (name, geometry generator expression, None for a plain line, "style" for the QML as it is or
# "plugin" for the QML with the plugin loaded, runs)
CANDIDATES = [
    ("plain line, no taper (reference)", None, 3),
    ("the style without the plugin: 4 stepped lines", "style", 3),
    ("the style with the plugin: a width at every point", "plugin", 3),
    ("buffer_by_m, 3 segments: a width at every point", "buffer_by_m(%s, 3)" % SCALE_M, 1),
]


def symbol_for(expression):
    if expression is None:
        return QgsLineSymbol.createSimple({"line_color": "17,17,17", "line_width": "0.5"})
    fill = QgsFillSymbol.createSimple({"color": "17,17,17", "outline_style": "no"})
    generator = QgsGeometryGeneratorSymbolLayer.create(
        {"geometryModifier": expression, "SymbolType": "Fill"})
    generator.setSubSymbol(fill)
    symbol = QgsLineSymbol()
    symbol.changeSymbolLayer(0, generator)
    return symbol


def render_seconds(layer, size, runs):
    settings = QgsMapSettings()
    settings.setLayers([layer])
    settings.setDestinationCrs(layer.crs())
    settings.setOutputSize(QSize(size, size))
    settings.setExtent(layer.extent())
    settings.setBackgroundColor(QColor("white"))
    context = QgsExpressionContext()
    context.appendScope(QgsExpressionContextUtils.mapSettingsScope(settings))
    settings.setExpressionContext(context)
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        job = QgsMapRendererSequentialJob(settings)
        job.start()
        job.waitForFinished()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    size = int(sys.argv[2]) if len(sys.argv) > 2 else 1600
    app = QgsApplication([], False)
    app.initQgis()
    layer = QgsVectorLayer(sys.argv[1], "strokes", "ogr")
    if not layer.isValid():
        print("cannot open", sys.argv[1])
        return 1
    simplify = QgsVectorSimplifyMethod()
    simplify.setSimplifyHints(QgsVectorSimplifyMethod.NoSimplification)
    layer.setSimplifyMethod(simplify)
    print("%d strokes, %d x %d px, QGIS %s" % (layer.featureCount(), size, size, Qgis.version()))
    plugin_dir = sys.argv[3] if len(sys.argv) > 3 else os.path.join(
        HERE, "..", "build", "qgis-plugin", "terrain_sketch_plugin")
    for name, expression, runs in CANDIDATES:
        if expression == "plugin":
            library = ctypes.CDLL(os.path.join(plugin_dir, "libterrain_sketch_provider.so"))
            library.terrain_sketch_register_provider()
        if expression in ("style", "plugin"):
            message, ok = layer.loadNamedStyle(STYLE)
            if not ok:
                print("cannot load", STYLE, message)
                return 1
        else:
            layer.setRenderer(QgsSingleSymbolRenderer(symbol_for(expression)))
        print("%-52s %7.2f s" % (name, render_seconds(layer, size, runs)), flush=True)
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
