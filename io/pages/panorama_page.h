// A panorama laid out on a page for its preview: azimuth across, elevation angle up, far strokes
// lighter and thinner than near ones.
#pragma once

#include "core/method/params.h"
#include "core/panorama/panorama.h"
#include "io/pages/sketch_page.h"

namespace tsk::io {

struct PanoramaPage {
  SketchPage page;
  double exaggeration = 1.0;  // of the elevation angles over the azimuths: at most 3
};

// Lays the strokes of `result` out: the field of view across the page (a full circle's strokes
// across the seam drawn at both ends), the strokes' elevation angles from top to bottom of it.
// Drawn strokes (strokes.drawn()) are smoothed and tapered on the page; exact ones are polylines
// through their samples. A page size (options.size) is taken landscape. The peaks' `leaders`
// are drawn with their names.
PanoramaPage lay_out_panorama(const PanoramaResult& result, const DrawnParams& strokes,
                              const PageOptions& options,
                              const std::vector<PeakLeader>& leaders = {});

}  // namespace tsk::io
