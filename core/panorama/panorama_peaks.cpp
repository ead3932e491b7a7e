#include "core/panorama/panorama_peaks.h"

#include <algorithm>
#include <cmath>

#include "core/method/resample.h"

namespace tsk {
namespace {

// The curvature drop at `d` map units, as the rays lower their samples.
double drop_at(const PanoramaRays& rays, double d) {
  const double metres = d * rays.metres_per_unit;
  return rays.bend * metres * metres;
}

// The tangent of the elevation angle of the DEM's surface at map point (x, y), `d` from O; NaN
// on nodata or off the DEM.
double tangent_at(const HeightGrid& dem, const GeoTransform& gt, const PanoramaRays& rays, double x,
                  double y, double d) {
  const PixelPoint px = gt.to_pixel(x, y);
  const double z = sample_bilinear(dem, px);
  return (z - drop_at(rays, d) - rays.eye) / (d * rays.metres_per_unit);
}

}  // namespace

std::vector<SeenPeak> see_peaks(const HeightGrid& dem, const GeoTransform& gt,
                                const PanoramaRays& rays, const std::vector<NamedPoint>& peaks) {
  std::vector<SeenPeak> seen;
  for (const NamedPoint& peak : peaks) {
    const double dx = peak.x - rays.observer_x, dy = peak.y - rays.observer_y;
    const double d = std::hypot(dx, dy);
    if (!(d >= rays.step && d <= rays.max_distance)) continue;
    const double offset = rays.field.offset_deg(std::atan2(dx, dy) * kDegPerRad);
    if (!(offset < rays.field.width_deg)) continue;
    const double top = tangent_at(dem, gt, rays, peak.x, peak.y, d);
    if (!std::isfinite(top)) continue;
    // Samples at the rays' step up to half a step before the peak, which must not hide it.
    bool hidden = false;
    for (double t = rays.step; t < d - 0.5 * rays.step && !hidden; t += rays.step) {
      const double along = t / d;
      const double sample =
          tangent_at(dem, gt, rays, rays.observer_x + along * dx, rays.observer_y + along * dy, t);
      hidden = sample > top;  // NaN (nodata) hides nothing
    }
    if (hidden) continue;
    SeenPeak s;
    s.name = peak.name;
    s.x = peak.x, s.y = peak.y;
    s.azimuth_deg = rays.field.from_deg + offset;
    s.elevation_deg = std::atan(top) * kDegPerRad;
    s.distance = d;
    seen.push_back(s);
  }
  return seen;
}

std::vector<PeakLeader> peak_leaders(std::vector<SeenPeak> seen, double skyline_deg, double row_deg,
                                     double label_deg) {
  std::sort(seen.begin(), seen.end(),
            [](const SeenPeak& a, const SeenPeak& b) { return a.azimuth_deg < b.azimuth_deg; });
  std::vector<double> row_ends;  // the azimuth each row is taken to
  std::vector<PeakLeader> leaders;
  for (const SeenPeak& peak : seen) {
    std::size_t row = 0;
    while (row < row_ends.size() && row_ends[row] > peak.azimuth_deg) ++row;
    if (row == row_ends.size()) row_ends.push_back(0.0);
    row_ends[row] = peak.azimuth_deg + label_deg;
    const double label_y = skyline_deg + row_deg * static_cast<double>(row + 1);
    leaders.push_back({peak, {peak.azimuth_deg, peak.elevation_deg}, {peak.azimuth_deg, label_y}});
  }
  return leaders;
}

}  // namespace tsk
