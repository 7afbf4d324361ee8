#include "render/cold_compile.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "core/stage_times.h"
#include "io/result_cache.h"
#include "render/cached_tables.h"
#include "render/device_key.h"
#include "render/ocean_renderer.h"

namespace lagoon::render {
namespace {

io::ResultKey marker_key(const vk::Context& ctx) {
  io::ResultKey key = table_key("drawn");  // with the build's fingerprint: its shaders
  add_device(key, ctx);
  return key;
}

bool turned_off() {
  const char* v = std::getenv("LAGOON_COLD_COMPILE");
  return v != nullptr && std::string(v) == "0";
}

}  // namespace

std::unique_ptr<ColdCompile> ColdCompile::start_if_cold(const vk::Context& ctx, vk::ContextOptions options,
                                                        const scene::Scene& scene) {
  if (turned_off() || ctx.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU || ctx.adopted())
    return nullptr;
  const io::ResultCache cache = io::ResultCache::from_environment();
  if (!cache.enabled() || cache.load(marker_key(ctx))) return nullptr;
  options.device_override = std::to_string(ctx.device_info().index);
  options.create_surface = nullptr;
  options.instance_extensions.clear();
  if (stage_times_enabled())
    std::fprintf(stderr, "lagoon: cold start: a second device compiles the frame too\n");
  std::unique_ptr<ColdCompile> helper(new ColdCompile());
  helper->thread_ = std::thread([h = helper.get(), options, scene] { h->run(options, scene); });
  return helper;
}

void ColdCompile::mark_warm(const vk::Context& ctx) {
  const io::ResultCache cache = io::ResultCache::from_environment();
  if (!cache.enabled() || ctx.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return;
  const io::ResultKey key = marker_key(ctx);
  if (!cache.load(key)) cache.store(key, std::as_bytes(std::span("1", 1)));
}

void ColdCompile::run(vk::ContextOptions options, scene::Scene scene) {
  const StageTimesMuted muted;  // the first device's stages are the run's
  try {
    auto ctx = vk::Context::create(options);
    if (!ctx) return;  // the first device's own errors say what is wrong
    {
      // A quarter of the size each way makes the same code for less of the cores. Only a size divisible by
      // 4: llvmpipe's code depends on whether a texture's size is a power of two (render-sized targets).
      if (scene.render.width % 4 == 0 && scene.render.height % 4 == 0 && scene.render.height >= 64)
        scene.render.width /= 4, scene.render.height /= 4;
      // At the bodies' start, so they replay no history: the code is the same at any time.
      scene.time_s = scene.bodies_start_s;
      auto renderer = OceanRenderer::create(**ctx, scene);
      if (renderer) (*renderer)->draw_for_code_only(scene);
    }
    (*ctx)->wait_idle();
    validation_failures_ = (*ctx)->validation().failures();
  } catch (const std::exception& e) {
    // Only a head start: the first device compiles what this one did not.
    if (stage_times_enabled())
      std::fprintf(stderr, "lagoon: cold start: the second device stopped: %s\n", e.what());
  }
}

uint32_t ColdCompile::join() {
  if (thread_.joinable()) thread_.join();
  return validation_failures_;
}

uint32_t ColdCompile::finish(std::unique_ptr<ColdCompile>& cold, vk::Context& ctx) {
  if (!cold) return 0;
  const uint32_t failures = cold->join();
  cold.reset();
  if (failures == 0 && ctx.validation().failures() == 0) mark_warm(ctx);
  return failures;
}

ColdCompile::~ColdCompile() {
  join();
}

}  // namespace lagoon::render
