#include "core/base/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/base/cgroup_memory.h"
#include "core/base/errors.h"

namespace tsk {
namespace {

// The megabytes TSK_MEMORY_MB gives for a run to plan for (on a machine shared with other work),
// else the machine's memory or, when less, its control group's limit (a container's).
double machine_memory() {
  if (const char* given = std::getenv("TSK_MEMORY_MB"); given && *given) {
    char* end = nullptr;
    const double megabytes = std::strtod(given, &end);
    if (*end != '\0' || !(megabytes >= 1.0) || !(megabytes <= 1e12)) {
      throw Error(
          std::string("TSK_MEMORY_MB must be the megabytes a run may plan for, from 1, got '") +
          given + "'");
    }
    return megabytes * 1024.0 * 1024.0;
  }
  const double physical =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  return std::min(physical, this_process_memory_limit());
}

bool over_half_the_memory(double bytes) {
  const double memory = machine_memory();
  return memory > 0 && bytes > 0.5 * memory;
}

// What a strip-by-strip run holds per profile of a strip: two strips of heights (the one processed
// and the one being read), the classification and, resampled, the band of DEM cells.
double strip_bytes_per_profile(const OrientedFrame& frame) {
  return (frame.resampled ? 13.0 : 9.0) *
         static_cast<double>(std::max<std::size_t>(1, frame.length));
}

// What a run plans to hold beside what it must: 512 MiB, less on a machine with under 2 GiB.
double run_budget() {
  return std::min(512.0 * 1024 * 1024, 0.25 * machine_memory());
}

}  // namespace

bool within_run_budget(double bytes) {
  return bytes <= run_budget();
}

bool too_large_to_turn_whole(const OrientedFrame& frame) {
  const double dem = frame.resampled ? 4.0 * static_cast<double>(frame.dem_rows) *
                                           static_cast<double>(frame.dem_cols)
                                     : 0.0;
  return over_half_the_memory(dem + 5.0 * static_cast<double>(frame.profiles) *
                                        static_cast<double>(frame.length));
}

std::size_t strip_profiles(const OrientedFrame& frame) {
  const double budget = run_budget();
  const double bytes_per_profile = strip_bytes_per_profile(frame);
  // Short profiles come more to a strip, at least 1 Mi cells, as every strip costs a read and a
  // pause in linking. (Not more for others: the first strip is read before any work starts.)
  // Long ones come fewer, about 4 Mi cells: two strips of 1024 profiles of 8000 cells were a
  // sixth of the 8000 x 8000 benchmark's peak memory, and 524 ran as fast. From 45 degrees, with
  // the blocks along a band's edge kept for the next band (io::BlockRetention), strips of 370
  // took 110 MB less than strips of 1024 and no longer (on 16000 x 16000: 256 against 1024,
  // 230 MB less, as fast).
  const double length = static_cast<double>(std::max<std::size_t>(1, frame.length));
  double most = std::clamp(std::floor(1024.0 * 1024 / length), 1024.0, 65536.0);
  if (frame.length > 4096) most = std::clamp(std::floor(4.0 * 1024 * 1024 / length), 256.0, 1024.0);
  return static_cast<std::size_t>(std::clamp(std::floor(budget / bytes_per_profile), 16.0, most));
}

void check_strip_fits(const OrientedFrame& frame, std::size_t strip) {
  if (strip == 0) throw Error("a strip needs at least one profile");
  const std::size_t held = std::min(strip, frame.profiles) + 2;
  if (over_half_the_memory(strip_bytes_per_profile(frame) * static_cast<double>(held))) {
    throw Error("strips of " + std::to_string(strip) + " profiles of " +
                std::to_string(frame.length) +
                " cells would take more than half of this machine's memory; choose fewer "
                "profiles per strip (0 chooses them)");
  }
}

void check_fits_in_memory(double bytes, const std::string& what, const std::string& remedy) {
  if (!over_half_the_memory(bytes)) return;
  char gigabytes[32];
  std::snprintf(gigabytes, sizeof gigabytes, "%.1f", bytes / 1e9);
  throw Error(what + " would take " + gigabytes + " GB, more than half of this machine's memory; " +
              remedy);
}

}  // namespace tsk
