// Stage 5 (SPEC 1.6): thinning the f-set zones to the t-set.
#pragma once

#include <cstddef>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/params.h"

namespace tsk {

// Per maximal run of consecutive f-set cells on one profile: (a) drop it when the cell right
// behind its last cell is occluding, (b) otherwise mark its last cell (and, for near_and_far,
// its first) as `thinned`.
void thin_profile(std::uint8_t* flags, std::size_t length, Placement placement);

}  // namespace tsk
