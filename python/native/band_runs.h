// The Python package's runs on a cluster (terrain_sketch.dask): the client plans the bands and
// surveys the filter once, each worker sketches a band from the DEM's file, and the client
// stitches the bands in order and writes the one output (core/method/bands.h). Bands, orders and
// the filter travel as bytes.
#pragma once

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "cli/options.h"
#include "core/method/bands.h"
#include "io/read/dem_reader.h"

namespace tsk::python {

struct BandPlan {
  std::size_t profiles = 0;  // of the view's grid
  std::string filter;        // a fixed filter, as bytes; empty for an adaptive one
  bool survey = false;       // the adaptive filter's survey is to be made (survey_parts.h)
  bool oblique = false;      // plan-oblique geometry: the DEM's lowest height is needed first
  std::size_t dem_rows = 0;
};

// The silhouettes command's `options` (as typed) for a run in bands. Throws cli::UsageError for
// options a run in bands cannot take (local adaptivity, outputs beyond OUTPUT) and as the command
// does.
cli::Options band_options(const std::vector<std::string>& options);

// The DEM as a task of a run in bands opens it: as the options say, without reading a sample of
// the DEM for its range, which only the notes the plan has already told need.
io::DemOptions task_dem(const cli::Options& o);

// A task's DEM as the run sketches it: the file's, or drawn for a scale far coarser than the DEM,
// the DEM averaged to that scale's cells, as sketch_silhouettes averages it on one machine (the
// same factor at every task, from the DEM and the options).
class TaskDem {
 public:
  TaskDem(const std::string& input, const cli::Options& o);
  // Opened as `opened` says (the plan reads a sample of the range for its notes; tasks do not).
  TaskDem(const std::string& input, const cli::Options& o, const io::DemOptions& opened);
  TaskDem(const TaskDem&) = delete;  // the averaged source reads through file_source_
  TaskDem& operator=(const TaskDem&) = delete;
  const DemSource& source() const { return source_; }
  const io::Dem& info() const { return file_.info(); }  // the file's CRS and notes
  std::size_t averaged() const { return averaged_; }    // cells a side; 1: as it is

 private:
  io::DemFile file_;
  std::size_t averaged_;
  DemSource file_source_, source_;
};

// Checks the silhouettes command's `options` (as typed) and paths for a run in bands (as
// band_options), tells the notes on the DEM to `err` as the command does, and resolves a fixed
// filter; an adaptive one is surveyed by the workers.
BandPlan plan_bands(const std::string& input, const std::string& output,
                    const std::vector<std::string>& options, std::ostream& err);

// The lowest height of the DEM's rows [first_row, first_row + rows), +infinity when none has
// data: a part of a plan-oblique run's reference height (lowest_height_of_rows).
double lowest_height_of(const std::string& input, const std::vector<std::string>& options,
                        std::size_t first_row, std::size_t rows);

// Sketches the band of profiles [first, first + count) from the DEM's file, with the filter of
// the plan and the DEM's lowest height `z_ref` (plan-oblique geometry); from `order` (bytes, or
// empty to guess over `halo` profiles).
std::string sketch_band_bytes(const std::string& input, const std::vector<std::string>& options,
                              const std::string& filter, double z_ref, std::size_t first,
                              std::size_t count, std::size_t halo, const std::string& order);

// A band's bytes as they come back, held where they lie: `owner` keeps them, and lets them go as
// the last copy of it goes.
struct BandBytes {
  std::shared_ptr<const void> owner;
  std::string_view bytes;
};

// The bands of a run as they come back, in order: the band as its worker guessed it, or no bytes
// after the last; and the band sketched again from an order of chains (bytes).
struct BandSource {
  std::function<BandBytes()> next;
  std::function<BandBytes(std::size_t first, std::size_t count, const std::string& order)> again;
};

// Stitches the bands of a run as they come and writes each stroke as soon as it is whole (drawn
// strokes: drawn here, in one run's order), into OUTPUT written whole at the end, with its note,
// as the silhouettes command writes it, then tells the adaptive filter's cut-offs to `err` as the
// command does. z_ref: the DEM's lowest height (plan-oblique geometry). Returns the stage
// statistics as JSON.
std::string stitch_bands(const std::string& input, const std::string& output,
                         const std::vector<std::string>& options, const std::string& filter,
                         double z_ref, std::size_t profiles, const BandSource& bands,
                         std::ostream& err);

}  // namespace tsk::python
