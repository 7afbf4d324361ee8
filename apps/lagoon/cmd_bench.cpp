// lagoon bench compute: the GPU ocean step against the FFTW CPU step, measured side by side in one run;
// bench render: a scene's frame and passes; bench wakes: the dynamic wave layer's step.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench_baseline.h"
#include "bench_bodies.h"
#include "bench_effects.h"
#include "bench_report.h"
#include "bench_water_share.h"
#include "commands.h"
#include "fftw_ocean_step.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "model_comparison.h"
#include "ocean/dynamic_layer.h"
#include "ocean/gpu/dynamic_layer_gpu.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/validate.h"
#include "render/ocean_renderer.h"
#include "scene_args.h"
#include "vk/device_select.h"
#include "vk/gpu_timer.h"

namespace lagoon::cli {
namespace {

// `count` cascades of N x N, with patches of 1000, 100 and 10 m.
ocean::OceanParams bench_params(uint32_t n, uint32_t count) {
  const double patches[] = {1000.0, 100.0, 10.0};
  ocean::OceanParams params;
  params.cascades.clear();
  for (uint32_t c = 0; c < count; ++c) params.cascades.push_back({patches[c], n});
  return params;
}

// Per-round times (ms) of one configuration, and per-round GPU/CPU ratios of wall time.
struct ComputeTimes {
  std::vector<double> gpu, gpu_device, fftw1, fftw2, ratio1, ratio2;
};

ComputeTimes time_ocean_step(vk::Context& ctx, const ocean::OceanParams& params, int rounds) {
  ocean::GpuOcean gpu(ctx, params);
  FftwOceanStep cpu1(params, gpu.spectra(), 1), cpu2(params, gpu.spectra(), 2);
  // One scope around the whole step: its device time, without the submit and wait the wall time has.
  vk::GpuTimer timer(ctx, 1);
  float t = 0;
  auto gpu_step = [&] {
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      vk::GpuScope scope(timer, cmd, "ocean step");
      gpu.record_step(cmd, t, 1 / 60.0);
    });
  };
  for (int w = 0; w < 3; ++w) gpu_step(), cpu1.step(t, 1 / 60.f), cpu2.step(t, 1 / 60.f);  // JIT, caches
  ComputeTimes times;
  for (int r = 0; r < rounds; ++r) {
    t += 1 / 60.f;
    times.gpu.push_back(time_ms(gpu_step));
    if (const auto device = timer.results(); !device.empty()) times.gpu_device.push_back(device[0].ms);
    times.fftw1.push_back(time_ms([&] { cpu1.step(t, 1 / 60.f); }));
    times.fftw2.push_back(time_ms([&] { cpu2.step(t, 1 / 60.f); }));
    times.ratio1.push_back(times.gpu.back() / times.fftw1.back());
    times.ratio2.push_back(times.gpu.back() / times.fftw2.back());
  }
  return times;
}

// Every surface model's step at 3 x 256² (issue 15's budget: none costs more than fft), in the same run and
// order as the rows above; the ratio column is the model's time over fft's.
bool bench_models(vk::Context& ctx, int rounds, nlohmann::json& results) {
  ocean::OceanParams params = bench_params(256, 3);
  double fft_ms = 0;
  for (ocean::SurfaceModel m : ocean::kSurfaceModels) {
    params.model = m;
    params.choppiness = m == ocean::SurfaceModel::Sines ? 0.0 : 1.0;  // sines moves points only vertically
    if (auto valid = ocean::validate(params); !valid) {
      std::fprintf(stderr, "lagoon bench: model %s: %s\n", ocean::to_string(m),
                   valid.error().message.c_str());
      return false;
    }
    const StepTime t = time_model_step(ctx, params, rounds);
    if (m == ocean::SurfaceModel::Fft) fft_ms = t.device_ms;
    const std::vector<double>& times = t.device_rounds.empty() ? t.wall_rounds : t.device_rounds;
    report_row(results, std::string("model_step/") + ocean::to_string(m) + "/N=256/cascades=3", times,
               t.device_rounds.empty() ? "wall" : "gpu timestamps", fft_ms > 0 ? t.device_ms / fft_ms : 0);
  }
  return true;
}

int run_bench_compute(const ParsedArgs& args, int rounds) {
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  std::printf(
      "device: %s (%s); %d rounds per configuration, medians; ratio = median of per-round GPU/CPU wall "
      "time\n",
      ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), rounds);
  std::printf("%-44s %12s %12s\n", "Benchmark", "Time (ms)", "Ratio");

  nlohmann::json results = nlohmann::json::array();
  for (uint32_t n : {128u, 256u, 512u}) {
    for (uint32_t count : {1u, 3u}) {
      const ocean::OceanParams params = bench_params(n, count);
      if (auto valid = ocean::validate(params); !valid) {
        std::fprintf(stderr, "lagoon bench: %s\n", valid.error().message.c_str());
        return kExitFailure;
      }
      const ComputeTimes times = time_ocean_step(*ctx, params, rounds);
      const std::string config = "/N=" + std::to_string(n) + "/cascades=" + std::to_string(count);
      report_row(results, "ocean_step/gpu" + config, times.gpu, "wall", 0);
      if (!times.gpu_device.empty())
        report_row(results, "ocean_step/gpu_timestamps" + config, times.gpu_device, "gpu timestamps", 0);
      report_row(results, "ocean_step/fftw_1thread" + config, times.fftw1, "wall", median(times.ratio1));
      report_row(results, "ocean_step/fftw_2threads" + config, times.fftw2, "wall", median(times.ratio2));
    }
  }
  if (!bench_models(*ctx, rounds, results)) return kExitFailure;
  if (auto path = args.get("json")) {
    const nlohmann::json doc{{"context", report_context(*ctx, rounds)}, {"benchmarks", results}};
    if (!write_report(*path, doc)) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return validation_status(*ctx);
}

// One step of the dynamic wave layer (issue 14's wakes) with two hulls: on the device (wall time and GPU
// timestamps) against the CPU reference in double precision (2 threads), for N = 256, 512 and 1024.
int run_bench_wakes(const ParsedArgs& args, int rounds) {
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  std::printf("device: %s (%s); %d rounds per configuration, medians; ratio = GPU / CPU wall time\n",
              ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), rounds);
  std::printf("%-44s %12s %12s\n", "Benchmark", "Time (ms)", "Ratio");
  nlohmann::json results = nlohmann::json::array();
  const std::vector<ocean::WakeSource> hulls{
      {.centre = {10, 20}, .velocity = {6, 0}, .heading = 1.57, .sigma = {1.25, 0.5}, .depression = 0.3},
      {.centre = {-5, 12}, .velocity = {0, 1.5}, .sigma = {0.5, 0.08}, .depression = 0.16, .depth = 4.4}};
  for (uint32_t n : {256u, 512u, 1024u}) {
    const ocean::DynamicLayerParams params{.n = n};
    ocean::DynamicLayerGpu gpu(*ctx, params);
    ocean::DynamicLayerCpu cpu(params, 2);
    vk::GpuTimer timer(*ctx, 1);
    auto gpu_step = [&] {
      ctx->submit_and_wait([&](VkCommandBuffer cmd) {
        timer.reset(cmd);
        vk::GpuScope scope(timer, cmd, "wake step");
        gpu.record_step(cmd, 0.1, hulls);
      });
    };
    for (int w = 0; w < 2; ++w) gpu_step();  // lavapipe compiles at the first dispatch
    std::vector<double> wall, device, reference, ratio;
    for (int r = 0; r < rounds; ++r) {
      wall.push_back(time_ms(gpu_step));
      if (const auto d = timer.results(); !d.empty()) device.push_back(d[0].ms);
      if (r < 3) reference.push_back(time_ms([&] { cpu.step(0.1, hulls); }));  // slow: three are enough
      ratio.push_back(wall.back() / reference.back());
    }
    const std::string config = "/N=" + std::to_string(n);
    report_row(results, "wake_step/gpu" + config, wall, "wall", 0);
    if (!device.empty())
      report_row(results, "wake_step/gpu_timestamps" + config, device, "gpu timestamps", 0);
    report_row(results, "wake_step/cpu_double_2threads" + config, reference, "wall", median(ratio));
  }
  if (auto path = args.get("json")) {
    const nlohmann::json doc{{"context", report_context(*ctx, rounds)}, {"benchmarks", results}};
    if (!write_report(*path, doc)) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return validation_status(*ctx);
}

struct FrameSize {
  long long width = 1280, height = 720;
};

// --width and --height of bench render; nullopt (after printing why) when either is out of range.
std::optional<FrameSize> frame_size_option(const ParsedArgs& args) {
  FrameSize size;
  for (auto [name, value] : {std::pair{"width", &size.width}, std::pair{"height", &size.height}}) {
    const auto v = integer_option(args, name, *value, 16, 8192);
    if (!v) {
      std::fprintf(stderr, "lagoon bench render: %s\n", v.error().message.c_str());
      return std::nullopt;
    }
    *value = *v;
  }
  return size;
}

// Each pass's GPU time and the frame's wall time over `rounds` frames, after two warm-up frames.
struct RenderTimes {
  std::vector<std::pair<std::string, std::vector<double>>> passes;  // in recording order
  std::vector<double> frame;
};

RenderTimes time_frames(render::OceanRenderer& renderer, scene::Scene& scene, int rounds) {
  RenderTimes times;
  std::vector<vk::PassTime> timings;
  const float t0 = scene.time_s;
  for (int w = 0; w < 2; ++w) renderer.render(scene, &timings);
  for (int r = 0; r < rounds; ++r) {
    scene.time_s = t0 + float(r) / 30.0f;
    times.frame.push_back(time_ms([&] { renderer.render(scene, &timings); }));
    for (size_t i = 0; i < timings.size(); ++i) {
      if (times.passes.size() <= i) times.passes.push_back({timings[i].name, {}});
      times.passes[i].second.push_back(timings[i].ms);
    }
  }
  return times;
}

// Prints the table and returns the "benchmarks" array of the JSON report.
nlohmann::json report_render(const RenderTimes& times) {
  std::printf("%-34s %12s\n", "Pass (GPU timestamps)", "Time (ms)");
  nlohmann::json results = nlohmann::json::array();
  for (const auto& [name, ms] : times.passes) {
    std::printf("%-34s %12.3f\n", name.c_str(), median(ms));
    results.push_back(result_entry("render/pass/" + name, ms, "gpu timestamps"));
  }
  const Spread frame = spread(times.frame);
  std::printf("%-34s %12.3f (min %.3f, max %.3f)\n", "frame (wall, incl. readback)", frame.median, frame.min,
              frame.max);
  results.push_back(result_entry("render/frame", times.frame, "wall"));
  std::printf(
      "GPU timestamps of passes on lavapipe can read low: its rasteriser threads may finish after the\n"
      "closing timestamp. The frame's wall time is the reliable figure.\n");
  return results;
}

// One frame of a scene: wall time of render() (submit, wait, readback) and each pass's GPU time.
int run_bench_render(const ParsedArgs& args, int rounds) {
  const auto size = frame_size_option(args);
  if (!size) return kExitUsage;
  if (args.has("baseline")) return run_bench_baseline(args, rounds, size->width, size->height);
  ParsedArgs scene_args = args;
  if (!args.has("scene")) scene_args.add("scene", "scenes/default.json");
  auto scene = load_scene_from_args(
      scene_args, "bench",
      {"render.width=" + std::to_string(size->width), "render.height=" + std::to_string(size->height)});
  if (!scene) return kExitFailure;
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  auto renderer = render::OceanRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "lagoon bench: %s\n", renderer.error().message.c_str());
    return kExitFailure;
  }
  std::printf("device: %s (%s); scene %s at %lldx%lld; %d frames after 2 warm-up frames, medians\n",
              ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), scene->source.c_str(),
              size->width, size->height, rounds);
  nlohmann::json results = report_render(time_frames(**renderer, *scene, rounds));
  WaterShare water;
  try {
    water = bench_water_share(*ctx, *scene, rounds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lagoon bench: %s\n", e.what());
    return kExitFailure;
  }
  for (const nlohmann::json& row : water.rows) results.push_back(row);
  if (auto path = args.get("json")) {
    nlohmann::json context = report_context(*ctx, rounds);
    context["water_colour_share_of_frame"] = water.share;
    context["water_colour_per_frame_ms"] = water.per_frame_ms;
    context["scene"] = scene->source;
    context["width"] = size->width;
    context["height"] = size->height;
    if (!write_report(*path, {{"context", context}, {"benchmarks", results}})) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return validation_status(*ctx);
}

// Options that only bench render (and bench bodies: --scene, --set) reads; the others refuse them rather
// than silently ignoring them.
std::optional<std::string> render_only_option(const ParsedArgs& args, const std::string& what) {
  for (const char* name : {"scene", "set", "width", "height", "baseline", "baseline-scenes"})
    if (args.has(name) && !(what == "bodies" && (std::string(name) == "scene" || std::string(name) == "set")))
      return std::string(name);
  return std::nullopt;
}

int run_bench(const ParsedArgs& args) {
  const std::string what = args.get("what").value_or("");
  for (const char* name : {"path", "fps", "out"})
    if (args.has(name) && what != "effects") {
      std::fprintf(stderr, "lagoon bench: --%s applies to 'bench effects' only\n", name);
      return kExitUsage;
    }
  if (what == "effects") {
    if (args.has("rounds") || args.has("json")) {
      std::fprintf(stderr,
                   "lagoon bench effects: --%s does not apply: the flight's frames are the rounds and "
                   "--out receives effects.json\n",
                   args.has("rounds") ? "rounds" : "json");
      return kExitUsage;
    }
    const auto size = frame_size_option(args);
    if (!size) return kExitUsage;
    return run_bench_effects(args, size->width, size->height);
  }
  if (what == "compute" || what == "render" || what == "wakes" || what == "bodies") {
    if (const auto option = render_only_option(args, what); what != "render" && option) {
      std::fprintf(stderr, "lagoon bench: --%s applies to 'bench render' only\n", option->c_str());
      return kExitUsage;
    }
    const auto rounds = rounds_option(args, what == "render" ? 10 : 15);
    if (!rounds) return kExitUsage;
    if (what == "wakes") return run_bench_wakes(args, *rounds);
    if (what == "bodies") return run_bench_bodies(args, *rounds);
    return what == "compute" ? run_bench_compute(args, *rounds) : run_bench_render(args, *rounds);
  }
  std::fprintf(stderr,
               "lagoon bench: unknown benchmark '%s'; available: compute, render, wakes, bodies, effects\n",
               what.c_str());
  return kExitUsage;
}

}  // namespace

const Command& bench_command() {
  static const Command command{
      .spec =
          {.name = "bench",
           .summary =
               "Measures performance side by side in one run. 'compute': the GPU ocean step on the "
               "chosen device (wall time and GPU timestamps) against the same step on the CPU with FFTW "
               "(1 and 2 threads), for N = 128, 256, 512 and 1 or 3 cascades; ratio = GPU wall time / "
               "CPU time. 'render': each pass of a scene's frame (GPU timestamps) and the whole frame "
               "(wall time, with readback). 'wakes': one step of the dynamic wave layer with two hulls "
               "(N = 256, 512, 1024) on the device against its CPU reference in double precision. 'bodies': "
               "the floating objects' and vehicles' physics of a scene per 60 Hz frame on the CPU (mean "
               "and worst frame of each second), frames back to back as in a catch-up (frame_ rows) and "
               "each at its slot of a 60 Hz clock as in a live loop (paced_ rows), with and without the "
               "wakes felt. 'effects': the MARS "
               "thesis's "
               "evaluation (tables 4.3-4.7): a scripted camera flight with no effects, each effect alone and "
               "all effects, min/avg/max FPS and per-pass GPU time, written as JSON, CSV, Markdown and a bar "
               "chart PNG (docs/evaluation.md).",
           .options =
               {{"what", "compute|render|wakes|bodies|effects",
                 "which benchmark: compute, render, wakes, bodies or effects", true},
                {"scene", "FILE",
                 "render: the scene (default scenes/default.json); bodies and effects: the scene "
                 "(default scenes/harbour.json)"},
                set_option(),
                {"width", "W", "render, effects: frame width in pixels, 16 to 8192 (default 1280)"},
                {"height", "H", "render, effects: frame height in pixels, 16 to 8192 (default 720)"},
                {"path", "PATH.json",
                 "effects: the camera flight (default scenes/paths/evaluation.json; docs/datasets.md)"},
                {"fps", "F",
                 "effects: frames per second of path time, 0.1 to 240 (default 10: 221 frames along the "
                 "default 22 s flight)"},
                {"out", "DIR",
                 "effects: folder for effects.json, effects.csv, effects.md and effects.png (default "
                 "out/bench-effects)"},
                {"json", "FILE",
                 "also write the results as Google Benchmark-style JSON: a \"context\" object "
                 "(device, type, driver, driver version, Vulkan API version, rounds) and "
                 "\"benchmarks\" (median real_time, min_time, max_time in ms; measure = \"gpu "
                 "timestamps\" or \"wall\")"},
                {"baseline", "OTHER_LAGOON",
                 "render: run this older build's `lagoon` (e.g. built from another commit in a git "
                 "worktree) side by side, each build in its own process, and print per-scene ratios "
                 "(this / baseline) of the frame and of each pass; without --scene, every scenes/*.json "
                 "of the working directory, skipping any the older build cannot render"},
                {"baseline-scenes", "DIR",
                 "render, with --baseline: the older build renders DIR/NAME.json, the scene of the same "
                 "name as it was at its commit (e.g. ../lagoon-base/scenes), where a scene's fields have "
                 "changed since; this build renders its own"},
                {"rounds", "R",
                 "measured rounds per configuration (default 15 compute, wakes and bodies, 10 render; "
                 "a round of bodies is 60 frames)"}},
           .positional = {"what"},
           .details = "Timings are medians after a warm-up (lavapipe compiles shaders at their first "
                      "dispatch). The machine's noise makes single numbers unreliable; compare ratios.\n"
                      "examples:\n  lagoon bench compute --rounds 5 --json out/compute.json\n"
                      "  lagoon bench render --scene scenes/open-ocean.json --width 640 --height 360\n"
                      "  lagoon bench render --baseline ../lagoon-base/build/bin/lagoon --rounds 5\n"
                      "  lagoon bench bodies --scene scenes/harbour.json --rounds 5\n"
                      "  lagoon bench effects --width 640 --height 360 --out out/effects\n"},
      .run = run_bench};
  return command;
}

}  // namespace lagoon::cli
