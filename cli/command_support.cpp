#include "cli/command_support.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "cli/dem_note_text.h"
#include "core/base/errors.h"
#include "core/drawn/drawing_scale.h"
#include "io/write/output_files.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {

io::HeldDemFile load_dem(const Options& o, std::ostream& err) {
  io::HeldDemFile dem = io::hold_dem(o.input, o.dem, o.params.view.azimuth_deg);
  print_notes(dem.dem.notes, err);
  return dem;
}

SilhouetteResult sketch_whole(const Options& o, const io::HeldDemFile& dem,
                              const ProgressFn& progress, std::ostream& err) {
  SilhouetteResult result = sketch_held_dem(dem.held(), o.params, progress);
  print_filter(result.filter, err);
  return result;
}

std::string dem_name(const Options& o) {
  return std::filesystem::path(o.input).filename().string();
}

RunFacts run_facts(const Options& o, const FilterReport& filter) {
  return {dem_name(o),
          o.dem.band,
          o.params.view,
          filter,
          o.params.strokes.drawn(),
          TSK_VERSION,
          o.params.strokes.scale};
}

void print_averaging(double scale, const DemGrid& grid, std::size_t averaged, std::ostream& err) {
  if (averaged <= 1) return;
  const auto old_precision = err.precision(4);
  err << "note: drawn for 1:" << number_text(scale) << ", the DEM was averaged " << averaged
      << " x " << averaged << " cells first (to "
      << std::min(grid.dx, grid.dy) * static_cast<double>(averaged)
      << " m a cell, about 0.4 mm on paper): the scale shows nothing finer\n";
  err.precision(old_precision);
}

void print_lost_weights(const Options& o, const std::string& driver, std::ostream& err) {
  if (!o.params.strokes.drawn() || io::keeps_m_values(driver)) return;
  err << "note: " << driver << " keeps no M values, so the drawn strokes' weights (their taper "
      << "and depth, which the styles draw) are left out; .gpkg, .fgb, .shp or .csv keep them\n";
}

void print_empty_run(const StageStats& stats, const SilhouetteParams& p, std::ostream& err,
                     DemOrigin origin) {
  const EmptyRun cause = empty_run(stats);
  if (cause == EmptyRun::not_empty) return;
  const auto old_precision = err.precision(3);
  err << "warning: no strokes: ";
  if (cause == EmptyRun::no_valid_cell && origin == DemOrigin::array) {
    err << "every height of the array is nodata (NaN, masked, or the value given as nodata=)\n";
  } else if (cause == EmptyRun::no_valid_cell) {
    err << "every cell of the DEM is nodata (its declared nodata value, NaN, or a height of 1e30 "
           "or more): check --band, the nodata value the file declares (gdal_edit.py -a_nodata or "
           "-unsetnodata), and the band's scale\n";
  } else if (cause == EmptyRun::nothing_seen) {
    err << "no cell of the DEM is hidden, and none slopes away from the viewer gently enough to "
           "be seen once tilted (under the base slope of "
        << p.view.base_slope_pct << " % over the exaggeration of " << p.view.ve << ", "
        << p.view.base_slope_pct / p.view.ve
        << " %): the DEM is flat, or faces the viewer everywhere. Another --azimuth or a larger "
           "--base-slope brings slopes into sight\n";
  } else if (cause == EmptyRun::all_filtered) {
    err << "the slope filter removed every candidate cell (c-set " << stats.pct(stats.candidate)
        << " % of the cells), and no cell is hidden. Lower cut-offs (--row-cut, --col-cut, "
           "--ctrl) keep more"
        << (p.adaptive.mode == FilterMode::fixed ? ", or --filter adaptive scales them" : "")
        << "\n";
  } else {
    err << "every chain was shorter than the shortest stroke kept (--min-cells "
        << p.chain.min_cells << ")";
    if (p.strokes.drawn() && p.strokes.scale > 0.0) {
      err << "; drawn for 1:" << number_text(p.strokes.scale) << ", strokes under "
          << kLeastStrokeMm << " mm on paper, or outlining under "
          << number_text(p.strokes.scale / kFullReliefPerScale * kVanishingShare)
          << " m of relief, are dropped too. A larger scale (a smaller N) keeps more\n";
    } else {
      err << ". A lower --min-cells keeps more\n";
    }
  }
  err.precision(old_precision);
}

void print_filter(const FilterReport& r, std::ostream& err) {
  if (r.choice.mode == FilterMode::fixed) return;
  const FilterParams& c = r.cutoffs;
  const auto old_precision = err.precision(3);
  err << "note: adaptive slope filter: ";
  if (std::isfinite(r.median_slope_pct)) {
    err << "median slope " << r.median_slope_pct << " % against " << kReferenceSlopePct
        << " % on the thesis's terrain, so the cut-offs are scaled by " << r.scale;
  } else {
    err << "no cell slopes (the DEM is flat, or too few of its cells are valid), so the cut-offs "
           "are scaled by the least, "
        << r.scale;
  }
  err << ": row " << c.row_cut_pct << " %, column " << c.col_cut_pct << " %, control point "
      << c.ctrl_col_pct << " % (--filter fixed keeps 20, 12, 8.75)\n";
  if (r.choice.adapt == Adaptivity::local) {
    err << "note: local adaptivity over " << r.choice.window << " cells scales them from "
        << r.local_lowest << " to " << r.local_highest << " times the thesis's\n";
  }
  err.precision(old_precision);
}

namespace {

// The figures of a JSON object, one a line, each line but the last ending with a comma.
void json_number(std::ostream& j, const char* key, double value, const char* indent = "  ") {
  j << ",\n" << indent << "\"" << key << "\": ";
  if (std::isfinite(value)) {
    j << value;
  } else {
    j << "null";
  }
}

void filter_json(std::ostream& j, const FilterReport& r) {
  j << ",\n  \"filter\": {\n    \"mode\": \""
    << (r.choice.mode == FilterMode::adaptive ? "adaptive" : "fixed") << "\",\n    \"adapt\": \""
    << (r.choice.adapt == Adaptivity::local ? "local" : "whole") << "\"";
  const char* in = "    ";
  json_number(j, "row_cut_pct", r.cutoffs.row_cut_pct, in);
  json_number(j, "col_cut_pct", r.cutoffs.col_cut_pct, in);
  json_number(j, "ctrl_col_pct", r.cutoffs.ctrl_col_pct, in);
  json_number(j, "ctrl_row_pct", r.cutoffs.ctrl_row_pct(), in);
  json_number(j, "scale", r.scale, in);
  json_number(j, "median_slope_pct", r.median_slope_pct, in);
  json_number(j, "reference_slope_pct", kReferenceSlopePct, in);
  json_number(j, "height_quantum", r.heights.quantum, in);
  json_number(j, "height_tolerance", r.heights.tolerance, in);
  if (r.choice.adapt == Adaptivity::local) {
    json_number(j, "window_cells", r.choice.window, in);
    json_number(j, "local_scale_lowest", r.local_lowest, in);
    json_number(j, "local_scale_highest", r.local_highest, in);
  }
  j << "\n  }";
}

}  // namespace

std::string stats_json(const StageStats& s, const FilterReport& filter) {
  std::ostringstream j;
  j.precision(6);
  j << std::fixed << "{\n  \"valid_cells\": " << s.valid;
  for (const StageFigure& f : stage_figures(s)) {
    if (f.is_count) {
      j << ",\n  \"" << f.key << "\": " << static_cast<long long>(f.value);
    } else {
      json_number(j, f.key, f.value);
    }
  }
  filter_json(j, filter);
  j << "\n}\n";
  return j.str();
}

std::string report_statistics(const Options& o, const StageStats& s, const FilterReport& filter) {
  std::string statistics = stats_json(s, filter);
  if (!o.stats_json.empty()) io::write_text_file(o.stats_json, statistics);
  return statistics;
}

void require_geotiff(const std::string& path) {
  const std::string ext = io::lowercase_extension(path);
  if (ext != ".tif" && ext != ".tiff")
    throw UsageError("the output raster must be a GeoTIFF (.tif)");
}

void require_html(const std::string& path) {
  const std::string ext = io::lowercase_extension(path);
  if (ext != ".html" && ext != ".htm")
    throw UsageError("the output is an HTML page: give it an .html name, got '" + path + "'");
}

}  // namespace tsk::cli
