// Reads a DEM through GDAL straight into the core's oriented grid, with its georeferencing.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "orient.h"
#include "strokes.h"

namespace tsk::io {

struct DemOptions {
  int band = 1;
  double azimuth_deg = 90.0;
  double cell_size = 0.0;  // > 0: use this cell size when the raster has no georeferencing
};

struct Dem {
  HeightGrid oriented;
  OrientedFrame frame;
  GeoTransform geotransform;
  std::string srs_wkt;        // empty when the raster has no CRS
  double ground_scale = 1.0;  // ground metres per map unit used for the cell sizes
  std::string notes;          // things the user should know (no CRS, assumed units), one per line
  std::size_t rows = 0, cols = 0;
  double lowest_height = 0;  // the DEM's lowest height, the plan-oblique reference (SPEC 1.9)
};

// Throws tsk::Error with a message for the user on anything it cannot read faithfully:
// not a raster, bad band, rotated or south-up georeferencing, a geographic CRS.
Dem read_dem(const std::string& path, const DemOptions& options);

// Reads a DEM strip by strip for DEMs too large for memory: profiles [first, first + count) are
// read window by window (rows or columns of the DEM for a cardinal view, the band of cells their
// samples need for any other) and turned into oriented rows.
class DemStripReader {
 public:
  DemStripReader(const std::string& path, const DemOptions& options, unsigned threads = 0);
  ~DemStripReader();
  const Dem& info() const { return dem_; }  // georeferencing and frame; `oriented` stays empty
  // Oriented profiles [first, first + count) into `strip`, whose memory may be reused.
  void read_profiles(std::size_t first, std::size_t count, HeightGrid& strip);
  double lowest_height();  // the DEM's lowest height, a full pass over the band

 private:
  Dem dem_;
  struct Source;
  std::unique_ptr<Source> source_;
};

// Every band of a raster as grids on its own pixel grid (row 0 north), nodata as NaN: the
// rasters to drape.
std::vector<HeightGrid> read_bands(const std::string& path);

}  // namespace tsk::io
