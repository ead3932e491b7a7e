// The silhouettes of a DEM held in the caller's memory (a numpy array), returned as columns: the
// Python package's sketch(). The same recipe as the silhouettes command's on a file
// (sketch_silhouettes), the same options (parsed from the command's table) and messages.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "core/base/parallel.h"
#include "io/read/memory_raster.h"

namespace tsk::python {

// The strokes as columns: stroke k's points are [offsets[k], offsets[k + 1]) of x, y (and m, the
// drawn strokes' weights); its attributes are row k of the columns, in the order and with the
// names of the vector outputs' fields.
struct StrokeColumns {
  std::vector<double> x, y, m;
  std::vector<std::int64_t> offsets{0};
  bool measured = false;             // drawn strokes: m holds a weight per point
  std::vector<std::string> classes;  // "factual" or "formulated"
  std::vector<std::int64_t> cells;
  std::vector<std::string> real_names;     // the real-valued fields, named
  std::vector<std::vector<double>> reals;  // one column per name, NaN for null
  std::string crs_wkt;                     // the DEM's CRS, "" when it has none
  std::string statistics;                  // the stage statistics as JSON (--stats-json's text)
};

// Sketches the band with the silhouettes command's `options` (as typed: "--azimuth", "90"; no
// INPUT, OUTPUT or options of outputs), telling its notes on `err`. Throws as the command does.
StrokeColumns sketch_array(const io::MemoryBand& band, const io::MemoryRasterInfo& info,
                           const std::vector<std::string>& options, const ProgressFn& progress,
                           std::ostream& err);

}  // namespace tsk::python
