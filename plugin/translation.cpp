#include "plugin/translation.h"

#include <qgsapplication.h>

#include <QCoreApplication>
#include <QTranslator>
#include <memory>

#include "plugin/plugin_paths.h"

namespace tsk::plugin {
namespace {

std::unique_ptr<QTranslator>& installed() {
  static std::unique_ptr<QTranslator> translator;
  return translator;
}

}  // namespace

bool installTranslation(const QString& locale, const QString& folder) {
  removeTranslation();
  auto translator = std::make_unique<QTranslator>();
  // QTranslator::load tries terrain_sketch_de_DE, then terrain_sketch_de.
  if (!translator->load(QStringLiteral("terrain_sketch_") + locale,
                        folder.isEmpty() ? pluginDir() + QStringLiteral("/i18n") : folder)) {
    return false;
  }
  QCoreApplication::installTranslator(translator.get());
  installed() = std::move(translator);
  return true;
}

QString qgisLanguage() {
  // QGIS sets its translation from --lang, or from the profile's locale when it overrides the
  // system's; QgsApplication::locale() reads the profile alone.
  const QString translation =
      QgsApplication::instance() ? QgsApplication::instance()->translation() : QString();
  return translation.isEmpty() ? QgsApplication::locale() : translation;
}

void removeTranslation() {
  if (installed()) QCoreApplication::removeTranslator(installed().get());
  installed().reset();
}

}  // namespace tsk::plugin
