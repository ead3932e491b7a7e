#include "cli/cli_app.h"

#include <cpl_conv.h>
#include <gdal.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <new>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli/dem_note_text.h"
#include "cli/interrupt.h"
#include "cli/option_table.h"
#include "cli/options.h"
#include "cli/progress_line.h"
#include "core/base/errors.h"
#include "io/write/output_set.h"

namespace tsk::cli {
namespace {

const char* const kNotes = R"(
INPUT is any raster GDAL reads (heights in metres, a projected CRS in metres);
a vector OUTPUT is any OGR format, chosen by extension (.gpkg, .shp, .geojson, .fgb, ...).
Outputs are written whole or not at all and replace an earlier output of the same name; the
input, and a GeoPackage holding anything else (a raster, other layers), are refused.
)";

// The usage of the program: its commands, and the notes on inputs and outputs.
std::string usage() {
  return program_usage() + kNotes;
}

using Command = std::string (*)(const Args&, std::ostream&, std::ostream&, const ProgressFn&);

const std::map<std::string, Command>& commands() {
  static const std::map<std::string, Command> table = {
      {"silhouettes", silhouettes}, {"profiles", profiles},       {"classify", classify},
      {"row-slope", row_slope},     {"filter-plot", filter_plot}, {"drape", drape},
      {"pstrokes", pstrokes},       {"panorama", panorama}};
  return table;
}

}  // namespace

std::string run_command(const std::string& name, const std::vector<std::string>& args,
                        std::ostream& out, std::ostream& err, const ProgressFn& progress) {
  const auto command = commands().find(name);
  if (command == commands().end()) throw Error("unknown command '" + name + "'");
  const auto waiting = [&err](const std::filesystem::path& destination) {
    err << "terrain-sketch: waiting for another run writing '" << destination.string() << "'\n";
  };
  io::OutputSet outputs({waiting, stop_if_interrupted});
  std::ostringstream said;
  std::string statistics = command->second(args, said, err, progress);
  stop_if_interrupted();  // the last chance to stop with nothing written
  outputs.commit();
  out << said.str();
  return statistics;
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
        bool show_progress) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    (args.empty() ? err : out) << usage();
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    out << "terrain-sketch " << TSK_VERSION << " (GDAL " << GDALVersionInfo("RELEASE_NAME")
        << ")\n";
    return 0;
  }
  if (!commands().count(args[0])) {
    err << "terrain-sketch: unknown command '" << args[0] << "'\n" << usage();
    return 2;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (std::find(rest.begin(), rest.end(), "--help") != rest.end() ||
      std::find(rest.begin(), rest.end(), "-h") != rest.end()) {
    out << command_help(*find_command(args[0]));
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
    run_command(args[0], rest, out, err, progress);
    return 0;
  } catch (const Cancelled&) {
    err << (line.started() ? "\n" : "") << "terrain-sketch: interrupted; no output written\n";
    return 130;
  } catch (const io::DemRefused& e) {
    err << "terrain-sketch: " << refusal_text(e) << "\n";
  } catch (const UsageError& e) {
    // Bad usage, as the README promises: a script can tell a mistyped call from a failed run.
    err << "terrain-sketch: " << e.what() << "\n";
    return 2;
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
