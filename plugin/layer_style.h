// Styles an algorithm's output layer with one of the plugin's QML files when QGIS loads it.
#pragma once

#include <qgsprocessingcontext.h>

#include <QString>

namespace tsk::plugin {

// How a raster's grey ramp meets its values.
enum class RampRange {
  style,  // as the QML file says
  data,   // from its own values, 2 % to 98 % of them: low relief shows as clearly as high
};

// Main thread: if QGIS will load `destinationId` on completion, applies styles/<style>.qml to it.
void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style, RampRange range = RampRange::style);

}  // namespace tsk::plugin
