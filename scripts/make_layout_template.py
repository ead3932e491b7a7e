"""Regenerates resources/layouts/terrain_sketch_a3.qpt, the print layout template for a sketch
page, with QGIS itself so that it loads without warnings.

Run with Debian's Python that has the qgis module:
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/make_layout_template.py

An A3 landscape page: a map filling it (the project's layers: the two silhouette layers over a
hillshade), a title, a legend of the layers and a scale bar, all in the styles' colours.
"""
import os
import sys

from qgis.core import (QgsApplication, QgsLayoutItemLabel, QgsLayoutItemLegend,
                       QgsLayoutItemMap, QgsLayoutItemScaleBar, QgsLayoutPoint, QgsLayoutSize,
                       QgsPrintLayout, QgsProject, QgsReadWriteContext, QgsUnitTypes)
from qgis.PyQt.QtGui import QColor, QFont

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "resources", "layouts", "terrain_sketch_a3.qpt")
MM = QgsUnitTypes.LayoutMillimeters


def place(item, x, y, w, h):
    item.attemptMove(QgsLayoutPoint(x, y, MM))
    item.attemptResize(QgsLayoutSize(w, h, MM))


def main():
    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()
    layout = QgsPrintLayout(QgsProject.instance())
    layout.initializeDefaults()
    layout.setName("Terrain sketch A3")
    page = layout.pageCollection().page(0)
    page.setPageSize("A3", page.Landscape)

    sketch = QgsLayoutItemMap(layout)
    sketch.setId("sketch")
    sketch.setFrameEnabled(True)
    sketch.setFrameStrokeColor(QColor(60, 60, 60))
    layout.addLayoutItem(sketch)
    place(sketch, 10, 22, 400, 255)

    title = QgsLayoutItemLabel(layout)
    title.setId("title")
    title.setText("Terrain sketch")
    font = QFont("Sans Serif", 20)
    title.setFont(font)
    title.setFontColor(QColor(17, 17, 17))
    layout.addLayoutItem(title)
    place(title, 10, 6, 250, 14)

    legend = QgsLayoutItemLegend(layout)
    legend.setId("legend")
    legend.setTitle("")
    legend.setLinkedMap(sketch)
    legend.setBackgroundEnabled(True)
    layout.addLayoutItem(legend)
    place(legend, 320, 4, 90, 16)

    scale = QgsLayoutItemScaleBar(layout)
    scale.setId("scale")
    scale.setLinkedMap(sketch)
    scale.setStyle("Single Box")
    scale.setUnits(QgsUnitTypes.DistanceKilometers)
    scale.setNumberOfSegments(4)
    scale.setNumberOfSegmentsLeft(0)
    scale.setUnitsPerSegment(1)
    scale.setUnitLabel("km")
    layout.addLayoutItem(scale)
    place(scale, 14, 280, 80, 12)

    os.makedirs(os.path.dirname(OUT), exist_ok=True)
    if not layout.saveAsTemplate(OUT, QgsReadWriteContext()):
        raise RuntimeError("could not write " + OUT)
    print("wrote", os.path.normpath(OUT))
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
