"""Regenerates resources/styles/*.qml with QGIS itself, so they load without warnings.

Run with Debian's Python that has the qgis module, after building the plugin (the drawn styles
hold its tapered line layer):
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_styles.py [PLUGIN_DIR]
PLUGIN_DIR defaults to build/qgis-plugin/terrain_sketch_plugin.
"""
import ctypes
import os
import sys

from osgeo import gdal
from qgis.core import (QgsApplication, QgsContrastEnhancement, QgsExpression, QgsLineSymbol,
                       QgsPalettedRasterRenderer, QgsPalLayerSettings, QgsProperty,
                       QgsRasterLayer, QgsTextFormat, QgsVectorLayerSimpleLabeling,
                       QgsSimpleLineSymbolLayer, QgsSingleBandGrayRenderer,
                       QgsSingleSymbolRenderer, QgsSymbolLayer, QgsUnitTypes, QgsVectorLayer,
                       QgsVectorSimplifyMethod)
from qgis.PyQt.QtCore import Qt
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

# Drawn strokes (LineString M, M the weight of each point in (0, 1]: its taper times its depth
# cue). The plugin's tapered line layer fills each stroke's outline with the width of its every
# point. Where the plugin is not loaded, QGIS drops that layer and four stepped stand-ins draw the
# taper: lines of the stroke, each narrower one running further towards the ends, the widest
# trimmed to the middle half as the weights' taper (the default --taper 0.25) is, every step's
# width scaled by the stroke's largest weight, its depth cue. They switch themselves off while
# the plugin's function terrain_sketch_draws_taper() is known. (QGIS's own buffer_by_m draws a
# width per point too, but takes minutes for a real DEM's strokes: bench/render_styles.py.)
DRAWN_STYLES = [("factual_drawn", "17,17,17", 0.7), ("formulated_drawn", "110,62,28", 0.4)]
TIP_WEIGHT, TAPER, STEPS = 0.15, 0.25, 4
TAPERED_LINE = "TerrainSketchTaperedLine"
STAND_IN_ENABLED = "not terrain_sketch_draws_taper()"


def taper_steps():
    """(share of the full width, trim at each end in percent of the length) of each step: where
    the weights' taper (kTipWeight + (1 - kTipWeight) (1 - (1 - u)^2)) reaches that width."""
    steps = []
    for j in range(STEPS):
        share = TIP_WEIGHT + (1 - TIP_WEIGHT) * j / (STEPS - 1)
        u = 1 - (1 - (share - TIP_WEIGHT) / (1 - TIP_WEIGHT)) ** 0.5
        steps.append((share, 100 * TAPER * u))
    return steps


def drawn_symbol(colour, full_mm):
    symbol = QgsLineSymbol()
    symbol.deleteSymbolLayer(0)
    tapered = QgsApplication.symbolLayerRegistry().createSymbolLayer(
        TAPERED_LINE, {"line_color": colour, "line_width": str(full_mm), "line_width_unit": "MM"})
    if tapered is None:
        raise RuntimeError("the plugin's tapered line layer is not registered")
    symbol.appendSymbolLayer(tapered)
    for share, trim in taper_steps():
        line = QgsSimpleLineSymbolLayer(QColor(*map(int, colour.split(","))), full_mm * share)
        line.setPenCapStyle(Qt.RoundCap)
        line.setPenJoinStyle(Qt.RoundJoin)
        for setter, unit in ((line.setTrimDistanceStart, line.setTrimDistanceStartUnit),
                             (line.setTrimDistanceEnd, line.setTrimDistanceEndUnit)):
            setter(trim)
            unit(QgsUnitTypes.RenderPercentage)
        line.setDataDefinedProperty(QgsSymbolLayer.PropertyStrokeWidth, QgsProperty.fromExpression(
            "%g * coalesce(m_max($geometry), 1)" % (full_mm * share)))
        line.setDataDefinedProperty(QgsSymbolLayer.PropertyLayerEnabled,
                                    QgsProperty.fromExpression(STAND_IN_ENABLED))
        symbol.appendSymbolLayer(line)
    return symbol


def drawn_styles():
    for name, colour, full_mm in DRAWN_STYLES:
        layer = QgsVectorLayer("LineStringM?crs=EPSG:32616&" + FIELDS, name, "memory")
        layer.setRenderer(QgsSingleSymbolRenderer(drawn_symbol(colour, full_mm)))
        # Simplifying the lines for drawing would drop the M values the widths come from.
        simplify = QgsVectorSimplifyMethod()
        simplify.setSimplifyHints(QgsVectorSimplifyMethod.NoSimplification)
        layer.setSimplifyMethod(simplify)
        save(layer, name)


# Panorama strokes (docs/PANORAMA.md), on the map and in the panorama: the classes' colours and
# widths, far strokes lighter (towards a quarter of the ink) and thinner (to half), as in the
# command line's preview.
PANORAMA_FAR = 'scale_linear("mean_dist", 0, maximum("mean_dist"), 0, 1)'
PANORAMA_COLOUR = ("color_mix_rgb(if(\"class\" = 'factual', '17,17,17', '110,62,28'), "
                   "'255,255,255', 0.75 * " + PANORAMA_FAR + ")")
PANORAMA_WIDTH = "if(\"class\" = 'factual', 0.6, 0.35) * (1 - 0.5 * " + PANORAMA_FAR + ")"


# On the map, over a hillshade, the strokes keep their classes' full colours: lightened, the far
# ones would vanish into the grey.
PANORAMA_MAP_COLOUR = "if(\"class\" = 'factual', '17,17,17', '110,62,28')"
PANORAMA_MAP_WIDTH = "if(\"class\" = 'factual', 0.6, 0.4)"


def panorama_style(name, colour, width):
    layer = QgsVectorLayer("LineString?crs=EPSG:32616&" + FIELDS, name, "memory")
    symbol = QgsLineSymbol.createSimple({"line_color": "17,17,17", "line_width": "0.5",
                                         "line_width_unit": "MM", "capstyle": "round",
                                         "joinstyle": "round"})
    line = symbol.symbolLayer(0)
    line.setDataDefinedProperty(QgsSymbolLayer.PropertyStrokeColor,
                                QgsProperty.fromExpression(colour))
    line.setDataDefinedProperty(QgsSymbolLayer.PropertyStrokeWidth,
                                QgsProperty.fromExpression(width))
    layer.setRenderer(QgsSingleSymbolRenderer(symbol))
    save(layer, name)


def peaks_style():
    """The panorama's peaks: thin grey leaders, each name at its leader's upper end."""
    layer = QgsVectorLayer("LineString?field=name:string&field=distance:double"
                           "&field=azimuth:double&field=elevation:double", "peaks", "memory")
    symbol = QgsLineSymbol.createSimple({"line_color": "119,119,119", "line_width": "0.15",
                                         "line_width_unit": "MM"})
    layer.setRenderer(QgsSingleSymbolRenderer(symbol))
    settings = QgsPalLayerSettings()
    settings.fieldName = "name"
    text = QgsTextFormat()
    text.setSize(8)
    text.setColor(QColor(51, 51, 51))
    settings.setFormat(text)
    properties = settings.dataDefinedProperties()
    for key, expression in ((QgsPalLayerSettings.PositionX, "x(end_point($geometry))"),
                            (QgsPalLayerSettings.PositionY, "y(end_point($geometry))"),
                            (QgsPalLayerSettings.Hali, "'Left'"),
                            (QgsPalLayerSettings.Vali, "'Bottom'")):
        properties.setProperty(key, QgsProperty.fromExpression(expression))
    settings.setDataDefinedProperties(properties)
    layer.setLabeling(QgsVectorLayerSimpleLabeling(settings))
    layer.setLabelsEnabled(True)
    save(layer, "panorama_peaks")


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
    # A panorama's visibility: hidden ground under a half-clear grey, seen ground clear, so that
    # the strokes and a hillshade show through.
    hidden, seen = QColor("#3c3c3c"), QColor(255, 255, 255, 0)
    visibility = QgsPalettedRasterRenderer(
        layer.dataProvider(), 1, [QgsPalettedRasterRenderer.Class(0, hidden, "hidden"),
                                  QgsPalettedRasterRenderer.Class(1, seen, "visible")])
    visibility.setOpacity(0.45)
    layer.setRenderer(visibility)
    save(layer, "visibility")
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


def register_plugin(plugin_dir):
    """Loads the built plugin's library so that its tapered line layer can be styled."""
    library = ctypes.CDLL(os.path.join(plugin_dir, "libterrain_sketch_provider.so"))
    if not library.terrain_sketch_register_provider() or not QgsExpression.isFunctionName(
            "terrain_sketch_draws_taper"):
        raise RuntimeError("could not register the plugin from " + plugin_dir)


def main():
    app = QgsApplication([], False)
    app.initQgis()
    register_plugin(sys.argv[1] if len(sys.argv) > 1 else
                    os.path.join(HERE, "..", "build", "qgis-plugin", "terrain_sketch_plugin"))
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
    drawn_styles()
    panorama_style("panorama", PANORAMA_COLOUR, PANORAMA_WIDTH)
    panorama_style("panorama_map", PANORAMA_MAP_COLOUR, PANORAMA_MAP_WIDTH)
    peaks_style()
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        raster_styles(tmp)
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
