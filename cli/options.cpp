#include "cli/options.h"

#include <cctype>
#include <map>
#include <optional>

#include "cli/interrupt.h"
#include "cli/option_table.h"
#include "core/base/errors.h"
#include "io/pages/preview.h"
#include "io/read/gdal_util.h"
#include "io/write/output_files.h"
#include "io/write/path_clashes.h"

namespace tsk::cli {
namespace {

// The page's options make sense only with a preview to put on it, and are checked before work.
void check_page(const Options& o) {
  const bool paged = !o.page.size.empty() || o.page.scale > 0.0 || o.page.plotter;
  if (paged && o.preview.empty())
    throw Error("--page, --page-scale and --plotter shape the --preview picture: give --preview");
  if (o.page.scale > 0.0 && o.page.size.empty())
    throw Error("--page-scale needs a --page to draw the sketch on at that scale");
  const bool png = io::lowercase_extension(o.preview) == ".png";
  if (!o.page.size.empty()) {
    const io::PageSize size = io::parse_page_size(o.page.size);
    if (png) io::check_png_page(size);
  }
  if (o.page.plotter && png)
    throw Error("--plotter draws vector art for a pen: give --preview a .svg or .pdf name");
}

// Every output replaces its file whole, so an output named as an input would destroy it (a DEM
// in a GeoPackage written over by its own strokes) and two outputs of one name would lose one.
// Each output's folder must exist and be writable.
void refuse_clashing_paths(const Options& o) {
  const std::vector<io::NamedFile> outputs = {{"OUTPUT", o.output},
                                              {"--stats-json", o.stats_json},
                                              {"--preview", o.preview},
                                              {"--visibility", o.visibility}};
  std::vector<io::NamedFile> inputs = {
      {"INPUT", o.input}, {"--source", o.source}, {"--peaks", o.peaks}};
  for (const io::NamedFile& input : inputs)
    if (!input.path.empty()) io::check_input_path(input.path);
  // All the outputs can be written, or none is: the strokes are not left for a preview that then
  // fails.
  for (const io::NamedFile& output : outputs)
    if (!output.path.empty()) io::check_output_path(output.path);
  const std::optional<io::PathClash> clash = io::find_clash(outputs, inputs);
  if (!clash) return;
  const std::string named = clash->output.name + " '" + clash->output.path + "' names ";
  if (clash->with_input) {
    throw Error(named + "a file the " + clash->other.name +
                " raster reads, which writing it would replace; choose another path");
  }
  throw Error(named + clash->other.name + " too; choose another path");
}

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

// The options in `args` set in `o`, the others kept as positional, and checked together.
std::vector<std::string> set_options(const CommandSpec& command,
                                     const std::vector<std::string>& args, Options& o) {
  std::vector<std::string> positional;
  // Each option's value as given: a second one would silently win over the first.
  std::map<std::string, std::string> given;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!looks_like_option(args[k])) {
      positional.push_back(args[k]);
      continue;
    }
    const std::string& name = args[k];
    const OptionSpec& option = find_option(name, command);
    if (option.value && k + 1 >= args.size()) throw Error(name + " needs a value");
    const std::string value = option.value ? args[++k] : std::string();
    const auto [earlier, first] = given.emplace(name, value);
    if (!first) {
      throw Error(name + " is given twice" +
                  (option.value ? " ('" + earlier->second + "', then '" + value + "')" : "") +
                  "; give each option once");
    }
    option.set(o, name, value);
  }
  o.params.validate();
  o.panorama.validate();
  o.pstrokes.validate();
  check_page(o);
  return positional;
}

// The options of `command` in `args` set in a fresh Options, with the positional arguments.
Options choose(const std::string& command_name, const std::vector<std::string>& args,
               std::vector<std::string>& positional) {
  const CommandSpec* command = find_command(command_name);
  if (!command) throw Error("internal: no command '" + command_name + "'");
  Options o;
  o.params.adaptive.mode = FilterMode::adaptive;  // the command line's default; SPEC's is fixed
  o.params.strokes.mode = StrokeMode::drawn;      // likewise; SPEC's strokes are exact
  o.dem.stop = stop_if_interrupted;               // Ctrl-C and SIGTERM stop the reading too
  try {
    positional = set_options(*command, args, o);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  return o;
}

}  // namespace

Options parse(const std::string& command_name, const std::vector<std::string>& args) {
  std::vector<std::string> positional;
  Options o = choose(command_name, args, positional);
  if (positional.size() != 2) throw UsageError("expected INPUT and OUTPUT");
  o.input = positional[0];
  o.output = positional[1];
  refuse_clashing_paths(o);
  return o;
}

Options parse_choices(const std::string& command_name, const std::vector<std::string>& args) {
  std::vector<std::string> positional;
  Options o = choose(command_name, args, positional);
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional[0] + "'");
  return o;
}

}  // namespace tsk::cli
