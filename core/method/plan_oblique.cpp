#include "core/method/plan_oblique.h"

namespace tsk {

double lowest_height(const HeightGrid& z) {
  LowestHeight lowest;
  lowest.add(z.data(), z.size());
  return lowest.value();
}

double plan_oblique_reference(const HeightGrid& z, const SilhouetteParams& params) {
  return params.geometry == Geometry::oblique ? lowest_height(z) : 0.0;
}

}  // namespace tsk
