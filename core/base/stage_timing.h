// Timing the per-profile stages without costing more than they do: the clock is read on every
// eighth profile only, and the threads' summed times are turned into shares of the wall time.
#pragma once

#include <chrono>
#include <cstddef>

#include "core/method/stage_stats.h"

namespace tsk {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `work`, adding its wall time to `seconds`.
template <typename Work>
void add_wall_time(double& seconds, Work&& work) {
  const Clock::time_point start = Clock::now();
  work();
  seconds += seconds_since(start);
}

// The stages that run profile by profile inside SilhouetteStream::add_strip.
inline constexpr double StageTimings::*kProfileStages[] = {
    &StageTimings::visibility, &StageTimings::candidates, &StageTimings::filter,
    &StageTimings::thinning, &StageTimings::chaining};

// The stages are timed on every eighth profile, their times counted eight times: reading the
// clock ten times a profile would cost more than the stages of profiles a few cells long.
inline constexpr std::size_t kTimedEvery = 8;

// The clock of one profile's stages: runs each stage, adding its time to `seconds` when the
// profile is one of those timed.
struct StageClock {
  bool timed;
  StageTimings& seconds;

  template <typename Work>
  void time(double StageTimings::*stage, Work&& work) {
    if (!timed) return work();
    add_wall_time(seconds.*stage, work);
  }
};

// Adds a thread's sampled stage times to `total`, each counted for the profiles not timed.
inline void add_sampled_times(const StageTimings& sampled, StageTimings& total) {
  for (auto stage : kProfileStages) total.*stage += kTimedEvery * sampled.*stage;
}

// Splits `wall` seconds between the per-profile stages by their shares of the threads' time
// `seconds` (summed over the threads), adding them to `timings`.
inline void share_out(const StageTimings& seconds, double wall, StageTimings& timings) {
  double total = 0;
  for (auto stage : kProfileStages) total += seconds.*stage;
  if (!(total > 0)) return;
  for (auto stage : kProfileStages) timings.*stage += wall * (seconds.*stage / total);
}

}  // namespace tsk
