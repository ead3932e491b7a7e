#include "options.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iterator>
#include <map>
#include <stdexcept>
#include <utility>

#include "errors.h"
#include "gdal_util.h"
#include "interrupt.h"
#include "output_files.h"

namespace tsk::cli {
namespace {

// Parses a whole number or a finite decimal, refusing trailing junk.
double parse_number(const std::string& option, const std::string& text) {
  // Decimal numbers only: std::stod also reads hexadecimal (0x5A is 90), "inf" and "nan".
  if (text.find_first_not_of("0123456789+-.eE") != std::string::npos)
    throw Error(option + " needs a number, got '" + text + "' (decimal digits only)");
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
  // Digits after an optional sign (not 1e0, 0x5A or 2.5), then within range: converting a double
  // beyond an integer's range is undefined.
  const std::size_t digits = text.find_first_not_of("+-") == 1 ? 1 : 0;
  const bool whole =
      !text.empty() && text.find_first_not_of("0123456789", digits) == std::string::npos;
  const double value = whole ? parse_number(option, text) : 0.0;
  if (!whole || !(value >= -1e9 && value <= 1e9)) {
    throw Error(option + " needs a whole number from -1000000000 to 1000000000, got '" + text +
                "'");
  }
  return static_cast<int>(value);
}

double parse_cell_size(const std::string& option, const std::string& text) {
  const double size = parse_number(option, text);
  if (!(size > 0 && std::isfinite(size)))
    throw Error(option + " must be positive, a number of metres; got '" + text + "'");
  return size;
}

// "X,Y": the observer's position in the DEM's CRS.
void parse_observer(const std::string& option, const std::string& text, Options& o) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos)
    throw Error(option + " needs X,Y in the DEM's CRS, got '" + text + "'");
  o.panorama.observer_x = parse_number(option, text.substr(0, comma));
  o.panorama.observer_y = parse_number(option, text.substr(comma + 1));
  o.observer_given = true;
}

// A panorama's range: a positive distance in map units.
double parse_range(const std::string& option, const std::string& text) {
  const double range = parse_number(option, text);
  if (!(range > 0.0))
    throw Error(option + " must be a positive distance in the DEM's map units; got '" + text + "'");
  return range;
}

// The preview's extension names its format: another would name one it cannot write.
std::string parse_preview_name(const std::string& option, const std::string& path) {
  const std::string ext = io::lowercase_extension(path);
  if (ext != ".png" && ext != ".svg" && ext != ".pdf")
    throw Error(option + " draws a PNG picture or SVG or PDF vector art: give it a .png, .svg or " +
                ".pdf name");
  return path;
}

// The page's options make sense only with a preview to put on it, and are checked before work.
void check_page(const Options& o) {
  const bool paged = !o.page.size.empty() || o.page.scale > 0.0 || o.page.plotter;
  if (paged && o.preview.empty())
    throw Error("--page, --page-scale and --plotter shape the --preview picture: give --preview");
  if (o.page.scale > 0.0 && o.page.size.empty())
    throw Error("--page-scale needs a --page to draw the sketch on at that scale");
  if (!o.page.size.empty()) io::parse_page_size(o.page.size);
  if (o.page.plotter && io::lowercase_extension(o.preview) == ".png")
    throw Error("--plotter draws vector art for a pen: give --preview a .svg or .pdf name");
}

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
  const std::pair<const char*, const std::string*> outputs[] = {{"OUTPUT", &o.output},
                                                                {"--stats-json", &o.stats_json},
                                                                {"--preview", &o.preview},
                                                                {"--visibility", &o.visibility}};
  // Every file GDAL reads for each input: a VRT's sources too.
  std::vector<std::pair<const char*, std::vector<std::string>>> inputs;
  for (const auto& [name, path] : {std::pair{"INPUT", &o.input}, std::pair{"--source", &o.source},
                                   std::pair{"--peaks", &o.peaks}}) {
    if (path->empty()) continue;
    io::check_input_path(*path);
    std::vector<std::string> files = io::dataset_files(*path);
    files.push_back(*path);
    inputs.emplace_back(name, std::move(files));
  }
  for (std::size_t k = 0; k < std::size(outputs); ++k) {
    const auto& [name, path] = outputs[k];
    // All the outputs can be written, or none is: the strokes are not left for a preview that
    // then fails.
    if (!path->empty()) io::check_output_path(*path);
    for (const auto& [input_name, files] : inputs) {
      for (const std::string& file : files) {
        if (!same_file(*path, file)) continue;
        throw Error(std::string(name) + " '" + *path + "' names a file the " + input_name +
                    " raster reads, which writing it would replace; choose another path");
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

}  // namespace

Options parse(const std::vector<std::string>& args) {
  Options o;
  o.params.adaptive.mode = FilterMode::adaptive;  // the command line's default; SPEC's is fixed
  o.params.strokes.mode = StrokeMode::drawn;      // likewise; SPEC's strokes are exact
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
      {"--filter", [&](auto&, auto& v) { o.params.adaptive.mode = parse_filter_mode(v); }},
      {"--adapt", [&](auto&, auto& v) { o.params.adaptive.adapt = parse_adaptivity(v); }},
      {"--adapt-window", [&](auto& n, auto& v) { o.params.adaptive.window = parse_int(n, v); }},
      {"--window", [&](auto& n, auto& v) { o.params.chain.window = parse_int(n, v); }},
      {"--min-cells", [&](auto& n, auto& v) { o.params.chain.min_cells = parse_int(n, v); }},
      {"--strokes", [&](auto&, auto& v) { o.params.strokes.mode = parse_stroke_mode(v); }},
      {"--smooth", [&](auto& n, auto& v) { o.params.strokes.smooth_cells = parse_number(n, v); }},
      {"--smooth-tolerance",
       [&](auto& n, auto& v) { o.params.strokes.tolerance_cells = parse_number(n, v); }},
      {"--join-gap",
       [&](auto& n, auto& v) { o.params.strokes.join_gap_cells = parse_number(n, v); }},
      {"--join-angle",
       [&](auto& n, auto& v) { o.params.strokes.join_angle_deg = parse_number(n, v); }},
      {"--taper", [&](auto& n, auto& v) { o.params.strokes.taper = parse_number(n, v); }},
      {"--depth-cue", [&](auto& n, auto& v) { o.params.strokes.depth_cue = parse_number(n, v); }},
      {"--extend", [&](auto& n, auto& v) { o.params.strokes.extend_cells = parse_number(n, v); }},
      {"--placement", [&](auto&, auto& v) { o.params.placement = parse_placement(v); }},
      {"--geometry", [&](auto&, auto& v) { o.params.geometry = parse_geometry(v); }},
      {"--band", [&](auto& n, auto& v) { o.dem.band = parse_int(n, v); }},
      {"--cell-size", [&](auto& n, auto& v) { o.dem.cell_size = parse_cell_size(n, v); }},
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
      {"--observer", [&](auto& n, auto& v) { parse_observer(n, v, o); }},
      {"--observer-height",
       [&](auto& n, auto& v) { o.panorama.observer_height = parse_number(n, v); }},
      {"--max-distance", [&](auto& n, auto& v) { o.panorama.max_distance = parse_range(n, v); }},
      {"--azimuth-from", [&](auto& n, auto& v) { o.panorama.azimuth_from = parse_number(n, v); }},
      {"--azimuth-to", [&](auto& n, auto& v) { o.panorama.azimuth_to = parse_number(n, v); }},
      {"--refraction", [&](auto& n, auto& v) { o.panorama.refraction = parse_number(n, v); }},
      {"--visibility", [&](auto&, auto& v) { o.visibility = v; }},
      {"--peaks", [&](auto&, auto& v) { o.peaks = v; }},
      {"--peak-names", [&](auto&, auto& v) { o.peak_names = v; }},
      {"--preview", [&](auto& n, auto& v) { o.preview = parse_preview_name(n, v); }},
      {"--page", [&](auto&, auto& v) { o.page.size = v; }},
      {"--page-scale",
       [&](auto& n, auto& v) {
         o.page.scale = parse_number(n, v);
         if (!(o.page.scale >= 1.0 && o.page.scale <= 1e9))
           throw Error(n + " is the N of 1:N, from 1 to 1000000000; got '" + v + "'");
       }},
  };
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    if (a == "--no-diagonals") {
      o.params.filter.diagonals = false;
    } else if (a == "--subcell") {
      o.params.subcell = true;
    } else if (a == "--timings") {
      o.timings = true;
    } else if (a == "--plotter") {
      o.page.plotter = true;
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
  o.dem.stop = stop_if_interrupted;  // Ctrl-C and SIGTERM stop the reading too
  o.params.validate();
  o.panorama.validate();
  check_page(o);
  refuse_clashing_paths(o);
  return o;
}

}  // namespace tsk::cli
