"""Terrain Sketch: loads the compiled processing provider.

qgis_process loads only Python plugins, so this shim loads the C++ library with ctypes and
asks it to register its provider; the desktop uses the same route. It loads a copy of the library
held in memory, not the file in the plugin folder, so that installing a new package over this one
neither crashes QGIS nor leaves the old library in use (load_private_copy).

The library is built against one QGIS release, whose C++ interface differs from the others', so
the shim first checks that it runs in that release and otherwise says so instead of loading it.

The plugin's folder is terrain_sketch_plugin, not terrain_sketch: QGIS puts its plugin folders
first on Python's path, where a folder named terrain_sketch hid the Python package of that name
from QGIS's Python console and scripts.
"""
import ctypes
import os
import shutil
import sys

from qgis.core import Qgis, QgsApplication, QgsMessageLog

from .build_info import BUILT_FOR_QGIS, BUILT_FOR_QGIS_VERSION_INT, PACKAGE

_LIBRARY = "libterrain_sketch_provider.so"
_TAG = "Terrain Sketch"
_PROVIDER_ID = "terrainsketch"
_FOLDER = os.path.dirname(os.path.abspath(__file__))  # this copy's plugin folder


def load_private_copy(path):
    """The library at `path`, loaded from a copy in memory that nothing else writes to.

    QGIS's installer (Install from ZIP) first unpacks the new package over the files of the one
    installed, rewriting the loaded library in place under the running code, and QGIS crashed when
    it then unloaded the plugin. A copy keeps the old code whole for as long as anything of it
    runs (the old provider, a tapered line already drawing), and the new package's library, copied
    in turn, loads beside it and takes effect without a restart: the dynamic loader would give
    back the library already loaded from the same path. Where no copy can be made or loaded, the
    file itself is."""
    try:
        copy = os.memfd_create(_LIBRARY, os.MFD_CLOEXEC)
    except (AttributeError, OSError):
        return ctypes.CDLL(path)
    try:
        with open(path, "rb") as source, open(copy, "wb", closefd=False) as target:
            shutil.copyfileobj(source, target)
        # The copy's descriptor stays open while QGIS runs: the loader knows a library by its
        # path, and a closed descriptor's number would name the next copy.
        return ctypes.CDLL("/proc/self/fd/%d" % copy)
    except OSError:
        os.close(copy)
        return ctypes.CDLL(path)


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


def other_copies():
    """Other plugin folders beside this one that hold Terrain Sketch's library (an earlier
    install under another folder name, such as terrain_sketch)."""
    parent = os.path.dirname(_FOLDER)
    found = []
    for name in sorted(os.listdir(parent)):
        folder = os.path.join(parent, name)
        if folder != _FOLDER and os.path.isfile(os.path.join(folder, _LIBRARY)):
            found.append(folder)
    return found


def already_registered():
    """The message for a provider that another copy of the plugin registered; None if none."""
    if QgsApplication.processingRegistry().providerById(_PROVIDER_ID) is None:
        return None
    others = other_copies()
    where = " (%s)" % ", ".join(others) if others else ""
    return ("Terrain Sketch was not loaded from %s: another copy of it is loaded already%s. "
            "Uninstall the other copy in Plugins > Manage and Install Plugins (an earlier "
            "version was installed under the folder name terrain_sketch), then restart QGIS."
            % (_FOLDER, where))


class TerrainSketchPlugin:
    def __init__(self, iface):
        self.iface = iface
        self.library = None
        self.refused = False

    def refuse(self, message):
        self.refused = True
        QgsMessageLog.logMessage(message, _TAG, Qgis.Critical)
        if self.iface is not None:
            self.iface.messageBar().pushCritical(_TAG, message)
        else:  # qgis_process: its messages go to the terminal
            sys.stderr.write(message + "\n")

    def initProcessing(self):
        if self.refused:
            return
        if self.library is None:
            refusal = release_mismatch() or already_registered()
            if refusal:
                return self.refuse(refusal)
            self.library = load_private_copy(os.path.join(_FOLDER, _LIBRARY))
            # The copy lives in no folder: the library is told where its styles and layouts are.
            self.library.terrain_sketch_set_plugin_folder(os.fsencode(_FOLDER))
        if not self.library.terrain_sketch_register_provider():
            raise RuntimeError("Terrain Sketch: the processing provider could not be registered")

    def initGui(self):
        self.initProcessing()

    def unload(self):
        if self.library is not None:
            self.library.terrain_sketch_unregister_provider()


def classFactory(iface):
    return TerrainSketchPlugin(iface)
