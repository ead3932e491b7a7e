// What the commands share: reading the DEM with its notes, small text outputs, the statistics.
#pragma once

#include <ostream>
#include <string>

#include "cli/dem_note_text.h"
#include "cli/options.h"
#include "core/method/run_note.h"
#include "core/method/silhouettes.h"
#include "io/read/dem_reader.h"

namespace tsk::cli {

// Reads the DEM whole for the view (io::hold_dem) and tells the user, on `err`, what they should
// know about it.
io::HeldDemFile load_dem(const Options& o, std::ostream& err);

// Every stage on the DEM held whole (sketch_held_dem), the filter it used told on `err`.
SilhouetteResult sketch_whole(const Options& o, const io::HeldDemFile& dem,
                              const ProgressFn& progress, std::ostream& err);

// Tells on `err` which cut-offs an adaptive filter chose, and why.
void print_filter(const FilterReport& report, std::ostream& err);

// Drawn for 1:scale far coarser than the DEM (`grid`): says that the DEM was averaged `averaged`
// cells a side first (SilhouetteResult::averaged; nothing when 1).
void print_averaging(double scale, const DemGrid& grid, std::size_t averaged, std::ostream& err);

// A run that drew no stroke at all (empty_run): says on `err` which stage left nothing, and what
// to change; nothing when it drew strokes.
void print_empty_run(const StageStats& stats, const SilhouetteParams& params, std::ostream& err,
                     DemOrigin origin = DemOrigin::file);

// Drawn strokes to a format that keeps no M values (io::keeps_m_values): says on `err` that
// their weights are lost, and which formats keep them.
void print_lost_weights(const Options& o, const std::string& driver, std::ostream& err);

// The DEM as the outputs' notes name it: its file's name.
std::string dem_name(const Options& o);

// What the outputs' notes say of the run (run_note.h): the DEM by its file's name and its band,
// the view, `filter` where one ran, the strokes' mode and scale, and the version.
RunFacts run_facts(const Options& o, const FilterReport& filter = {});

// The stage statistics and the filter used as a JSON object (--stats-json).
std::string stats_json(const StageStats& s, const FilterReport& filter);

// The run's statistics as JSON (stats_json), also written to --stats-json when it was given:
// what the commands that count return.
std::string report_statistics(const Options& o, const StageStats& s, const FilterReport& filter);

// Throws Error unless `path` names a GeoTIFF (.tif, .tiff).
void require_geotiff(const std::string& path);

// Throws Error unless `path` names an HTML page (.html, .htm).
void require_html(const std::string& path);

}  // namespace tsk::cli
