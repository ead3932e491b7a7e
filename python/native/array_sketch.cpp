#include "python/native/array_sketch.h"

#include <cmath>

#include "cli/command_support.h"
#include "cli/dem_note_text.h"
#include "cli/options.h"
#include "core/method/strokes.h"

namespace tsk::python {
namespace {

// Takes a stroke's attributes in output order (set_stroke_attributes) into the columns.
struct ColumnRow {
  StrokeColumns& columns;
  void set(int, const char* text) { columns.classes.emplace_back(text); }
  void set(int, std::int64_t value) { columns.cells.push_back(value); }
  void set(int field, double value) {
    columns.reals[static_cast<std::size_t>(field - 2)].push_back(value);
  }
};

void add_stroke(const Stroke& stroke, StrokeColumns& columns) {
  for (const StrokePoint& point : stroke.points) {
    columns.x.push_back(point.x);
    columns.y.push_back(point.y);
  }
  columns.m.insert(columns.m.end(), stroke.weights.begin(), stroke.weights.end());
  columns.offsets.push_back(static_cast<std::int64_t>(columns.x.size()));
  ColumnRow row{columns};
  set_stroke_attributes(row, stroke);
}

// The DEM of an array; a refusal words its remedy with the keywords, not GDAL's tools.
io::DemFile array_dem(const io::MemoryBand& band, const io::MemoryRasterInfo& info,
                      const io::DemOptions& options) {
  try {
    return io::DemFile(io::wrap_memory_raster(band, info), "array", options);
  } catch (const io::DemRefused& refused) {
    throw Error(cli::refusal_text(refused, cli::DemOrigin::array));
  }
}

}  // namespace

StrokeColumns sketch_array(const io::MemoryBand& band, const io::MemoryRasterInfo& info,
                           const std::vector<std::string>& options, const ProgressFn& progress,
                           std::ostream& err) {
  const cli::Options o = cli::parse_choices("silhouettes", options);
  const io::DemFile dem = array_dem(band, info, o.dem);
  cli::print_notes(dem.info().notes, err, cli::DemOrigin::array);
  StrokeColumns columns;
  columns.measured = o.params.strokes.drawn();
  columns.crs_wkt = dem.info().srs_wkt;
  for (const StrokeRealField& field : stroke_real_fields()) {
    columns.real_names.emplace_back(field.name);
    columns.reals.emplace_back();
  }
  // The same recipe as the silhouettes command's without a preview: strip by strip.
  const SilhouetteResult result =
      sketch_silhouettes(dem.source(), o.params, static_cast<std::size_t>(o.strips), progress,
                         [&columns](Stroke&& stroke) { add_stroke(stroke, columns); });
  cli::print_filter(result.filter, err);
  cli::print_averaging(o.params.strokes.scale, dem.info().grid, result.averaged, err);
  cli::print_empty_run(result.stats, o.params, err, cli::DemOrigin::array);
  columns.statistics = cli::stats_json(result.stats, result.filter);
  return columns;
}

}  // namespace tsk::python
