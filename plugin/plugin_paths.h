// Where the installed plugin keeps its files: styles, icon, translations, beside the library.
#pragma once

#include <QString>

namespace tsk::plugin {

// The plugin's folder: the one setPluginDir() was given, else the folder holding this shared
// library (the shim loads a private copy of the library, which lives in no folder).
QString pluginDir();
void setPluginDir(const QString& folder);
QString stylePath(const QString& name);   // e.g. "factual" -> <dir>/styles/factual.qml
QString layoutPath(const QString& name);  // e.g. "terrain_sketch_a3" -> <dir>/layouts/....qpt
QString iconPath();

}  // namespace tsk::plugin
