// lagoon bench compute: the GPU ocean step against the FFTW CPU step, measured side by side in one run.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "fftw_ocean_step.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "ocean/gpu/gpu_ocean.h"
#include "ocean/validate.h"
#include "render/ocean_renderer.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

template <typename F>
double time_ms(F&& f) {
  const auto t0 = Clock::now();
  f();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// --rounds, or `fallback`; nullopt (after printing why) when the value is not a whole number in [1, 1000].
std::optional<int> rounds_option(const ParsedArgs& args, int fallback) {
  const auto rounds = integer_option(args, "rounds", fallback, 1, 1000);
  if (!rounds) {
    std::fprintf(stderr, "lagoon bench: %s\n", rounds.error().message.c_str());
    return std::nullopt;
  }
  return int(*rounds);
}

// Writes the --json report atomically (no half-written file); false, with the reason on stderr, on failure.
bool write_report(const std::string& path, const nlohmann::json& doc) {
  const std::string text = doc.dump(2) + "\n";
  if (auto written = io::write_file_atomic(path, std::as_bytes(std::span(text.data(), text.size())));
      !written) {
    std::fprintf(stderr, "lagoon bench: %s\n", written.error().message.c_str());
    return false;
  }
  return true;
}

int run_bench_compute(const ParsedArgs& args, int rounds) {
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  std::printf("device: %s (%s); %d rounds per configuration, medians; ratio = median of per-round GPU/CPU\n",
              ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), rounds);
  std::printf("%-34s %12s %12s\n", "Benchmark", "Time (ms)", "Ratio");

  nlohmann::json results = nlohmann::json::array();
  auto report = [&](const std::string& name, double ms, double ratio) {
    std::printf("%-34s %12.3f %12s\n", name.c_str(), ms,
                ratio > 0 ? (std::to_string(ratio).substr(0, 6) + "x").c_str() : "");
    nlohmann::json entry{{"name", name},
                         {"run_type", "iteration"},
                         {"iterations", rounds},
                         {"real_time", ms},
                         {"time_unit", "ms"}};
    if (ratio > 0) entry["ratio_gpu_over_cpu"] = ratio;
    results.push_back(entry);
  };

  const double patches[] = {1000.0, 100.0, 10.0};
  for (uint32_t n : {128u, 256u, 512u}) {
    for (uint32_t count : {1u, 3u}) {
      ocean::OceanParams params;
      params.cascades.clear();
      for (uint32_t c = 0; c < count; ++c) params.cascades.push_back({patches[c], n});
      if (auto valid = ocean::validate(params); !valid) {
        std::fprintf(stderr, "lagoon bench: %s\n", valid.error().message.c_str());
        return kExitFailure;
      }
      ocean::GpuOcean gpu(*ctx, params);
      FftwOceanStep cpu1(params, gpu.spectra(), 1), cpu2(params, gpu.spectra(), 2);
      float t = 0;
      auto gpu_step = [&] {
        ctx->submit_and_wait([&](VkCommandBuffer cmd) { gpu.record_step(cmd, t, 1 / 60.0); });
      };
      for (int w = 0; w < 3; ++w) gpu_step(), cpu1.step(t, 1 / 60.f), cpu2.step(t, 1 / 60.f);  // JIT, caches
      std::vector<double> g, c1, c2, r1, r2;
      for (int r = 0; r < rounds; ++r) {
        t += 1 / 60.f;
        g.push_back(time_ms(gpu_step));
        c1.push_back(time_ms([&] { cpu1.step(t, 1 / 60.f); }));
        c2.push_back(time_ms([&] { cpu2.step(t, 1 / 60.f); }));
        r1.push_back(g.back() / c1.back());
        r2.push_back(g.back() / c2.back());
      }
      const std::string config = "/N=" + std::to_string(n) + "/cascades=" + std::to_string(count);
      report("ocean_step/gpu" + config, median(g), 0);
      report("ocean_step/fftw_1thread" + config, median(c1), median(r1));
      report("ocean_step/fftw_2threads" + config, median(c2), median(r2));
    }
  }
  if (auto path = args.get("json")) {
    const nlohmann::json doc{
        {"context",
         {{"device", ctx->device_info().name},
          {"driver", ctx->device_info().driver_name + " " + ctx->device_info().driver_info},
          {"rounds", rounds}}},
        {"benchmarks", results}};
    if (!write_report(*path, doc)) return kExitFailure;
    std::printf("wrote %s\n", path->c_str());
  }
  return validation_status(*ctx);
}

// The frame at 1280x720: wall time of render() (submit, wait, readback) and each pass's GPU time, medians.
int run_bench_render(const ParsedArgs& args, int rounds) {
  ParsedArgs scene_args = args;
  if (!args.has("scene")) scene_args.add("scene", "scenes/default.json");
  auto scene = load_scene_from_args(scene_args, "bench", {"render.width=1280", "render.height=720"});
  if (!scene) return kExitFailure;
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  auto renderer = render::OceanRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "lagoon bench: %s\n", renderer.error().message.c_str());
    return kExitFailure;
  }
  std::printf("device: %s (%s); scene %s at 1280x720; %d frames after 2 warm-up frames, medians\n",
              ctx->device_info().name.c_str(), ctx->device_info().type.c_str(), scene->source.c_str(),
              rounds);
  std::vector<vk::PassTime> timings;
  const float t0 = scene->time_s;
  for (int w = 0; w < 2; ++w) (*renderer)->render(*scene, &timings);
  std::vector<double> frame;
  std::vector<std::pair<std::string, std::vector<double>>> passes;
  for (int r = 0; r < rounds; ++r) {
    scene->time_s = t0 + float(r) / 30.0f;
    frame.push_back(time_ms([&] { (*renderer)->render(*scene, &timings); }));
    for (size_t i = 0; i < timings.size(); ++i) {
      if (passes.size() <= i) passes.push_back({timings[i].name, {}});
      passes[i].second.push_back(timings[i].ms);
    }
  }
  std::printf("%-34s %12s\n", "Pass (GPU timestamps)", "Time (ms)");
  nlohmann::json results = nlohmann::json::array();
  for (const auto& [name, ms] : passes) {
    std::printf("%-34s %12.3f\n", name.c_str(), median(ms));
    results.push_back({{"name", "render/pass/" + name},
                       {"real_time", median(ms)},
                       {"time_unit", "ms"},
                       {"iterations", rounds}});
  }
  std::printf("%-34s %12.3f\n", "frame (wall, incl. readback)", median(frame));
  results.push_back(
      {{"name", "render/frame"}, {"real_time", median(frame)}, {"time_unit", "ms"}, {"iterations", rounds}});
  std::printf(
      "GPU timestamps of passes on lavapipe can read low: its rasteriser threads may finish after the\n"
      "closing timestamp. The frame's wall time is the reliable figure.\n");
  if (auto path = args.get("json")) {
    const nlohmann::json doc{{"context", {{"device", ctx->device_info().name}, {"rounds", rounds}}},
                             {"benchmarks", results}};
    if (!write_report(*path, doc)) return kExitFailure;
  }
  return validation_status(*ctx);
}

int run_bench(const ParsedArgs& args) {
  const std::string what = args.get("what").value_or("");
  if (what == "compute" || what == "render") {
    const auto rounds = rounds_option(args, what == "compute" ? 15 : 10);
    if (!rounds) return kExitUsage;
    return what == "compute" ? run_bench_compute(args, *rounds) : run_bench_render(args, *rounds);
  }
  std::fprintf(stderr, "lagoon bench: unknown benchmark '%s'; available: compute, render\n", what.c_str());
  return kExitUsage;
}

}  // namespace

const Command& bench_command() {
  static const Command command{
      .spec = {.name = "bench",
               .summary =
                   "Measures performance side by side in one run. 'compute': the GPU ocean step on the "
                   "chosen device against the same step on the CPU with FFTW (1 and 2 threads), for "
                   "N = 128, 256, 512 and 1 or 3 cascades; ratio = GPU time / CPU time.",
               .options = {{"what", "compute|render", "which benchmark: compute or render", true},
                           {"scene", "FILE", "render: the scene (default scenes/default.json), at 1280x720"},
                           set_option(),
                           {"json", "FILE", "also write the results as Google Benchmark-style JSON"},
                           {"rounds", "R", "measured rounds per configuration (default 15)"}},
               .positional = {"what"},
               .details =
                   "Timings are wall-clock medians after a warm-up (lavapipe compiles shaders at their "
                   "first dispatch). The machine's noise makes single numbers unreliable; compare ratios.\n"},
      .run = run_bench};
  return command;
}

}  // namespace lagoon::cli
