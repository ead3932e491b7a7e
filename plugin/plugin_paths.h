// Where the installed plugin keeps its files: styles, icon, translations, beside the library.
#pragma once

#include <QString>

namespace tsk::plugin {

// The folder holding this shared library.
QString pluginDir();
QString stylePath(const QString& name);   // e.g. "factual" -> <dir>/styles/factual.qml
QString layoutPath(const QString& name);  // e.g. "terrain_sketch_a3" -> <dir>/layouts/....qpt
QString iconPath();

}  // namespace tsk::plugin
