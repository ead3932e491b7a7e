// The Python package's runs on a cluster (terrain_sketch.dask): the client plans the bands and
// surveys the filter once, each worker sketches a band from the DEM's file, and the client
// stitches the bands in order and writes the one output (core/method/bands.h). Bands, orders and
// the filter travel as bytes.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/method/bands.h"

namespace tsk::python {

struct BandPlan {
  std::size_t profiles = 0;  // of the view's grid
  std::string filter;        // the filter surveyed once, as bytes
};

// Checks the silhouettes command's `options` (as typed) and paths for a run in bands, and surveys
// the DEM's filter once. Throws cli::UsageError for options a run in bands cannot take (drawn
// strokes, local adaptivity, plan-oblique geometry, outputs beyond OUTPUT) and as the command does.
BandPlan plan_bands(const std::string& input, const std::string& output,
                    const std::vector<std::string>& options);

// Sketches the band of profiles [first, first + count) from the DEM's file, with the filter of
// the plan; from `order` (bytes, or empty to guess over `halo` profiles).
std::string sketch_band_bytes(const std::string& input, const std::vector<std::string>& options,
                              const std::string& filter, std::size_t first, std::size_t count,
                              std::size_t halo, const std::string& order);

// The bands of a run as they come back, in order: the band as its worker guessed it, or an empty
// string after the last; and the band sketched again from an order of chains (bytes).
struct BandSource {
  std::function<std::string()> next;
  std::function<std::string(std::size_t first, std::size_t count, const std::string& order)> again;
};

// Stitches the bands of a run as they come and writes each stroke as soon as it is whole, into
// OUTPUT written whole at the end (with its note, as the silhouettes command writes it). Returns
// the stage statistics as JSON.
std::string stitch_bands(const std::string& input, const std::string& output,
                         const std::vector<std::string>& options, const std::string& filter,
                         std::size_t profiles, const BandSource& bands);

}  // namespace tsk::python
