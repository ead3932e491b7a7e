"""Terrain Sketch: loads the compiled processing provider.

qgis_process loads only Python plugins, so this shim loads the C++ library with ctypes and
asks it to register its provider; the desktop uses the same route.
"""
import ctypes
import os

_LIBRARY = "libterrain_sketch_provider.so"


class TerrainSketchPlugin:
    def __init__(self, iface):
        self.iface = iface
        self.library = None

    def initProcessing(self):
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
