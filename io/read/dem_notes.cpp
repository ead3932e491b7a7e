#include "io/read/dem_notes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/base/grid.h"

namespace tsk::io {

namespace {

// True for the heights DEM producers write where they have none (-9999, -32767, -32768,
// -99999): read as heights, in a raster that does not declare them nodata, they make cliffs at
// its holes and edges that the silhouettes outline. (Float's fill values, which no terrain has,
// are read as nodata.)
bool is_common_fill_value(double z) {
  return z == -9999.0 || z == -32767.0 || z == -32768.0 || z == -99999.0;
}

// True when heights spanning `relief` rise more than five times the width `across` of their DEM
// (in the same unit): no terrain does, heights in millimetres or centimetres over cells in
// metres do, and every bump of them then occludes.
bool implausible_relief(double relief, double across) {
  return relief > 5.0 * across;
}

// The EPSG code of the WGS 84 UTM zone of a point (degrees).
int utm_epsg(double lon, double lat) {
  const int zone = std::clamp(static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1, 1, 60);
  return (lat >= 0 ? 32600 : 32700) + zone;
}

// Mercator projections (Web Mercator among them) have map units that grow away from the equator;
// transverse Mercator ("+proj=tmerc", UTM) does not.
bool is_mercator(const std::string& proj) {
  const std::string key = "+proj=merc";
  const std::size_t at = proj.find(key);
  return at != std::string::npos &&
         (at + key.size() == proj.size() || proj[at + key.size()] == ' ');
}

// The coordinate farthest from the CRS's origin among the DEM's corners, in map units (not
// finite when a corner is not).
double farthest_coordinate(const DemFacts& f) {
  const double east = f.west + static_cast<double>(f.cols) * f.cell_x;
  const double south = f.north - static_cast<double>(f.rows) * f.cell_y;
  double farthest = 0.0;
  for (const double c : {f.west, east, f.north, south}) {
    if (!std::isfinite(c)) return c;
    farthest = std::max(farthest, std::fabs(c));
  }
  return farthest;
}

// True when coordinates as far out as `farthest` cannot tell a thousandth of a `cell` apart as
// doubles (sub-cell places and smoothing move points by less than a cell): a corner not finite,
// or cells too small for how far from the origin they lie (doubles at x are about x * 2^-52
// apart). A DEM at 1e308 drew its strokes collapsed onto a few coordinates, without a word.
bool too_far_for_cells(double farthest, double cell) {
  return !std::isfinite(farthest) || farthest * DBL_EPSILON > 1e-3 * cell;
}

// Notes on the band's values: a fill value among them, or a relief no terrain has.
void assess_values(const DemFacts& f, double ground_scale, std::vector<DemNote>& notes) {
  // A range with its least above its greatest is none: QGIS's statistics of a band without a
  // valid cell are +-DBL_MAX, which are no fill values.
  if (!f.has_range || !(f.lowest_value <= f.highest_value)) return;
  for (const double value : {f.lowest_value, f.highest_value}) {
    // Float's fill values are read as nodata (mark_nodata); the others may be heights.
    const bool taken = std::fabs(value) >= kFillMagnitude;
    if (taken || is_common_fill_value(value)) {
      notes.push_back({taken ? DemNoteCode::fill_taken : DemNoteCode::fill_value, {value}, {}});
      return;
    }
  }
  const double relief = std::fabs(f.scale) * (f.highest_value - f.lowest_value);
  const double across =
      std::max(static_cast<double>(f.cols) * f.cell_x, static_cast<double>(f.rows) * f.cell_y) *
      ground_scale;
  if (implausible_relief(relief, across))
    notes.push_back({DemNoteCode::implausible_relief, {relief, across}, {}});
}

}  // namespace

DemAssessment assess_dem(const DemFacts& f) {
  DemAssessment a;
  const double farthest = farthest_coordinate(f), cell = std::min(f.cell_x, f.cell_y);
  if (too_far_for_cells(farthest, cell)) {
    a.refused = true;
    a.notes.push_back({DemNoteCode::too_far, {farthest, cell}, {}});
    return a;
  }
  if (f.has_crs && f.geographic) {
    a.refused = true;
    a.notes.push_back({DemNoteCode::geographic_crs,
                       {static_cast<double>(utm_epsg(f.centre_lon, f.centre_lat))},
                       f.crs_id});
    return a;
  }
  if (f.colour_band) {
    // Sketched, a photograph's red channel gave a thousand strokes of nonsense without a word.
    a.refused = true;
    a.notes.push_back({DemNoteCode::colour_image,
                       {static_cast<double>(f.bands), static_cast<double>(f.band)},
                       {}});
    return a;
  }
  if (!f.has_crs) {
    a.notes.push_back({DemNoteCode::no_crs, {}, {}});
  } else {
    if (is_mercator(f.proj) && f.has_centre) {
      a.ground_scale = std::cos(f.centre_lat * M_PI / 180.0);
      a.notes.push_back({DemNoteCode::mercator_scaled, {a.ground_scale}, {}});
    }
    if (!f.unit_is_metre) a.notes.push_back({DemNoteCode::unit_not_metre, {}, f.unit});
  }
  if (f.bands > 1) {
    a.notes.push_back({DemNoteCode::several_bands,
                       {static_cast<double>(f.bands), static_cast<double>(f.band)},
                       {}});
  }
  assess_values(f, a.ground_scale, a.notes);
  if (f.scale != 1.0 || f.offset != 0.0)
    a.notes.push_back({DemNoteCode::scaled_values, {f.scale, f.offset}, {}});
  return a;
}

}  // namespace tsk::io
