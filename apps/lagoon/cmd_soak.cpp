// lagoon soak: a long run that must stay healthy. The ocean is stepped many times and many frames are
// rendered; after every step and frame the GPU counts non-finite texels in the fields, resident memory
// after a warm-up must not grow by 1 % or more, and the validation layer (always on here) must stay silent.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "commands.h"
#include "gpu_session.h"
#include "ocean/gpu/field_check.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/ocean_renderer.h"
#include "scene_args.h"
#include "vk/context.h"

namespace lagoon::cli {
namespace {

// Resident set size from /proc/self/statm, in bytes.
uint64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * uint64_t(::sysconf(_SC_PAGESIZE));
}

// One phase's figures: units run, non-finite texels seen, memory after the warm-up and at the end.
struct Phase {
  const char* name;
  long long units = 0;
  uint64_t non_finite = 0;
  long long first_bad_unit = -1;
  uint64_t rss_after_warmup = 0, rss_end = 0, rss_peak = 0;

  double growth_percent() const {
    return rss_after_warmup == 0
               ? 0.0
               : 100.0 * (double(rss_end) - double(rss_after_warmup)) / double(rss_after_warmup);
  }
  // Called after each unit; the first tenth of the run is the warm-up (pools, caches, lazily built
  // pipelines).
  void account(long long unit, long long total, uint64_t bad) {
    units = unit + 1;
    if (bad > 0 && first_bad_unit < 0) first_bad_unit = unit;
    non_finite += bad;
    const uint64_t rss = resident_bytes();
    if (unit + 1 == std::max(1LL, total / 10)) rss_after_warmup = rss;
    if (rss_after_warmup > 0) rss_peak = std::max(rss_peak, rss);
    rss_end = rss;
  }
  void print() const {
    std::printf(
        "%-7s %lld  non-finite texels %llu%s  RSS after warm-up %.1f MiB, end %.1f MiB, peak %.1f MiB: "
        "%+.2f %%\n",
        name, units, static_cast<unsigned long long>(non_finite),
        first_bad_unit >= 0 ? (" (first at " + std::to_string(first_bad_unit) + ")").c_str() : "",
        double(rss_after_warmup) / 1048576.0, double(rss_end) / 1048576.0, double(rss_peak) / 1048576.0,
        growth_percent());
  }
};

void progress(const char* what, long long done, long long total) {
  if (done == total || done % std::max(1LL, total / 100) == 0)
    std::fprintf(stderr, "\rlagoon soak: %s %lld/%lld", what, done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

// Steps a GPU ocean of the scene `steps` times, `batch` steps per submission, checking every step.
Phase soak_ocean(vk::Context& ctx, const scene::Scene& scene, long long steps, double dt) {
  Phase phase{"steps"};
  ocean::GpuOcean gpu(ctx, scene.ocean);
  ocean::FieldCheck check(ctx);
  constexpr long long kBatch = 10;
  for (long long s = 0; s < steps;) {
    const long long end = std::min(steps, s + kBatch);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) {
      for (long long k = s; k < end; ++k) {
        gpu.record_step(cmd, scene.time_s + double(k) * dt, k == 0 ? 0.0 : dt);
        check.record(cmd, gpu);
      }
    });
    const uint64_t bad = check.take();
    for (; s < end; ++s) phase.account(s, steps, s + 1 == end ? bad : 0);
    progress("ocean step", s, steps);
  }
  return phase;
}

// Renders `frames` frames at successive times through the whole renderer, checking its ocean each frame.
Result<Phase> soak_frames(vk::Context& ctx, scene::Scene scene, long long frames, double dt) {
  Phase phase{"frames"};
  auto renderer = render::OceanRenderer::create(ctx, scene);
  if (!renderer) return renderer.error();
  ocean::FieldCheck check(ctx);
  const double t0 = scene.time_s;
  for (long long f = 0; f < frames; ++f) {
    scene.time_s = float(t0 + double(f) * dt);
    (void)(*renderer)->render(scene);
    ctx.submit_and_wait([&](VkCommandBuffer cmd) { check.record(cmd, (*renderer)->ocean()); });
    phase.account(f, frames, check.take());
    progress("frame", f + 1, frames);
  }
  return phase;
}

int run_soak(const ParsedArgs& args) {
  const auto steps = integer_option(args, "steps", 10000, 0, 10000000);
  const auto frames = integer_option(args, "frames", 2000, 0, 10000000);
  const auto width = integer_option(args, "width", 640, 16, 8192);
  const auto height = integer_option(args, "height", 360, 16, 8192);
  for (const auto* r : {&steps, &frames, &width, &height})
    if (!*r) {
      std::fprintf(stderr, "lagoon soak: %s\n", r->error().message.c_str());
      return kExitUsage;
    }
  const auto max_growth = number_option(args, "max-growth", 1.0, 0.0, 1000.0);
  if (!max_growth) {
    std::fprintf(stderr, "lagoon soak: %s\n", max_growth.error().message.c_str());
    return kExitUsage;
  }
  auto scene = load_scene_from_args(
      args, "soak", {"render.width=" + std::to_string(*width), "render.height=" + std::to_string(*height)});
  if (!scene) return kExitFailure;
  vk::ContextOptions options = vk::ContextOptions::from_environment();
  options.validation = true;  // a soak is also a check that the validation layer stays silent
  auto ctx = vk::Context::create(options);
  if (!ctx) {
    std::fprintf(stderr, "lagoon soak: %s\n", ctx.error().message.c_str());
    return kExitFailure;
  }
  const double dt = 1.0 / 30.0;
  std::vector<Phase> phases;
  if (*steps > 0) phases.push_back(soak_ocean(**ctx, *scene, *steps, dt));
  if (*frames > 0) {
    auto phase = soak_frames(**ctx, *scene, *frames, dt);
    if (!phase) {
      std::fprintf(stderr, "lagoon soak: %s: %s\n", scene->source.c_str(), phase.error().message.c_str());
      return kExitFailure;
    }
    phases.push_back(*phase);
  }
  std::printf("soak of %s on %s (%dx%d frames)\n", scene->source.c_str(), (*ctx)->device_info().name.c_str(),
              int(*width), int(*height));
  bool healthy = true;
  for (const Phase& p : phases) {
    p.print();
    healthy = healthy && p.non_finite == 0 && p.growth_percent() < *max_growth;
  }
  const uint32_t validation_errors = (*ctx)->validation().failures();
  std::printf("validation errors %u\n", validation_errors);
  if (validation_errors > 0) return kExitValidation;
  if (healthy)
    std::printf("healthy\n");
  else
    std::printf("NOT healthy: non-finite fields or resident memory grew by %g %% or more\n", *max_growth);
  return healthy ? kExitOk : kExitFailure;
}

}  // namespace

const Command& soak_command() {
  static const Command command{
      .spec = {.name = "soak",
               .summary =
                   "Long-run check: steps the ocean and renders frames, checking every step and frame for "
                   "NaN/Inf in the fields, resident-memory growth after warm-up (below --max-growth) and "
                   "validation errors (the layer is always on).",
               .options = {scene_option(),
                           {"steps", "N", "ocean steps of 1/30 s (default 10000; 0 skips the phase)"},
                           {"frames", "N",
                            "frames rendered through the whole renderer (default 2000; 0 skips)"},
                           {"width", "W", "frame width (default 640)"},
                           {"height", "H", "frame height (default 360)"},
                           {"max-growth", "PERCENT",
                            "largest allowed resident-memory growth after warm-up (default 1)"},
                           set_option()},
               .details =
                   "The first tenth of each phase is its warm-up; memory is compared from there to the end.\n"
                   "Exit 0 when healthy, 1 when a field held NaN/Inf or memory grew, 3 on validation "
                   "errors.\nexample:\n  lagoon soak --scene scenes/default.json --steps 10000 --frames "
                   "2000\n"},
      .run = run_soak};
  return command;
}

}  // namespace lagoon::cli
