#include "python/native/band_runs.h"

#include "cli/command_support.h"
#include "cli/dem_note_text.h"
#include "cli/options.h"
#include "core/base/byte_stream.h"
#include "core/drawn/drawn_strokes.h"
#include "core/method/averaged_dem.h"
#include "core/method/run_note.h"
#include "io/write/vector_writer.h"

namespace tsk::python {

// The options of a run in bands: the silhouettes command's, but what it cannot take.
cli::Options band_options(const std::vector<std::string>& options) {
  const cli::Options o = cli::parse_choices("silhouettes", options);
  if (o.params.adaptive.mode == FilterMode::adaptive &&
      o.params.adaptive.adapt == Adaptivity::local)
    throw cli::UsageError("a run in bands adapts the filter to the whole DEM, not locally");
  if (!o.preview.empty() || !o.stats_json.empty() || o.timings)
    throw cli::UsageError("a run in bands writes OUTPUT only: no preview, stats_json or timings");
  return o;
}

io::DemOptions task_dem(const cli::Options& o) {
  io::DemOptions dem = o.dem;
  dem.sample_range = false;
  return dem;
}

TaskDem::TaskDem(const std::string& input, const cli::Options& o)
    : TaskDem(input, o, task_dem(o)) {}

TaskDem::TaskDem(const std::string& input, const cli::Options& o, const io::DemOptions& opened)
    : file_(input, opened),
      averaged_(run_averaging(o.params, file_.info().grid, file_.info().geotransform)),
      file_source_(file_.source()),
      source_(averaged_dem(file_source_, averaged_)) {}

namespace {

// The run's options and paths as the silhouettes command parses them, after refusing what a run
// in bands cannot take (before the paths, as the command checks its options first).
cli::Options band_run(const std::string& input, const std::string& output,
                      const std::vector<std::string>& options) {
  band_options(options);
  std::vector<std::string> args = {input, output};
  args.insert(args.end(), options.begin(), options.end());
  return cli::parse("silhouettes", args);
}

}  // namespace

BandPlan plan_bands(const std::string& input, const std::string& output,
                    const std::vector<std::string>& options, std::ostream& err) {
  const cli::Options o = band_run(input, output, options);
  cli::print_lost_weights(o, io::check_vector_output(o.output, o.format), err);
  const TaskDem dem(o.input, o, o.dem);  // with a sample of its range, for the notes
  cli::print_notes(dem.info().notes, err);
  const OrientedFrame frame = make_frame(dem.source().grid, o.params.view.azimuth_deg);
  const bool survey = o.params.adaptive.mode == FilterMode::adaptive;
  o.params.validate();
  return {frame.profiles,
          survey ? std::string() : filter_report_bytes(ResolvedParams(o.params).filter()), survey,
          o.params.geometry == Geometry::oblique, dem.source().grid.rows};
}

double lowest_height_of(const std::string& input, const std::vector<std::string>& options,
                        std::size_t first_row, std::size_t rows) {
  const cli::Options o = band_options(options);
  const TaskDem dem(input, o);
  const DemGrid& grid = dem.source().grid;
  if (first_row > grid.rows || rows > grid.rows - first_row)
    throw Error("rows " + std::to_string(first_row) + " + " + std::to_string(rows) +
                " do not lie in the DEM's " + std::to_string(grid.rows));
  return lowest_height_of_rows(first_row, rows, grid.cols, dem.source().read);
}

std::string sketch_band_bytes(const std::string& input, const std::vector<std::string>& options,
                              const std::string& filter, double z_ref, std::size_t first,
                              std::size_t count, std::size_t halo, const std::string& order) {
  const cli::Options o = band_options(options);
  const ResolvedParams params = resolve_as_reported(o.params, filter_report_from_bytes(filter));
  const TaskDem dem(input, o);
  BandSpec spec{first, count, std::nullopt, halo};
  if (!order.empty()) spec.order = orders_from_bytes(order);
  return band_bytes(sketch_band(dem.source(), params, spec, z_ref));
}

std::string stitch_bands(const std::string& input, const std::string& output,
                         const std::vector<std::string>& options, const std::string& filter,
                         double z_ref, std::size_t profiles, const BandSource& bands,
                         std::ostream& err) {
  const cli::Options o = band_run(input, output, options);
  const ResolvedParams params = resolve_as_reported(o.params, filter_report_from_bytes(filter));
  const TaskDem dem(o.input, o);  // its CRS, and the grid sketched for the drawing
  const bool drawn = params->strokes.drawn();
  std::optional<DrawingSetup> drawing;
  if (drawn) {
    const OrientedFrame frame = make_frame(dem.source().grid, params->view.azimuth_deg);
    drawing = drawing_setup(frame, dem.source().geotransform, params.params(), z_ref);
  }
  SilhouetteResult result;
  io::write_strokes(
      o.output, o.format, dem.info().srs_wkt,
      [&](const io::StrokeWriter& write) {
        BandStitcher stitcher(
            params, [&write](Stroke&& stroke) { write(stroke); }, drawing);
        const auto again = [&bands](std::size_t first, std::size_t count, const BandOrders& order) {
          return band_from_bytes(bands.again(first, count, orders_bytes(order)).bytes);
        };
        for (BandBytes band = bands.next(); !band.bytes.empty(); band = bands.next())
          stitcher.add(band_from_bytes(band.bytes), again);
        result = stitcher.finish(profiles);
      },
      io::kStrokeLayer, drawn,
      [&] {
        RunFacts facts = cli::run_facts(o, result.filter);
        facts.averaged = dem.averaged();
        return run_note(facts);
      });
  cli::print_filter(result.filter, err);
  cli::print_averaging(o.params.strokes.scale, dem.info().grid, dem.averaged(), err);
  cli::print_empty_run(result.stats, o.params, err);
  return cli::stats_json(result.stats, result.filter);
}

}  // namespace tsk::python
