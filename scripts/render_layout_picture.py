"""Renders the sample's drawn strokes in QGIS through the A3 layout template, over a hillshade,
as a map designer would print them: docs/qgis_drawn_layout.png (and a PDF beside it if asked).

    QT_QPA_PLATFORM=offscreen /usr/bin/python3 scripts/render_layout_picture.py BUILD_DIR OUT.png

The strokes come from the command line with its defaults (drawn strokes, map geometry), split
into the two layers and styled with resources/styles/*_drawn.qml as the QGIS algorithm styles
them.
"""
import os
import subprocess
import sys
import tempfile

from qgis.core import (QgsApplication, QgsLayoutExporter, QgsPrintLayout, QgsProject,
                       QgsRasterLayer, QgsReadWriteContext, QgsRectangle, QgsVectorLayer)
from qgis.PyQt.QtXml import QDomDocument

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLE = os.path.join(REPO, "resources", "sample", "jacksboro_utm16n.tif")
TEMPLATE = os.path.join(REPO, "resources", "layouts", "terrain_sketch_a3.qpt")


def main():
    build, out = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="tsk-layout-")
    strokes = os.path.join(work, "strokes.gpkg")
    subprocess.run([os.path.join(build, "cli", "terrain-sketch"), "silhouettes", SAMPLE, strokes],
                   check=True, capture_output=True)
    shade = os.path.join(work, "hillshade.tif")
    subprocess.run(["gdaldem", "hillshade", "-q", "-z", "2", "-multidirectional", SAMPLE, shade],
                   check=True)
    QgsApplication.setPrefixPath("/usr", True)
    app = QgsApplication([], False)
    app.initQgis()
    project = QgsProject.instance()
    hillshade = QgsRasterLayer(shade, "Hillshade")
    hillshade.renderer().setOpacity(0.55)
    project.addMapLayer(hillshade)
    project.setCrs(hillshade.crs())
    for cls, name in (("formulated", "Formulated silhouettes"), ("factual", "Factual silhouettes")):
        layer = QgsVectorLayer(strokes + "|layername=silhouettes", name, "ogr")
        layer.setSubsetString("class = '%s'" % cls)
        message, ok = layer.loadNamedStyle(os.path.join(REPO, "resources", "styles",
                                                        cls + "_drawn.qml"))
        if not ok:
            raise RuntimeError(message)
        project.addMapLayer(layer)
    layout = QgsPrintLayout(project)
    document = QDomDocument()
    with open(TEMPLATE) as f:
        document.setContent(f.read())
    layout.loadFromTemplate(document, QgsReadWriteContext())
    sketch = layout.itemById("sketch")
    legend = layout.itemById("legend")
    # The legend lists the two silhouette layers, not the hillshade.
    root = legend.model().rootGroup()
    for child in list(root.children()):
        if child.name() == "Hillshade":
            root.removeChildNode(child)
    legend.setAutoUpdateModel(False)
    sketch.setLayers([project.mapLayersByName(n)[0] for n in
                      ("Factual silhouettes", "Formulated silhouettes", "Hillshade")])
    sketch.setKeepLayerSet(True)
    sketch.setCrs(hillshade.crs())
    # The whole sample at 1:130 000: 32 km fill some 245 mm of the 255 mm tall frame.
    strokes_extent = project.mapLayersByName("Factual silhouettes")[0].extent()
    strokes_extent.combineExtentWith(project.mapLayersByName("Formulated silhouettes")[0].extent())
    # 1:130 000 over the 400 x 255 mm frame, centred on the strokes.
    half_w, half_h = 0.400 * 130000 / 2, 0.255 * 130000 / 2
    centre = strokes_extent.center()
    sketch.setExtent(QgsRectangle(centre.x() - half_w, centre.y() - half_h,
                                  centre.x() + half_w, centre.y() + half_h))
    exporter = QgsLayoutExporter(layout)
    settings = QgsLayoutExporter.ImageExportSettings()
    settings.dpi = 110
    if exporter.exportToImage(out, settings) != QgsLayoutExporter.Success:
        raise RuntimeError("could not export " + out)
    if len(sys.argv) > 3:
        exporter.exportToPdf(sys.argv[3], QgsLayoutExporter.PdfExportSettings())
    print("wrote", out)
    app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())
