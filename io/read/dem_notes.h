// What a front end should tell the user about a DEM before reading it, decided once for both: the
// front end gathers the facts (from GDAL, or from QGIS's layer), assess_dem turns them into notes
// with codes and numbers, and each front end words the notes its own way (tr() in QGIS).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tsk::io {

struct DemFacts {
  std::size_t rows = 0, cols = 0;
  double cell_x = 0, cell_y = 0;  // cell width and height in map units
  double west = 0, north = 0;     // the north-west corner, map units
  int bands = 1, band = 1;
  bool colour_band = false;  // the band is an image's red, green, blue or alpha channel
  bool has_crs = false;
  bool geographic = false;
  std::string crs_id;         // the CRS's authority id or name, for messages
  bool unit_is_metre = true;  // the CRS's linear unit (a projected CRS)
  std::string unit;           // its name, when it is not the metre
  std::string proj;           // the CRS as a PROJ string ("+proj=merc ...")
  bool has_centre = false;    // the DEM's centre in degrees is known (geographic, Mercator)
  double centre_lon = 0, centre_lat = 0;
  bool has_range = false;  // the band's (approximate) least and greatest values
  double lowest_value = 0, highest_value = 0;
  double scale = 1, offset = 0;  // heights = values x scale + offset
};

enum class DemNoteCode {
  geographic_crs,      // refused; numbers: the EPSG code of the centre's UTM zone
  too_far,             // refused: coordinates cannot tell the cells apart; numbers: the farthest
                       // coordinate (not finite when a corner is not), the smaller cell side
  colour_image,        // refused: the band is a colour channel; numbers: the band count, the band
  no_crs,              // cell sizes taken as metres, outputs without a CRS
  mercator_scaled,     // numbers: ground metres per map unit at the centre
  unit_not_metre,      // text: the unit's name
  several_bands,       // numbers: the band count, the band used
  fill_value,          // numbers: the lowest or highest value, a common fill value
  fill_taken,          // numbers: the lowest or highest value, float's fill value, read as nodata
  implausible_relief,  // numbers: the relief, the DEM's width (same unit)
  scaled_values,       // numbers: scale, offset
  assumed_cell_size,   // no geotransform; numbers: the cell size given, the ground control points
  cell_size_ignored,   // a cell size given for a georeferenced raster; numbers: it
};

struct DemNote {
  DemNoteCode code;
  std::vector<double> numbers;
  std::string text;
};

struct DemAssessment {
  bool refused = false;       // the first note says why
  double ground_scale = 1.0;  // ground metres per map unit, for the cell sizes
  std::vector<DemNote> notes;
};

DemAssessment assess_dem(const DemFacts& facts);

}  // namespace tsk::io
