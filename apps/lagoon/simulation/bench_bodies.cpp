#include "bench_bodies.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "bench_report.h"
#include "exit_codes.h"
#include "ocean/initial_spectrum.h"
#include "scene_args.h"
#include "world/floating_objects.h"

namespace lagoon::cli {
namespace {

constexpr int kFramesPerRound = 60;  // one second of a 60 Hz display

// Per round: the mean and the worst frame time over a second of 60 Hz frames (the sea's knots and the wake
// layer's steps fall on some frames only, so the mean is the figure a frame budget compares with).
struct BodyTimes {
  std::vector<double> mean, worst;
};

// `paced`: each frame starts at its slot of a 60 Hz clock, as in a live loop, so what the physics hands to
// other threads (the sea's next knot, the wake layers' next step) has the rest of the frame to run; back to
// back, it competes with the following frames, as in a catch-up to a late time.
BodyTimes time_bodies(world::FloatingObjects& moving, double t0, int rounds, bool paced) {
  BodyTimes times;
  moving.advance(t0);  // the history up to t0, not measured
  double t = t0;
  const auto frame = std::chrono::duration<double>(1.0 / kFramesPerRound);
  auto slot = std::chrono::steady_clock::now();
  for (int r = 0; r < rounds; ++r) {
    double sum = 0, worst = 0;
    for (int f = 0; f < kFramesPerRound; ++f) {
      t += 1.0 / kFramesPerRound;
      if (paced) {
        slot += std::chrono::duration_cast<std::chrono::steady_clock::duration>(frame);
        std::this_thread::sleep_until(slot);
      }
      const double ms = time_ms([&] { moving.advance(t); });
      sum += ms;
      worst = std::max(worst, ms);
    }
    times.mean.push_back(sum / kFramesPerRound);
    times.worst.push_back(worst);
  }
  return times;
}

}  // namespace

int run_bench_bodies(const ParsedArgs& args, int rounds) {
  ParsedArgs scene_args = args;
  if (!args.has("scene")) scene_args.add("scene", "scenes/harbour.json");
  auto scene = load_scene_from_args(scene_args, "bench");
  if (!scene) return kExitFailure;
  const auto spectra = ocean::make_cascade_spectra(scene->ocean);
  std::printf(
      "CPU, 60 Hz frames, %d rounds of %d frames from t = %g s; per frame: median over rounds of the "
      "round's mean (and of its worst frame)\n",
      rounds, kFramesPerRound, double(scene->time_s));
  std::printf("%-44s %12s\n", "Benchmark", "Time (ms)");
  nlohmann::json results = nlohmann::json::array();
  struct Config {
    const char* name;
    bool wakes;
  };
  for (const Config c : {Config{"as_scene", scene->wakes.felt_by_bodies}, Config{"without_wakes", false}}) {
    if (c.wakes != scene->wakes.felt_by_bodies && c.wakes) continue;
    if (std::string(c.name) == "without_wakes" && !scene->wakes.felt_by_bodies) continue;  // the same run
    scene::Scene s = *scene;
    s.wakes.felt_by_bodies = c.wakes;
    auto moving = world::FloatingObjects::create(s, s.ocean, spectra);
    if (!moving) {
      std::fprintf(stderr, "lagoon bench: %s\n", moving.error().message.c_str());
      return kExitFailure;
    }
    if ((*moving)->empty()) {
      std::fprintf(stderr,
                   "lagoon bench bodies: %s has no floating object or vehicle; try scenes/harbour.json\n",
                   s.source.string().c_str());
      return kExitFailure;
    }
    const BodyTimes times = time_bodies(**moving, double(s.time_s), rounds, false);
    report_row(results, std::string("bodies/frame_mean/") + c.name, times.mean, "wall", 0);
    report_row(results, std::string("bodies/frame_worst/") + c.name, times.worst, "wall", 0);
    const BodyTimes paced = time_bodies(**moving, double(s.time_s) + rounds + 1, rounds, true);
    report_row(results, std::string("bodies/paced_mean/") + c.name, paced.mean, "wall", 0);
    report_row(results, std::string("bodies/paced_worst/") + c.name, paced.worst, "wall", 0);
  }
  if (auto path = args.get("json")) {
    const nlohmann::json doc{{"context", {{"device", "CPU"}, {"rounds", rounds}, {"scene", scene->source}}},
                             {"benchmarks", results}};
    if (!write_report(*path, doc)) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return kExitOk;
}

}  // namespace lagoon::cli
