#include "core/method/thinning.h"

namespace tsk {

namespace {

// The far rule cell by cell: a cell is its zone's last when the next cell is not in the f-set,
// and the zone is kept when that next cell is not occluding. Each cell depends only on itself and
// the next, so the loop has no branches for the compiler to keep: it runs on whole vectors of
// cells, where walking the zones missed a branch at most zone ends (the f-set is 40 % of a
// low-relief DEM's cells, in zones of a few).
void mark_far_ends(std::uint8_t* flags, std::size_t length) {
  if (length == 0) return;
  // The bits moved onto `thinned`: a cell's own f-set bit, the next cell's f-set and occluding.
  static_assert(cell::filtered << 1 == cell::thinned && cell::occluding << 3 == cell::thinned,
                "the shifts below move f-set and occluding onto thinned");
  for (std::size_t i = 0; i + 1 < length; ++i) {
    const unsigned here = flags[i], next = flags[i + 1];
    const unsigned last_kept =
        ((here & ~next & cell::filtered) << 1) & ~((next & cell::occluding) << 3);
    flags[i] = static_cast<std::uint8_t>(here | last_kept);
  }
  // Nothing lies behind the profile's last cell.
  if (flags[length - 1] & cell::filtered) flags[length - 1] |= cell::thinned;
}

}  // namespace

void thin_profile(std::uint8_t* flags, std::size_t length, Placement placement) {
  if (placement == Placement::far) return mark_far_ends(flags, length);
  for (std::size_t i = next_cell_with(flags, 0, length, cell::filtered); i < length;
       i = next_cell_with(flags, i, length, cell::filtered)) {
    const std::size_t first = i;
    while (i + 1 < length && (flags[i + 1] & cell::filtered)) ++i;
    const std::size_t last = i;
    const bool leads_to_factual = last + 1 < length && (flags[last + 1] & cell::occluding);
    if (!leads_to_factual) {
      flags[first] |= cell::thinned;
      flags[last] |= cell::thinned;
    }
    ++i;
  }
}

}  // namespace tsk
