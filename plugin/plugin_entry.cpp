// C entry points called by the plugin's Python shim (qgis_process loads only Python plugins; the
// same route serves the desktop): register and unregister the provider, load translations.
#include <qgsapplication.h>
#include <qgsprocessingregistry.h>

#include <QLocale>
#include <QTranslator>
#include <memory>

#include "plugin_paths.h"
#include "provider.h"

namespace {

// The registered provider (owned by the registry while registered) and our translator.
tsk::plugin::TerrainSketchProvider* gProvider = nullptr;
std::unique_ptr<QTranslator> gTranslator;

void loadTranslation() {
  if (gTranslator) return;
  const QString locale = QgsApplication::locale();
  auto translator = std::make_unique<QTranslator>();
  if (translator->load(QStringLiteral("terrain_sketch_") + locale,
                       tsk::plugin::pluginDir() + QStringLiteral("/i18n"))) {
    QCoreApplication::installTranslator(translator.get());
    gTranslator = std::move(translator);
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int terrain_sketch_register_provider() {
  if (gProvider) return 1;
  loadTranslation();
  auto provider = std::make_unique<tsk::plugin::TerrainSketchProvider>();
  if (!QgsApplication::processingRegistry()->addProvider(provider.get())) return 0;
  gProvider = provider.release();  // the registry owns it now
  return 1;
}

extern "C" __attribute__((visibility("default"))) void terrain_sketch_unregister_provider() {
  if (gProvider) QgsApplication::processingRegistry()->removeProvider(gProvider);
  gProvider = nullptr;
  if (gTranslator) QCoreApplication::removeTranslator(gTranslator.get());
  gTranslator.reset();
}
