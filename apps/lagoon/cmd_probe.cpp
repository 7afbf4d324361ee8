// lagoon probe: wave height, normal and velocity at points, from WaveQuery (CPU, exact time, no GPU).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.h"
#include "ocean/wave_query.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

std::optional<glm::dvec2> parse_point(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  auto x = parse_number(text.substr(0, comma)), z = parse_number(text.substr(comma + 1));
  if (!x || !z) return std::nullopt;
  return glm::dvec2(*x, *z);
}

// The spacing of doubles at v: the finest difference an input of that size can express.
double resolution(double v) {
  return std::nextafter(std::abs(v), HUGE_VAL) - std::abs(v);
}

int run_probe(const ParsedArgs& args) {
  const auto time = parse_number(*args.get("time"));
  if (!time) {
    std::fprintf(stderr, "lagoon probe: --time %s is not a number of seconds\n", args.get("time")->c_str());
    return kExitUsage;
  }
  if (std::abs(*time) > ocean::kWaveQueryMaxTimeS) {
    std::fprintf(stderr,
                 "lagoon probe: --time %s is beyond ±%.0f s: a double that large is resolved only to %.3g s, "
                 "so the phases of the waves would be noise; give a time within that range\n",
                 args.get("time")->c_str(), ocean::kWaveQueryMaxTimeS, resolution(*time));
    return kExitUsage;
  }
  std::vector<glm::dvec2> points;
  for (const std::string& at : args.all("at")) {
    auto p = parse_point(at);
    if (!p) {
      std::fprintf(stderr, "lagoon probe: --at %s must be two numbers X,Z in metres, e.g. --at 12.5,-3\n",
                   at.c_str());
      return kExitUsage;
    }
    if (std::max(std::abs(p->x), std::abs(p->y)) > ocean::kWaveQueryMaxCoordinateM) {
      std::fprintf(stderr,
                   "lagoon probe: --at %s is beyond ±%.0f m: a double that large is resolved only to %.3g m, "
                   "so the answer would not describe that point; the ocean repeats, so probe an equivalent "
                   "point nearer the origin\n",
                   at.c_str(), ocean::kWaveQueryMaxCoordinateM,
                   resolution(std::max(std::abs(p->x), std::abs(p->y))));
      return kExitUsage;
    }
    points.push_back(*p);
  }
  auto scene = load_scene_from_args(args, "probe");
  if (!scene) return kExitFailure;
  ocean::WaveQuery query(scene->ocean);
  const auto samples = query.sample(*time, points);
  for (size_t i = 0; i < samples.size(); ++i) {
    const ocean::WaveSample& s = samples[i];
    const nlohmann::json line{{"x", points[i].x},
                              {"z", points[i].y},
                              {"time_s", *time},
                              {"height_m", s.height},
                              {"normal", {s.normal.x, s.normal.y, s.normal.z}},
                              {"velocity_mps", {s.velocity.x, s.velocity.y, s.velocity.z}},
                              {"rest_position", {s.rest_position.x, s.rest_position.y}},
                              {"error_bound_m", s.error_bound_m},
                              {"converged", s.converged}};
    std::printf("%s\n", line.dump().c_str());
  }
  return kExitOk;
}

}  // namespace

const Command& probe_command() {
  static const Command command{
      .spec =
          {.name = "probe",
           .summary = "Prints one JSON object per point: the wave height, normal and surface velocity at "
                      "(x, z) and time T (summed over all cascades, horizontal displacement inverted), and "
                      "the query's error bound. Computed on the CPU (WaveQuery); needs no Vulkan device.",
           .options = {scene_option(),
                       {"time", "T", "simulation time in seconds", true},
                       {"at", "X,Z", "a point in metres (repeatable)", true, true},
                       set_option()},
           .details =
               "example:\n  lagoon probe --scene scenes/default.json --time 3.5 --at 0,0 --at 12.5,-40\n"},
      .run = run_probe};
  return command;
}

}  // namespace lagoon::cli
