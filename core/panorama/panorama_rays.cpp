#include "core/panorama/panorama_rays.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/errors.h"
#include "core/method/resample.h"

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerDeg = kPi / 180.0;
// Samples any DEM may take, whatever its size.
constexpr std::size_t kMostSamplesAlways = std::size_t{1} << 27;

// A number as a message shows it: all its significant digits, 1e-09 rather than 0.
std::string number(double v) {
  return number_text(v);
}

void require(bool ok, const std::string& message) {
  if (!ok) throw Error(message);
}

// The height under O: bilinear, or the cell O stands in where bilinear reaches past the DEM's
// edge or onto nodata beside it.
double ground_at_observer(const HeightGrid& dem, const PixelPoint& o, double x, double y) {
  float ground = sample_bilinear(dem, o);
  if (!is_data(ground))
    ground = dem(static_cast<std::size_t>(o.row), static_cast<std::size_t>(o.col));
  require(is_data(ground), "the observer at " + number(x) + ", " + number(y) +
                               " stands on a cell without data: choose a point on the terrain");
  return static_cast<double>(ground);
}

// The distance from O to the DEM's farthest corner, map units.
double farthest_corner(const HeightGrid& dem, const GeoTransform& gt, double x, double y) {
  double farthest = 0.0;
  for (double row : {0.0, static_cast<double>(dem.rows())}) {
    for (double col : {0.0, static_cast<double>(dem.cols())}) {
      double cx, cy;
      gt.apply({col, row}, cx, cy);
      farthest = std::max(farthest, std::hypot(cx - x, cy - y));
    }
  }
  return farthest;
}

}  // namespace

void PanoramaView::validate() const {
  require(std::isfinite(observer_x) && std::isfinite(observer_y),
          "the observer's coordinates must be finite numbers");
  require(std::isfinite(observer_height) && observer_height >= 0.0 && observer_height <= 1e5,
          "the observer height must be from 0 to 100000 metres above the ground, got " +
              number(observer_height));
  require(std::isfinite(max_distance) && max_distance >= 0.0,
          "the range (maximum distance) must be positive, got " + number(max_distance));
  require(std::isfinite(refraction) && refraction >= 0.0 && refraction < 1.0,
          "the refraction coefficient must be at least 0 and below 1, got " + number(refraction));
  require(std::isfinite(earth_radius) && earth_radius > 0.0,
          "the earth radius must be positive, got " + number(earth_radius));
  require(std::isfinite(metres_per_unit) && metres_per_unit > 0.0,
          "the metres per map unit must be positive");
  require(exaggeration == 0.0 || (exaggeration >= 1.0 && exaggeration <= 50.0),
          "the panorama's exaggeration must be from 1 to 50, or 0 to choose it, got " +
              number(exaggeration));
  require(samples_per_cell >= 1 && samples_per_cell <= kMostSamplesPerCell,
          "the samples per cell must be from 1 to " + std::to_string(kMostSamplesPerCell) +
              ", got " + std::to_string(samples_per_cell));
  field_of_view(azimuth_from, azimuth_to);
}

FieldOfView field_of_view(double azimuth_from, double azimuth_to) {
  require(std::isfinite(azimuth_from) && std::isfinite(azimuth_to) &&
              std::fabs(azimuth_from) <= 1e6 && std::fabs(azimuth_to) <= 1e6,
          "the azimuths of the field of view must be numbers of degrees from -1000000 to "
          "1000000, got " +
              number(azimuth_from) + " and " + number(azimuth_to));
  const double width = azimuth_to - azimuth_from;
  require(width != 0.0, "the field of view from " + number(azimuth_from) + " to " +
                            number(azimuth_to) +
                            " degrees is empty: give two different azimuths (0 and 360 for all "
                            "round)");
  FieldOfView field;
  field.from_deg = std::fmod(std::fmod(azimuth_from, 360.0) + 360.0, 360.0);
  const double turned = std::fmod(std::fmod(width, 360.0) + 360.0, 360.0);
  field.full_circle = turned == 0.0;
  field.width_deg = field.full_circle ? 360.0 : turned;
  return field;
}

double PanoramaRays::azimuth_deg(std::size_t r) const {
  return field.from_deg + (static_cast<double>(r) + 0.5) * ray_spacing_deg();
}

PixelPoint PanoramaRays::direction(std::size_t r) const {
  // In a full circle the rays come in four quarters of equal count (plan_rays): a ray's vector is
  // its first quarter's turned by whole quarter turns, which is exact.
  const std::size_t quarter = field.full_circle ? rays / 4 : rays;
  const std::size_t turns = r / quarter;
  const double angle =
      (field.from_deg + (static_cast<double>(r % quarter) + 0.5) * ray_spacing_deg()) * kRadPerDeg;
  double east = std::sin(angle), north = std::cos(angle);
  for (std::size_t t = 0; t < turns; ++t) {
    const double turned_east = north;  // a quarter turn clockwise: (e, n) -> (n, -e)
    north = -east;
    east = turned_east;
  }
  return {east, north};
}

namespace {

// The bearing of (east, north) in degrees, -180..180, within 1e-6 degrees: atan on [0, 1] by
// Abramowitz and Stegun's polynomial 4.4.49 (error under 2e-8 radians).
double close_bearing_deg(double east, double north) {
  const double ax = std::fabs(east), ay = std::fabs(north);
  const bool steep = ax <= ay;  // within 45 degrees of north or south
  const double z = steep ? ax / ay : ay / ax;
  const double z2 = z * z;
  double p = 0.0028662257;
  for (double c : {-0.0161657367, 0.0429096138, -0.0752896400, 0.1065626393, -0.1420889944,
                   0.1999355085, -0.3333314528, 1.0})
    p = p * z2 + c;
  const double from_axis = z * p * kDegPerRad;
  const double from_north = steep ? from_axis : 90.0 - from_axis;
  const double unsigned_bearing = north >= 0.0 ? from_north : 180.0 - from_north;
  return east >= 0.0 ? unsigned_bearing : -unsigned_bearing;
}

// Whether (east, north) lies clockwise of the unit vector `edge` (or on it), within half a turn.
bool clockwise_of(PixelPoint edge, double east, double north) {
  return east * edge.row - north * edge.col >= 0.0;
}

}  // namespace

RayLocator::RayLocator(const PanoramaRays& rays)
    : rays_(rays), bounds_(rays.rays + 1), walkable_(rays.ray_spacing_deg() < 90.0) {
  for (std::size_t j = 0; j <= rays.rays; ++j) {
    const double azimuth =
        (rays.field.from_deg + static_cast<double>(j) * rays.ray_spacing_deg()) * kRadPerDeg;
    bounds_[j] = {std::sin(azimuth), std::cos(azimuth)};
  }
}

std::size_t RayLocator::ray_of(double east, double north) const {
  const FieldOfView& field = rays_.field;
  const std::size_t n = rays_.rays;
  const double spacing = rays_.ray_spacing_deg();
  const auto band = [&](double offset) {
    return offset < field.width_deg ? std::min(n - 1, static_cast<std::size_t>(offset / spacing))
                                    : n;
  };
  const double close = field.offset_deg(close_bearing_deg(east, north));
  // Near the field's ends, and the full circle's seam, the exact bearing decides.
  constexpr double kMargin = 1e-3;  // degrees, far above the close bearing's error
  if (close < kMargin || close > 360.0 - kMargin || std::fabs(close - field.width_deg) < kMargin)
    return band(field.offset_deg(std::atan2(east, north) * kDegPerRad));
  std::size_t r = band(close);
  if (r == n) return n;
  while (r > 0 && !clockwise_of(bounds_[r], east, north)) --r;
  while (r + 1 < n && clockwise_of(bounds_[r + 1], east, north)) ++r;
  return r;
}

bool RayLocator::near_field_ends(double east, double north, double distance) const {
  // Four times ray_of's margin, which is itself far above the close bearing's error.
  constexpr double kSine = 6.981e-5;  // sin(0.004 degrees)
  const auto near = [&](const PixelPoint& edge) {
    const double across = east * edge.row - north * edge.col;
    const double along = east * edge.col + north * edge.row;
    return along > 0.0 && std::fabs(across) <= kSine * distance;
  };
  return near(bounds_.front()) || near(bounds_.back());
}

std::size_t RayLocator::ray_near(double east, double north, double distance,
                                 std::size_t hint) const {
  const std::size_t n = rays_.rays;
  if (!walkable_ || hint >= n || near_field_ends(east, north, distance)) return ray_of(east, north);
  // Along the edges, clockwise_of is true up to the direction and false past it (for half a turn
  // each way): a band whose first edge says true and whose second says false holds it, and no
  // other band does. ray_of's walk from its close bearing ends in that same band.
  constexpr int kMostSteps = 4;
  std::size_t r = hint;
  for (int s = 0; s < kMostSteps && r > 0 && !clockwise_of(bounds_[r], east, north); ++s) --r;
  for (int s = 0; s < kMostSteps && r + 1 < n && clockwise_of(bounds_[r + 1], east, north); ++s)
    ++r;
  if (clockwise_of(bounds_[r], east, north) && !clockwise_of(bounds_[r + 1], east, north)) return r;
  return ray_of(east, north);
}

PanoramaRays plan_rays(const HeightGrid& dem, const GeoTransform& gt, const PanoramaView& view) {
  view.validate();
  const auto& a = gt.a;
  require(a[2] == 0.0 && a[4] == 0.0 && a[1] > 0.0 && a[5] < 0.0,
          "a panorama needs a north-up DEM (no rotation, rows from north to south)");
  require(dem.rows() > 0 && dem.cols() > 0, "the DEM has no cells");
  PanoramaRays rays;
  rays.observer_x = view.observer_x;
  rays.observer_y = view.observer_y;
  rays.observer = gt.to_pixel(view.observer_x, view.observer_y);
  const PixelPoint& o = rays.observer;
  require(o.col >= 0.0 && o.row >= 0.0 && o.col < static_cast<double>(dem.cols()) &&
              o.row < static_cast<double>(dem.rows()),
          "the observer at " + number(view.observer_x) + ", " + number(view.observer_y) +
              " lies outside the DEM: choose a point on it");
  rays.eye = ground_at_observer(dem, o, view.observer_x, view.observer_y) + view.observer_height;
  rays.step = std::min(a[1], -a[5]) / view.samples_per_cell;
  rays.metres_per_unit = view.metres_per_unit;
  rays.col_per_x = 1.0 / a[1];
  rays.row_per_y = 1.0 / a[5];
  const double farthest = farthest_corner(dem, gt, view.observer_x, view.observer_y);
  rays.max_distance = view.max_distance > 0.0 ? std::min(view.max_distance, farthest) : farthest;
  const double reach = rays.max_distance / rays.step;  // the range in steps
  // A longer range helps only where the DEM reaches farther (a one-cell DEM reaches half a cell).
  require(reach >= 1.0, rays.max_distance < farthest
                            ? "the range of " + number(rays.max_distance) +
                                  " map units is shorter than a cell: give a longer --max-distance"
                            : "the DEM reaches only " + number(farthest) +
                                  " map units from the observer, less than a sample: a panorama "
                                  "needs more of the DEM around it");
  rays.field = field_of_view(view.azimuth_from, view.azimuth_to);
  // Neighbouring rays at most a step apart at the far end (docs/PANORAMA.md 1.1).
  const double needed = std::ceil(rays.field.width_deg * kRadPerDeg * reach);
  require(needed < 1e9 && reach < 1e9, "the panorama would need " + number(needed) +
                                           " rays: the range is too long for the cell size");
  rays.rays = std::max<std::size_t>(4, static_cast<std::size_t>(needed));
  if (rays.field.full_circle) rays.rays = (rays.rays + 3) / 4 * 4;
  rays.samples = static_cast<std::size_t>(std::floor(reach));
  // About 2 pi (range / step)^2 samples, a few for each step² in range; far more only where the
  // cells are far from square or the DEM a thin strip. Refused before any work or allocation.
  const double samples = static_cast<double>(rays.rays) * static_cast<double>(rays.samples);
  const double per_cell = 64.0 * view.samples_per_cell * view.samples_per_cell;
  const double budget =
      std::max(static_cast<double>(kMostSamplesAlways), per_cell * static_cast<double>(dem.size()));
  require(samples <= budget,
          "a panorama over this DEM would take " + number(samples) + " samples, more than " +
              number(per_cell) +
              " for each of its cells: its cells are far from square or "
              "it is a thin strip; resample it to square cells (gdalwarp -tr) or give a "
              "shorter --max-distance");
  checked_cell_count(rays.rays, rays.samples);
  rays.drop.resize(rays.samples);
  rays.inverse_distance.resize(rays.samples);
  rays.bend = (1.0 - view.refraction) / (2.0 * view.earth_radius);
  const double bend = rays.bend;
  for (std::size_t k = 0; k < rays.samples; ++k) {
    const double metres = rays.distance(k + 1) * view.metres_per_unit;
    rays.drop[k] = bend * metres * metres;
    rays.inverse_distance[k] = 1.0 / metres;
  }
  return rays;
}

}  // namespace tsk
