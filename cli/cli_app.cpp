#include "cli_app.h"

#include <cpl_conv.h>
#include <gdal.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <utility>

#include "dem_reader.h"
#include "gdal_util.h"
#include "interrupt.h"
#include "output_files.h"
#include "preview.h"
#include "raster_writer.h"
#include "silhouettes.h"
#include "terrain_sketch.h"
#include "vector_writer.h"

namespace tsk::cli {
namespace {

const char* const kUsage = R"(usage: terrain-sketch COMMAND INPUT OUTPUT [options]
       terrain-sketch --version

commands:
  silhouettes   Factual and Formulated Silhouettes as vector strokes (OUTPUT: vector)
  profiles      the profile plot: cross-sections across the view in plan-oblique geometry,
                hidden parts removed, every --every N cells (OUTPUT: vector)
  classify      per-cell stage of the method (visible, hidden, occluding, c-set, f-set,
                t-set) on the DEM grid, with a colour table (OUTPUT: GeoTIFF)
  row-slope     |slope across the line of sight| in percent on the DEM grid (OUTPUT: GeoTIFF)
  pstrokes      the P-stroke sketch: short strokes across the view where profiles along or
                across it bend (Visvalingam effective areas), kept out of the f-set (OUTPUT: vector)
  drape         project --source RASTER (on the DEM's grid, all bands: a hillshade, a slope
                map, an image) into plan-oblique space, hidden areas removed (OUTPUT: GeoTIFF)
  filter-plot   column against row slope with the c-set and the slope filter's removal region,
                to tune the control point (OUTPUT: HTML page with an SVG diagram)

INPUT is any raster GDAL reads (heights in metres, a projected CRS in metres);
a vector OUTPUT is any OGR format, chosen by extension (.gpkg, .shp, .geojson, .fgb, ...).
Outputs are written whole or not at all and replace an earlier output of the same name; the
input, and a GeoPackage holding anything else (a raster, other layers), are refused.

view:
  --azimuth DEG        bearing the viewer faces, clockwise from north (default 90: from the
                       west); 0, 90, 180, 270 are exact, others resample the DEM
  --ve X               vertical exaggeration, > 0 (default 2.5)
  --base-slope PCT     base slope added along the line of sight, percent (default 40)
slope filter:
  --row-cut PCT        row slope cut-off, percent (default 20)
  --col-cut PCT        column slope cut-off, percent (default 12)
  --ctrl PCT           column slope of the control point, percent (default 8.75)
  --no-diagonals       remove the whole rectangle below both cut-offs
strokes:
  --window N           formulated chaining search window, cells (default 3)
  --min-cells N        drop strokes with fewer cells (default 3)
  --placement P        far (default) or near_and_far: which end of an f-set zone to keep
  --subcell            place factual points at the sub-cell peak of the profile
  --geometry G         map (cell centres) or oblique (plan oblique sketch) (default map)
input and output:
  --band N             raster band (default 1)
  --cell-size M        cell size in metres for a raster without georeferencing
  --format DRIVER      OGR driver name, overriding the extension
  --stats-json FILE    write the stage statistics as JSON
  --preview PNG        render the oblique sketch to a PNG picture
  --threads N          worker threads (default: all cores)
  --timings            print the time of reading, each stage and writing to stderr
  --strips N           read and process N profiles at a time (default: 1024, more for profiles
                       under 1024 cells, fewer for profiles so long that strips would pass
                       512 MB; memory is about 9 bytes x cells of N profiles, 13 at a
                       non-cardinal azimuth)
profiles:
  --every N            draw every N-th cross-section (default 10)
pstrokes (tolerances: effective areas in m2 of the profiles' distance-height triangles):
  --convex-column M2   (default 15000)   --concave-column M2  (default 60000)
  --convex-row M2      (default 30000)   --concave-row M2     (default 15000)
  --half-length N      cells drawn each side of a seed across the view (default 1)
drape:
  --source RASTER      the raster to drape, on the DEM's grid
)";

// Parses a whole number or a finite decimal, refusing trailing junk.
double parse_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::out_of_range&) {
    throw Error(option + " got '" + text + "', too large or too small a number");
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0) throw Error(option + " needs a number, got '" + text + "'");
  return value;
}

int parse_int(const std::string& option, const std::string& text) {
  const double value = parse_number(option, text);
  // The range first: converting a double beyond an integer's range is undefined.
  if (!(value >= -1e9 && value <= 1e9) || value != std::trunc(value)) {
    throw Error(option + " needs a whole number from -1000000000 to 1000000000, got '" + text +
                "'");
  }
  return static_cast<int>(value);
}

struct Options {
  std::string input, output, format, stats_json, preview, source;
  bool timings = false;
  int every = 10;
  int strips = 0;
  io::DemOptions dem;
  SilhouetteParams params;
  PStrokeParams pstrokes;
};

// True when paths a and b name one file: the same existing file, or the same path to be made.
bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  const auto full_a = std::filesystem::weakly_canonical(a, ec);
  if (ec) return false;
  const auto full_b = std::filesystem::weakly_canonical(b, ec);
  return !ec && full_a == full_b;
}

// Every output replaces its file whole, so an output named as an input would destroy it (a DEM
// in a GeoPackage written over by its own strokes) and two outputs of one name would lose one.
// Each output's folder must exist and be writable.
void refuse_clashing_paths(const Options& o) {
  const std::pair<const char*, const std::string*> outputs[] = {
      {"OUTPUT", &o.output}, {"--stats-json", &o.stats_json}, {"--preview", &o.preview}};
  const std::pair<const char*, const std::string*> inputs[] = {{"INPUT", &o.input},
                                                               {"--source", &o.source}};
  for (std::size_t k = 0; k < std::size(outputs); ++k) {
    const auto& [name, path] = outputs[k];
    // All the outputs can be written, or none is: the strokes are not left for a preview that
    // then fails.
    if (!path->empty()) io::check_output_path(*path);
    for (const auto& [input_name, input] : inputs) {
      if (same_file(*path, *input)) {
        throw Error(std::string(name) + " '" + *path + "' names the " + input_name +
                    " raster, which writing it would replace; choose another path");
      }
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (same_file(*path, *outputs[j].second)) {
        throw Error(std::string(name) + " '" + *path + "' names " + outputs[j].first +
                    " too; choose another path");
      }
    }
  }
}

Options parse(const std::vector<std::string>& args) {
  Options o;
  std::vector<std::string> positional;
  using Setter = std::function<void(const std::string&, const std::string&)>;
  const std::map<std::string, Setter> with_value = {
      {"--azimuth", [&](auto& n, auto& v) { o.params.view.azimuth_deg = parse_number(n, v); }},
      {"--ve", [&](auto& n, auto& v) { o.params.view.ve = parse_number(n, v); }},
      {"--base-slope",
       [&](auto& n, auto& v) { o.params.view.base_slope_pct = parse_number(n, v); }},
      {"--row-cut", [&](auto& n, auto& v) { o.params.filter.row_cut_pct = parse_number(n, v); }},
      {"--col-cut", [&](auto& n, auto& v) { o.params.filter.col_cut_pct = parse_number(n, v); }},
      {"--ctrl", [&](auto& n, auto& v) { o.params.filter.ctrl_col_pct = parse_number(n, v); }},
      {"--window", [&](auto& n, auto& v) { o.params.chain.window = parse_int(n, v); }},
      {"--min-cells", [&](auto& n, auto& v) { o.params.chain.min_cells = parse_int(n, v); }},
      {"--placement", [&](auto&, auto& v) { o.params.placement = parse_placement(v); }},
      {"--geometry", [&](auto&, auto& v) { o.params.geometry = parse_geometry(v); }},
      {"--band", [&](auto& n, auto& v) { o.dem.band = parse_int(n, v); }},
      {"--cell-size", [&](auto& n, auto& v) { o.dem.cell_size = parse_number(n, v); }},
      {"--threads",
       [&](auto& n, auto& v) {
         const int t = parse_int(n, v);
         if (t < 0) throw Error("--threads must be 0 or more");
         o.params.threads = static_cast<unsigned>(t);
       }},
      {"--format", [&](auto&, auto& v) { o.format = v; }},
      {"--strips",
       [&](auto& n, auto& v) {
         o.strips = parse_int(n, v);
         if (o.strips < 1) throw Error("--strips needs at least 1 profile per strip");
       }},
      {"--source", [&](auto&, auto& v) { o.source = v; }},
      {"--convex-column",
       [&](auto& n, auto& v) { o.pstrokes.convex_column_m2 = parse_number(n, v); }},
      {"--concave-column",
       [&](auto& n, auto& v) { o.pstrokes.concave_column_m2 = parse_number(n, v); }},
      {"--convex-row", [&](auto& n, auto& v) { o.pstrokes.convex_row_m2 = parse_number(n, v); }},
      {"--concave-row", [&](auto& n, auto& v) { o.pstrokes.concave_row_m2 = parse_number(n, v); }},
      {"--half-length", [&](auto& n, auto& v) { o.pstrokes.half_length = parse_int(n, v); }},
      {"--every",
       [&](auto& n, auto& v) {
         o.every = parse_int(n, v);
         if (o.every < 1) throw Error("--every must be at least 1");
       }},
      {"--stats-json", [&](auto&, auto& v) { o.stats_json = v; }},
      {"--preview", [&](auto&, auto& v) { o.preview = v; }},
  };
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a == "--no-diagonals") {
      o.params.filter.diagonals = false;
    } else if (a == "--subcell") {
      o.params.subcell = true;
    } else if (a == "--timings") {
      o.timings = true;
    } else if (auto it = with_value.find(a); it != with_value.end()) {
      if (k + 1 >= args.size()) throw Error(a + " needs a value");
      it->second(a, args[++k]);
    } else if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))) {
      throw Error("unknown option '" + a + "'");
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() != 2) throw Error("expected INPUT and OUTPUT");
  o.input = positional[0];
  o.output = positional[1];
  o.dem.azimuth_deg = o.params.view.azimuth_deg;
  o.params.validate();
  refuse_clashing_paths(o);
  return o;
}

std::string stats_json(const StageStats& s) {
  std::ostringstream j;
  j.precision(6);
  j << std::fixed << "{\n  \"valid_cells\": " << s.valid;
  for (const StageFigure& f : stage_figures(s)) {
    j << ",\n  \"" << f.key << "\": ";
    if (f.is_count) {
      j << static_cast<long long>(f.value);
    } else {
      j << f.value;
    }
  }
  j << "\n}\n";
  return j.str();
}

// GDAL's progress line on a terminal, 0...10...20...30 up to 100 - done., a dot every 2.5 %.
class ProgressLine {
 public:
  explicit ProgressLine(std::ostream& err) : err_(err) {}
  void show(double fraction) {
    const int step = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kSteps);
    if (step <= shown_) return;
    while (shown_ < step) {
      ++shown_;
      if (shown_ % 4 == 0) {
        err_ << shown_ / 4 * 10;
      } else {
        err_ << '.';
      }
    }
    if (step == kSteps) err_ << " - done.\n";
    err_.flush();
  }
  bool started() const { return shown_ >= 0 && shown_ < kSteps; }

 private:
  static constexpr int kSteps = 40;
  std::ostream& err_;
  int shown_ = -1;  // the last step shown
};

// Reads the DEM for the view and tells the user what they should know about it.
io::Dem load_dem(const Options& o, std::ostream& err) {
  io::Dem dem = io::read_dem(o.input, o.dem);
  if (!dem.notes.empty()) err << "note: " << dem.notes;
  return dem;
}

void write_text(const std::string& path, const std::string& text) {
  io::write_atomically(path, [&](const std::filesystem::path& staged) {
    std::ofstream f(staged);
    f << text;
    f.close();
    if (!f) throw Error("cannot write '" + path + "'");
  });
}

int silhouettes(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
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

void require_geotiff(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".tif" && ext != ".tiff") throw Error("the output raster must be a GeoTIFF (.tif)");
}

int classify(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const ProgressFn& progress) {
  const Options o = parse(args);
  require_geotiff(o.output);
  const io::Dem dem = load_dem(o, err);
  const SilhouetteResult result =
      run_silhouettes(dem.oriented, dem.frame, dem.geotransform, o.params, progress);
  stop_if_interrupted();
  io::write_classification(o.output, classification_map(result.flags, dem.frame), dem.geotransform,
                           dem.srs_wkt);
  if (!o.stats_json.empty()) write_text(o.stats_json, stats_json(result.stats));
  const StageStats& s = result.stats;
  out << o.output << ": hidden " << s.pct(s.hidden) << " %, occluding " << s.pct(s.occluding)
      << " %, c-set " << s.pct(s.candidate) << " %, f-set " << s.pct(s.filtered) << " %, t-set "
      << s.pct(s.thinned) << " %\n";
  return 0;
}

int row_slope(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
              const ProgressFn& /* their steps report no progress */) {
  const Options o = parse(args);
  require_geotiff(o.output);
  const io::Dem dem = load_dem(o, err);
  const HeightGrid slope = row_slope_map(dem.oriented, dem.frame);
  stop_if_interrupted();
  io::write_float_raster(o.output, {slope}, dem.geotransform, dem.srs_wkt);
  out << o.output << ": row slope in percent across azimuth " << dem.frame.azimuth_deg << "\n";
  return 0;
}

int profiles(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const ProgressFn& /* their steps report no progress */) {
  const Options o = parse(args);
  io::check_vector_output(o.output, o.format);
  const io::Dem dem = load_dem(o, err);
  CellFlags flags;
  classify_visibility(dem.oriented, dem.frame.d, o.params.view, flags, o.params.threads);
  const auto lines = profile_plot(dem.oriented, flags, dem.frame, o.params.view, dem.geotransform,
                                  static_cast<std::size_t>(o.every), dem.lowest_height);
  stop_if_interrupted();
  io::write_profile_lines(o.output, o.format, lines, dem.srs_wkt);
  out << o.output << ": " << lines.size() << " visible cross-section pieces\n";
  return 0;
}

int pstrokes(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const ProgressFn& progress) {
  const Options o = parse(args);
  o.pstrokes.validate();
  io::check_vector_output(o.output, o.format);
  const io::Dem dem = load_dem(o, err);
  const SilhouetteResult result =
      run_silhouettes(dem.oriented, dem.frame, dem.geotransform, o.params, progress);
  stop_if_interrupted();
  const auto strokes =
      pstroke_sketch(dem.oriented, result.flags, dem.frame, o.params.view, dem.geotransform,
                     o.params.geometry, o.pstrokes, dem.lowest_height, o.params.threads);
  io::write_pstrokes(o.output, o.format, strokes, dem.srs_wkt);
  out << o.output << ": " << strokes.size() << " P-strokes\n";
  return 0;
}

int drape(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
          const ProgressFn& /* their steps report no progress */) {
  const Options o = parse(args);
  require_geotiff(o.output);
  if (o.source.empty()) throw Error("drape needs --source RASTER, the raster to drape");
  const io::Dem dem = load_dem(o, err);
  const std::vector<HeightGrid> source = io::read_bands(o.source);
  CellFlags flags;
  classify_visibility(dem.oriented, dem.frame.d, o.params.view, flags, o.params.threads);
  const PlanObliqueDrape drape(dem.oriented, flags, dem.frame, o.params.view, dem.lowest_height);
  std::vector<HeightGrid> bands;
  for (const HeightGrid& band : source) bands.push_back(drape.drape(band));
  stop_if_interrupted();
  io::write_float_raster(o.output, bands, drape.geotransform(dem.geotransform), dem.srs_wkt);
  out << o.output << ": " << bands.size() << " band(s) draped, " << drape.cols() << " x "
      << drape.rows() << " cells\n";
  return 0;
}

int filter_plot(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
                const ProgressFn& progress) {
  const Options o = parse(args);
  const io::Dem dem = load_dem(o, err);
  const SilhouetteResult result =
      run_silhouettes(dem.oriented, dem.frame, dem.geotransform, o.params, progress);
  stop_if_interrupted();
  const double range = diagram_range_pct(o.params.filter);
  const SlopeScatter scatter =
      slope_scatter(dem.oriented, result.flags, dem.frame.d, dem.frame.w, range);
  write_text(o.output, filter_diagram_html(
                           scatter, o.params.filter,
                           "Slope filter: " + std::filesystem::path(o.input).filename().string()));
  out << o.output << ": c-set " << result.stats.pct(result.stats.candidate) << " %, f-set "
      << result.stats.pct(result.stats.filtered) << " %\n";
  return 0;
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        bool show_progress) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    (args.empty() ? err : out) << kUsage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    out << "terrain-sketch " << TSK_VERSION << " (GDAL " << GDALVersionInfo("RELEASE_NAME")
        << ")\n";
    return 0;
  }
  using Command =
      int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&, const ProgressFn&);
  const std::map<std::string, Command> commands = {
      {"silhouettes", silhouettes}, {"profiles", profiles},       {"classify", classify},
      {"row-slope", row_slope},     {"filter-plot", filter_plot}, {"drape", drape},
      {"pstrokes", pstrokes}};
  const auto command = commands.find(args[0]);
  if (command == commands.end()) {
    err << "terrain-sketch: unknown command '" << args[0] << "'\n" << kUsage;
    return 2;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (!rest.empty() && (rest[0] == "--help" || rest[0] == "-h")) {
    out << kUsage;
    return 0;
  }
  // Every raster block is read once: GDAL's default cache (5 % of RAM) would only hold a second
  // copy of the DEM. Keep it small unless the user chose a size.
  if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(64 << 20);
  ProgressLine line(err);
  const ProgressFn progress = [&line, show_progress](double fraction) {
    if (show_progress) line.show(fraction);
    return !interrupted();
  };
  try {
    return command->second(rest, out, err, progress);
  } catch (const Cancelled&) {
    err << (line.started() ? "\n" : "") << "terrain-sketch: interrupted; no output written\n";
    return 130;
  } catch (const Error& e) {
    err << "terrain-sketch: " << e.what() << "\n";
  } catch (const std::bad_alloc&) {
    err << "terrain-sketch: out of memory\n";
  } catch (const std::exception& e) {
    err << "terrain-sketch: unexpected failure: " << e.what() << "\n";
  }
  return 1;
}

}  // namespace tsk::cli
