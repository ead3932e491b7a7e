"""Regenerates resources/layouts/terrain_sketch_a3.qpt, the print layout template for a sketch
page, with QGIS itself so that it loads without warnings.

Run with Debian's Python that has the qgis module:
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_layout_template.py

An A3 landscape page, ready to print once Terrain sketch > Silhouettes has run in the project:
- a map of the project's layers (the two silhouette layers over a hillshade) that follows the
  factual strokes' extent (@terrain_sketch_layer, set when they load), with a north arrow that
  turns with it; a finite extent of its own otherwise, which "Set to Map Canvas Extent" replaces;
- the project's title (or "Terrain sketch"), a key of the two stroke classes drawn in the styles'
  colours (a legend of the layers listed the hillshade's ramp too), a scale bar, the run's note
  (@terrain_sketch_note: DEM, view, exaggeration, filter) and the credits.
"""
import os
import sys

from qgis.core import (QgsApplication, QgsLayoutItemLabel, QgsLayoutItemMap,
                       QgsLayoutItemPicture, QgsLayoutItemPolyline, QgsLayoutItemScaleBar,
                       QgsLayoutObject, QgsLayoutPoint, QgsLayoutSize, QgsLineSymbol,
                       QgsPrintLayout, QgsProject, QgsProperty, QgsReadWriteContext,
                       QgsRectangle, QgsScaleBarSettings, QgsUnitTypes)
from qgis.PyQt.QtCore import QPointF
from qgis.PyQt.QtGui import QColor, QFont, QPolygonF

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "layouts", "terrain_sketch_a3.qpt")
# The page the plugin makes for a panorama: it sets the map's layers, extent and height, moves the
# note under it and sets the layout's variable @terrain_sketch_panorama_note.
PANORAMA_OUT = os.path.join(HERE, "..", "resources", "layouts", "terrain_sketch_panorama.qpt")
MM = QgsUnitTypes.LayoutMillimeters
INK, SEPIA = "17,17,17,255", "110,62,28,255"  # the factual and formulated styles' colours
# The factual strokes' extent in the project's CRS, when the plugin has named their layer.
STROKES = ("transform(layer_property(@terrain_sketch_layer, 'extent'), "
           "layer_property(@terrain_sketch_layer, 'crs'), @project_crs)")


def place(item, x, y, w, h):
    item.attemptMove(QgsLayoutPoint(x, y, MM))
    item.attemptResize(QgsLayoutSize(w, h, MM))


def label(layout, item_id, text, size, x, y, w, h, colour=(17, 17, 17)):
    item = QgsLayoutItemLabel(layout)
    item.setId(item_id)
    item.setText(text)
    item.setFont(QFont("Sans Serif", size))
    item.setFontColor(QColor(*colour))
    layout.addLayoutItem(item)
    place(item, x, y, w, h)
    return item


def add_map(layout):
    sketch = QgsLayoutItemMap(layout)
    sketch.setId("sketch")
    sketch.setFrameEnabled(True)
    sketch.setFrameStrokeColor(QColor(60, 60, 60))
    layout.addLayoutItem(sketch)
    place(sketch, 10, 22, 400, 250)
    # The sample DEM's ground (UTM 16N) until the strokes' layer is known, in the frame's
    # proportions (others make QGIS resize the frame when the extent changes).
    aspect = 400 / 250
    half_w, centre_x, centre_y = 1.06 * aspect * 32700 / 2, 748320, 4022065
    sketch.setExtent(QgsRectangle(centre_x - half_w, centre_y - half_w / aspect,
                                  centre_x + half_w, centre_y + half_w / aspect))
    # Centred on the strokes, with a margin, in the frame's proportions.
    width = ("with_variable('e', {0}, 1.06 * max(x_max(@e) - x_min(@e), "
             "{1} * (y_max(@e) - y_min(@e))))").format(STROKES, aspect)
    centre_x = "with_variable('e', {0}, (x_min(@e) + x_max(@e)) / 2)".format(STROKES)
    centre_y = "with_variable('e', {0}, (y_min(@e) + y_max(@e)) / 2)".format(STROKES)
    props = sketch.dataDefinedProperties()
    for key, text in ((QgsLayoutObject.MapXMin, "({c_x}) - ({w}) / 2"),
                      (QgsLayoutObject.MapXMax, "({c_x}) + ({w}) / 2"),
                      (QgsLayoutObject.MapYMin, "({c_y}) - ({w}) / {twice}"),
                      (QgsLayoutObject.MapYMax, "({c_y}) + ({w}) / {twice}")):
        expression = text.format(c_x=centre_x, c_y=centre_y, w=width, twice=2 * aspect)
        props.setProperty(key, QgsProperty.fromExpression(expression))
    sketch.setDataDefinedProperties(props)
    return sketch


def add_key(layout):
    """A line of each stroke class in its style's colour, with its name."""
    for row, (name, colour, width) in enumerate((("Factual silhouettes", INK, "0.6"),
                                                  ("Formulated silhouettes", SEPIA, "0.35"))):
        y = 279.5 + 6 * row
        line = QgsLayoutItemPolyline(QPolygonF([QPointF(120, y), QPointF(135, y)]), layout)
        line.setId("key_" + name.split()[0].lower())
        line.setSymbol(QgsLineSymbol.createSimple(
            {"line_color": colour, "line_width": width, "capstyle": "round"}))
        layout.addLayoutItem(line)
        label(layout, "key_label_" + name.split()[0].lower(), name, 9, 138, y - 2.5, 60, 5)


def main():
    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()
    layout = QgsPrintLayout(QgsProject.instance())
    layout.initializeDefaults()
    layout.setName("Terrain sketch A3")
    page = layout.pageCollection().page(0)
    page.setPageSize("A3", page.Landscape)

    sketch = add_map(layout)
    label(layout, "title", "[% coalesce(nullif(@project_title, ''), 'Terrain sketch') %]", 20,
          10, 6, 300, 14)

    north = QgsLayoutItemPicture(layout)
    north.setId("north")
    north.setPicturePath(":/images/north_arrows/layout_default_north_arrow.svg")
    north.setLinkedMap(sketch)
    north.setNorthMode(QgsLayoutItemPicture.GridNorth)
    north.setBackgroundEnabled(True)
    north.setBackgroundColor(QColor(255, 255, 255, 200))
    layout.addLayoutItem(north)
    place(north, 392, 26, 14, 18)

    scale = QgsLayoutItemScaleBar(layout)
    scale.setId("scale")
    scale.setLinkedMap(sketch)
    scale.setStyle("Single Box")
    scale.setUnits(QgsUnitTypes.DistanceKilometers)
    scale.setNumberOfSegments(4)
    scale.setNumberOfSegmentsLeft(0)
    scale.setUnitsPerSegment(1)
    scale.setUnitLabel("km")
    scale.setSegmentSizeMode(QgsScaleBarSettings.SegmentSizeFitWidth)
    scale.setMinimumBarWidth(40)
    scale.setMaximumBarWidth(90)
    layout.addLayoutItem(scale)
    place(scale, 12, 276, 100, 14)

    add_key(layout)
    label(layout, "note",
          "[% coalesce(@terrain_sketch_note, 'Run Terrain sketch > Silhouettes in this project "
          "to note the DEM and the view here.') %]", 8, 205, 276, 205, 12, (60, 60, 60))
    label(layout, "credits",
          "Silhouettes: Terrain Sketch, after \"Beyond Factual to Formulated Silhouettes\" "
          "(PhD thesis, University of Hull). Relief: the DEM named above.", 7, 205, 289, 205, 6,
          (90, 90, 90))

    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    save(layout, OUT)
    save(panorama_layout(), PANORAMA_OUT)
    app.exitQgis()
    return 0


def save(layout, path):
    if not layout.saveAsTemplate(path, QgsReadWriteContext()):
        raise RuntimeError("could not write " + path)
    print("wrote", os.path.normpath(path))


def panorama_layout():
    layout = QgsPrintLayout(QgsProject.instance())
    layout.initializeDefaults()
    page = layout.pageCollection().page(0)
    page.setPageSize("A3", page.Landscape)
    view = QgsLayoutItemMap(layout)
    view.setId("panorama")
    view.setKeepLayerSet(True)
    layout.addLayoutItem(view)
    place(view, 10, 24, 400, 100)
    label(layout, "title", "[% @layout_name %]", 20, 10, 6, 400, 14)
    label(layout, "note", "[% @terrain_sketch_panorama_note %]", 9, 10, 128, 400, 20, (60, 60, 60))
    return layout


if __name__ == "__main__":
    sys.exit(main())
