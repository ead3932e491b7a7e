// terrain-sketch panorama: the silhouettes seen from a viewpoint (docs/PANORAMA.md), on the map
// and in the panorama, with the visibility raster and a preview.
#include <cpl_conv.h>
#include <gdal.h>

#include <future>
#include <optional>
#include <ostream>
#include <string>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/dem_note_text.h"
#include "cli/interrupt.h"
#include "core/base/errors.h"
#include "core/base/stage_timing.h"
#include "core/panorama/panorama.h"
#include "io/pages/panorama_page.h"
#include "io/pages/preview.h"
#include "io/read/named_points.h"
#include "io/write/raster_writer.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {
namespace {

// Wall seconds of a panorama's steps, each after the one before, for --timings.
struct PanoramaTimes {
  double read = 0, peaks = 0, strokes = 0, visibility = 0, preview = 0;
};

void print_timings(const PanoramaTimes& t, const PanoramaRun& run, std::ostream& err) {
  err << "timings (s): read " << t.read << ", survey " << run.survey_seconds << ", rays "
      << run.rays_seconds << ", peaks " << t.peaks << ", write strokes " << t.strokes
      << ", visibility " << t.visibility << ", preview " << t.preview << "\n";
}

// Everything that can be refused before the DEM is read.
void check_before_work(const Options& o) {
  if (!o.observer_given)
    throw UsageError("panorama needs --observer X,Y: where the viewer stands, in the DEM's CRS");
  const std::string driver = io::check_vector_output(o.output, o.format);
  if (driver != "GPKG" && driver != "SQLite")
    throw UsageError(
        "a panorama's strokes go in two layers (map and panorama): name OUTPUT .gpkg or "
        ".sqlite");
  if (!o.visibility.empty()) require_geotiff(o.visibility);
}

// The DEM as it lies, read whole: the view from the west is its own grid, unturned.
io::HeldDemFile read_whole_dem(const Options& o, std::ostream& err) {
  // Read once, block row after block row, into a grid held whole: GDAL's cache would only hold
  // a second copy of some of it, at the peak of memory. Keep it small unless the user chose one.
  if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(16 << 20);
  io::HeldDemFile dem = io::hold_dem(o.input, o.dem, 90.0);
  print_notes(dem.dem.notes, err);
  return dem;
}

// The outputs, put in place together when the run has done (io/write/output_set.h).
void write_outputs(const Options& o, const io::Dem& dem, const PanoramaRun& run,
                   const std::vector<PeakLeader>& leaders, const ProgressFn& progress,
                   PanoramaTimes& times, std::ostream& err) {
  const PanoramaResult& result = run.result;
  const std::vector<PeakLeader>* peaks = o.peaks.empty() ? nullptr : &leaders;
  const std::string note =
      panorama_note(dem_name(o), o.dem.band, o.panorama, run.exaggeration, TSK_VERSION);
  add_wall_time(times.strokes, [&] {
    io::write_panorama_strokes(o.output, o.format, result.strokes, dem.srs_wkt, peaks,
                               run.exaggeration, note);
  });
  err << "note: the panorama layer draws its elevation angles " << elevation_drawn(run.exaggeration)
      << " (--panorama-exaggeration)\n";
  stop_if_interrupted();
  if (!o.visibility.empty()) {
    add_wall_time(times.visibility, [&] {
      io::write_visibility(
          o.visibility,
          // The progress line is full by now: what `progress` does here is stop on Ctrl-C.
          visibility_raster(result, dem.rows, dem.cols, dem.geotransform, o.params.threads,
                            progress),
          dem.geotransform, dem.srs_wkt, note);
    });
  }
  if (!o.preview.empty()) {
    double exaggeration = 1.0;
    add_wall_time(times.preview, [&] {
      const io::PanoramaPage page = lay_out_panorama(result, o.params.strokes, o.page, leaders);
      io::write_page(o.preview, page.page, o.page, progress);
      exaggeration = page.exaggeration;
    });
    err << "note: the preview's elevation angles are drawn " << elevation_drawn(exaggeration)
        << "\n";
  }
}

}  // namespace

std::string panorama(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress) {
  const Options o = parse("panorama", args);
  check_before_work(o);
  PanoramaTimes times;
  std::optional<io::HeldDemFile> held;
  add_wall_time(times.read, [&] { held.emplace(read_whole_dem(o, err)); });
  const io::Dem& dem = held->dem;
  // The peaks are read before the work, so that a bad file is refused first.
  std::vector<NamedPoint> peaks;
  if (!o.peaks.empty())
    add_wall_time(times.peaks,
                  [&] { peaks = io::read_named_points(o.peaks, o.peak_names, dem.srs_wkt); });
  const PanoramaChoice choice{o.panorama, o.params, !o.visibility.empty()};
  const PanoramaRun run = sketch_panorama_on(held->held(), choice, progress);
  const PanoramaResult& result = run.result;
  print_filter(run.filter, err);
  std::vector<PeakLeader> leaders;
  add_wall_time(times.peaks, [&] {
    leaders = lead_peaks(result, see_peaks(dem.oriented, dem.geotransform, result.rays, peaks));
  });
  // The outputs need the DEM's grid and georeferencing, not its heights: freed, they make room
  // for the visibility raster. Freed alongside the writing: giving a large DEM's pages back takes
  // the kernel a while (the future waits for it, whatever happens).
  HeightGrid heights = std::move(held->dem.oriented);
  held->dem.oriented = HeightGrid();
  const std::future<void> freed =
      std::async(std::launch::async, [&heights] { heights = HeightGrid(); });
  write_outputs(o, dem, run, leaders, progress, times, err);
  if (o.timings) print_timings(times, run, err);
  const std::string statistics = report_statistics(o, result.stats, run.filter);
  const StageStats& s = result.stats;
  out << o.output << ": " << s.factual_strokes << " factual and " << s.formulated_strokes
      << " formulated strokes from " << result.rays.rays << " rays of " << result.rays.samples
      << " samples (hidden " << s.pct(s.hidden) << " %, c-set " << s.pct(s.candidate)
      << " %, f-set " << s.pct(s.filtered) << " %, t-set " << s.pct(s.thinned) << " %)\n";
  if (!o.peaks.empty())
    out << leaders.size() << " of the " << peaks.size() << " peaks are in sight, labelled\n";
  return statistics;
}

}  // namespace tsk::cli
