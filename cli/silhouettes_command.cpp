// terrain-sketch silhouettes: the strokes, written as they complete.
#include <chrono>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

#include "command_support.h"
#include "commands.h"
#include "interrupt.h"
#include "preview.h"
#include "vector_writer.h"

namespace tsk::cli {

int silhouettes(const Args& args, std::ostream& out, std::ostream& err,
                const ProgressFn& progress) {
  const Options o = parse(args);
  io::check_vector_output(o.output, o.format);  // before any work
  // The preview draws the whole turned grid, so it needs the DEM whole (read_dem refuses one too
  // large to hold).
  const bool whole = !o.preview.empty();
  if (whole && o.strips > 0) throw Error("--preview needs the whole DEM in memory; drop --strips");
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  double read_s = 0, write_s = 0;
  io::Dem dem;
  std::unique_ptr<io::DemStripReader> reader;
  if (whole) {
    const auto start = Clock::now();
    dem = load_dem(o, err);
    read_s = since(start);
  } else {
    reader = std::make_unique<io::DemStripReader>(o.input, o.dem, o.params.threads);
    dem = reader->info();
    if (!dem.notes.empty()) err << "note: " << dem.notes;
  }
  // Strokes are written as they complete, so they are never all held (but for the preview).
  SilhouetteResult result;
  std::vector<Stroke> drawn;
  Clock::time_point produced;
  io::write_strokes(o.output, o.format, dem.srs_wkt, [&](const io::StrokeWriter& write) {
    const StrokeSink sink = [&](Stroke&& stroke) {
      const auto start = Clock::now();
      write(stroke);
      write_s += since(start);
      if (whole) drawn.push_back(std::move(stroke));
    };
    if (whole) {
      SilhouetteStream stream(dem.frame, dem.geotransform, o.params, dem.lowest_height, progress,
                              sink);
      stream.add_strip(dem.oriented, 0, dem.frame.profiles, true);
      result = stream.finish();
    } else {
      // Strips bound the memory, and they are faster than the whole DEM: the next strip is read
      // while the stages work on this one, into memory reused from strip to strip rather than a
      // DEM's worth of fresh pages.
      const double z_ref = o.params.geometry == Geometry::oblique ? reader->lowest_height() : 0.0;
      const std::size_t strip =
          o.strips > 0 ? static_cast<std::size_t>(o.strips) : strip_profiles(dem.frame);
      result = run_in_strips(
          dem.frame, dem.geotransform, o.params, z_ref, strip,
          [&](std::size_t first, std::size_t count, HeightGrid& heights) {
            const auto start = Clock::now();
            reader->read_profiles(first, count, heights);
            read_s += since(start);
          },
          progress, sink);
    }
    stop_if_interrupted();  // the last chance to stop with nothing written
    // The statistics and the preview go out before the strokes are committed, so that a failure
    // to write them discards the strokes too.
    if (!o.stats_json.empty()) write_text(o.stats_json, stats_json(result.stats));
    if (whole) {
      result.strokes = std::move(drawn);
      io::write_preview(o.preview, result, dem.oriented, dem.frame, o.params.view);
    }
    produced = Clock::now();
  });
  if (o.timings) {
    const StageTimings& t = result.timings;
    err << "timings (s): read " << read_s << (whole ? "" : " (alongside the stages)")
        << ", visibility " << t.visibility << ", candidates " << t.candidates << ", filter "
        << t.filter << ", thinning " << t.thinning << ", chaining " << t.chaining << ", strokes "
        << t.strokes << ", write " << write_s << " (alongside the stages) + " << since(produced)
        << " (spatial index, commit)\n";
  }
  const StageStats& s = result.stats;
  out << o.output << ": " << s.factual_strokes << " factual and " << s.formulated_strokes
      << " formulated strokes (c-set " << s.pct(s.candidate) << " %, f-set " << s.pct(s.filtered)
      << " %, t-set " << s.pct(s.thinned) << " %, g-set " << s.pct(s.generalised) << " %)\n";
  return 0;
}

}  // namespace tsk::cli
