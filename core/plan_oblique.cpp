#include "plan_oblique.h"

namespace tsk {

double lowest_height(const HeightGrid& z) {
  LowestHeight lowest;
  lowest.add(z.data(), z.size());
  return lowest.value();
}

}  // namespace tsk
