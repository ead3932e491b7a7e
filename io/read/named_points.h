// Named points from any OGR vector layer, in the DEM's CRS: the peaks a panorama labels.
#pragma once

#include <string>
#include <vector>

#include "core/panorama/panorama_peaks.h"

namespace tsk::io {

// The points of the first layer of `path` with their `name_field`, transformed into the CRS of
// `srs_wkt` when both have a CRS. Multi-points give each of their points; other geometries are
// refused. Throws Error naming the cause: not a vector file, no such field (listing those
// there are), a geometry that is not a point, a CRS that cannot be transformed.
std::vector<NamedPoint> read_named_points(const std::string& path, const std::string& name_field,
                                          const std::string& srs_wkt);

}  // namespace tsk::io
