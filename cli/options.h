// The command line's options: parsed, range-checked, and the paths checked before any work.
#pragma once

#include <string>
#include <vector>

#include "core/applications/pstrokes.h"
#include "core/method/params.h"
#include "core/panorama/panorama_rays.h"
#include "io/pages/sketch_page.h"
#include "io/read/dem_reader.h"

namespace tsk::cli {

// Bad arguments, named: an unknown option, a bad value, a missing one, an output of the wrong
// kind. What the Python package raises as ValueError; its other errors are the run's.
class UsageError : public Error {
 public:
  using Error::Error;
};

struct Options {
  std::string input, output, format, stats_json, preview, source;
  std::string visibility;                  // panorama: the visibility raster
  std::string peaks, peak_names = "name";  // panorama: named points to label, their name field
  bool observer_given = false;
  PanoramaView panorama;  // the panorama's view (its observer when observer_given)
  bool timings = false;
  int every = 10;
  int strips = 0;
  io::DemOptions dem;
  io::PageOptions page;  // the preview's page
  SilhouetteParams params;
  PStrokeParams pstrokes;
};

// Parses the arguments of the command `command` (option_table.h) without its name. Throws
// UsageError naming the option on anything it cannot take (an option of another command too),
// and Error when an output would replace an input or another output, or could not be written.
Options parse(const std::string& command, const std::vector<std::string>& args);

// The options alone, for a front end that brings its own DEM and outputs (the Python package's
// arrays): as parse, without INPUT and OUTPUT (refused when given) and their checks.
Options parse_choices(const std::string& command, const std::vector<std::string>& args);

}  // namespace tsk::cli
