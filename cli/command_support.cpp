#include "command_support.h"

#include <filesystem>
#include <sstream>

#include "dem_note_text.h"
#include "errors.h"
#include "output_files.h"

namespace tsk::cli {

io::Dem load_dem(const Options& o, std::ostream& err) {
  io::Dem dem = io::read_dem(o.input, o.dem);
  print_notes(dem.notes, err);
  return dem;
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

void require_geotiff(const std::string& path) {
  const std::string ext = io::lowercase_extension(path);
  if (ext != ".tif" && ext != ".tiff") throw Error("the output raster must be a GeoTIFF (.tif)");
}

}  // namespace tsk::cli
