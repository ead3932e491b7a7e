"""Two copies of the plugin in one QGIS, as after an upgrade that left a copy under the folder's
old name: the copy loaded second is refused with a message that names the other's folder, nothing
is raised, and the first copy's provider stays registered. The second copy's library, asked to
register all the same (as an earlier shim asks it), says no without crashing QGIS and leaves the
first copy's tapered line in place. The shim loads its library from a copy in memory, or from the
file where it cannot.
    QT_QPA_PLATFORM=offscreen /usr/bin/python3 tests/e2e/plugin_copies_test.py BUILD_DIR"""
import contextlib
import ctypes
import io
import os
import shutil
import sys
import tempfile

build = sys.argv[1]
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
plugins = tempfile.mkdtemp(prefix="tsk-plugins-")
built = os.path.join(build, "qgis-plugin", "terrain_sketch_plugin")
shutil.copytree(built, os.path.join(plugins, "terrain_sketch_plugin"))
shutil.copytree(built, os.path.join(plugins, "terrain_sketch"))  # the folder's old name
sys.path.insert(0, plugins)

from qgis.core import QgsApplication  # noqa: E402

app = QgsApplication([], False)
app.initQgis()
errors = []
try:
    import terrain_sketch_plugin  # noqa: E402

    terrain_sketch_plugin.classFactory(None).initProcessing()
    registry = QgsApplication.processingRegistry()
    first = registry.providerById("terrainsketch")
    if first is None:
        errors.append("the first copy registered no provider")
    import terrain_sketch  # the other copy, under the old name  # noqa: E402

    said = io.StringIO()
    second = terrain_sketch.classFactory(None)
    with contextlib.redirect_stderr(said):
        second.initProcessing()  # raised "could not be registered" before
    message = said.getvalue()
    first_folder = os.path.join(plugins, "terrain_sketch_plugin")
    if "another copy" not in message or first_folder not in message:
        errors.append("the second copy's message: %r" % message)
    if not second.refused or second.library is not None:
        errors.append("the second copy loaded its library")
    if registry.providerById("terrainsketch") is not first:
        errors.append("the first copy's provider is no longer the one registered")
    library = ctypes.CDLL(os.path.join(plugins, "terrain_sketch", "libterrain_sketch_provider.so"))
    if library.terrain_sketch_register_provider() != 0:  # crashed QGIS before
        errors.append("the second copy's library registered a provider")
    if registry.providerById("terrainsketch") is not first:
        errors.append("the second copy's library replaced the first copy's provider")
    if QgsApplication.symbolLayerRegistry().symbolLayerMetadata("TerrainSketchTaperedLine") is None:
        errors.append("the second copy's library removed the tapered line")
    # The shim loads its library from a copy in memory (an upgrade rewrites the file in place),
    # and the file itself where no such copy can be made.
    first_library = os.path.join(first_folder, "libterrain_sketch_provider.so")
    in_memory = terrain_sketch_plugin.load_private_copy(first_library)._name
    if not in_memory.startswith("/proc/self/fd/"):
        errors.append("the library was not loaded from a copy in memory: %s" % in_memory)
    memfd_create = os.memfd_create
    try:
        del os.memfd_create
        from_file = terrain_sketch_plugin.load_private_copy(first_library)._name
    finally:
        os.memfd_create = memfd_create
    if from_file != first_library:
        errors.append("without copies in memory, the library was loaded from %s" % from_file)
except Exception as e:  # noqa: BLE001 - any failure is the test's
    errors.append("raised: %r" % e)
finally:
    shutil.rmtree(plugins, ignore_errors=True)
if errors:
    print("FAILED:\n  " + "\n  ".join(errors))
    sys.exit(1)
print("plugin copies: 1 passed, 0 failed")
