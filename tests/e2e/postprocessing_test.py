"""Every algorithm run as the Processing dialog runs it, with its defaults: each output a
QgsProcessingOutputLayerDefinition to a temporary output in the project, then Processing's own
post-processing (handleAlgorithmResults), which loads the results. No error may be reported,
every layer output must be in the project, styled by its name, and no run may leave an empty
temporary folder behind (QGIS makes one for each temporary file it names, as a check reading a
temporary output made it name one more). Every output records the run that made it: its file
(a GeoTIFF's image description, a GeoPackage layer's description) and, once loaded, its layer's
metadata; the layers of a view are named for it ("Row slope, from 90°").

Usage (QGIS's Python): /usr/bin/python3 postprocessing_test.py BUILD_DIR REPO_DIR
Prints one line per algorithm and 'N passed, N failed'; exits 1 on any failure.
"""
import os
import sys

build, repo = (os.path.abspath(a) for a in sys.argv[1:3])
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import headless_qgis  # noqa: E402

app = headless_qgis.start(build)
from processing.gui.Postprocessing import handleAlgorithmResults  # noqa: E402
from qgis.core import (QgsApplication, QgsLayoutExporter, QgsProcessingContext,  # noqa: E402
                       QgsProcessingFeedback, QgsProcessingOutputLayerDefinition,
                       QgsProcessingUtils, QgsProject)
from qgis.PyQt.QtGui import QImage  # noqa: E402
from osgeo import gdal  # noqa: E402

SAMPLE = os.path.join(repo, "resources", "sample", "jacksboro_utm16n.tif")
SUMMIT = "749008.1394,4009477.9308 [EPSG:32616]"
DEM_NAME = "jacksboro_utm16n, band 1"


class Feedback(QgsProcessingFeedback):
    """Keeps what Processing reports as errors (the dialog shows them in red)."""

    def __init__(self):
        super().__init__()
        self.errors = []

    def reportError(self, error, fatalError=False):  # noqa: N802 (QGIS's name)
        self.errors.append(error)


def temporary_folders():
    """The folders QGIS has made for temporary files so far."""
    top = QgsProcessingUtils.tempFolder()
    return {os.path.join(top, name) for name in os.listdir(top)
            if os.path.isdir(os.path.join(top, name))}


def file_note(value):
    """What an output file records of its run: a GeoTIFF's image description, or a GeoPackage
    layer's description; None for an output that is no file (a temporary vector layer)."""
    path, _, layer = str(value).partition("|layername=")
    if path.lower().endswith(".tif"):
        return gdal.Open(path).GetMetadataItem("TIFFTAG_IMAGEDESCRIPTION") or ""
    if not path.lower().endswith(".gpkg"):
        return None
    dataset = gdal.OpenEx(path, gdal.OF_VECTOR)
    found = dataset.GetLayerByName(layer) if layer else dataset.GetLayer(0)
    return found.GetMetadataItem("DESCRIPTION") or ""


def unrecorded(alg, results, project):
    """The outputs whose file or loaded layer does not record the run, and the layers of a view
    not named for it."""
    wrong = []
    for name, value in results.items():
        note = file_note(value) if alg.outputDefinition(name).type() in (
            "outputVector", "outputRaster", "outputLayer") and value else None
        if note is not None and not note.startswith(DEM_NAME):
            wrong.append(f"{name}'s file: {file_note(value)!r}")
    for layer in project.mapLayers().values():
        abstract = layer.metadata().abstract()
        if alg.name() != "drape" and not (abstract.startswith(DEM_NAME) and
                                          "Terrain Sketch" in abstract):
            wrong.append(f"layer {layer.name()}'s abstract: {abstract!r}")
        if alg.name() not in ("drape", "panorama") and ", from " not in layer.name():
            wrong.append(f"layer name {layer.name()!r}")
    return wrong


def run_as_dialog(alg_id, inputs):
    """Runs `alg_id` with `inputs` and every destination a temporary output, as the dialog does;
    returns (Processing's errors, the empty temporary folders it left and the outputs that do not
    record the run, the outputs not loaded into the project)."""
    folders_before = temporary_folders()
    project = QgsProject.instance()
    project.removeAllMapLayers()
    project.layoutManager().clear()
    alg = QgsApplication.processingRegistry().createAlgorithmById("terrainsketch:" + alg_id)
    params = dict(inputs)
    for output in alg.destinationParameterDefinitions():
        params[output.name()] = QgsProcessingOutputLayerDefinition("TEMPORARY_OUTPUT", project)
    context = QgsProcessingContext()
    context.setProject(project)
    feedback = Feedback()
    ok, message = alg.checkParameterValues(params, context)
    if not ok:
        return [message], []
    results, ran = alg.run(params, context, feedback)
    if not ran:
        return feedback.errors or ["the run failed"], []
    # By name: QGIS 3.22 has a showResults argument before the parameters, 3.40 has not.
    handleAlgorithmResults(alg, context, feedback, parameters=params)
    loaded = {layer.source() for layer in project.mapLayers().values()}
    loaded |= {layer.id() for layer in project.mapLayers().values()}
    missing = [name for name, value in results.items()
               if alg.outputDefinition(name).type() in ("outputVector", "outputRaster", "outputLayer")
               and value and not any(str(value) in source or source in str(value)
                                     for source in loaded)]
    empty = [f"empty temporary folder {folder}"
             for folder in sorted(temporary_folders() - folders_before) if not os.listdir(folder)]
    return feedback.errors + empty + unrecorded(alg, results, project), missing


CASES = [
    ("silhouettes", {"INPUT": SAMPLE}),
    ("profileplot", {"INPUT": SAMPLE}),
    ("pstrokes", {"INPUT": SAMPLE}),
    ("classification", {"INPUT": SAMPLE}),
    ("rowslope", {"INPUT": SAMPLE}),
    ("drape", {"INPUT": SAMPLE, "SOURCE": SAMPLE}),
    ("panorama", {"INPUT": SAMPLE, "OBSERVER": SUMMIT, "AZIMUTH_FROM": 300, "AZIMUTH_TO": 30}),
]
passed = failed = 0
for alg_id, inputs in CASES:
    errors, missing = run_as_dialog(alg_id, inputs)
    ok = not errors and not missing
    passed, failed = passed + ok, failed + (not ok)
    print(("ok      " if ok else "FAILED  ") + alg_id +
          ("" if ok else f": errors {errors}, not loaded {missing}"), flush=True)
# Drawn for 1:250 000, the strokes' styles draw their widths true at that scale: the renderer's
# reference scale, set as Processing loads the layers.
errors, missing = run_as_dialog("silhouettes", {"INPUT": SAMPLE, "DRAWN_FOR": 250000})
scales = [layer.renderer().referenceScale() for layer in QgsProject.instance().mapLayers().values()]
notes = [layer.metadata().abstract() for layer in QgsProject.instance().mapLayers().values()]
ok = (not errors and not missing and scales == [250000, 250000] and
      all("drawn strokes for 1:250,000" in note for note in notes))
passed, failed = passed + ok, failed + (not ok)
print(("ok      " if ok else "FAILED  ") + "drawn for a scale" +
      ("" if ok else f": errors {errors}, not loaded {missing}, scales {scales}, notes {notes}"),
      flush=True)

# The peaks in sight come labelled: the style's label settings are on once the layer loads.
peaks = os.path.join(os.environ.get("TMPDIR", "/tmp"), "tsk_postprocessing_peaks.geojson")
with open(peaks, "w") as f:
    f.write('{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": '
            '"urn:ogc:def:crs:EPSG::32616"}}, "features": [{"type": "Feature", "properties": '
            '{"name": "Summit"}, "geometry": {"type": "Point", "coordinates": '
            '[749008.1394, 4009477.9308]}}, {"type": "Feature", "properties": {"name": "East"}, '
            '"geometry": {"type": "Point", "coordinates": [758000, 4012000]}}]}')
errors, missing = run_as_dialog("panorama", {"INPUT": SAMPLE, "OBSERVER": SUMMIT,
                                             "OBSERVER_HEIGHT": 2, "PEAKS": peaks})
labelled = [layer for layer in QgsProject.instance().mapLayers().values()
            if layer.type() == layer.VectorLayer and "name" in layer.fields().names()]
ok = not errors and not missing and len(labelled) == 1 and labelled[0].labelsEnabled()
passed, failed = passed + ok, failed + (not ok)
print(("ok      " if ok else "FAILED  ") + "panorama peaks labelled" +
      ("" if ok else f": errors {errors}, not loaded {missing}, layers {labelled}"), flush=True)

# The panorama gets a print layout of its own: the CRS-less layer in the DEM's project zoomed to
# 1:6.7 billion. The page's map holds the panorama and its labels, and draws them.
layouts = [layout for layout in QgsProject.instance().layoutManager().printLayouts()
           if layout.name().startswith("Panorama")]
page_png = os.path.join(os.environ.get("TMPDIR", "/tmp"), "tsk_postprocessing_panorama.png")
drawn = 0
if len(layouts) == 1:
    view = layouts[0].itemById("panorama")
    panorama = [layer for layer in view.layers() if "azimuth_min" in layer.fields().names()]
    settings = QgsLayoutExporter.ImageExportSettings()
    settings.dpi = 60
    QgsLayoutExporter(layouts[0]).exportToImage(page_png, settings)
    image = QImage(page_png)
    drawn = sum(1 for y in range(0, image.height(), 2) for x in range(0, image.width(), 2)
                if image.pixelColor(x, y).lightness() < 128)
    note = layouts[0].itemById("note").currentText()
ok = (len(layouts) == 1 and len(view.layers()) == 2 and len(panorama) == 1 and
      view.extent().contains(panorama[0].extent()) and drawn > 100 and "times as tall" in note)
passed, failed = passed + ok, failed + (not ok)
print(("ok      " if ok else "FAILED  ") + "panorama layout" +
      ("" if ok else f": layouts {[layout.name() for layout in layouts]}, drawn {drawn}"),
      flush=True)
print(f"post-processing: {passed} passed, {failed} failed")
app.exitQgis()
sys.exit(1 if failed else 0)
