// lagoon render: one frame of a scene, headless, to a PNG.
#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "core/stage_times.h"
#include "dataset/ground_truth.h"
#include "dataset/render_sequence.h"
#include "dataset/sequence.h"
#include "gpu_session.h"
#include "io/png.h"
#include "io/sha256.h"
#include "render/cold_compile.h"
#include "render/ocean_renderer.h"
#include "scene/scene.h"
#include "scene_args.h"

namespace lagoon::cli {
namespace {

// --width/--height/--time are shorthands for --set, so they are validated exactly like the scene file.
// nullopt (after printing why) when one is not a number.
std::optional<std::vector<std::string>> shorthand_overrides(const ParsedArgs& args) {
  std::vector<std::string> overrides;
  for (const char* key : {"width", "height"}) {
    if (auto v = args.get(key)) {
      if (!parse_integer(*v)) {
        std::fprintf(stderr, "lagoon render: --%s %s is not a whole number of pixels\n", key, v->c_str());
        return std::nullopt;
      }
      overrides.push_back(std::string("render.") + key + "=" + *v);
    }
  }
  if (auto v = args.get("time")) {
    if (!parse_number(*v)) {
      std::fprintf(stderr, "lagoon render: --time %s is not a number of seconds\n", v->c_str());
      return std::nullopt;
    }
    overrides.push_back("time_s=" + *v);
  }
  return overrides;
}

// --frames, --fps and --shard. nullopt (after printing why) when one is out of range.
std::optional<dataset::FrameSequence> frame_sequence_option(const ParsedArgs& args) {
  dataset::FrameSequence sequence;
  const auto frames_arg = integer_option(args, "frames", 1, 1, 100000);
  if (!frames_arg) {
    std::fprintf(stderr, "lagoon render: %s\n", frames_arg.error().message.c_str());
    return std::nullopt;
  }
  sequence.frames = *frames_arg;
  if (auto v = args.get("fps")) {
    auto f = parse_number(*v);
    if (!f || *f <= 0 || *f > 1000) {
      std::fprintf(stderr, "lagoon render: --fps %s must be a number of frames per second in (0, 1000]\n",
                   v->c_str());
      return std::nullopt;
    }
    sequence.fps = *f;
  }
  if (auto v = args.get("shard")) {
    Result<dataset::Shard> shard = dataset::parse_shard(*v);
    if (!shard) {
      std::fprintf(stderr, "lagoon render: %s\n", shard.error().message.c_str());
      return std::nullopt;
    }
    sequence.shard = *shard;
  }
  return sequence;
}

// The camera flight of --path, checked to cover every frame. nullopt (after printing why) when it cannot be
// read or is too short; an absent --path gives an empty optional in the Result.
std::optional<std::optional<scene::CameraPath>> camera_path_option(const ParsedArgs& args,
                                                                   const dataset::FrameSequence& sequence) {
  const auto file = args.get("path");
  if (!file) return std::optional<scene::CameraPath>{};
  Result<scene::CameraPath> path = scene::load_camera_path(*file);
  if (!path) {
    std::fprintf(stderr, "lagoon render: %s\n", path.error().message.c_str());
    return std::nullopt;
  }
  const double needed = sequence.offset_s(sequence.frames - 1);
  if (needed > path->duration_s() + 1e-9) {
    std::fprintf(
        stderr,
        "lagoon render: %s: the path lasts %.3g s but --frames %lld at --fps %.3g needs %.3g s; render "
        "fewer frames, raise --fps or add keyframes\n",
        file->c_str(), path->duration_s(), sequence.frames, sequence.fps, needed);
    return std::nullopt;
  }
  return std::optional<scene::CameraPath>(std::move(*path));
}

// --aov's comma-separated list, each once, in the order given. nullopt (after printing why) for an unknown
// one.
std::optional<std::vector<std::string>> aov_option(const ParsedArgs& args) {
  std::vector<std::string> aovs;
  const std::string list = args.get("aov").value_or("");
  for (size_t start = 0; start < list.size();) {
    size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    const std::string name = list.substr(start, end - start);
    start = end + 1;
    if (!dataset::find_aov(name)) {
      std::fprintf(stderr, "lagoon render: --aov %s: unknown ground truth '%s'; available: %s\n",
                   list.c_str(), name.c_str(), dataset::aov_names().c_str());
      return std::nullopt;
    }
    if (std::find(aovs.begin(), aovs.end(), name) == aovs.end()) aovs.push_back(name);
  }
  if (args.has("aov") && aovs.empty()) {
    std::fprintf(stderr, "lagoon render: --aov needs a list, e.g. --aov depth,normal\n");
    return std::nullopt;
  }
  return aovs;
}

// A file's SHA-256 for the manifest's run record ("" when unreadable: loading it reports why).
std::string checksum(const std::string& file) {
  Result<std::string> sha = io::sha256_file(file);
  return sha ? *sha : "";
}

// What the manifest records as the run: two shards may share a folder only when all of it is equal.
nlohmann::json run_record(const ParsedArgs& args, const std::vector<std::string>& overrides,
                          const dataset::FrameSequence& sequence) {
  nlohmann::json run{{"scene", *args.get("scene")},
                     {"scene_sha256", checksum(*args.get("scene"))},
                     {"set", overrides},
                     {"frames", sequence.frames},
                     {"fps", sequence.fps},
                     {"shards", sequence.shard.count}};
  for (const std::string& s : args.all("set")) run["set"].push_back(s);
  if (auto path = args.get("path")) run["path"] = {{"file", *path}, {"sha256", checksum(*path)}};
  if (auto aov = args.get("aov")) run["aov"] = *aov;
  return run;
}

// What was written, on which device, and each pass's GPU time.
void print_summary(const std::string& out_path, const io::Image8& image, const scene::Scene& scene,
                   const vk::Context& ctx, const std::vector<vk::PassTime>& timings) {
  std::printf("wrote %s (%ux%u, t = %.2f s) on %s (%s)\n", out_path.c_str(), image.width, image.height,
              scene.time_s, ctx.device_info().name.c_str(), ctx.device_info().type.c_str());
  for (const auto& t : timings) std::printf("  %-10s %8.2f ms GPU\n", t.name.c_str(), t.ms);
}

// Progress on stderr: a bar of this shard's frames, with those an earlier run finished.
void print_progress(size_t done, size_t total, size_t skipped) {
  const int bar = int(40 * done / std::max<size_t>(total, 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu frames", std::string(bar, '#').c_str(),
               std::string(40 - bar, ' ').c_str(), done, total);
  if (skipped) std::fprintf(stderr, " (%zu already done)", skipped);
}

int render_sequence(const ParsedArgs& args, const std::vector<std::string>& overrides,
                    const dataset::FrameSequence& sequence, const std::optional<scene::CameraPath>& path,
                    const std::vector<std::string>& aovs, const std::string& out_path, scene::Scene& scene,
                    vk::Context& ctx, render::OceanRenderer& renderer) {
  bool bar = false;
  const dataset::SequenceRun run{.out_png = out_path,
                                 .sequence = sequence,
                                 .path = path,
                                 .aovs = aovs,
                                 .run = run_record(args, overrides, sequence),
                                 .progress = [&bar](size_t done, size_t total, size_t skipped) {
                                   print_progress(done, total, skipped);
                                   bar = true;
                                 }};
  const Result<dataset::SequenceSummary> summary = dataset::render_sequence(run, scene, ctx, renderer);
  if (bar) std::fprintf(stderr, "\n");
  // A frame drawn with validation errors was not written: the exit code says why.
  if (int status = validation_status(ctx); status != kExitOk) return status;
  if (!summary) {
    std::fprintf(stderr, "lagoon render: %s\n", summary.error().message.c_str());
    return kExitFailure;
  }
  std::printf(
      "shard %lld/%lld: %zu frames of %lld (%zu rendered, %zu already done) at %.3g fps, %ux%u, on %s; "
      "manifest %s\n",
      sequence.shard.index, sequence.shard.count, summary->frames, sequence.frames,
      summary->frames - summary->skipped, summary->skipped, sequence.fps, scene.render.width,
      scene.render.height, ctx.device_info().name.c_str(), summary->manifest.c_str());
  return kExitOk;
}

// Waits for a cold start's second device: its validation errors fail the run, as the first device's do.
int finish_cold_start(std::unique_ptr<render::ColdCompile> cold, vk::Context& ctx, int status) {
  if (render::ColdCompile::finish(cold, ctx) > 0) {
    std::fprintf(stderr,
                 "lagoon: the Vulkan validation layer reported errors on the cold start's second device "
                 "(render/cold_compile.h); see the messages above\n");
    return kExitValidation;
  }
  return status;
}

int run_render(const ParsedArgs& args) {
  const std::string out_path = *args.get("out");
  if (out_path.size() < 5 || out_path.substr(out_path.size() - 4) != ".png") {
    std::fprintf(stderr, "lagoon render: --out %s must name a .png file\n", out_path.c_str());
    return kExitUsage;
  }
  const auto overrides = shorthand_overrides(args);
  if (!overrides) return kExitUsage;
  const auto sequence = frame_sequence_option(args);
  if (!sequence) return kExitUsage;
  const auto aovs = aov_option(args);
  if (!aovs) return kExitUsage;
  const auto path = camera_path_option(args, *sequence);
  if (!path) return kExitFailure;
  StageTimer t_scene("scene");
  auto scene = load_scene_from_args(args, "render", *overrides);
  if (!scene) return kExitFailure;
  t_scene.end();
  StageTimer t_device("device");
  auto ctx = open_context();
  if (!ctx) return kExitFailure;
  t_device.end();

  // A first run of this build on a CPU device compiles the frame's code on a second one meanwhile.
  auto cold = render::ColdCompile::start_if_cold(*ctx, vk::ContextOptions::from_environment(), *scene);
  auto renderer = render::OceanRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "lagoon render: %s: %s\n", scene->source.c_str(), renderer.error().message.c_str());
    return kExitFailure;
  }
  if (sequence->frames > 1 || args.has("shard") || *path || !aovs->empty()) {
    const int status =
        render_sequence(args, *overrides, *sequence, *path, *aovs, out_path, *scene, *ctx, **renderer);
    return finish_cold_start(std::move(cold), *ctx, status);
  }
  std::vector<vk::PassTime> timings;
  const io::Image8 image = (*renderer)->render(*scene, &timings);
  // A frame rendered with validation errors is not written: it cannot be trusted.
  if (int status = finish_cold_start(std::move(cold), *ctx, validation_status(*ctx)); status != kExitOk)
    return status;
  StageTimer t_png("PNG");
  if (auto written = io::write_png(out_path, image); !written) {
    std::fprintf(stderr, "lagoon render: %s\n", written.error().message.c_str());
    return kExitFailure;
  }
  print_summary(out_path, image, *scene, *ctx, timings);
  return kExitOk;
}

}  // namespace

const Command& render_command() {
  static const Command command{
      .spec =
          {.name = "render",
           .summary = "Renders a frame of a scene headless as a PNG, or a sequence with ground truth and a "
                      "manifest, sharded across processes. Every file is written under a temporary name and "
                      "renamed when complete, so a failed run leaves nothing half-written.",
           .options = {scene_option(),
                       {"out", "FILE.png", "output image; missing folders are created", true},
                       {"width", "W", "image width in pixels (same as --set render.width=W)"},
                       {"height", "H", "image height in pixels (same as --set render.height=H)"},
                       {"time", "T", "simulation time in seconds (same as --set time_s=T)"},
                       {"frames", "N",
                        "render N frames: OUT_0000.png, OUT_0001.png, ..., each with its metadata "
                        "(OUT_0000.json) and listed in a manifest (OUT.shard-0-of-1.jsonl); a second run "
                        "skips the frames already finished (default 1)"},
                       {"fps", "F", "frames per second of simulation time between frames (default 30)"},
                       {"shard", "I/N",
                        "render only frames I, I+N, I+2N, ... (I from 0), with their own manifest "
                        "OUT.shard-I-of-N.jsonl: one shard per cluster task (docs/datasets.md)"},
                       {"aov", "LIST",
                        "ground truth beside each frame as float32 .npy (OUT_0000.depth.npy, ...): any of "
                        "depth (m along the optical axis), normal (world), water_mask (0 air, 1 surface, 2 "
                        "under water), object_id, and under the water clean, transmission, backscatter "
                        "(the image formation terms, linear RGB; docs/datasets.md)"},
                       {"path", "PATH.json",
                        "fly the camera along this keyframed path, frame k at its time k/fps "
                        "(scenes/paths/evaluation.json; docs/datasets.md)"},
                       {"set", "PATH=VALUE", "override a scene field, e.g. --set camera.fov_deg=40", false,
                        true}},
           .details =
               "A sequence carries its foam and wakes from frame to frame, as a live run does, from its "
               "first frame's warm-up at t = time_s; frame k is at time_s + k/fps. Every shard steps "
               "through the frames before its own without drawing them, so frames drawn by different "
               "shards, or after a restart, are byte-identical to those of one run. One frame k alone: "
               "--frames N --shard k/N.\n\n"
               "examples:\n  lagoon render --scene scenes/default.json --out out/default.png --width 640 "
               "--height 360\n"
               "  lagoon render --scene scenes/harbour.json --path scenes/paths/evaluation.json --frames 660 "
               "--fps 30 --shard 0/4 --out set/frame.png\n"
               "  lagoon dataset verify set\n"},
      .run = run_render};
  return command;
}

}  // namespace lagoon::cli
