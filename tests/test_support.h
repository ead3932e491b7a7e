// Helpers shared by the stage tests: random terrains with printed seeds and whole-DEM runs.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "analytic_terrain.h"
#include "catch_compat.h"
#include "core/terrain_sketch.h"
#include "resampled_silhouettes.h"
#include "whole_grid_stages.h"

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
  return run_silhouettes(orient(dem, frame), frame, GeoTransform{}, ResolvedParams(params));
}

// The DEM turned a quarter clockwise: what was east is south.
inline HeightGrid rotate_clockwise(const HeightGrid& dem) {
  HeightGrid out(dem.cols(), dem.rows());
  for (std::size_t r = 0; r < out.rows(); ++r) {
    for (std::size_t c = 0; c < out.cols(); ++c) out(r, c) = dem(dem.rows() - 1 - c, r);
  }
  return out;
}

// Requires `actual` to hold the strokes of `expected`, in the same order, point for point.
inline void require_same_strokes(const SilhouetteResult& expected, const SilhouetteResult& actual) {
  REQUIRE(actual.strokes.size() == expected.strokes.size());
  for (std::size_t k = 0; k < expected.strokes.size(); ++k) {
    const Stroke& a = expected.strokes[k];
    const Stroke& b = actual.strokes[k];
    REQUIRE(a.cls == b.cls);
    REQUIRE(a.cells == b.cells);
    REQUIRE(a.chain.front().p == b.chain.front().p);
    REQUIRE(a.chain.front().i == b.chain.front().i);
    REQUIRE((a.mean_depth_m == b.mean_depth_m ||
             (std::isnan(a.mean_depth_m) && std::isnan(b.mean_depth_m))));
    REQUIRE(a.mean_row_slope_pct == b.mean_row_slope_pct);
    REQUIRE(a.points.size() == b.points.size());
    for (std::size_t q = 0; q < a.points.size(); ++q) {
      REQUIRE(a.points[q].x == b.points[q].x);
      REQUIRE(a.points[q].y == b.points[q].y);
    }
  }
}

}  // namespace tsk::test
