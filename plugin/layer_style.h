// Styles an algorithm's output layer with one of the plugin's QML files when QGIS loads it.
#pragma once

#include <qgsprocessingcontext.h>

#include <QString>
#include <memory>

#include "plugin/panorama_layout.h"

namespace tsk::plugin {

// How a raster's grey ramp meets its values.
enum class RampRange {
  style,  // as the QML file says
  data,   // from its own values, 2 % to 98 % of them: low relief shows as clearly as high
};

// What a loaded output records of the run that made it: its layer's title and abstract (Layer
// Properties > Metadata). For a sketch's factual strokes, the project's variables a print layout
// reads too: @terrain_sketch_layer (the layer's id, whose extent the layout template's map
// follows) and @terrain_sketch_note (the abstract, the template's note).
struct RunNote {
  QString title;
  QString abstract;
  bool sketch = false;
  // A panorama's layers go to its layout as they load; its strokes (`panorama`) set the map.
  std::shared_ptr<PanoramaLayout> layout;
  bool panorama = false;
  // Drawn strokes drawn for 1:referenceScale: the style's widths are true at that scale and grow
  // and shrink with the map's (0: the same on paper at every scale).
  double referenceScale = 0.0;
};

// Main thread: if QGIS will load `destinationId` on completion, applies styles/<style>.qml to it,
// and `note` when it has an abstract.
void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style, RampRange range = RampRange::style,
                       const RunNote& note = {});

}  // namespace tsk::plugin
