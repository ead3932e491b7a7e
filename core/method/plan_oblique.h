// Plan-oblique geometry (SPEC 1.9): a point is drawn along its profile, shifted towards the far
// side in proportion to its height above the DEM's lowest height, as the raised viewer sees it.
// Strokes, the profile plot, P-strokes, the drape and the preview all place points with it.
#pragma once

#include "core/base/grid.h"
#include "core/method/params.h"

namespace tsk {

class PlanObliqueShift {
 public:
  // d: the spacing along profiles (ground units); z_ref: the DEM's lowest height.
  PlanObliqueShift(const ViewParams& view, double d, double z_ref)
      : cells_per_metre_(view.ve / (view.base_slope() * d)), z_ref_(z_ref) {}
  // The position along the profile, in cells, at which a point at position `along` (cells) with
  // height z is drawn.
  double operator()(double along, double z) const {
    return along + cells_per_metre_ * (z - z_ref_);
  }

 private:
  double cells_per_metre_;
  double z_ref_;
};

// The lowest valid height of a grid, 0 when there is none: the plan-oblique reference of a DEM
// held whole.
double lowest_height(const HeightGrid& z);

// The plan-oblique reference of a DEM held whole for a run with `params`: its lowest height in
// plan-oblique geometry; map geometry needs none, which spares a pass over the grid.
double plan_oblique_reference(const HeightGrid& z, const SilhouetteParams& params);

}  // namespace tsk
