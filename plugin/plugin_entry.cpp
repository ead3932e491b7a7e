// C entry points called by the plugin's Python shim (qgis_process loads only Python plugins; the
// same route serves the desktop): register and unregister the provider with its translation, and
// the drawn styles' tapered line.
#include <qgsapplication.h>
#include <qgsprocessingregistry.h>

#include <QFile>
#include <memory>

#include "plugin/plugin_paths.h"
#include "plugin/provider.h"
#include "plugin/tapered_line.h"
#include "plugin/translation.h"

namespace {

// The registered provider; the registry owns it while it is registered.
tsk::plugin::TerrainSketchProvider* gProvider = nullptr;

}  // namespace

extern "C" __attribute__((visibility("default"))) int terrain_sketch_register_provider() {
  if (gProvider) return 1;
  QgsProcessingRegistry* registry = QgsApplication::processingRegistry();
  auto provider = std::make_unique<tsk::plugin::TerrainSketchProvider>();
  // Another copy of the plugin (another folder) registered it: this one adds nothing, and leaves
  // the other's tapered line and translation alone.
  if (registry->providerById(provider->id())) return 0;
  tsk::plugin::installTranslation(tsk::plugin::qgisLanguage());
  tsk::plugin::registerTaperedLine();
  // The registry owns the provider from the call on: it deletes one it refuses (deleting it here
  // too crashed QGIS when a second copy of the plugin was loaded).
  tsk::plugin::TerrainSketchProvider* offered = provider.release();
  if (!registry->addProvider(offered)) {
    tsk::plugin::removeTranslation();
    return 0;
  }
  gProvider = offered;
  return 1;
}

// The plugin folder (as the file system names it) that holds the styles, layouts and translations,
// for a library loaded from a copy outside it (the shim's; see plugin/python/__init__.py).
extern "C" __attribute__((visibility("default"))) void terrain_sketch_set_plugin_folder(
    const char* folder) {
  tsk::plugin::setPluginDir(folder ? QFile::decodeName(folder) : QString());
}

extern "C" __attribute__((visibility("default"))) void terrain_sketch_unregister_provider() {
  if (gProvider) QgsApplication::processingRegistry()->removeProvider(gProvider);
  gProvider = nullptr;
  tsk::plugin::unregisterTaperedLine();
  tsk::plugin::removeTranslation();
}
