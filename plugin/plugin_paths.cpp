#include "plugin/plugin_paths.h"

#include <dlfcn.h>

#include <QFileInfo>

namespace tsk::plugin {
namespace {

QString& givenPluginDir() {
  static QString folder;
  return folder;
}

}  // namespace

void setPluginDir(const QString& folder) {
  givenPluginDir() = folder;
}

QString pluginDir() {
  if (!givenPluginDir().isEmpty()) return givenPluginDir();
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&pluginDir), &info) == 0 || !info.dli_fname) return QString();
  return QFileInfo(QString::fromLocal8Bit(info.dli_fname)).absolutePath();
}

QString stylePath(const QString& name) {
  return pluginDir() + "/styles/" + name + ".qml";
}

QString layoutPath(const QString& name) {
  return pluginDir() + "/layouts/" + name + ".qpt";
}

QString iconPath() {
  return pluginDir() + "/icons/terrain_sketch.svg";
}

}  // namespace tsk::plugin
