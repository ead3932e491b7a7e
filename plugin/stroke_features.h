// Adapter from core strokes to QGIS features with the SPEC attribute fields.
#pragma once

#include <qgsfeature.h>
#include <qgsfields.h>
#include <qgsgeometry.h>

#include <vector>

#include "core/method/strokes.h"

namespace tsk::plugin {

// class, cells, then the core's real-valued stroke fields in their order.
QgsFields strokeFields();

// A line through `points`.
QgsGeometry lineGeometry(const std::vector<StrokePoint>& points, const std::vector<double>& m = {});

// A line feature for `stroke`; NaN attributes become null.
QgsFeature strokeFeature(const Stroke& stroke, const QgsFields& fields);

}  // namespace tsk::plugin
