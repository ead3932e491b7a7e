// What the commands share: reading the DEM with its notes, small text outputs, the statistics.
#pragma once

#include <ostream>
#include <string>

#include "dem_reader.h"
#include "options.h"
#include "silhouettes.h"

namespace tsk::cli {

// Reads the DEM for the view and tells the user, on `err`, what they should know about it.
io::Dem load_dem(const Options& o, std::ostream& err);

// The stage statistics as a JSON object (--stats-json).
std::string stats_json(const StageStats& s);

// Throws Error unless `path` names a GeoTIFF (.tif, .tiff).
void require_geotiff(const std::string& path);

}  // namespace tsk::cli
