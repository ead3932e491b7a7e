#include "cli_app.h"

#include <cpl_conv.h>
#include <gdal.h>

#include <map>
#include <new>

#include "commands.h"
#include "dem_note_text.h"
#include "errors.h"
#include "interrupt.h"
#include "progress_line.h"

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
  panorama      the silhouettes seen from a viewpoint (--observer), all round or over a
                field of view, with earth curvature: strokes on the map and in the panorama
                (OUTPUT: .gpkg or .sqlite, layers map and panorama)
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
  --filter F           adaptive (default): the cut-offs below are scaled by the DEM's median
                       slope over 24 %, the thesis's terrain's at 75 m (x1/16 to x4), and
                       height steps within half the DEM's height quantum count as flat;
                       fixed: the cut-offs as given, the thesis's filter (SPEC 1.5)
  --adapt A            whole (default): one scale for the DEM; local: each neighbourhood of
                       --adapt-window cells has its own, so a plain beside mountains keeps its
                       subtle breaks of slope (reads the DEM once more)
  --adapt-window N     local adaptivity's neighbourhood, DEM cells, 8-100000 (default 100)
  --row-cut PCT        row slope cut-off, percent (default 20)
  --col-cut PCT        column slope cut-off, percent (default 12)
  --ctrl PCT           column slope of the control point, percent (default 8.75)
  --no-diagonals       remove the whole rectangle below both cut-offs
strokes:
  --strokes S          drawn (default): strokes a cartographer would publish, joined where
                       they continue each other, smoothed, weighted for taper and depth (M
                       values); exact: SPEC's strokes, one point per cell (the thesis's)
  --window N           formulated chaining search window, cells (default 3)
  --min-cells N        drop strokes with fewer cells (default 3; drawn: after joining)
  --join-gap CELLS     drawn: join ends this close, 0-20 (default 2.5; 0: no joining)
  --join-angle DEG     drawn: ...whose directions agree within this, 0-90 (default 35)
  --smooth CELLS       drawn: Gaussian smoothing along the stroke, sigma 0-20 (default 1.5)
  --smooth-tolerance CELLS
                       drawn: farthest a point lies from its cell, 0-2 (default 1)
  --taper SHARE        drawn: share of a stroke thinned at each end, 0-0.5 (default 0.25)
  --depth-cue SHARE    drawn: weight lost from front to back, 0-0.95 (default 0.5)
  --extend CELLS       drawn: run each end on along its direction, 0-10 (default 0)
  --placement P        far (default) or near_and_far: which end of an f-set zone to keep
  --subcell            place factual points at the sub-cell peak of the profile
  --geometry G         map (cell centres) or oblique (plan oblique sketch) (default map)
input and output:
  --band N             raster band (default 1)
  --cell-size M        cell size in metres for a raster without georeferencing
  --format DRIVER      OGR driver name, overriding the extension
  --stats-json FILE    write the stage statistics as JSON
  --preview FILE       render the oblique sketch: .png a picture, .svg or .pdf vector art (a
                       layer per class, a path per stroke, tapered strokes as filled outlines,
                       for Illustrator, Inkscape or print)
  --page SIZE          draw the preview on a page: A4, A3, A2, A1, A0, letter, tabloid or
                       WxH in mm (turned to suit the sketch; a PNG at 150 dpi)
  --page-scale N       draw it at 1:N of the ground (default: fit the page)
  --plotter            vector art for a pen plotter: single lines, strokes merged where they
                       meet and ordered to cut pen-up travel (printed before and after)
  --threads N          worker threads (default: all cores)
  --timings            print the time of reading, each stage and writing to stderr
  --strips N           read and process N profiles at a time (default: 1024, more for profiles
                       under 1024 cells, fewer for profiles so long that strips would pass
                       512 MB; memory is about 9 bytes x cells of N profiles, 13 at a
                       non-cardinal azimuth)
panorama (the slope filter and stroke options above apply; the view options do not):
  --observer X,Y       where the viewer stands, in the DEM's CRS (required)
  --observer-height M  eye height above the ground, metres, 0-100000 (default 1.7)
  --max-distance M     farthest distance drawn, map units, > 0 (default: the farthest corner)
  --azimuth-from DEG   the field of view, clockwise from --azimuth-from to --azimuth-to
  --azimuth-to DEG     (default 0 to 360: all round)
  --refraction K       refraction coefficient, 0 <= K < 1 (default 0.13)
  --visibility FILE    write a Byte GeoTIFF on the DEM's grid: 1 visible, 0 hidden, 255 out
                       of range
  --peaks FILE         points to label where the observer sees them (any OGR layer): a
                       `peaks` layer of leaders in the panorama, and names on the preview
  --peak-names FIELD   the points' field holding their names (default name)
  --preview FILE       the panorama, azimuth across, elevation up, far strokes lighter (.png,
                       .svg, .pdf; --page SIZE draws it on a landscape page)
profiles:
  --every N            draw every N-th cross-section (default 10)
pstrokes (tolerances: effective areas in m2 of the profiles' distance-height triangles):
  --convex-column M2   (default 15000)   --concave-column M2  (default 60000)
  --convex-row M2      (default 30000)   --concave-row M2     (default 15000)
  --half-length N      cells drawn each side of a seed across the view (default 1)
drape:
  --source RASTER      the raster to drape, on the DEM's grid
)";

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
  using Command = int (*)(const Args&, std::ostream&, std::ostream&, const ProgressFn&);
  const std::map<std::string, Command> commands = {
      {"silhouettes", silhouettes}, {"profiles", profiles},       {"classify", classify},
      {"row-slope", row_slope},     {"filter-plot", filter_plot}, {"drape", drape},
      {"pstrokes", pstrokes},       {"panorama", panorama}};
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
  } catch (const io::DemRefused& e) {
    err << "terrain-sketch: " << refusal_text(e) << "\n";
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
