// terrain-sketch silhouettes: the strokes, written as they complete.
#include <cmath>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/dem_note_text.h"
#include "cli/interrupt.h"
#include "core/base/stage_timing.h"
#include "core/drawn/drawing_scale.h"
#include "core/method/run_note.h"
#include "io/pages/preview.h"
#include "io/read/page_heights.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {
namespace {

void print_timings(const StageTimings& t, double write_s, double commit_s, std::ostream& err) {
  err << "timings (s): read " << t.reading << " (alongside the stages), visibility " << t.visibility
      << ", candidates " << t.candidates << ", filter " << t.filter << ", thinning " << t.thinning
      << ", chaining " << t.chaining << ", strokes " << t.strokes << ", write " << write_s
      << " (alongside the stages) + " << commit_s << " (spatial index, commit)\n";
}

// The preview's page, its strokes laid out during the run, finished with the run's reference
// height.
io::PlotterReport write_preview(const Options& o, const SilhouetteResult& result,
                                io::SketchLayout& layout, const std::string& note,
                                const ProgressFn& progress) {
  io::SketchPage page = layout.take_page(result.z_ref);
  page.description = note;
  return io::write_page(o.preview, page, o.page, progress);
}

// The run in a sentence, for the outputs' metadata.
std::string note_of(const Options& o, const SilhouetteResult& result) {
  RunFacts facts = run_facts(o, result.filter);
  facts.averaged = result.averaged;
  return run_note(facts);
}

// The DEM of a run. For a preview, which draws over the DEM turned to the view, it is held whole
// when it can be; a DEM too large for that is read strip by strip, as without a preview, and its
// page is laid out over the DEM averaged for it (io::page_averaging), so that a DEM of any size
// has a preview.
struct RunDem {
  std::optional<io::HeldDemFile> held;
  std::optional<io::DemFile> file;
  std::optional<io::PageHeights> page;  // a preview's heights when the DEM is not held
  const io::Dem& info() const { return held ? held->dem : file->info(); }
  // The heights, frame and georeferencing that the preview's page is laid out over.
  const HeightGrid& page_grid() const { return page ? page->oriented : held->dem.oriented; }
  const OrientedFrame& page_frame() const { return page ? page->frame : held->dem.frame; }
  const GeoTransform& page_geotransform() const {
    return page ? page->geotransform : held->dem.geotransform;
  }
  std::optional<io::HeightRange> page_averaged() const {
    if (!page) return std::nullopt;
    return io::HeightRange{page->lowest, page->highest};
  }
  SilhouetteResult sketch(const Options& o, const ProgressFn& progress, StrokeSink sink) const {
    if (held) return sketch_held_strokes(held->held(), o.params, progress, std::move(sink));
    return sketch_silhouettes(file->source(), o.params, static_cast<std::size_t>(o.strips),
                              progress, std::move(sink));
  }
};

// Opens the DEM of a run, and reads what a preview draws over, telling `progress` as it does.
void open_run_dem(const Options& o, RunDem& dem, std::ostream& err, const ProgressFn& progress) {
  if (!o.preview.empty()) {
    io::DemOptions size_only = o.dem;
    size_only.sample_range = false;  // the grid is all that the choice needs
    const DemGrid grid = io::DemFile(o.input, size_only).info().grid;
    const std::size_t factor = io::page_averaging(grid, o.params.view.azimuth_deg);
    if (factor == 1) {
      dem.held.emplace(load_dem(o, err));
      return;
    }
    dem.file.emplace(o.input, o.dem);
    print_notes(dem.info().notes, err);
    err << "note: the preview is laid out over the DEM averaged " << factor << " x " << factor
        << " cells (" << dem.info().cols << " x " << dem.info().rows
        << " cells turned whole would take more than half of the memory), read first; the "
           "strokes are drawn from its own cells\n";
    dem.page.emplace(io::read_page_heights(*dem.file, o.params.view.azimuth_deg, factor, progress));
    return;
  }
  dem.file.emplace(o.input, o.dem);
  print_notes(dem.info().notes, err);
}

// A scale rounded to two significant figures, as map scales are given (1:547 312 is 1:550 000).
double round_scale(double scale) {
  const double unit = std::pow(10.0, std::floor(std::log10(scale)) - 1.0);
  return std::round(scale / unit) * unit;
}

// Strokes drawn for the DEM's own scale (0.4 mm a cell) crowd into a grey texture on a preview
// at a much smaller scale. A page states the map's scale: drawn strokes without --drawn-for are
// drawn for it, in the vector output too, since both show one sketch. A picture without a page
// size states none, so a warning names what to give. A page the sketch does not fit at the
// scale asked for is refused here, before the run.
void fit_strokes_to_preview(Options& o, const RunDem& dem, std::ostream& err) {
  // The preview's scale in map units, as --drawn-for takes it (ground metres per map unit apart).
  const double shown = io::preview_scale(dem.page_grid(), dem.page_frame(), o.params.view, o.page,
                                         dem.page_averaged()) /
                       dem.info().ground_scale;
  if (!o.params.strokes.drawn() || o.params.strokes.scale > 0.0) return;
  const double own = own_scale(dem.info().geotransform);
  if (!std::isfinite(shown) || !(own > 0.0) || !(shown > own)) return;
  if (!o.page.size.empty()) {
    o.params.strokes.scale = o.page.scale > 0.0 ? shown : round_scale(shown);
    err << "note: drawn for the page at 1:" << number_text(o.params.strokes.scale)
        << ", smaller than the DEM's own 1:" << number_text(own)
        << " (0.4 mm a cell), whose strokes would crowd into a grey texture there; --drawn-for "
           "N draws for another scale\n";
  } else if (shown > 2.0 * own) {
    err << "warning: the " << o.page.width_px
        << "-pixel preview shows the sketch at about 1:" << number_text(round_scale(shown))
        << " (96 pixels to the inch), " << std::lround(shown / own)
        << " times smaller than its strokes are drawn for (the DEM's "
        << "own 1:" << number_text(own) << ", 0.4 mm a cell): they crowd into a grey "
        << "texture there. --page SIZE draws them for a page, --drawn-for N for a map at 1:N\n";
  }
}

void print_plotter(const io::PlotterReport& r, bool millimetres, std::ostream& err) {
  const char* unit = millimetres ? " mm" : " px";
  err << "plotter: " << r.strokes << " strokes drawn as " << r.paths << " paths; pen-up travel "
      << std::lround(r.travel_before) << unit << " in the strokes' order, "
      << std::lround(r.travel_after) << unit << " ordered\n";
}

}  // namespace

std::string silhouettes(const Args& args, std::ostream& out, std::ostream& err,
                        const ProgressFn& progress) {
  Options o = parse("silhouettes", args);
  print_lost_weights(o, io::check_vector_output(o.output, o.format), err);  // before any work
  RunDem dem;
  open_run_dem(o, dem, err, progress);
  // Strokes are written as they complete, so they are never all held; the preview keeps their
  // paths on its page, laid out stroke by stroke as the run hands them on.
  std::optional<io::SketchLayout> layout;
  if (!o.preview.empty()) {
    fit_strokes_to_preview(o, dem, err);
    layout.emplace(dem.page_grid(), dem.page_frame(), dem.page_geotransform(), o.params.view,
                   o.params.geometry, o.page, dem.page_averaged());
  }
  SilhouetteResult result;
  io::PlotterReport plotter;
  double write_s = 0;
  Clock::time_point produced;
  std::string note;  // the run in a sentence, once it is made
  io::write_strokes(
      o.output, o.format, dem.info().srs_wkt,
      [&](const io::StrokeWriter& write) {
        result = dem.sketch(o, progress, [&](Stroke&& stroke) {
          // Two clock readings a stroke only when asked: 1.3 % of an exact run's time.
          const Clock::time_point start = o.timings ? Clock::now() : Clock::time_point();
          write(stroke);
          if (o.timings) write_s += seconds_since(start);
          if (layout) layout->add(stroke);
        });
        produced = Clock::now();
        note = note_of(o, result);
      },
      io::kStrokeLayer, o.params.strokes.drawn(), [&] { return note; });
  const double commit_s = seconds_since(produced);
  // All three go in place together when the run has done (io/write/output_set.h).
  stop_if_interrupted();
  const std::string statistics = report_statistics(o, result.stats, result.filter);
  if (layout) plotter = write_preview(o, result, *layout, note, progress);
  print_filter(result.filter, err);
  print_averaging(o.params.strokes.scale, dem.info().grid, result.averaged, err);
  print_empty_run(result.stats, o.params, err);
  if (o.page.plotter) print_plotter(plotter, !o.page.size.empty(), err);
  if (o.timings) print_timings(result.timings, write_s, commit_s, err);
  const StageStats& s = result.stats;
  out << o.output << ": " << s.factual_strokes << " factual and " << s.formulated_strokes
      << " formulated strokes (c-set " << s.pct(s.candidate) << " %, f-set " << s.pct(s.filtered)
      << " %, t-set " << s.pct(s.thinned) << " %, g-set " << s.pct(s.generalised) << " %)\n";
  return statistics;
}

}  // namespace tsk::cli
