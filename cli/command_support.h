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

// The parameters for a run on a DEM read whole by load_dem: the filter adapted to the DEM (read
// once more, window by window), told on `err`, with what it used in `report`.
SilhouetteParams adapt_filter_to(const Options& o, const io::Dem& dem, FilterReport& report,
                                 std::ostream& err);

// Tells on `err` which cut-offs an adaptive filter chose, and why.
void print_filter(const FilterReport& report, std::ostream& err);

// The stage statistics and the filter used as a JSON object (--stats-json).
std::string stats_json(const StageStats& s, const FilterReport& filter);

// Throws Error unless `path` names a GeoTIFF (.tif, .tiff).
void require_geotiff(const std::string& path);

}  // namespace tsk::cli
