// Start-up stage times for people who wait: with LAGOON_STAGE_TIMES=1 in the environment, each stage a
// command goes through (opening the device, building the LUTs, the warm-up, the frame, writing) prints
// "lagoon: <stage> <ms> ms" to stderr when it ends. Off (and free) otherwise. Plain C++, no dependency.
#pragma once
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lagoon {

inline bool stage_times_enabled() {
  static const bool enabled = [] {
    const char* v = std::getenv("LAGOON_STAGE_TIMES");
    return v != nullptr && std::strcmp(v, "0") != 0 && v[0] != '\0';
  }();
  return enabled;
}

// Set on a thread whose stages are not the run's own (a second device's, render/cold_compile.h).
inline thread_local bool stage_times_muted = false;

// Mutes this thread's stage times while it lives.
class StageTimesMuted {
 public:
  StageTimesMuted() { stage_times_muted = true; }
  ~StageTimesMuted() { stage_times_muted = false; }
  StageTimesMuted(const StageTimesMuted&) = delete;
  StageTimesMuted& operator=(const StageTimesMuted&) = delete;
};

// Prints its stage's wall time when it goes out of scope (or at end()).
class StageTimer {
 public:
  explicit StageTimer(const char* stage) : stage_(stage), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { end(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  void end() {
    if (!stage_) return;
    if (stage_times_enabled() && !stage_times_muted) {
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
      std::fprintf(stderr, "lagoon: %-28s %8.1f ms\n", stage_, ms);
    }
    stage_ = nullptr;
  }

 private:
  const char* stage_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace lagoon
