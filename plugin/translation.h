// Loads the plugin's Qt translation for a locale from <plugin dir>/i18n.
#pragma once

#include <QString>

namespace tsk::plugin {

// Installs terrain_sketch_<locale>.qm (e.g. "de" or "de_DE") from `folder` (default: the
// plugin's i18n folder) if there is one; returns whether a translation is now installed.
// Calling it again replaces the previous one.
bool installTranslation(const QString& locale, const QString& folder = QString());
void removeTranslation();

// The language QGIS shows its own strings in: `qgis --lang de`, else the profile's locale.
QString qgisLanguage();

}  // namespace tsk::plugin
