// Peaks seen from a panorama's observer (docs/PANORAMA.md 6): which named points the eye reaches,
// and where they stand in the panorama, to be labelled there.
#pragma once

#include <string>
#include <vector>

#include "core/method/strokes.h"
#include "core/panorama/panorama_rays.h"

namespace tsk {

struct NamedPoint {
  std::string name;
  double x = 0.0, y = 0.0;  // in the DEM's CRS
};

// A peak in sight: where it stands in the panorama (x the azimuth, unwrapped as the strokes'
// are; y the elevation angle, degrees) and how far off it lies.
struct SeenPeak {
  std::string name;
  double x = 0.0, y = 0.0;  // map
  double azimuth_deg = 0.0, elevation_deg = 0.0;
  double distance = 0.0;  // map units
};

// The peaks of `peaks` within the rays' range and field of view whose top the eye sees: no
// sample on the straight sight line to it, at the rays' step, rises above that line (SPEC 1.2's
// test, on the DEM's bilinear surface with the curvature drop). A peak's height is the DEM's
// there; peaks on nodata or off the DEM are not seen. In the order given.
std::vector<SeenPeak> see_peaks(const HeightGrid& dem, const GeoTransform& geotransform,
                                const PanoramaRays& rays, const std::vector<NamedPoint>& peaks);

// A peak's leader in the panorama: a line from its top straight up to its label, above the
// skyline, in rows so that the labels of neighbouring peaks do not overlap.
struct PeakLeader {
  SeenPeak peak;
  StrokePoint top, label;  // panorama degrees: the peak, and where its label starts
};

// Leaders for `seen` (in azimuth order): their labels in rows `row_deg` apart, the first a row
// above `skyline_deg`; a label goes to the lowest row whose last label lies at least
// `label_deg` of azimuth before it.
std::vector<PeakLeader> peak_leaders(std::vector<SeenPeak> seen, double skyline_deg, double row_deg,
                                     double label_deg);

}  // namespace tsk
