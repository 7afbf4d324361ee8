// lagoon soak: a long run that must stay healthy. The ocean is stepped many times and many frames are
// rendered; after every step and frame the GPU counts non-finite texels in the fields, and resident memory
// after a warm-up must not grow by 1 % or more. With --validation the layer must also stay silent (it keeps
// 2-4 KB of its own per queue submission, so long runs with it need a larger --max-growth;
// docs/reliability.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "commands.h"
#include "core/free_heap.h"
#include "gpu_session.h"
#include "io/atomic_file.h"
#include "ocean/gpu/field_check.h"
#include "ocean/gpu/gpu_ocean.h"
#include "render/ocean_renderer.h"
#include "scene_args.h"
#include "vk/context.h"

namespace lagoon::cli {
namespace {

// Resident set size from /proc/self/statm, in bytes. The heap's free memory is handed back first: memory a
// compiler or a warm-up freed stays resident otherwise, and later allocations (a leak among them) fill it
// without the resident set growing (15 MiB of it hid a 5 MiB leak once shader compilation grew).
uint64_t resident_bytes() {
  release_free_heap();
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
  std::vector<uint64_t> samples;  // resident set after each unit, bytes
  // --retain-kib: memory deliberately kept per unit, so a run can show that the check catches a leak.
  size_t retain_bytes = 0;
  std::vector<std::vector<char>> retained;

  double growth_percent() const {
    return rss_after_warmup == 0
               ? 0.0
               : 100.0 * (double(rss_end) - double(rss_after_warmup)) / double(rss_after_warmup);
  }
  // Units of warm-up (pools, caches, lazily built pipelines, the driver's threads' first allocations);
  // memory is compared from its end. 0 = the first tenth of the run.
  long long warmup = 0;
  void account(long long unit, long long total, uint64_t bad) {
    units = unit + 1;
    if (bad > 0 && first_bad_unit < 0) first_bad_unit = unit;
    non_finite += bad;
    if (retain_bytes > 0) {
      retained.emplace_back(retain_bytes, char{1});  // written, so it is resident
    }
    const uint64_t rss = resident_bytes();
    samples.push_back(rss);
    // With the free heap trimmed a sample holds only live memory, including what a frame has in flight
    // (2-4 MiB at 64 x 36): each end is the least of up to 10 samples, so a leak raises the floor and a
    // transient does not count.
    const long long first = std::clamp(warmup > 0 ? warmup : total / 10, 1LL, total) - 1;
    const long long window = std::clamp((total - first) / 5, 1LL, 10LL);
    if (unit + 1 == std::min(first + window, total))
      rss_after_warmup = *std::min_element(samples.begin() + first, samples.end());
    if (unit >= first) rss_peak = std::max(rss_peak, rss);
    rss_end = *std::min_element(samples.end() - std::min<long long>(window, unit + 1), samples.end());
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

// --curve FILE: the resident set after every step and frame, for plotting (docs/reliability.md).
bool write_curve(const std::string& path, const std::vector<Phase>& phases) {
  std::string csv = "phase,unit,rss_mib\n";
  for (const Phase& p : phases)
    for (size_t i = 0; i < p.samples.size(); ++i)
      csv += std::string(p.name) + "," + std::to_string(i + 1) + "," +
             std::to_string(double(p.samples[i]) / 1048576.0) + "\n";
  std::vector<std::byte> bytes(csv.size());
  std::memcpy(bytes.data(), csv.data(), csv.size());
  if (auto r = io::write_file_atomic(path, bytes); !r) {
    std::fprintf(stderr, "lagoon soak: --curve: %s\n", r.error().message.c_str());
    return false;
  }
  return true;
}

void progress(const char* what, long long done, long long total) {
  if (done == total || done % std::max(1LL, total / 100) == 0)
    std::fprintf(stderr, "\rlagoon soak: %s %lld/%lld", what, done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

// Steps a GPU ocean of the scene `steps` times, `batch` steps per submission, checking every step.
Phase soak_ocean(vk::Context& ctx, const scene::Scene& scene, long long steps, double dt, const Phase& how) {
  Phase phase = how;
  phase.name = "steps";
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
Result<Phase> soak_frames(vk::Context& ctx, scene::Scene scene, long long frames, double dt,
                          const Phase& how) {
  Phase phase = how;
  phase.name = "frames";
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
  const auto retain_kib = integer_option(args, "retain-kib", 0, 0, 65536);
  const auto warmup = integer_option(args, "warmup", 0, 0, 10000000);
  for (const auto* r : {&retain_kib, &warmup})
    if (!*r) {
      std::fprintf(stderr, "lagoon soak: %s\n", r->error().message.c_str());
      return kExitUsage;
    }
  if (!max_growth) {
    std::fprintf(stderr, "lagoon soak: %s\n", max_growth.error().message.c_str());
    return kExitUsage;
  }
  Phase how{""};
  how.retain_bytes = size_t(*retain_kib) * 1024;
  how.warmup = *warmup;
  auto scene = load_scene_from_args(
      args, "soak", {"render.width=" + std::to_string(*width), "render.height=" + std::to_string(*height)});
  if (!scene) return kExitFailure;
  vk::ContextOptions options = vk::ContextOptions::from_environment();
  // The layer's own bookkeeping grows with every submission, so memory is judged only without it.
  const bool validation = args.has("validation") || options.validation;
  options.validation = validation;
  auto ctx = vk::Context::create(options);
  if (!ctx) {
    std::fprintf(stderr, "lagoon soak: %s\n", ctx.error().message.c_str());
    return kExitFailure;
  }
  const double dt = 1.0 / 30.0;
  std::vector<Phase> phases;
  if (*steps > 0) phases.push_back(soak_ocean(**ctx, *scene, *steps, dt, how));
  if (*frames > 0) {
    auto phase = soak_frames(**ctx, *scene, *frames, dt, how);
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
  if (auto curve = args.get("curve"); curve && !write_curve(*curve, phases)) return kExitFailure;
  if (validation) {
    const uint32_t validation_errors = (*ctx)->validation().failures();
    std::printf("validation errors %u\n", validation_errors);
    if (validation_errors > 0) return kExitValidation;
  }
  if (healthy)
    std::printf("healthy\n");
  else
    std::printf("NOT healthy: non-finite fields or resident memory grew by %g %% or more\n", *max_growth);
  return healthy ? kExitOk : kExitFailure;
}

}  // namespace

const Command& soak_command() {
  static const Command command{
      .spec =
          {.name = "soak",
           .summary = "Long-run check: steps the ocean and renders frames, checking every step and frame for "
                      "NaN/Inf in the fields and resident-memory growth after warm-up (below --max-growth), "
                      "and with --validation for validation errors.",
           .options = {scene_option(),
                       {"steps", "N", "ocean steps of 1/30 s (default 10000; 0 skips the phase)"},
                       {"frames", "N", "frames rendered through the whole renderer (default 2000; 0 skips)"},
                       {"width", "W", "frame width (default 640)"},
                       {"height", "H", "frame height (default 360)"},
                       {"max-growth", "PERCENT",
                        "largest allowed resident-memory growth after warm-up (default 1)"},
                       {"validation", "",
                        "run with the Vulkan validation layer (also LAGOON_VALIDATION=1) and fail on any "
                        "of its messages; the layer itself keeps 2-4 KB per submission"},
                       {"warmup", "N",
                        "steps and frames of warm-up before memory is measured (default: a tenth of "
                        "each phase)"},
                       {"curve", "FILE", "write the resident set after every step and frame (CSV)"},
                       {"retain-kib", "N",
                        "self-test of the memory check: keep N KiB alive per step and frame (default 0)"},
                       set_option()},
           .details =
               "The warm-up (--warmup, else the first tenth of each phase) fills pools and caches; memory "
               "is compared from its end to the end of the phase.\n"
               "Exit 0 when healthy, 1 when a field held NaN/Inf or memory grew, 3 on validation "
               "errors (--validation).\nexample:\n  lagoon soak --scene scenes/default.json --steps 10000 "
               "--frames "
               "2000\n"},
      .run = run_soak};
  return command;
}

}  // namespace lagoon::cli
