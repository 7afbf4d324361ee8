// lagoon render: one frame of a scene, headless, to a PNG.
#include <cstdio>
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

int run_render(const ParsedArgs& args) {
  const std::string out_path = *args.get("out");
  if (out_path.size() < 5 || out_path.substr(out_path.size() - 4) != ".png") {
    std::fprintf(stderr, "lagoon render: --out %s must name a .png file\n", out_path.c_str());
    return kExitUsage;
  }
  // --width/--height/--time are shorthands for --set, so they are validated exactly like the scene file.
  std::vector<std::string> overrides;
  for (const char* key : {"width", "height"}) {
    if (auto v = args.get(key)) {
      if (!parse_integer(*v)) {
        std::fprintf(stderr, "lagoon render: --%s %s is not a whole number of pixels\n", key, v->c_str());
        return kExitUsage;
      }
      overrides.push_back(std::string("render.") + key + "=" + *v);
    }
  }
  if (auto v = args.get("time")) {
    if (!parse_number(*v)) {
      std::fprintf(stderr, "lagoon render: --time %s is not a number of seconds\n", v->c_str());
      return kExitUsage;
    }
    overrides.push_back("time_s=" + *v);
  }
  double fps = 30.0;
  const auto frames_arg = integer_option(args, "frames", 1, 1, 100000);
  if (!frames_arg) {
    std::fprintf(stderr, "lagoon render: %s\n", frames_arg.error().message.c_str());
    return kExitUsage;
  }
  const long long frames = *frames_arg;
  if (auto v = args.get("fps")) {
    auto f = parse_number(*v);
    if (!f || *f <= 0 || *f > 1000) {
      std::fprintf(stderr, "lagoon render: --fps %s must be a number of frames per second in (0, 1000]\n",
                   v->c_str());
      return kExitUsage;
    }
    fps = *f;
  }
  auto scene = load_scene_from_args(args, "render", overrides);
  if (!scene) return kExitFailure;
  auto ctx = open_context();
  if (!ctx) return kExitFailure;

  auto renderer = render::OceanRenderer::create(*ctx, *scene);
  if (!renderer) {
    std::fprintf(stderr, "lagoon render: %s: %s\n", scene->source.c_str(), renderer.error().message.c_str());
    return kExitFailure;
  }
  // One PNG per frame: out.png for a single frame, out_0000.png, out_0001.png ... for several.
  const std::string stem = out_path.substr(0, out_path.size() - 4);
  const double t0 = scene->time_s;
  std::vector<vk::PassTime> timings;
  io::Image8 image;
  for (long long f = 0; f < frames; ++f) {
    scene->time_s = float(t0 + double(f) / fps);
    image = (*renderer)->render(*scene, &timings);
    // A frame rendered with validation errors is not written: it cannot be trusted.
    if (int status = validation_status(*ctx); status != kExitOk) return status;
    char suffix[24];  // "_" + up to 19 digits + NUL
    std::snprintf(suffix, sizeof(suffix), "_%04lld", f);
    const std::string path = frames == 1 ? out_path : stem + suffix + ".png";
    if (auto written = io::write_png(path, image); !written) {
      std::fprintf(stderr, "lagoon render: %s\n", written.error().message.c_str());
      return kExitFailure;
    }
    if (frames > 1) {
      const int done = int(40 * (f + 1) / frames);
      std::fprintf(stderr, "\r[%s%s] %lld/%lld frames", std::string(done, '#').c_str(),
                   std::string(40 - done, ' ').c_str(), f + 1, frames);
    }
  }
  if (frames > 1) std::fprintf(stderr, "\n");
  if (frames == 1) {
    std::printf("wrote %s (%ux%u, t = %.2f s) on %s (%s)\n", out_path.c_str(), image.width, image.height,
                scene->time_s, ctx->device_info().name.c_str(), ctx->device_info().type.c_str());
  } else {
    std::printf("wrote %s_0000.png .. %s_%04lld.png (%lld frames at %.3g fps, %ux%u) on %s (%s)\n",
                stem.c_str(), stem.c_str(), frames - 1, frames, fps, image.width, image.height,
                ctx->device_info().name.c_str(), ctx->device_info().type.c_str());
  }
  for (const auto& t : timings) std::printf("  %-10s %8.2f ms GPU\n", t.name.c_str(), t.ms);
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
