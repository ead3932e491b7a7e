"""The A3 layout template as a map designer meets it: Silhouettes run as the Processing dialog runs
it (a file output loaded by Processing's own post-processing) over a hillshade, then a layout made
from the template as the Layout Manager makes one, with nothing set by hand, exported to PDF. The
page must show the strokes: a finite map extent around them, a scale bar, a key of the two stroke
classes and no legend of other layers, and the run's note. The PDF is also rendered to PNG.

Usage (QGIS's Python): /usr/bin/python3 layout_template_test.py BUILD_DIR REPO_DIR OUT_DIR
Prints one line per check and 'N passed, N failed'; exits 1 on any failure.
"""
import math
import os
import subprocess
import sys

build, repo, out = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(out, exist_ok=True)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import headless_qgis  # noqa: E402

app = headless_qgis.start(build)
from processing.gui.Postprocessing import handleAlgorithmResults  # noqa: E402
from qgis.core import (QgsApplication, QgsCoordinateTransform,  # noqa: E402
                       QgsExpressionContextUtils, QgsLayoutExporter,
                       QgsLayoutItemLegend, QgsLayoutItemRegistry, QgsPrintLayout,
                       QgsProcessingContext, QgsProcessingFeedback,
                       QgsProcessingOutputLayerDefinition, QgsProject, QgsRasterLayer,
                       QgsReadWriteContext)
from qgis.PyQt.QtGui import QImage  # noqa: E402
from osgeo import gdal  # noqa: E402
from qgis.PyQt.QtXml import QDomDocument  # noqa: E402

SAMPLE = os.path.join(repo, "resources", "sample", "jacksboro_utm16n.tif")
TEMPLATE = os.path.join(build, "qgis-plugin", "terrain_sketch_plugin", "layouts",
                        "terrain_sketch_a3.qpt")
passed = failed = 0


def check(name, ok, detail=""):
    global passed, failed
    passed, failed = passed + bool(ok), failed + (not ok)
    print(("ok      " if ok else "FAILED  ") + name + ("" if ok else ": " + str(detail)),
          flush=True)


def run_silhouettes(project):
    """Silhouettes from 250 degrees into files, loaded as the dialog loads them."""
    alg = QgsApplication.processingRegistry().createAlgorithmById("terrainsketch:silhouettes")
    params = {"INPUT": SAMPLE, "AZIMUTH": 250}
    for name in ("FACTUAL", "FORMULATED"):
        params[name] = QgsProcessingOutputLayerDefinition(
            os.path.join(out, name.lower() + ".gpkg"), project)
    context = QgsProcessingContext()
    context.setProject(project)
    feedback = QgsProcessingFeedback()
    results, ran = alg.run(params, context, feedback)
    check("silhouettes ran", ran)
    # The files record the run too, for whoever opens them elsewhere: each GeoPackage layer's
    # description (gpkg_contents).
    for name in ("factual", "formulated"):
        dataset = gdal.OpenEx(os.path.join(out, name + ".gpkg"), gdal.OF_VECTOR)
        description = dataset.GetLayer(0).GetMetadataItem("DESCRIPTION") or ""
        check(name + ".gpkg records the run",
              description.startswith("jacksboro_utm16n, band 1. Seen from 250") and
              "Terrain Sketch" in description, description)
    handleAlgorithmResults(alg, context, feedback, parameters=params)


def layout_from_template(project):
    layout = QgsPrintLayout(project)
    document = QDomDocument()
    with open(TEMPLATE) as f:
        document.setContent(f.read())
    _, ok = layout.loadFromTemplate(document, QgsReadWriteContext())
    check("template loads", ok)
    layout.refresh()
    return layout


def check_page(project, layout):
    variables = QgsExpressionContextUtils.projectScope(project)
    factual = [project.mapLayer(variables.variable("terrain_sketch_layer"))]
    check("the run names the factual layer for layouts", factual[0] is not None,
          variables.variableNames())
    # Its name is the file's or the view's, as Processing's setting says; its metadata say both.
    title = factual[0].metadata().title()
    check("layer metadata say the view", title.startswith("Factual silhouettes") and "250" in title
          and "jacksboro_utm16n" in factual[0].metadata().abstract(), title)
    sketch = layout.itemById("sketch")
    extent = sketch.extent()
    finite = all(math.isfinite(v) for v in (extent.xMinimum(), extent.yMinimum(),
                                            extent.xMaximum(), extent.yMaximum()))
    check("map extent finite", finite and extent.width() > 0, extent.toString())
    strokes = QgsCoordinateTransform(factual[0].crs(), project.crs(), project).transformBoundingBox(
        factual[0].extent())
    check("map shows the strokes", extent.contains(strokes) and
          extent.width() < 1.5 * strokes.width() + 1.5 * strokes.height(),
          (extent.toString(), strokes.toString()))
    scale = layout.itemById("scale")
    check("scale bar", scale is not None and scale.type() == QgsLayoutItemRegistry.LayoutScaleBar)
    legends = [item for item in layout.items() if isinstance(item, QgsLayoutItemLegend)]
    check("no legend of the hillshade's ramp", not legends)
    keys = [layout.itemById("key_label_" + c).currentText() for c in ("factual", "formulated")]
    check("key of the stroke classes", keys == ["Factual silhouettes", "Formulated silhouettes"],
          keys)
    note = layout.itemById("note").currentText()
    check("view note", "jacksboro_utm16n" in note and "250" in note and "filter" in note, note)
    check("north arrow follows the map", layout.itemById("north").linkedMap() is sketch)


def export(layout):
    pdf, png = os.path.join(out, "layout.pdf"), os.path.join(out, "layout")
    result = QgsLayoutExporter(layout).exportToPdf(pdf, QgsLayoutExporter.PdfExportSettings())
    check("PDF exported", result == QgsLayoutExporter.Success, result)
    subprocess.run(["pdftoppm", "-png", "-r", "60", "-singlefile", pdf, png], check=True)
    image = QImage(png + ".png")
    # Inside the map frame, away from its edge: dark strokes and the hillshade's greys.
    dark = sum(1 for y in range(80, image.height() - 120, 3) for x in range(40, image.width() - 40, 3)
               if image.pixelColor(x, y).lightness() < 60)
    check("strokes drawn on the page", dark > 200, dark)


project = QgsProject.instance()
shade = os.path.join(out, "hillshade.tif")
subprocess.run(["gdaldem", "hillshade", "-q", "-multidirectional", SAMPLE, shade], check=True)
hillshade = QgsRasterLayer(shade, "Hillshade")
project.addMapLayer(hillshade)
project.setCrs(hillshade.crs())
run_silhouettes(project)
layout = layout_from_template(project)
check_page(project, layout)
export(layout)
print(f"layout template: {passed} passed, {failed} failed")
app.exitQgis()
sys.exit(1 if failed else 0)
