// C entry points called by the plugin's Python shim (qgis_process loads only Python plugins; the
// same route serves the desktop): register and unregister the provider with its translation, and
// the drawn styles' tapered line.
#include <qgsapplication.h>
#include <qgsprocessingregistry.h>

#include <memory>

#include "plugin/provider.h"
#include "plugin/tapered_line.h"
#include "plugin/translation.h"

namespace {

// The registered provider; the registry owns it while it is registered.
tsk::plugin::TerrainSketchProvider* gProvider = nullptr;

}  // namespace

extern "C" __attribute__((visibility("default"))) int terrain_sketch_register_provider() {
  if (gProvider) return 1;
  tsk::plugin::installTranslation(tsk::plugin::qgisLanguage());
  tsk::plugin::registerTaperedLine();
  auto provider = std::make_unique<tsk::plugin::TerrainSketchProvider>();
  if (!QgsApplication::processingRegistry()->addProvider(provider.get())) return 0;
  gProvider = provider.release();
  return 1;
}

extern "C" __attribute__((visibility("default"))) void terrain_sketch_unregister_provider() {
  if (gProvider) QgsApplication::processingRegistry()->removeProvider(gProvider);
  gProvider = nullptr;
  tsk::plugin::unregisterTaperedLine();
  tsk::plugin::removeTranslation();
}
