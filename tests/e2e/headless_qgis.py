"""QGIS started headless with Processing and the plugin of a build registered, as the end-to-end
scripts run it (the plugin from BUILD_DIR/qgis-plugin, not an installed profile)."""
import os
import sys


def start(build):
    """Starts QGIS (offscreen unless QT_QPA_PLATFORM says otherwise) and registers Processing and
    the Terrain Sketch provider; returns the QgsApplication, to end with exitQgis()."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    sys.path.append("/usr/share/qgis/python/plugins")
    sys.path.insert(0, os.path.join(build, "qgis-plugin"))
    from qgis.core import QgsApplication

    app = QgsApplication([], False)
    app.initQgis()
    from processing.core.Processing import Processing
    import terrain_sketch_plugin

    terrain_sketch_plugin.classFactory(None).initProcessing()
    Processing.initialize()
    return app
