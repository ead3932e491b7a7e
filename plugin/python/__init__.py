"""Terrain Sketch: loads the compiled processing provider.

qgis_process loads only Python plugins, so this shim loads the C++ library with ctypes and
asks it to register its provider; the desktop uses the same route.

The library is built against one QGIS release, whose C++ interface differs from the others', so
the shim first checks that it runs in that release and otherwise says so instead of loading it.
"""
import ctypes
import os
import sys

from qgis.core import Qgis, QgsMessageLog

from .build_info import BUILT_FOR_QGIS, BUILT_FOR_QGIS_VERSION_INT, PACKAGE

_LIBRARY = "libterrain_sketch_provider.so"
_TAG = "Terrain Sketch"


def release_mismatch():
    """The message for a QGIS of another release than the one built for; None when it is it."""
    running = Qgis.QGIS_VERSION_INT
    if running // 100 == BUILT_FOR_QGIS_VERSION_INT // 100:
        return None
    here = "%d.%d" % (running // 10000, running // 100 % 100)
    return ("Terrain Sketch was not loaded: this package (%s) is built for QGIS %s, and this is "
            "QGIS %s. A compiled plugin works only in the QGIS release it was built for. Install "
            "the Terrain Sketch package for QGIS %s, or build it from source against this QGIS "
            "(see the README)." % (PACKAGE, BUILT_FOR_QGIS, here, here))


class TerrainSketchPlugin:
    def __init__(self, iface):
        self.iface = iface
        self.library = None
        self.refused = False

    def initProcessing(self):
        if self.refused:
            return
        mismatch = release_mismatch()
        if mismatch:
            self.refused = True
            QgsMessageLog.logMessage(mismatch, _TAG, Qgis.Critical)
            if self.iface is not None:
                self.iface.messageBar().pushCritical(_TAG, mismatch)
            else:  # qgis_process: its messages go to the terminal
                sys.stderr.write(mismatch + "\n")
            return
        if self.library is None:
            self.library = ctypes.CDLL(os.path.join(os.path.dirname(__file__), _LIBRARY))
        if not self.library.terrain_sketch_register_provider():
            raise RuntimeError("Terrain Sketch: the processing provider could not be registered")

    def initGui(self):
        self.initProcessing()

    def unload(self):
        if self.library is not None:
            self.library.terrain_sketch_unregister_provider()


def classFactory(iface):
    return TerrainSketchPlugin(iface)
