// A panorama's view from a point observer and the rays cast from it (docs/PANORAMA.md 1-1.2):
// SPEC 1.1's oriented profiles become rays, ordered left to right as the viewer turns clockwise.
#pragma once

#include <cstddef>
#include <vector>

#include "core/base/geotransform.h"
#include "core/base/grid.h"

namespace tsk {

inline constexpr int kMostSamplesPerCell = 8;  // PanoramaView::samples_per_cell's highest

struct PanoramaView {
  double observer_x = 0.0, observer_y = 0.0;  // O, in the DEM's CRS
  double observer_height = 1.7;               // eye height above the ground at O, metres, >= 0
  double max_distance = 0.0;  // farthest distance drawn, map units, > 0; 0: the farthest corner
  double azimuth_from = 0.0, azimuth_to = 360.0;  // degrees clockwise from grid north
  double refraction = 0.13;                       // k, 0 <= k < 1
  double earth_radius = 6371000.0;                // R, metres
  double metres_per_unit = 1.0;                   // ground metres in a map unit of the DEM's CRS
  // How many times as tall as its azimuths are wide the panorama layer draws its elevation
  // angles, 1 to 50; 0: chosen for the panorama (panorama_exaggeration).
  double exaggeration = 0.0;
  // Samples along each ray per DEM cell, 1 to 8. More follow the terrain between the cells'
  // centres, so that what is seen depends less on the DEM's grid (a DEM warped to another CRS
  // sees what it saw), at samples_per_cell² times the work.
  int samples_per_cell = 1;
  void validate() const;
};

// Degrees in a radian.
inline constexpr double kDegPerRad = 180.0 / 3.14159265358979323846;

// The field of view: from `from_deg`, `width_deg` clockwise; a full circle joins its ends.
struct FieldOfView {
  double from_deg = 0.0, width_deg = 360.0;  // from_deg in [0, 360)
  bool full_circle = true;
  // How far clockwise `azimuth_deg` (-360..360, as atan2 gives it in degrees) lies from the
  // field's start, in [0, 360); it is in the field when that is below width_deg.
  double offset_deg(double azimuth_deg) const {
    double offset = azimuth_deg - from_deg;  // without fmod: this runs for every cell
    while (offset < 0.0) offset += 360.0;
    while (offset >= 360.0) offset -= 360.0;
    return offset;
  }
};

// Throws Error when the azimuths are not finite or the field between them is empty (equal
// azimuths); a width that is a whole number of turns is the full circle.
FieldOfView field_of_view(double azimuth_from, double azimuth_to);

// The rays of a view over one DEM: where they start, how far apart their samples are, how many
// there are and where they point. Sample i (1..samples) of a ray lies at distance i * step.
struct PanoramaRays {
  PixelPoint observer;  // O in DEM pixels
  double observer_x = 0, observer_y = 0;
  double eye = 0.0;   // h0: the ground at O plus the observer height, metres
  double step = 1.0;  // s: the DEM's smaller cell size, map units
  double metres_per_unit = 1.0;
  double max_distance = 0;  // map units
  FieldOfView field;
  std::size_t rays = 0, samples = 0;
  double col_per_x = 1.0, row_per_y = -1.0;  // DEM pixels per map unit (north-up grids)
  double bend = 0.0;                     // (1 - k) / 2R: the curvature drop at d metres is bend d^2
  std::vector<double> drop;              // per sample: the curvature drop (1 - k) d^2 / 2R, metres
  std::vector<double> inverse_distance;  // per sample: 1 / d, per metre

  double ray_spacing_deg() const { return field.width_deg / static_cast<double>(rays); }
  // Azimuth of ray r, degrees from field.from_deg on (unwrapped: up to from_deg + 360).
  double azimuth_deg(std::size_t r) const;
  // The unit vector of ray r in map coordinates (east, north). In a full circle, rays a quarter
  // turn apart have exactly turned vectors, so a DEM turned about O meets the same samples.
  PixelPoint direction(std::size_t r) const;
  // Distance of sample i (1-based) from O, map units.
  double distance(std::size_t i) const { return static_cast<double>(i) * step; }
  double step_metres() const { return step * metres_per_unit; }
};

// Finds the ray whose band of azimuths holds a direction from O, for every cell of a raster: a
// close bearing from a polynomial, then the exact band by the rays' boundary vectors (libm's
// atan2 for every cell took half of a visibility raster's time).
class RayLocator {
 public:
  explicit RayLocator(const PanoramaRays& rays);
  // The ray r whose band [from + r spacing, from + (r + 1) spacing) holds the direction
  // (east, north) from O, not (0, 0); rays.rays when it lies outside the field of view.
  std::size_t ray_of(double east, double north) const;
  // ray_of(east, north), found by walking from `hint`, the ray of a direction close by (a
  // neighbouring cell's), when a few rays' walk ends in a band whose two edges both hold the
  // direction between them; `distance` is the direction's length. A raster's rows walk from
  // cell to cell; the bearing and the band's arithmetic are left for the rest.
  std::size_t ray_near(double east, double north, double distance, std::size_t hint) const;

 private:
  // Whether the direction lies within a few thousandths of a degree of the field's first or
  // last edge, where ray_of takes the exact bearing.
  bool near_field_ends(double east, double north, double distance) const;

  const PanoramaRays& rays_;
  std::vector<PixelPoint> bounds_;  // the band edges' unit vectors (east, north), rays + 1
  // Bands under a quarter turn wide: only one band holds a direction between its edges.
  bool walkable_;
};

// Plans the rays of `view` over `dem` (north-up, georeferenced by `geotransform`). Throws Error
// naming the cause for an observer outside the DEM or on nodata, an empty field of view, a
// rotated grid, or a view whose parameters are out of range.
PanoramaRays plan_rays(const HeightGrid& dem, const GeoTransform& geotransform,
                       const PanoramaView& view);

}  // namespace tsk
