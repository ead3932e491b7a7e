#include "options.h"

#include <cctype>
#include <filesystem>
#include <iterator>
#include <utility>

#include "errors.h"
#include "gdal_util.h"
#include "interrupt.h"
#include "option_table.h"
#include "output_files.h"

namespace tsk::cli {
namespace {

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

namespace {

bool looks_like_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && !std::isdigit(static_cast<unsigned char>(arg[1]));
}

const OptionSpec& find_option(const std::string& name, const CommandSpec& command) {
  for (const OptionSpec& option : option_table()) {
    if (name != option.name) continue;
    if (option.commands & command.bit) return option;
    std::string takers;
    for (const CommandSpec& other : command_table()) {
      if (option.commands & other.bit)
        takers += std::string(takers.empty() ? "" : ", ") + other.name;
    }
    throw Error(std::string(command.name) + " does not take " + name + " (an option of " + takers +
                "); `terrain-sketch " + command.name + " --help` lists the options it takes");
  }
  throw Error("unknown option '" + name + "'; `terrain-sketch " + command.name +
              " --help` lists the options it takes");
}

}  // namespace

Options parse(const std::string& command_name, const std::vector<std::string>& args) {
  const CommandSpec* command = find_command(command_name);
  if (!command) throw Error("internal: no command '" + command_name + "'");
  Options o;
  o.params.adaptive.mode = FilterMode::adaptive;  // the command line's default; SPEC's is fixed
  o.params.strokes.mode = StrokeMode::drawn;      // likewise; SPEC's strokes are exact
  std::vector<std::string> positional;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!looks_like_option(args[k])) {
      positional.push_back(args[k]);
      continue;
    }
    const std::string& name = args[k];
    const OptionSpec& option = find_option(name, *command);
    if (option.value && k + 1 >= args.size()) throw Error(name + " needs a value");
    const std::string value = option.value ? args[++k] : std::string();
    option.set(o, name, value);
  }
  if (positional.size() != 2) throw Error("expected INPUT and OUTPUT");
  o.input = positional[0];
  o.output = positional[1];
  o.dem.stop = stop_if_interrupted;  // Ctrl-C and SIGTERM stop the reading too
  o.params.validate();
  o.panorama.validate();
  check_page(o);
  refuse_clashing_paths(o);
  return o;
}

}  // namespace tsk::cli
