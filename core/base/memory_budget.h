// How much of the machine a run may take, decided in one place: whether a DEM may be turned
// whole, and how many profiles a strip-by-strip run reads at a time. The machine's memory is its
// physical memory or, when less, its control group's limit (cgroup_memory.h), or the megabytes
// that the environment variable TSK_MEMORY_MB gives (each function here throws Error when that is
// not a number from 1).
#pragma once

#include <cstddef>
#include <string>

#include "core/method/frame.h"

namespace tsk {

// True when turning a whole DEM for this view and classifying it would take more than half of
// this machine's memory: the turned grid at 5 bytes a cell and, resampled, the DEM beside it at 4.
// Reading that much could not fail cleanly: memory is promised freely and taken at first use.
bool too_large_to_turn_whole(const OrientedFrame& frame);

// True when `bytes` fit in what a run plans to hold beside its strips: 512 MiB, or a quarter of
// the machine's memory when that is less.
bool within_run_budget(double bytes);

// Profiles per strip for a strip-by-strip run of this view: 1024, more for profiles under 1024
// cells (1 Mi cells a strip, up to 65536 profiles), fewer for profiles over 4096 cells (4 Mi
// cells a strip, at least 256 profiles) and for profiles so long that a run's
// strips (two of heights, the classification and, resampled, the band: 9 or 13 bytes a cell)
// would pass 512 MiB (or a quarter of the machine's memory, when that is less), at least 16.
std::size_t strip_profiles(const OrientedFrame& frame);

// Throws Error when strips of `strip` profiles are none or would take more than half of this
// machine's memory.
void check_strip_fits(const OrientedFrame& frame, std::size_t strip);

// Throws Error, "`what` would take N GB, more than half of this machine's memory; `remedy`", when
// `bytes` would: checked before the allocation, which could not fail cleanly.
void check_fits_in_memory(double bytes, const std::string& what, const std::string& remedy);

}  // namespace tsk
