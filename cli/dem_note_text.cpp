#include "cli/dem_note_text.h"

#include <cmath>

#include "core/base/errors.h"

namespace tsk::cli {

std::string note_text(const io::DemNote& note, DemOrigin origin) {
  const auto number = [&note](std::size_t k) { return number_text(note.numbers.at(k)); };
  const bool array = origin == DemOrigin::array;
  switch (note.code) {
    case io::DemNoteCode::geographic_crs:
      return "the CRS is geographic";
    case io::DemNoteCode::too_far:
      return std::string(std::isfinite(note.numbers.at(0))
                             ? "its corners lie up to " + number(0) +
                                   " from the CRS's origin, too far for coordinates to tell a "
                                   "thousandth of its " +
                                   number(1) + " cells apart"
                             : "a corner of it lies at a coordinate that is not a finite number") +
             ": its georeferencing is wrong" +
             (array ? "; give the transform in the CRS's units (transform=)"
                    : std::string("; set its corners, e.g. ") + io::kSetCorners);
    case io::DemNoteCode::colour_image:
      return "band " + number(1) + " of its " + number(0) +
             " is a colour channel (red, green, blue or alpha) of an image, not heights: give a "
             "DEM";
    case io::DemNoteCode::no_crs:
      return array ? "no CRS (crs=): the strokes have none, cell sizes taken as metres"
                   : "no CRS: coordinates are written without one, cell sizes taken as metres";
    case io::DemNoteCode::mercator_scaled:
      return "Mercator projection: map units are not ground metres here; cell sizes scaled by "
             "cos(latitude of the centre) = " +
             number(0);
    case io::DemNoteCode::unit_not_metre:
      return "the CRS's linear unit is " + (note.text.empty() ? "not the metre" : note.text) +
             ", not the metre; heights must be in that same unit";
    case io::DemNoteCode::several_bands:
      return "the raster has " + number(0) + " bands; band " + number(1) + " is used (--band)";
    case io::DemNoteCode::fill_value:
      return "some heights are " + number(0) +
             ", a common fill value: if those cells have no data, " +
             (array ? "pass nodata=" + number(0)
                    : "declare it as nodata (gdal_edit.py -a_nodata " + number(0) + " INPUT)");
    case io::DemNoteCode::fill_taken:
      return "some heights are " + number(0) +
             ", a fill value (of magnitude 1e30 or more, as float's) that no terrain has: those "
             "cells are taken as nodata";
    case io::DemNoteCode::implausible_relief:
      return "heights span " + number(0) + " over a DEM " + number(1) +
             " across, more than any terrain: if they are millimetres or centimetres, " +
             (array ? std::string("divide them by 1000 or 100")
                    : std::string("give the band a scale (gdal_edit.py -scale 0.001 INPUT)"));
    case io::DemNoteCode::scaled_values:
      return "heights are the band's values x " + number(0) + " + " + number(1) +
             ", its scale and offset";
    case io::DemNoteCode::assumed_cell_size:
      if (note.numbers.size() > 1 && note.numbers[1] > 0)
        return "its " + number(1) +
               " ground control points are not used (gdalwarp places it by them): cells taken "
               "as " +
               number(0) + " m squares in the grid's own frame";
      return std::string(array ? "no transform" : "no georeferencing") + ": cells taken as " +
             number(0) + " m squares";
    case io::DemNoteCode::cell_size_ignored:
      return array ? "cell_size=" + number(0) + " is ignored: the transform gives the cells"
                   : "--cell-size " + number(0) +
                         " is ignored: the raster's georeferencing gives its cells";
  }
  return "";
}

std::string refusal_text(const io::DemRefused& refused, DemOrigin origin) {
  const io::DemNote& note = refused.note();
  if (note.code == io::DemNoteCode::colour_image || note.code == io::DemNoteCode::too_far)
    return "'" + refused.path() + "': " + note_text(note, origin);
  if (note.code != io::DemNoteCode::geographic_crs) return refused.what();
  const std::string utm = "EPSG:" + number_text(note.numbers.at(0));
  return "'" + refused.path() +
         "' is in a geographic CRS: its cell sizes are degrees, not metres like its heights. "
         "Reproject it to a metric CRS first, e.g. " +
         (origin == DemOrigin::array ? "the UTM zone of its centre, " + utm
                                     : "gdalwarp -t_srs " + utm + " -r bilinear " +
                                           io::kWarpNoData + " INPUT OUTPUT_utm.tif");
}

void print_notes(const std::vector<io::DemNote>& notes, std::ostream& err, DemOrigin origin) {
  for (const io::DemNote& note : notes) err << "note: " << note_text(note, origin) << "\n";
}

}  // namespace tsk::cli
