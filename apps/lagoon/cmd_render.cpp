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
  auto scene = load_scene_from_args(args, "render", overrides);
  if (!scene) return kExitFailure;
  auto ctx = open_context();
  if (!ctx) return kExitFailure;

  std::vector<vk::PassTime> timings;
  io::Image8 image;
  {
    auto renderer = render::OceanRenderer::create(*ctx, *scene);
    if (!renderer) {
      std::fprintf(stderr, "lagoon render: %s: %s\n", scene->source.c_str(),
                   renderer.error().message.c_str());
      return kExitFailure;
    }
    image = (*renderer)->render(*scene, &timings);
  }
  // A run with validation errors writes nothing: its image cannot be trusted.
  if (int status = validation_status(*ctx); status != kExitOk) return status;
  if (auto written = io::write_png(out_path, image); !written) {
    std::fprintf(stderr, "lagoon render: %s\n", written.error().message.c_str());
    return kExitFailure;
  }
  std::printf("wrote %s (%ux%u, t = %.2f s) on %s (%s)\n", out_path.c_str(), image.width, image.height,
              scene->time_s, ctx->device_info().name.c_str(), ctx->device_info().type.c_str());
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
                           {"set", "PATH=VALUE", "override a scene field, e.g. --set camera.fov_deg=40",
                            false, true}},
               .details =
                   "example:\n  lagoon render --scene scenes/default.json --out out/default.png --width 640 "
                   "--height 360\n"},
      .run = run_render};
  return command;
}

}  // namespace lagoon::cli
