// How far a live frame moves the simulation (docs/demo.md, "Time"): the wall clock's time since the last
// frame, at most kMaxLiveStepS. A frame's catch-up (foam ticks, wake steps, 120 Hz physics) grows with its
// step, so on a device slower than 4 frames a second an unbounded step made the next frame slower still;
// there the world now runs slower than the clock instead.
#pragma once
#include <algorithm>

namespace lagoon::demo {

inline constexpr double kMaxLiveStepS = 0.25;

inline double live_step_s(double wall_dt_s) {
  return std::clamp(wall_dt_s, 0.0, kMaxLiveStepS);
}

}  // namespace lagoon::demo
