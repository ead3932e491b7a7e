// A DEM averaged block by block: what a sketch drawn for a scale far coarser than the DEM is
// drawn from, as a cartographer generalises the terrain before drawing it at that scale.
#pragma once

#include <cstddef>
#include <memory>

#include "core/method/silhouettes.h"

namespace tsk {

// `dem` with each block of factor x factor cells averaged to one cell `factor` times as large:
// the mean of the block's cells with data (the blocks at the east and south edges hold fewer
// cells), NaN where none has data. Its windows are read from `dem`, a block row at a time, so
// the averaged DEM is never held whole. `dem` must outlive the result. factor 1 is `dem` itself.
DemSource averaged_dem(const DemSource& dem, std::size_t factor);

// averaged_dem(dem, factor) read whole and held: each cell of `dem` read once, the northern half
// through dem.read and, when `dem` has a reader alongside, the southern half through it on a
// thread of its own. Tells `progress` of the first half. Throws what the readers throw, Cancelled
// when `progress` says stop.
HeightGrid read_averaged(const DemSource& dem, std::size_t factor, const ProgressFn& progress = {});

// A DEM of `grid` and `geotransform` whose windows are read from `heights`, from any thread.
DemSource held_source(std::shared_ptr<const HeightGrid> heights, const DemGrid& grid,
                      const GeoTransform& geotransform);

// The grid of `grid` averaged `factor` cells a side (averaged_dem's).
DemGrid averaged_grid(const DemGrid& grid, std::size_t factor);

// The geotransform of a DEM of `geotransform` averaged `factor` cells a side.
GeoTransform averaged_geotransform(const GeoTransform& geotransform, std::size_t factor);

// The cells a side a run of `params` averages its DEM by before the method: for drawn strokes
// with a scale, scale_averaging's; 1 for exact strokes, the thesis's method on the DEM as it is.
std::size_t run_averaging(const SilhouetteParams& params, const DemGrid& grid,
                          const GeoTransform& geotransform);

}  // namespace tsk
