"""Runs inside the real QGIS desktop (qgis.bin --code) for upgrade_test.sh: installs the plugin from
one ZIP through QGIS's installer, runs Silhouettes and draws its styled layers, installs a newer
ZIP over it the same way, draws the same layers again, runs Silhouettes with the new library, and
writes what it found to a JSON report. Always exits QGIS."""
import os
import sys
import traceback

from qgis.core import (QgsApplication, QgsMapRendererSequentialJob, QgsMapSettings, QgsProject,
                       QgsRectangle)
from qgis.PyQt.QtCore import QSize, QTimer
from qgis.PyQt.QtGui import QColor
from qgis.utils import iface

sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.environ["TSK_E2E_SCRIPTS"])
from desktop_report import finish  # noqa: E402

OUT = os.environ["TSK_E2E_OUT"]
DEM = os.environ["TSK_E2E_DEM"]
report = {"ok": False}


def install(zip_path):
    from pyplugin_installer import instance as plugin_installer
    plugin_installer().installFromZipFile(zip_path)


def plugin_library():
    import qgis.utils
    return qgis.utils.plugins["terrain_sketch_plugin"].library


def run_and_load(tag):
    """Silhouettes run and loaded as the Processing toolbox does; the layers it loaded."""
    import processing
    outputs = {"FACTUAL": os.path.join(OUT, tag + "_factual.gpkg"),
               "FORMULATED": os.path.join(OUT, tag + "_formulated.gpkg")}
    processing.runAndLoadResults("terrainsketch:silhouettes",
                                 dict(outputs, INPUT=DEM, AZIMUTH=270))
    return [layer for layer in QgsProject.instance().mapLayers().values()
            if layer.source().split("|")[0] in outputs.values()]


def draw(layers, name):
    """The layers drawn as the canvas draws them, saved; the image and its inked pixels."""
    settings = QgsMapSettings()
    settings.setLayers(layers)
    extent = QgsRectangle()
    for layer in layers:
        extent.combineExtentWith(layer.extent())
    settings.setExtent(extent)
    settings.setOutputSize(QSize(800, 800))
    settings.setBackgroundColor(QColor("white"))
    job = QgsMapRendererSequentialJob(settings)
    job.start()
    job.waitForFinished()
    image = job.renderedImage()
    image.save(os.path.join(OUT, name))
    inked = sum(1 for y in range(0, image.height(), 2) for x in range(0, image.width(), 2)
                if QColor(image.pixel(x, y)).lightness() < 200)
    return image, inked


def symbol_layers(layers):
    return sorted({layer.renderer().symbol().symbolLayer(k).layerType() for layer in layers
                   for k in range(layer.renderer().symbol().symbolLayerCount())})


def go():
    try:
        install(os.environ["TSK_E2E_ZIP"])
        report["first_marker"] = hasattr(plugin_library(), "tsk_upgrade_marker")
        first = run_and_load("first")
        report["first_layers"] = len(first)
        report["first_symbol_layers"] = symbol_layers(first)
        before, report["inked_before"] = draw(first, "before_upgrade.png")
        install(os.environ["TSK_E2E_NEWER_ZIP"])  # crashed QGIS here before
        registry = QgsApplication.processingRegistry()
        report["provider_after"] = registry.providerById("terrainsketch") is not None
        report["newer_marker"] = hasattr(plugin_library(), "tsk_upgrade_marker")
        # The layers drawn before, by the symbol layers the first library made.
        after, report["inked_after"] = draw(first, "after_upgrade.png")
        report["same_drawing"] = before == after
        newer = run_and_load("newer")
        report["newer_layers"] = len(newer)
        report["newer_features"] = sum(layer.featureCount() for layer in newer)
        report["newer_symbol_layers"] = symbol_layers(newer)
        report["ok"] = True
    except Exception:
        report["error"] = traceback.format_exc()
    finish(report)


def when_ready(waited_ms=0):
    if iface.mainWindow().isVisible() or waited_ms >= 60000:
        QTimer.singleShot(1000, go)
    else:
        QTimer.singleShot(250, lambda: when_ready(waited_ms + 250))


QTimer.singleShot(0, when_ready)
