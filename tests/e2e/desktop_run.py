"""Runs inside the real QGIS desktop (qgis.bin --code): runs the Terrain sketch algorithms from
Processing, loads their styled outputs, saves screenshots of the canvas and writes what it found
to a JSON report for desktop_test.sh to check. Always exits QGIS."""
import os
import sys
import traceback

from qgis.core import (QgsApplication, QgsProcessingFeedback, QgsProject, QgsRectangle,
                       QgsWkbTypes)
from qgis.PyQt.QtCore import QTimer
from qgis.utils import iface

sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.environ["TSK_E2E_SCRIPTS"])
from desktop_report import finish  # noqa: E402

OUT = os.environ["TSK_E2E_OUT"]
DEM = os.environ["TSK_E2E_DEM"]
report = {"ok": False, "screenshots": [], "log": [], "not_loaded": {}}


def record_message(message, tag, level):
    report["log"].append("%s [%d] %s" % (tag, int(level), message))


QgsApplication.messageLog().messageReceived.connect(record_message)


class RecordingFeedback(QgsProcessingFeedback):
    """Keeps what an algorithm and the result loading report, for the report on failure."""

    def __init__(self):
        super().__init__()
        self.errors = []

    def reportError(self, error, fatalError=False):
        self.errors.append(error)


def describe(layer):
    renderer = layer.renderer()
    info = {"name": layer.name(), "file": os.path.basename(layer.source().split("|")[0]),
            "crs": layer.crs().authid(), "renderer": renderer.type()}
    if layer.type() == layer.VectorLayer:
        symbol = renderer.symbol() if hasattr(renderer, "symbol") else None
        info["features"] = layer.featureCount()
        if symbol is not None:
            info["colour"] = symbol.color().name()
            info["symbol_layers"] = [symbol.symbolLayer(k).layerType()
                                     for k in range(symbol.symbolLayerCount())]
            info["geometry_type"] = QgsWkbTypes.displayString(layer.wkbType())
    elif hasattr(renderer, "contrastEnhancement") and renderer.contrastEnhancement():
        info["ramp_max"] = renderer.contrastEnhancement().maximumValue()
    return info


def show_only(files, rotation):
    root = QgsProject.instance().layerTreeRoot()
    extent = QgsRectangle()
    for layer in QgsProject.instance().mapLayers().values():
        visible = os.path.basename(layer.source().split("|")[0]) in files
        root.findLayer(layer.id()).setItemVisibilityChecked(visible)
        if visible:
            extent.combineExtentWith(layer.extent())
    canvas = iface.mapCanvas()
    canvas.setRotation(rotation)
    canvas.setExtent(extent)
    canvas.refresh()


# (screenshot, files of the visible layers, canvas rotation): the oblique sketch with the
# azimuth (90) up, then the classification map north up. Layers are found by their files, as
# their names follow the user's language (German names from our translation under LANG=de).
STROKES = {"factual.gpkg", "formulated.gpkg"}
SHOTS = [("qgis_desktop.png", STROKES | {"profiles.gpkg"}, -90),
         ("qgis_drape.png", STROKES | {"draped.tif"}, -90),
         ("qgis_pstrokes.png", STROKES | {"pstrokes.gpkg"}, -90),
         ("qgis_classification.png", {"classes.tif"}, 0),
         ("qgis_rowslope.png", {"rowslope.tif"}, 0),
         ("qgis_panorama_map.png", {"panorama_map.gpkg", "seen.tif"}, 0)]


def take(index):
    try:
        if index > 0:
            path = os.path.join(OUT, SHOTS[index - 1][0])
            iface.mapCanvas().saveAsImage(path)
            report["screenshots"].append(path)
        if index == len(SHOTS):
            report["ok"] = True
            finish(report)
            return
        show_only(SHOTS[index][1], SHOTS[index][2])
        QTimer.singleShot(4000, lambda: take(index + 1))
    except Exception:
        report["error"] = traceback.format_exc()
        finish(report)


def loaded_layer(path):
    for layer in QgsProject.instance().mapLayers().values():
        if layer.source().split("|")[0] == path:
            return layer
    return None


def run_and_load(alg, params):
    """Runs an algorithm as the Processing toolbox does and notes outputs that did not load."""
    import processing
    feedback = RecordingFeedback()
    results = processing.runAndLoadResults(alg, params, feedback=feedback)
    report["results"][alg] = {k: (v if isinstance(v, (int, float)) else str(v))
                              for k, v in results.items()}
    for key, value in params.items():
        if key in results and isinstance(value, str) and value.startswith(OUT):
            if loaded_layer(value) is None:
                report["not_loaded"][value] = feedback.errors
    return results


def dialogs():
    """Every algorithm's dialog as the toolbox opens it, given values as a user or a history entry
    gives them; what the dialog would run is read back from its widgets."""
    import processing
    report["dialogs"] = {}
    for alg in QgsApplication.processingRegistry().providerById("terrainsketch").algorithms():
        given = {"INPUT": DEM, "SOURCE": DEM, "OBSERVER": "749008.1394,4009477.9308 [EPSG:32616]"}
        if alg.id() == "terrainsketch:silhouettes":
            given["DRAWN_FOR"] = 250000
        given = {k: v for k, v in given.items() if alg.parameterDefinition(k) is not None}
        dialog = processing.createAlgorithmDialog(alg.id(), given)
        try:
            read = dialog.mainWidget().createProcessingParameters() if dialog else {}
        except Exception as e:  # noqa: BLE001 - the parameter the dialog refused goes to the report
            read = {"refused": str(e.args[0].name()) if e.args else repr(e)}
        report["dialogs"][alg.id()] = {k: (v if isinstance(v, (int, float)) else str(v))
                                       for k, v in read.items()}
        if dialog:
            dialog.close()
            dialog.deleteLater()


def python_package():
    """The Python package terrain_sketch as QGIS's Python console imports it, beside the plugin
    (whose folder once had the same name and hid it): a run of it from inside QGIS."""
    if not os.environ.get("TSK_E2E_PYTHON_PACKAGE"):
        return
    try:
        import terrain_sketch
        report["python_package"] = {"file": terrain_sketch.__file__}
        stats = terrain_sketch.silhouettes(DEM, os.path.join(OUT, "python.gpkg"))
        report["python_package"]["formulated_strokes"] = stats.get("formulated_strokes")
    except Exception:  # noqa: BLE001 - any failure goes into the report
        report.setdefault("python_package", {})["error"] = traceback.format_exc()


def run():
    try:
        import processing
        import qgis.utils
        python_package()
        dialogs()
        report["plugin_active"] = "terrain_sketch_plugin" in qgis.utils.active_plugins
        report["provider"] = QgsApplication.processingRegistry().providerById(
            "terrainsketch") is not None
        common = {"INPUT": DEM, "BAND": 1}
        runs = [("terrainsketch:silhouettes", {"GEOMETRY": 1,
                                               "FACTUAL": os.path.join(OUT, "factual.gpkg"),
                                               "FORMULATED": os.path.join(OUT, "formulated.gpkg")}),
                ("terrainsketch:profileplot", {"EVERY": 12,
                                               "OUTPUT": os.path.join(OUT, "profiles.gpkg")}),
                ("terrainsketch:classification", {"OUTPUT": os.path.join(OUT, "classes.tif")}),
                ("terrainsketch:rowslope", {"OUTPUT": os.path.join(OUT, "rowslope.tif")}),
                ("terrainsketch:pstrokes", {"GEOMETRY": 1,
                                            "OUTPUT": os.path.join(OUT, "pstrokes.gpkg")}),
                # The panorama from the sample's summit, the observer a point as the canvas
                # gives it.
                ("terrainsketch:panorama", {
                    "OBSERVER": "749008.1394,4009477.9308 [EPSG:32616]", "OBSERVER_HEIGHT": 2,
                    "MAP_OUTPUT": os.path.join(OUT, "panorama_map.gpkg"),
                    "PANORAMA_OUTPUT": os.path.join(OUT, "panorama.gpkg"),
                    "VISIBILITY": os.path.join(OUT, "seen.tif")})]
        report["results"] = {}
        for alg, params in runs:
            run_and_load(alg, dict(common, **params))
        hillshade = processing.run("native:hillshade", {"INPUT": DEM, "Z_FACTOR": 2.5,
                                                         "AZIMUTH": 300, "V_ANGLE": 40,
                                                         "OUTPUT": os.path.join(OUT, "hs.tif")})
        draped_path = os.path.join(OUT, "draped.tif")
        run_and_load("terrainsketch:drape", dict(common, SOURCE=hillshade["OUTPUT"],
                                                 OUTPUT=draped_path))
        report["layers"] = [describe(l) for l in QgsProject.instance().mapLayers().values()]
        # The draped raster goes to the bottom, under the strokes.
        draped = loaded_layer(draped_path)
        if draped is None:
            raise RuntimeError("the draped raster was not loaded")
        root = QgsProject.instance().layerTreeRoot()
        node = root.findLayer(draped.id())
        root.insertChildNode(-1, node.clone())
        node.parent().removeChildNode(node)
        # QGIS gives an empty project the CRS of its first layer once the event loop runs, which
        # these runs held up: an extent given before then would be read in EPSG:4326.
        QTimer.singleShot(1000, lambda: take(0))
    except Exception:
        report["error"] = traceback.format_exc()
        finish(report)


def install_from_zip():
    """Installs the plugin package as a user does: Plugin Manager, Install from ZIP (QGIS's
    installer, which unpacks it into the profile, loads and enables it)."""
    from pyplugin_installer import instance as plugin_installer
    try:
        plugin_installer().installFromZipFile(os.environ["TSK_E2E_ZIP"])
        report["installed_from_zip"] = True
    except Exception:  # noqa: BLE001 - any failure goes into the report
        report["error"] = "install from ZIP: " + traceback.format_exc()


def when_ready(waited_ms=0):
    """Starts once the main window is up and both providers are registered, so the run does not
    race the end of QGIS's start-up on a slow machine."""
    registry = QgsApplication.processingRegistry()
    if waited_ms == 0 and iface.mainWindow().isVisible() and "installed_from_zip" not in report:
        install_from_zip()
    ready = (iface.mainWindow().isVisible() and registry.providerById("native") is not None
             and registry.providerById("terrainsketch") is not None)
    if ready or waited_ms >= 60000:
        report["start_wait_ms"] = waited_ms
        QTimer.singleShot(1000, run)
    else:
        QTimer.singleShot(250, lambda: when_ready(waited_ms + 250))


QTimer.singleShot(0, lambda: when_ready(0))
