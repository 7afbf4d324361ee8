// lagoon probe: wave height, normal and velocity at points, from WaveQuery (CPU, exact time, no GPU); or the
// pose and velocities of a floating object (objects[].floating) or a vehicle (vehicles[]), simulated from
// time 0 on the CPU.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "commands.h"
#include "ocean/springs.h"
#include "ocean/wave_query.h"
#include "scene_args.h"
#include "world/floating_objects.h"
#include "world/moving_pose.h"
#include "world/water_probe.h"

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

// The floating object or vehicle called `name`; prints why there is none.
std::optional<world::MovingTarget> find_target(const scene::Scene& scene, const std::string& name) {
  std::string names;
  const auto list = [&names](const std::string& n) { names += (names.empty() ? "\"" : ", \"") + n + "\""; };
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    if (scene.objects[o].name == name) {
      if (scene.objects[o].floating.enabled) return world::MovingTarget{false, o};
      std::fprintf(stderr,
                   "lagoon probe: objects[%zu] \"%s\" does not float; set objects[%zu].floating.enabled to "
                   "true (docs/physics.md) to probe its motion\n",
                   o, name.c_str(), o);
      return std::nullopt;
    }
    list(scene.objects[o].name);
  }
  for (size_t v = 0; v < scene.vehicles.size(); ++v) {
    if (scene.vehicles[v].name == name) return world::MovingTarget{true, v};
    list(scene.vehicles[v].name);
  }
  std::fprintf(stderr, "lagoon probe: no object or vehicle is named \"%s\"; the scene's: %s\n", name.c_str(),
               names.empty() ? "none" : names.c_str());
  return std::nullopt;
}

// --object: the body's pose and velocities at `frames` times from `time`, 1/fps apart.
int probe_object(const ParsedArgs& args, const scene::Scene& scene, double time) {
  const auto frames = integer_option(args, "frames", 1, 1, 100000);
  const auto fps = number_option(args, "fps", 30, 0.001, 10000);
  if (!frames || !fps) {
    std::fprintf(stderr, "lagoon probe: %s\n", (!frames ? frames.error() : fps.error()).message.c_str());
    return kExitUsage;
  }
  const auto target = find_target(scene, *args.get("object"));
  if (!target) return kExitFailure;
  auto moving = world::FloatingObjects::create(scene, scene.ocean, ocean::make_cascade_spectra(scene.ocean));
  if (!moving) {
    std::fprintf(stderr, "lagoon probe: %s\n", moving.error().message.c_str());
    return kExitFailure;
  }
  for (long long f = 0; f < *frames; ++f) {
    const double t = time + double(f) / *fps;
    (*moving)->advance(t);
    std::printf("%s\n", world::moving_pose(scene, **moving, *target, t).dump().c_str());
  }
  return kExitOk;
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
  if (args.get("object") && !args.all("at").empty()) {
    std::fprintf(
        stderr,
        "lagoon probe: give --at (the water at points) or --object (a floating body or vehicle), not "
        "both\n");
    return kExitUsage;
  }
  if (!args.get("object") && args.all("at").empty()) {
    std::fprintf(stderr,
                 "lagoon probe: give --at X,Z (the water at a point) or --object NAME (a floating body)\n");
    return kExitUsage;
  }
  if (args.get("object")) {
    auto scene = load_scene_from_args(args, "probe");
    return scene ? probe_object(args, *scene, *time) : kExitFailure;
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
  if (scene->ocean.model == ocean::SurfaceModel::Springs &&
      ocean::springs_steps_for(scene->ocean.springs, *time) > ocean::kSpringsMaxCatchUpSteps) {
    std::fprintf(
        stderr,
        "lagoon probe: --time %s needs %llu steps of the springs grid from rest, more than %llu; give "
        "a time below %.0f s or a longer ocean.springs.step_s\n",
        args.get("time")->c_str(), (unsigned long long)ocean::springs_steps_for(scene->ocean.springs, *time),
        (unsigned long long)ocean::kSpringsMaxCatchUpSteps,
        double(ocean::kSpringsMaxCatchUpSteps) * scene->ocean.springs.step_s);
    return kExitUsage;
  }
  ocean::WaveQuery query(scene->ocean);
  auto water = world::water_at_points(*scene, query, *time, points);
  if (!water) {
    std::fprintf(stderr, "lagoon probe: %s\n", water.error().message.c_str());
    return kExitFailure;
  }
  for (size_t i = 0; i < water->samples.size(); ++i) {
    const ocean::WaveSample& s = water->samples[i];
    const double wake = water->wake_heights[i];
    const nlohmann::json line{{"x", points[i].x},
                              {"z", points[i].y},
                              {"time_s", *time},
                              {"height_m", s.height},
                              {"wake_height_m", wake},
                              {"normal", world::json_vec3(s.normal)},
                              {"velocity_mps", world::json_vec3(s.velocity)},
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
           .summary =
               "Prints one JSON object per point: the wave height, normal and surface velocity at "
               "(x, z) and time T (summed over all cascades, horizontal displacement inverted, plus the "
               "vehicles' wakes, also given alone as wake_height_m), and the query's error bound (of the "
               "cascades' part). Or, with --object, one per frame: a floating object's or a "
               "vehicle's pose "
               "(model origin, orientation as a quaternion w, x, y, z), centre of mass and velocities, "
               "simulated from the scene's bodies_start_s (0 unless set). Computed on the CPU; needs "
               "no Vulkan device.",
           .options =
               {scene_option(),
                {"time", "T", "simulation time in seconds", true},
                {"at", "X,Z", "a point in metres (repeatable)", false, true},
                {"object", "NAME",
                 "a floating object (objects[].name with floating.enabled) or a vehicle (vehicles[].name)",
                 false},
                {"frames", "N", "with --object: N lines, from T on (default 1)", false},
                {"fps", "F", "with --object: lines per second of simulation time (default 30)", false},
                set_option()},
           .details =
               "examples:\n  lagoon probe --scene scenes/default.json --time 3.5 --at 0,0 --at 12.5,-40\n"
               "  lagoon probe --scene harbour.json --object buoy --time 5 --frames 60 --fps 30\n"},
      .run = run_probe};
  return command;
}

}  // namespace lagoon::cli
