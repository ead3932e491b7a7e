// Application (SPEC 3, thesis section 8.1; Visvalingam and Dowson 1998): the P-stroke sketch.
// Every column profile (along the line of sight) and row profile (across it) is scored with
// Visvalingam's effective-area line generalisation; cells whose convex or concave score passes
// its class's tolerance seed short strokes drawn along the cross-section, never in or into the
// f-set of the silhouettes.
#pragma once

#include <vector>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/orient.h"
#include "core/method/params.h"
#include "core/method/strokes.h"

namespace tsk {

// Effective areas in square metres of the (distance, height) triangles, unexaggerated heights.
struct PStrokeParams {
  double convex_column_m2 = 15000;  // the thesis's sparse sketch of a 50 m DEM
  double concave_column_m2 = 60000;
  double convex_row_m2 = 30000;
  double concave_row_m2 = 15000;
  int half_length = 1;  // cells drawn on each side of a seed along the cross-section
  void validate() const;
};

// Visvalingam-Whyatt on one line: the effective area of each vertex (the triangle area when it
// is eliminated, never less than an area eliminated before it), signed positive where the vertex
// lies above the chord of its neighbours (convex), negative below (concave). Endpoints get 0.
std::vector<double> effective_areas(const std::vector<double>& x, const std::vector<double>& y);

enum class PStrokeClass : std::uint8_t { convex_column, concave_column, convex_row, concave_row };
const char* pstroke_class_name(PStrokeClass c);

struct PStroke {
  PStrokeClass cls;
  double score_m2;  // the effective area that selected the seed
  ChainCell seed;
  std::vector<StrokePoint> points;
};

// Needs the visibility and f-set flags of a silhouette run on the same grid; z_ref is the DEM's
// lowest height, the plan-oblique reference (SPEC 1.9). Reports to `progress`, and a false answer
// throws Cancelled.
std::vector<PStroke> pstroke_sketch(const HeightGrid& oriented, const CellFlags& flags,
                                    const OrientedFrame& frame, const ViewParams& view,
                                    const GeoTransform& geotransform, Geometry geometry,
                                    const PStrokeParams& params, double z_ref, unsigned threads = 0,
                                    const ProgressFn& progress = {});

}  // namespace tsk
