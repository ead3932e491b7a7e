// Panorama strokes (docs/PANORAMA.md 1.7-1.9): one class's chains linked ray after ray, with the
// seam of a full circle closed, as strokes in map and panorama geometry.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/method/chaining.h"
#include "core/method/strokes.h"
#include "core/panorama/panorama_ray.h"

namespace tsk {

struct PanoramaStroke {
  Stroke map;                     // in the DEM's CRS, with SPEC 1.8's attributes
  std::vector<StrokePoint> view;  // x: azimuth, y: elevation angle, degrees
  double azimuth_min = 0.0, azimuth_max = 0.0;
};

// Links one class's candidates ray after ray (SPEC 1.7), and hands out the strokes of at least
// `min_cells` samples in the order their chains started. With `leap_samples` above 0, a stroke
// ends where its chain steps more than that along the next ray, and the chain goes on as another.
class PanoramaLinker {
 public:
  static constexpr std::int32_t kLeapCells = 4;  // a leap: more than 4 cells along the next ray
  PanoramaLinker(bool factual, int window, int min_cells, bool full_circle,
                 std::int32_t leap_samples);
  void add_ray(std::size_t r, const ProfileCandidates& candidates,
               const std::vector<StrokeCell>& cells, const std::vector<StrokePoint>& view);
  // After the last ray: closes the seam of a full circle and returns every stroke kept.
  std::vector<PanoramaStroke> finish();

 private:
  struct Open {
    StrokeBuilder builder;
    std::vector<StrokePoint> view;
    std::vector<StrokeCell> cells;  // kept only for chains that start on the first ray
    std::size_t id = 0;
    std::int32_t last_sample = 0;  // of its last cell
    bool from_first_ray = false;
  };
  void close(Open& open);
  void keep(std::size_t id, Open& open);
  void close_seam(const std::vector<ChainRef>& last_joined);

  bool factual_, full_circle_;
  std::int32_t leap_samples_;
  int window_, min_cells_;
  ChainLinker linker_;
  std::vector<Open> open_;
  std::vector<Open> held_;  // chains that start on the first ray, closed, for the seam
  ProfileCandidates first_, last_;
  std::vector<ChainRef> first_joined_, last_joined_;
  std::vector<std::pair<std::size_t, PanoramaStroke>> kept_;
};

}  // namespace tsk
