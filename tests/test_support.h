// Helpers shared by the stage tests: random terrains with printed seeds and whole-DEM runs.
#pragma once

#include <cstdint>
#include <random>

#include "terrain_sketch.h"

namespace tsk::test {

// Rough random terrain: a sum of a few random waves plus noise, with optional nodata holes.
inline HeightGrid random_terrain(std::size_t rows, std::size_t cols, std::uint32_t seed,
                                 double hole_share = 0.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double kx[4], ky[4], amp[4], phase[4];
  for (int k = 0; k < 4; ++k) {
    kx[k] = (u(rng) - 0.5) * 0.8, ky[k] = (u(rng) - 0.5) * 0.8;
    amp[k] = 5 + 40 * u(rng), phase[k] = 6.28 * u(rng);
  }
  HeightGrid g(rows, cols);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      double z = 100.0 + 3.0 * u(rng);
      for (int k = 0; k < 4; ++k) z += amp[k] * std::sin(kx[k] * c + ky[k] * r + phase[k]);
      g(r, c) = u(rng) < hole_share ? kNoData : static_cast<float>(z);
    }
  }
  return g;
}

// Runs the pipeline on a DEM (row 0 north, pixel coordinates as map coordinates).
inline SilhouetteResult run_on_dem(const HeightGrid& dem, SilhouetteParams params, double dx = 10,
                                   double dy = 10) {
  const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), dx, dy, params.view.azimuth_deg);
  return run_silhouettes(orient(dem, frame), frame, GeoTransform{}, params);
}

// The DEM turned a quarter clockwise: what was east is south.
inline HeightGrid rotate_clockwise(const HeightGrid& dem) {
  HeightGrid out(dem.cols(), dem.rows());
  for (std::size_t r = 0; r < out.rows(); ++r) {
    for (std::size_t c = 0; c < out.cols(); ++c) out(r, c) = dem(dem.rows() - 1 - c, r);
  }
  return out;
}

}  // namespace tsk::test
