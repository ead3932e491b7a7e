#include "core/method/thinning.h"

namespace tsk {

void thin_profile(std::uint8_t* flags, std::size_t length, Placement placement) {
  for (std::size_t i = next_cell_with(flags, 0, length, cell::filtered); i < length;
       i = next_cell_with(flags, i, length, cell::filtered)) {
    const std::size_t first = i;
    while (i + 1 < length && (flags[i + 1] & cell::filtered)) ++i;
    const std::size_t last = i;
    const bool leads_to_factual = last + 1 < length && (flags[last + 1] & cell::occluding);
    if (!leads_to_factual) {
      flags[last] |= cell::thinned;
      if (placement == Placement::near_and_far) flags[first] |= cell::thinned;
    }
    ++i;
  }
}

}  // namespace tsk
