#include "cli/option_table.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "cli/options.h"
#include "core/base/errors.h"
#include "core/method/params.h"
#include "io/write/output_files.h"

namespace tsk::cli {
namespace {

// The widest line of the help, in characters.
constexpr std::size_t kHelpWidth = 96;

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

// A whole number of at least `lowest`.
int parse_count(const std::string& option, const std::string& text, int lowest,
                const char* meaning) {
  const int value = parse_int(option, text);
  if (value < lowest) throw Error(option + " needs at least " + std::to_string(lowest) + meaning);
  return value;
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

// A JSON file's name: its extension says what it holds, so that no other file is written over.
std::string parse_json_name(const std::string& option, const std::string& path) {
  if (io::lowercase_extension(path) != ".json")
    throw Error(option + " writes JSON: give it a .json name, got '" + path + "'");
  return path;
}

double parse_page_scale(const std::string& option, const std::string& text) {
  const double scale = parse_number(option, text);
  if (!(scale >= 1.0 && scale <= 1e9))
    throw Error(option + " is the N of 1:N, from 1 to 1000000000; got '" + text + "'");
  return scale;
}

// Who takes what: the commands that run the method's stages take its filter, and so on.
constexpr unsigned kAll = 0xffu;
constexpr unsigned kViewed = kAll & ~kPanorama;  // every command that looks along an azimuth
constexpr unsigned kExaggerated = kViewed & ~kRowSlope;
constexpr unsigned kFiltered = kSilhouettes | kClassify | kPStrokes | kFilterPlot | kPanorama;
constexpr unsigned kChained = kSilhouettes | kClassify | kPanorama;
constexpr unsigned kStroked = kSilhouettes | kClassify;  // drawn strokes, counted in --stats-json
constexpr unsigned kVectors = kSilhouettes | kProfiles | kPStrokes | kPanorama;
constexpr unsigned kThreaded = kAll & ~kRowSlope;
constexpr unsigned kPreviewed = kSilhouettes | kPanorama;
constexpr unsigned kCounted = kSilhouettes | kClassify | kPanorama;  // --stats-json

const char* const kView = "view";
const char* const kFilter = "slope filter";
const char* const kStrokes = "strokes";
const char* const kInputOutput = "input and output";
const char* const kPanoramaSection = "panorama";
const char* const kPStrokesSection =
    "P-strokes (effective areas in m2 of distance-height triangles)";

#define TSK_SET(field, parser) \
  [](Options& o, const std::string& n, const std::string& v) { o.field = parser(n, v); }
#define TSK_FLAG(field) [](Options& o, const std::string&, const std::string&) { o.field = true; }

const std::vector<OptionSpec> kOptionTable = {
    {"--azimuth", "DEG", kView,
     "bearing the viewer faces, clockwise from north (default 90: from the\n"
     "west); 0, 90, 180, 270 are exact, others resample the DEM",
     kViewed, TSK_SET(params.view.azimuth_deg, parse_number)},
    {"--ve", "X", kView, "vertical exaggeration, > 0 (default 2.5)", kExaggerated,
     TSK_SET(params.view.ve, parse_number)},
    {"--base-slope", "PCT", kView, "base slope added along the line of sight, percent (default 40)",
     kExaggerated, TSK_SET(params.view.base_slope_pct, parse_number)},
    {"--filter", "F", kFilter,
     "adaptive (default): the cut-offs below are scaled by the DEM's median\n"
     "slope over 24 %, the thesis's terrain's at 75 m (x1/16 to x4), and\n"
     "height steps within half the DEM's height quantum count as flat;\n"
     "fixed: the cut-offs as given, the thesis's filter (SPEC 1.5)",
     kFiltered,
     [](Options& o, const std::string&, const std::string& v) {
       o.params.adaptive.mode = parse_filter_mode(v);
     }},
    {"--adapt", "A", kFilter,
     "whole (default): one scale for the DEM; local: each neighbourhood of\n"
     "--adapt-window cells has its own, so a plain beside mountains keeps its\n"
     "subtle breaks of slope (reads the DEM once more)",
     kFiltered,
     [](Options& o, const std::string&, const std::string& v) {
       o.params.adaptive.adapt = parse_adaptivity(v);
     }},
    {"--adapt-window", "N", kFilter,
     "local adaptivity's neighbourhood, DEM cells, 8-100000 (default 100)", kFiltered,
     TSK_SET(params.adaptive.window, parse_int)},
    {"--row-cut", "PCT", kFilter, "row slope cut-off, percent (default 20)", kFiltered,
     TSK_SET(params.filter.row_cut_pct, parse_number)},
    {"--col-cut", "PCT", kFilter, "column slope cut-off, percent (default 12)", kFiltered,
     TSK_SET(params.filter.col_cut_pct, parse_number)},
    {"--ctrl", "PCT", kFilter, "column slope of the control point, percent (default 8.75)",
     kFiltered, TSK_SET(params.filter.ctrl_col_pct, parse_number)},
    {"--no-diagonals", nullptr, kFilter, "remove the whole rectangle below both cut-offs",
     kFiltered,
     [](Options& o, const std::string&, const std::string&) { o.params.filter.diagonals = false; }},
    {"--strokes", "S", kStrokes,
     "drawn (default): strokes a cartographer would publish, joined where\n"
     "they continue each other, smoothed, weighted for taper and depth (M\n"
     "values); exact: SPEC's strokes, one point per cell (the thesis's)",
     kStroked | kPanorama,
     [](Options& o, const std::string&, const std::string& v) {
       o.params.strokes.mode = parse_stroke_mode(v);
     }},
    {"--window", "N", kStrokes, "formulated chaining search window, cells (default 3)", kChained,
     TSK_SET(params.chain.window, parse_int)},
    {"--min-cells", "N", kStrokes,
     "drop strokes with fewer cells (default 3; drawn: after joining, shorter pieces kept "
     "only between longer ones)",
     kChained, TSK_SET(params.chain.min_cells, parse_int)},
    {"--join-gap", "CELLS", kStrokes,
     "drawn: join ends this close, 0-20 (default 2.5; 0: no joining)", kStroked,
     TSK_SET(params.strokes.join_gap_cells, parse_number)},
    {"--join-angle", "DEG", kStrokes,
     "drawn: ...whose directions agree within this, 0-90 (default 35)", kStroked,
     TSK_SET(params.strokes.join_angle_deg, parse_number)},
    {"--smooth", "CELLS", kStrokes,
     "drawn: Gaussian smoothing along the stroke, sigma 0-20 (default 1.5)", kStroked,
     TSK_SET(params.strokes.smooth_cells, parse_number)},
    {"--smooth-tolerance", "CELLS", kStrokes,
     "drawn: farthest a point lies from its cell, 0-2 (default 1)", kStroked,
     TSK_SET(params.strokes.tolerance_cells, parse_number)},
    {"--taper", "SHARE", kStrokes,
     "drawn: share of a stroke thinned at each end, 0-0.5 (default 0.25)", kStroked | kPanorama,
     TSK_SET(params.strokes.taper, parse_number)},
    {"--depth-cue", "SHARE", kStrokes,
     "drawn: weight lost from front to back, 0-0.95 (default 0.5)", kStroked,
     TSK_SET(params.strokes.depth_cue, parse_number)},
    {"--extend", "CELLS", kStrokes, "drawn: run each end on along its direction, 0-10 (default 0)",
     kStroked, TSK_SET(params.strokes.extend_cells, parse_number)},
    {"--drawn-for", "N", kStrokes,
     "drawn: for a map at 1:N: sized on paper, too little relief dropped, a DEM finer than "
     "0.4 mm a cell averaged to it (default: none)",
     // Not classify's: its raster stays on the DEM's grid, which the scale would average.
     kSilhouettes, TSK_SET(params.strokes.scale, parse_number)},
    {"--placement", "P", kStrokes,
     "far (default) or near_and_far: which end of an f-set zone to keep", kChained,
     [](Options& o, const std::string&, const std::string& v) {
       o.params.placement = parse_placement(v);
     }},
    {"--subcell", nullptr, kStrokes, "place factual points at the sub-cell peak of the profile",
     kSilhouettes, TSK_FLAG(params.subcell)},
    {"--geometry", "G", kStrokes,
     "map (cell centres) or oblique (plan oblique sketch) (default map)", kSilhouettes | kPStrokes,
     [](Options& o, const std::string&, const std::string& v) {
       o.params.geometry = parse_geometry(v);
     }},
    {"--band", "N", kInputOutput, "raster band (default 1)", kAll, TSK_SET(dem.band, parse_int)},
    {"--cell-size", "M", kInputOutput, "cell size in metres for a raster without georeferencing",
     kAll, TSK_SET(dem.cell_size, parse_cell_size)},
    {"--format", "DRIVER", kInputOutput, "OGR driver name, overriding the extension", kVectors,
     [](Options& o, const std::string&, const std::string& v) { o.format = v; }},
    {"--stats-json", "FILE.json", kInputOutput, "write the stage statistics as JSON", kCounted,
     TSK_SET(stats_json, parse_json_name)},
    {"--preview", "FILE", kInputOutput,
     "silhouettes: the oblique sketch; panorama: the panorama, azimuth across,\n"
     "elevation up, far strokes lighter. .png a picture, .svg or .pdf vector\n"
     "art (a layer per class, a path per stroke, tapered strokes as filled\n"
     "outlines, for Illustrator, Inkscape or print)",
     kPreviewed, TSK_SET(preview, parse_preview_name)},
    {"--page", "SIZE", kInputOutput,
     "draw the preview on a page: A4, A3, A2, A1, A0, letter, tabloid or\n"
     "WxH in mm (turned to suit the sketch; a PNG at 150 dpi). silhouettes:\n"
     "drawn strokes are drawn for the page's scale when it is smaller than\n"
     "the DEM's own (0.4 mm a cell) and --drawn-for is not given",
     kPreviewed, [](Options& o, const std::string&, const std::string& v) { o.page.size = v; }},
    {"--page-scale", "N", kInputOutput, "draw it at 1:N of the ground (default: fit the page)",
     kSilhouettes, TSK_SET(page.scale, parse_page_scale)},
    {"--plotter", nullptr, kInputOutput,
     "vector art for a pen plotter: single lines, strokes merged where they\n"
     "meet and ordered to cut pen-up travel (printed before and after)",
     kPreviewed, TSK_FLAG(page.plotter)},
    {"--threads", "N", kInputOutput, "worker threads (default: all cores)", kThreaded,
     [](Options& o, const std::string& n, const std::string& v) {
       o.params.threads = static_cast<unsigned>(parse_count(n, v, 0, " (0: all cores)"));
     }},
    {"--timings", nullptr, kInputOutput,
     "report the time of reading, each stage and writing on stderr", kSilhouettes | kPanorama,
     TSK_FLAG(timings)},
    {"--strips", "N", kInputOutput,
     "read and process N profiles at a time (default: 1024, more for profiles\n"
     "under 1024 cells, fewer for profiles over 4096 cells (4 Mi cells a\n"
     "strip, at least 256) or for profiles so long that strips would pass\n"
     "512 MB; memory is about 9 bytes x cells of N profiles, 13 at a\n"
     "non-cardinal azimuth)",
     kSilhouettes,
     [](Options& o, const std::string& n, const std::string& v) {
       o.strips = parse_count(n, v, 1, " profile per strip");
     }},
    {"--observer", "X,Y", kPanoramaSection, "where the viewer stands, in the DEM's CRS (required)",
     kPanorama,
     [](Options& o, const std::string& n, const std::string& v) { parse_observer(n, v, o); }},
    {"--observer-height", "M", kPanoramaSection,
     "eye height above the ground, metres, 0-100000 (default 1.7)", kPanorama,
     TSK_SET(panorama.observer_height, parse_number)},
    {"--max-distance", "M", kPanoramaSection,
     "farthest distance drawn, map units, > 0 (default: the farthest corner)", kPanorama,
     TSK_SET(panorama.max_distance, parse_range)},
    {"--azimuth-from", "DEG", kPanoramaSection,
     "the field of view, clockwise from --azimuth-from to --azimuth-to", kPanorama,
     TSK_SET(panorama.azimuth_from, parse_number)},
    {"--azimuth-to", "DEG", kPanoramaSection, "(default 0 to 360: all round)", kPanorama,
     TSK_SET(panorama.azimuth_to, parse_number)},
    {"--refraction", "K", kPanoramaSection, "refraction coefficient, 0 <= K < 1 (default 0.13)",
     kPanorama, TSK_SET(panorama.refraction, parse_number)},
    {"--panorama-exaggeration", "K", kPanoramaSection,
     "the panorama layer's elevation angles drawn K times as tall as its\n"
     "azimuths are wide, 1-50 (default 0: chosen, up to 5, so that a wide\n"
     "field is no flat strip)",
     kPanorama, TSK_SET(panorama.exaggeration, parse_number)},
    {"--samples-per-cell", "N", kPanoramaSection,
     "samples along each ray per DEM cell, 1-8 (default 1): more follow the\n"
     "terrain between the cells' centres, so that what is seen depends less\n"
     "on the DEM's grid (a DEM warped to another CRS sees the same), at N^2\n"
     "times the work",
     kPanorama, TSK_SET(panorama.samples_per_cell, parse_int)},
    {"--visibility", "FILE", kPanoramaSection,
     "write a Byte GeoTIFF on the DEM's grid: 1 visible, 0 hidden, 255 out\n"
     "of range",
     kPanorama, [](Options& o, const std::string&, const std::string& v) { o.visibility = v; }},
    {"--peaks", "FILE", kPanoramaSection,
     "points to label where the observer sees them (any OGR layer): a\n"
     "`peaks` layer of leaders in the panorama, and names on the preview",
     kPanorama, [](Options& o, const std::string&, const std::string& v) { o.peaks = v; }},
    {"--peak-names", "FIELD", kPanoramaSection,
     "the points' field holding their names (default name)", kPanorama,
     [](Options& o, const std::string&, const std::string& v) { o.peak_names = v; }},
    {"--every", "N", "profiles", "draw every N-th cross-section (default 10)", kProfiles,
     [](Options& o, const std::string& n, const std::string& v) {
       o.every = parse_count(n, v, 1, " (every cross-section)");
     }},
    {"--convex-column", "M2", kPStrokesSection, "(default 15000)", kPStrokes,
     TSK_SET(pstrokes.convex_column_m2, parse_number)},
    {"--concave-column", "M2", kPStrokesSection, "(default 60000)", kPStrokes,
     TSK_SET(pstrokes.concave_column_m2, parse_number)},
    {"--convex-row", "M2", kPStrokesSection, "(default 30000)", kPStrokes,
     TSK_SET(pstrokes.convex_row_m2, parse_number)},
    {"--concave-row", "M2", kPStrokesSection, "(default 15000)", kPStrokes,
     TSK_SET(pstrokes.concave_row_m2, parse_number)},
    {"--half-length", "N", kPStrokesSection,
     "cells drawn each side of a seed across the view (default 1)", kPStrokes,
     TSK_SET(pstrokes.half_length, parse_int)},
    {"--source", "RASTER", "drape", "the raster to drape, on the DEM's grid (required)", kDrape,
     [](Options& o, const std::string&, const std::string& v) { o.source = v; }},
};

#undef TSK_SET
#undef TSK_FLAG

const std::vector<CommandSpec> kCommandTable = {
    {"silhouettes", kSilhouettes,
     "Factual and Formulated Silhouettes as vector strokes (OUTPUT: vector)"},
    {"profiles", kProfiles,
     "the profile plot: cross-sections across the view in plan-oblique geometry,\n"
     "hidden parts removed, every --every N cells (OUTPUT: vector)"},
    {"classify", kClassify,
     "per-cell stage of the method (visible, hidden, occluding, c-set, f-set,\n"
     "t-set) on the DEM grid, with a colour table (OUTPUT: GeoTIFF); the stroke\n"
     "options change only --stats-json's g-set and stroke counts"},
    {"row-slope", kRowSlope,
     "|slope across the line of sight| in percent on the DEM grid (OUTPUT: GeoTIFF)"},
    {"pstrokes", kPStrokes,
     "the P-stroke sketch: short strokes across the view where profiles along or\n"
     "across it bend (Visvalingam effective areas), kept out of the f-set (OUTPUT: vector)"},
    {"drape", kDrape,
     "project --source RASTER (on the DEM's grid, all bands: a hillshade, a slope\n"
     "map, an image) into plan-oblique space, hidden areas removed (OUTPUT: GeoTIFF)"},
    {"panorama", kPanorama,
     "the silhouettes seen from a viewpoint (--observer), all round or over a\n"
     "field of view, with earth curvature: strokes on the map and in the panorama\n"
     "(OUTPUT: .gpkg or .sqlite, layers map and panorama)"},
    {"filter-plot", kFilterPlot,
     "column against row slope with the c-set and the slope filter's removal region,\n"
     "to tune the control point (OUTPUT: HTML page with an SVG diagram)"},
};

// `text` laid out from column `indent` up to kHelpWidth: every line after the first indented,
// and a line too long for the width broken at its last space that fits.
std::string indent_lines(const std::string& text, std::size_t indent) {
  const std::size_t room = kHelpWidth > indent + 20 ? kHelpWidth - indent : 20;
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line = text.substr(start, end - start);
    while (line.size() > room) {
      const std::size_t cut = line.rfind(' ', room);
      if (cut == std::string::npos || cut == 0) break;
      out += line.substr(0, cut) + "\n" + std::string(indent, ' ');
      line.erase(0, cut + 1);
    }
    out += line;
    if (end == text.size()) break;
    out += "\n" + std::string(indent, ' ');
    start = end + 1;
  }
  return out;
}

}  // namespace

const std::vector<CommandSpec>& command_table() {
  return kCommandTable;
}

const std::vector<OptionSpec>& option_table() {
  return kOptionTable;
}

const CommandSpec* find_command(const std::string& name) {
  for (const CommandSpec& command : kCommandTable) {
    if (name == command.name) return &command;
  }
  return nullptr;
}

std::string program_usage() {
  constexpr std::size_t kSummaryColumn = 16;
  std::string usage =
      "usage: terrain-sketch COMMAND INPUT OUTPUT [options]\n"
      "       terrain-sketch COMMAND --help    (the options COMMAND takes)\n"
      "       terrain-sketch --version\n\ncommands:\n";
  for (const CommandSpec& command : kCommandTable) {
    const std::string name = command.name;
    usage += "  " + name + std::string(kSummaryColumn - 2 - name.size(), ' ') +
             indent_lines(command.summary, kSummaryColumn) + "\n";
  }
  return usage;
}

std::string command_help(const CommandSpec& command) {
  constexpr std::size_t kHelpColumn = 23;
  std::string help = std::string("usage: terrain-sketch ") + command.name +
                     " INPUT OUTPUT [options]\n\n" + command.summary + "\n";
  std::string section;
  for (const OptionSpec& option : kOptionTable) {
    if ((option.commands & command.bit) == 0) continue;
    if (section != option.section) {
      section = option.section;
      help += "\n" + section + ":\n";
    }
    std::string head = std::string("  ") + option.name + (option.value ? " " : "") +
                       (option.value ? option.value : "");
    head += head.size() + 1 < kHelpColumn ? std::string(kHelpColumn - head.size(), ' ')
                                          : "\n" + std::string(kHelpColumn, ' ');
    help += head + indent_lines(option.help, kHelpColumn) + "\n";
  }
  return help;
}

}  // namespace tsk::cli
