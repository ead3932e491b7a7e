// Where the DEM's pixels lie in its CRS.
#pragma once

#include <array>

#include "core/method/frame.h"

namespace tsk {

// GDAL-style affine georeferencing: x = a0 + col * a1 + row * a2, y = a3 + col * a4 + row * a5,
// where (col, row) is a DEM pixel position (cell corners at integers).
struct GeoTransform {
  std::array<double, 6> a{0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  void apply(const PixelPoint& px, double& x, double& y) const {
    x = a[0] + px.col * a[1] + px.row * a[2];
    y = a[3] + px.col * a[4] + px.row * a[5];
  }
  // The pixel position of map point (x, y): apply() inverted (the transform must not be
  // singular).
  PixelPoint to_pixel(double x, double y) const {
    const double det = a[1] * a[5] - a[2] * a[4];
    const double u = x - a[0], v = y - a[3];
    return {(a[5] * u - a[2] * v) / det, (a[1] * v - a[4] * u) / det};
  }
};

}  // namespace tsk
