"""Runs inside the real QGIS desktop (qgis.bin --code): runs the Terrain sketch algorithm from
Processing, loads the styled outputs, saves a screenshot of the canvas and writes what it found
to a JSON report for desktop_test.sh to check. Always exits QGIS."""
import json
import os
import traceback

from qgis.core import QgsApplication, QgsProject, QgsRectangle
from qgis.PyQt.QtCore import QTimer
from qgis.utils import iface

OUT = os.environ["TSK_E2E_OUT"]
DEM = os.environ["TSK_E2E_DEM"]
report = {"ok": False}


def finish():
    QgsProject.instance().setDirty(False)  # no "save project?" prompt on exit
    with open(os.path.join(OUT, "report.json"), "w") as f:
        json.dump(report, f, indent=2)
    iface.actionExit().trigger()


def describe(layer):
    renderer = layer.renderer()
    symbol = renderer.symbol() if hasattr(renderer, "symbol") else None
    width_prop = None
    if symbol is not None:
        prop = symbol.symbolLayer(0).dataDefinedProperties().property(
            symbol.symbolLayer(0).PropertyStrokeWidth)
        width_prop = prop.expressionString() if prop.isActive() else None
    return {
        "name": layer.name(),
        "features": layer.featureCount(),
        "crs": layer.crs().authid(),
        "renderer": renderer.type(),
        "colour": symbol.color().name() if symbol else None,
        "width_expression": width_prop,
    }


def save_screenshot():
    if "screenshot" in report:
        return
    try:
        path = os.path.join(OUT, "qgis_desktop.png")
        iface.mapCanvas().saveAsImage(path)
        report["screenshot"] = path
        report["ok"] = True
    except Exception:
        report["error"] = traceback.format_exc()
    finish()


def run():
    try:
        import processing
        import qgis.utils
        report["plugin_active"] = "terrain_sketch" in qgis.utils.active_plugins
        report["provider"] = QgsApplication.processingRegistry().providerById(
            "terrainsketch") is not None
        results = processing.runAndLoadResults("terrainsketch:silhouettes", {
            "INPUT": DEM, "BAND": 1, "GEOMETRY": 1,
            "FACTUAL": os.path.join(OUT, "factual.gpkg"),
            "FORMULATED": os.path.join(OUT, "formulated.gpkg")})
        report["results"] = {k: (v if isinstance(v, (int, float)) else str(v))
                             for k, v in results.items()}
        layers = [l for l in QgsProject.instance().mapLayers().values()]
        report["layers"] = [describe(l) for l in layers]
        extent = QgsRectangle()
        for layer in layers:
            extent.combineExtentWith(layer.extent())
        canvas = iface.mapCanvas()
        canvas.setRotation(-90)  # azimuth 90 up: the plan-oblique strokes read as the sketch
        canvas.setExtent(extent)
        canvas.refresh()
        canvas.mapCanvasRefreshed.connect(save_screenshot)
        QTimer.singleShot(20000, save_screenshot)  # in case no refresh signal comes
    except Exception:
        report["error"] = traceback.format_exc()
        finish()


QTimer.singleShot(1000, run)
