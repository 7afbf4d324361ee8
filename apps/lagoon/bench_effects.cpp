#include "bench_effects.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>

#include "bench_report.h"
#include "effects_chart.h"
#include "exit_codes.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "render/ocean_renderer.h"
#include "report_text.h"
#include "scene/camera_path.h"
#include "scene/effects.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

namespace fs = std::filesystem;

void all_off(scene::Scene& s) {
  s.render.effects = scene::no_effects();
  s.wakes.enabled = false;
  s.sediment.enabled = false;
}

// Per configuration: every frame's wall time and each pass's GPU times.
struct FlightTimes {
  std::vector<double> frame_ms;
  std::vector<std::pair<std::string, std::vector<double>>> passes;  // in recording order of first appearance
};

struct FlightSummary {
  std::string name, description;
  double min_fps = 0, avg_fps = 0, max_fps = 0;
  std::map<std::string, double> pass_ms;  // mean over the frames that ran the pass
};

double mean(const std::vector<double>& v) {
  return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

FlightSummary summarise(const EffectConfig& config, const FlightTimes& t) {
  FlightSummary s{.name = config.name, .description = config.description};
  const auto [fastest, slowest] = std::minmax_element(t.frame_ms.begin(), t.frame_ms.end());
  s.min_fps = 1000.0 / *slowest;
  s.max_fps = 1000.0 / *fastest;
  // The mean frame rate of the run: frames over the time they took (as a frame counter reports it).
  s.avg_fps = 1000.0 * double(t.frame_ms.size()) / std::accumulate(t.frame_ms.begin(), t.frame_ms.end(), 0.0);
  for (const auto& [name, ms] : t.passes) s.pass_ms[name] = mean(ms);
  return s;
}

// Flies `path` at `fps` frames per second of path time, continuously as an interactive run would (foam and
// wakes carry over from frame to frame). Unmeasured first: one frame with the camera taken as above the
// water, below it and across the waterline, so every pipeline the flight may need is compiled (lavapipe
// compiles at first use, which would charge hundreds of ms to whichever test first crosses the surface), then
// the start, whose warm-up is set-up.
FlightTimes fly(render::OceanRenderer& renderer, scene::Scene scene, const scene::CameraPath& path,
                double fps) {
  FlightTimes times;
  const float t0 = scene.time_s;
  const scene::Camera lens = scene.camera;
  std::vector<vk::PassTime> timings;
  scene.camera = path.at(0, lens);
  for (world::CameraSide side :
       {world::CameraSide::Above, world::CameraSide::Below, world::CameraSide::Waterline}) {
    renderer.camera_medium().force(side);
    renderer.render(scene, &timings);
  }
  renderer.camera_medium().force(std::nullopt);
  renderer.render(scene, &timings);
  const long long frames = (long long)std::floor(path.duration_s() * fps + 1e-9) + 1;
  for (long long f = 0; f < frames; ++f) {
    const double t = double(f) / fps;
    scene.time_s = t0 + float(t);
    scene.camera = path.at(t, lens);
    times.frame_ms.push_back(time_ms([&] { renderer.render(scene, &timings); }));
    for (const vk::PassTime& p : timings) {
      auto it = std::find_if(times.passes.begin(), times.passes.end(),
                             [&](const auto& e) { return e.first == p.name; });
      if (it == times.passes.end()) it = times.passes.insert(times.passes.end(), {p.name, {}});
      it->second.push_back(p.ms);
    }
  }
  return times;
}

std::vector<std::string> pass_names(const std::vector<FlightSummary>& rows) {
  std::vector<std::string> names;
  for (const FlightSummary& r : rows)
    for (const auto& [name, ms] : r.pass_ms)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::string markdown(const std::vector<FlightSummary>& rows, const std::string& caption) {
  std::string md = "| Test | Description | min. FPS | avg. FPS | max. FPS |\n|---|---|---:|---:|---:|\n";
  for (const FlightSummary& r : rows)
    md += "| " + r.name + " | " + r.description + " | " + fixed(r.min_fps) + " | " + fixed(r.avg_fps) +
          " | " + fixed(r.max_fps) + " |\n";
  md += "\n" + caption + "\n\n";
  const std::vector<std::string> names = pass_names(rows);
  md += "| Test |";
  std::string rule = "|---|";
  for (const std::string& n : names) md += " " + n + " |", rule += "---:|";
  md += "\n" + rule + "\n";
  for (const FlightSummary& r : rows) {
    md += "| " + r.name + " |";
    for (const std::string& n : names)
      md += r.pass_ms.count(n) ? " " + fixed(r.pass_ms.at(n), 2) + " |" : " - |";
    md += "\n";
  }
  md += "\nMean GPU time per pass (ms, GPU timestamps) over the same frames; - where the pass did not run.\n";
  return md;
}

std::string csv(const std::vector<FlightSummary>& rows) {
  const std::vector<std::string> names = pass_names(rows);
  std::string text = "test,min_fps,avg_fps,max_fps";
  for (const std::string& n : names) text += ",gpu_ms_" + n;
  text += "\n";
  for (const FlightSummary& r : rows) {
    text += r.name + "," + fixed(r.min_fps, 3) + "," + fixed(r.avg_fps, 3) + "," + fixed(r.max_fps, 3);
    for (const std::string& n : names) text += "," + (r.pass_ms.count(n) ? fixed(r.pass_ms.at(n), 4) : "");
    text += "\n";
  }
  return text;
}

nlohmann::json json_report(const std::vector<FlightSummary>& rows, nlohmann::json context) {
  nlohmann::json tests = nlohmann::json::array();
  for (const FlightSummary& r : rows)
    tests.push_back({{"name", r.name},
                     {"description", r.description},
                     {"min_fps", r.min_fps},
                     {"avg_fps", r.avg_fps},
                     {"max_fps", r.max_fps},
                     {"gpu_ms_per_pass", r.pass_ms}});
  return {{"context", std::move(context)}, {"tests", tests}};
}

}  // namespace

const std::vector<EffectConfig>& effect_configs() {
  static const std::vector<EffectConfig> configs = [] {
    std::vector<EffectConfig> list{
        {"none", "no effects: the sea's surface lit by sun and sky, no reflection, refraction or foam",
         [](scene::Scene&) {}}};
    // Each of the scene's effects alone (scene/effects.h), with those it needs to be seen.
    for (const scene::EffectKind& k : scene::kEffects) {
      if (k.measured_with) continue;
      list.push_back({k.name, k.summary, [&k](scene::Scene& s) {
                        for (const scene::EffectKind& other : scene::kEffects)
                          if (&other == &k ||
                              (other.measured_with && k.name == std::string(other.measured_with)))
                            s.render.effects.*other.flag = true;
                      }});
    }
    list.push_back({"wakes", "vehicles' wakes and foam trails (the dynamic wave layer)",
                    [](scene::Scene& s) { s.wakes.enabled = true; }});
    list.push_back({"sediment", "sediment stirred up by vehicles near the floor",
                    [](scene::Scene& s) { s.sediment.enabled = true; }});
    list.push_back({"all", "every effect above together", [](scene::Scene& s) {
                      for (const scene::EffectKind& k : scene::kEffects) s.render.effects.*k.flag = true;
                      s.wakes.enabled = s.sediment.enabled = true;
                    }});
    return list;
  }();
  return configs;
}

scene::Scene with_effects(const scene::Scene& scene, const EffectConfig& config) {
  scene::Scene s = scene;
  all_off(s);
  config.apply(s);
  return s;
}

int run_bench_effects(const ParsedArgs& args, long long width, long long height) {
  const auto fps = number_option(args, "fps", 10, 0.1, 240);
  if (!fps) {
    std::fprintf(stderr, "lagoon bench effects: %s\n", fps.error().message.c_str());
    return kExitUsage;
  }
  ParsedArgs scene_args = args;
  if (!args.has("scene")) scene_args.add("scene", "scenes/harbour.json");
  auto scene = load_scene_from_args(
      scene_args, "bench",
      {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
  if (!scene) return kExitFailure;
  const std::string path_file = args.get("path").value_or("scenes/paths/evaluation.json");
  Result<scene::CameraPath> path = scene::load_camera_path(path_file);
  if (!path) {
    std::fprintf(stderr, "lagoon bench effects: %s\n", path.error().message.c_str());
    return kExitFailure;
  }
  const fs::path out = args.get("out").value_or("out/bench-effects");
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  const long long frames = (long long)std::floor(path->duration_s() * *fps + 1e-9) + 1;
  std::printf(
      "device: %s (%s); scene %s at %lldx%lld; path %s (%.3g s) at %.3g frames per second of path "
      "time: %lld frames per test\n",
      ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), scene->source.c_str(), width, height,
      path_file.c_str(), path->duration_s(), *fps, frames);
  std::printf("%-12s %10s %10s %10s\n", "Test", "min. FPS", "avg. FPS", "max. FPS");
  std::vector<FlightSummary> rows;
  for (const EffectConfig& config : effect_configs()) {
    const scene::Scene configured = with_effects(*scene, config);
    auto renderer = render::OceanRenderer::create(*ctx, configured);
    if (!renderer) {
      std::fprintf(stderr, "lagoon bench effects: %s\n", renderer.error().message.c_str());
      return kExitFailure;
    }
    rows.push_back(summarise(config, fly(**renderer, configured, *path, *fps)));
    const FlightSummary& r = rows.back();
    std::printf("%-12s %10.1f %10.1f %10.1f\n", r.name.c_str(), r.min_fps, r.avg_fps, r.max_fps);
    std::fflush(stdout);
  }
  if (int status = validation_status(*ctx); status != kExitOk) return status;

  nlohmann::json context = report_context(*ctx, int(frames));
  context["scene"] = scene->source;
  context["path"] = path_file;
  context["path_fps"] = *fps;
  context["frames_per_test"] = frames;
  context["width"] = width;
  context["height"] = height;
  const std::string caption =
      "Table: the effects evaluation on " + ctx->device_info().name + " (" + ctx->device_info().type + "), " +
      std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(frames) +
      " frames along " + path_file + ". FPS from each frame's wall time (render, submit, wait, readback).";
  std::vector<EffectBar> bars;
  for (const FlightSummary& r : rows) bars.push_back({r.name, r.min_fps, r.avg_fps, r.max_fps});
  Result<io::Image8> chart = effects_chart(bars, ctx->device_info().name);
  if (!chart) {
    std::fprintf(stderr, "lagoon bench effects: %s\n", chart.error().message.c_str());
    return kExitFailure;
  }
  constexpr const char* kCommand = "lagoon bench effects";
  if (!write_report_text(out / "effects.json", json_report(rows, context).dump(2) + "\n", kCommand) ||
      !write_report_text(out / "effects.csv", csv(rows), kCommand) ||
      !write_report_text(out / "effects.md", markdown(rows, caption), kCommand))
    return kExitFailure;
  if (Result<void> ok = io::write_png(out / "effects.png", *chart); !ok) {
    std::fprintf(stderr, "lagoon bench effects: %s\n", ok.error().message.c_str());
    return kExitFailure;
  }
  std::printf("wrote %s/effects.{json,csv,md,png}\n", out.c_str());
  return kExitOk;
}

}  // namespace lagoon::cli
