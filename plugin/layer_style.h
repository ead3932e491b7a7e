// Styles an algorithm's output layer with one of the plugin's QML files when QGIS loads it.
#pragma once

#include <qgsprocessingcontext.h>

#include <QString>

namespace tsk::plugin {

// Main thread: if QGIS will load `destinationId` on completion, applies styles/<style>.qml to it.
void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style);

}  // namespace tsk::plugin
