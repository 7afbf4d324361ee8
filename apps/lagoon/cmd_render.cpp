// lagoon render: one frame of a scene, headless, to a PNG.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "gpu_session.h"
#include "io/png.h"
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

// --frames and --fps: how many frames, and the simulation time between them (1/fps).
struct FrameRun {
  long long frames = 1;
  double fps = 30.0;
};

// nullopt (after printing why) when either is out of range.
std::optional<FrameRun> frame_run_option(const ParsedArgs& args) {
  FrameRun run;
  const auto frames_arg = integer_option(args, "frames", 1, 1, 100000);
  if (!frames_arg) {
    std::fprintf(stderr, "lagoon render: %s\n", frames_arg.error().message.c_str());
    return std::nullopt;
  }
  run.frames = *frames_arg;
  if (auto v = args.get("fps")) {
    auto f = parse_number(*v);
    if (!f || *f <= 0 || *f > 1000) {
      std::fprintf(stderr, "lagoon render: --fps %s must be a number of frames per second in (0, 1000]\n",
                   v->c_str());
      return std::nullopt;
    }
    run.fps = *f;
  }
  return run;
}

// One PNG per frame: out.png for a single frame, out_0000.png, out_0001.png ... for several.
std::string frame_path(const std::string& out_path, long long frame, long long frames) {
  if (frames == 1) return out_path;
  char suffix[24];  // "_" + up to 19 digits + NUL
  std::snprintf(suffix, sizeof(suffix), "_%04lld", frame);
  return out_path.substr(0, out_path.size() - 4) + suffix + ".png";
}

void print_progress(long long done_frames, long long frames) {
  const int done = int(40 * done_frames / frames);
  std::fprintf(stderr, "\r[%s%s] %lld/%lld frames", std::string(done, '#').c_str(),
               std::string(40 - done, ' ').c_str(), done_frames, frames);
}

// What was written, on which device, and each pass's GPU time (of the last frame).
void print_summary(const std::string& out_path, const FrameRun& run, const io::Image8& image,
                   const scene::Scene& scene, const vk::Context& ctx,
                   const std::vector<vk::PassTime>& timings) {
  if (run.frames == 1) {
    std::printf("wrote %s (%ux%u, t = %.2f s) on %s (%s)\n", out_path.c_str(), image.width, image.height,
                scene.time_s, ctx.device_info().name.c_str(), ctx.device_info().type.c_str());
  } else {
    const std::string stem = out_path.substr(0, out_path.size() - 4);
    std::printf("wrote %s_0000.png .. %s_%04lld.png (%lld frames at %.3g fps, %ux%u) on %s (%s)\n",
                stem.c_str(), stem.c_str(), run.frames - 1, run.frames, run.fps, image.width, image.height,
                ctx.device_info().name.c_str(), ctx.device_info().type.c_str());
  }
  for (const auto& t : timings) std::printf("  %-10s %8.2f ms GPU\n", t.name.c_str(), t.ms);
}

int run_render(const ParsedArgs& args) {
  const std::string out_path = *args.get("out");
  if (out_path.size() < 5 || out_path.substr(out_path.size() - 4) != ".png") {
    std::fprintf(stderr, "lagoon render: --out %s must name a .png file\n", out_path.c_str());
    return kExitUsage;
  }
  const auto overrides = shorthand_overrides(args);
  if (!overrides) return kExitUsage;
  const auto run = frame_run_option(args);
  if (!run) return kExitUsage;
  auto scene = load_scene_from_args(args, "render", *overrides);
  if (!scene) return kExitFailure;
  auto ctx = open_context();
  if (!ctx) return kExitFailure;

  auto renderer = render::OceanRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "lagoon render: %s: %s\n", scene->source.c_str(), renderer.error().message.c_str());
    return kExitFailure;
  }
  const double t0 = scene->time_s;
  std::vector<vk::PassTime> timings;
  io::Image8 image;
  for (long long f = 0; f < run->frames; ++f) {
    scene->time_s = float(t0 + double(f) / run->fps);
    image = (*renderer)->render(*scene, &timings);
    // A frame rendered with validation errors is not written: it cannot be trusted.
    if (int status = validation_status(*ctx); status != kExitOk) return status;
    if (auto written = io::write_png(frame_path(out_path, f, run->frames), image); !written) {
      std::fprintf(stderr, "lagoon render: %s\n", written.error().message.c_str());
      return kExitFailure;
    }
    if (run->frames > 1) print_progress(f + 1, run->frames);
  }
  if (run->frames > 1) std::fprintf(stderr, "\n");
  print_summary(out_path, *run, image, *scene, *ctx, timings);
  return kExitOk;
}

}  // namespace

const Command& render_command() {
  static const Command command{
      .spec = {.name = "render",
               .summary = "Renders one frame of a scene headless and writes it as a PNG. The file is written "
                          "under a temporary name and renamed when complete, so a failed run leaves nothing.",
               .options = {scene_option(),
                           {"out", "FILE.png", "output image; missing folders are created", true},
                           {"width", "W", "image width in pixels (same as --set render.width=W)"},
                           {"height", "H", "image height in pixels (same as --set render.height=H)"},
                           {"time", "T", "simulation time in seconds (same as --set time_s=T)"},
                           {"frames", "N", "render N frames: OUT_0000.png, OUT_0001.png, ... (default 1)"},
                           {"fps", "F", "frames per second of simulation time between frames (default 30)"},
                           {"set", "PATH=VALUE", "override a scene field, e.g. --set camera.fov_deg=40",
                            false, true}},
               .details =
                   "example:\n  lagoon render --scene scenes/default.json --out out/default.png --width 640 "
                   "--height 360\n"},
      .run = run_render};
  return command;
}

}  // namespace lagoon::cli
