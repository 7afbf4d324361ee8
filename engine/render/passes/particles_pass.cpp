#include "render/passes/particles_pass.h"

#include <algorithm>
#include <cmath>

#include "lagoon_shaders/shaders.h"
#include "shared/sediment.h"
#include "shared/surface.h"
#include "vk/rendering.h"

namespace lagoon::render {
namespace {

// How far the lattice reaches from the camera: one candidate per cell, cells as small as the density asks,
// so a dense cloud is drawn closer in. Beyond a few metres particles are below a pixel and faded.
constexpr float kMinReachM = 1.5f, kMaxReachM = 12.0f;
constexpr uint32_t kCandidates = LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE;

}  // namespace

gpu::ParticlesPush particles_push(const scene::Scene& scene) {
  const scene::Particles& p = scene.underwater.particles;
  // Half a particle per cell on average: a cell keeps its candidate with probability 2 × share × the noise's
  // density (mean 1/2), which must stay below 1 everywhere or the densest clouds clip and the mean falls
  // short (one particle per cell drew 89 % of the density asked; tests/gpu/render/particles_test.cpp). Above
  // about 600 per m³ the finest cells (the nearest reach) still clip.
  const float by_density = p.density_per_m3 > 0 ? std::cbrt(0.5f / p.density_per_m3) : 1e3f;
  const float cell = std::clamp(by_density, 2.0f * kMinReachM / LAGOON_PARTICLES_SIDE,
                                2.0f * kMaxReachM / LAGOON_PARTICLES_SIDE);
  const glm::vec3 corner =
      (glm::floor(scene.camera.position / cell) - float(LAGOON_PARTICLES_SIDE / 2)) * cell;
  return {.lattice = glm::vec4(corner, cell),
          .drift = glm::vec4(p.drift_mps, scene.time_s),
          .look = glm::vec4(std::min(p.density_per_m3 * cell * cell * cell, 1.0f), p.size_mm * 1e-3f,
                            p.patch_size_m, p.albedo),
          .seed = glm::uvec4(p.seed, 0, 0, 0)};
}

ParticlesPass::ParticlesPass(vk::Context& ctx, const WaterLuts& luts, const Samplers& samplers,
                             VkFormat color_format, VkFormat depth_format, bool grains)
    : luts_(luts), samplers_(samplers) {
  vk::GraphicsDesc desc{.vertex = &shaders::render_particles_vert,
                        .fragment = &shaders::render_particles_frag,
                        .color_formats = {color_format},
                        .depth_format = depth_format,
                        .depth_test = true,
                        .depth_write = false,
                        .alpha_blend = true};
  pipeline_ = vk::GraphicsPipeline::create(ctx, desc);
  if (!grains) return;
  desc.vertex = &shaders::render_sediment_grains_vert;
  grains_ = vk::GraphicsPipeline::create(ctx, desc);
}

void ParticlesPass::record(const FrameContext& frame, vk::Target color, vk::Target depth) const {
  const scene::Scene& scene = frame.scene;
  const bool particles = scene.render.effects.particles && scene.underwater.particles.density_per_m3 > 0;
  if (!particles && grains_.empty()) return;
  vk::GpuScope scope(frame.timer(), frame.cmd, "particles");
  vk::begin_rendering(frame.cmd, frame.extent, {{.view = color.view}},
                      vk::DepthTarget{.view = depth.view, .clear = {}});
  std::vector<vk::Binding> bindings{
      vk::bind(LAGOON_SURFACE_BIND_FRAME, frame.uniforms()),
      vk::bind(LAGOON_SURFACE_BIND_UW_TARGET, sampled(luts_.uw_target, samplers_.clamp)),
      vk::bind(LAGOON_SURFACE_BIND_UW_DOWN, sampled(luts_.uw_down, samplers_.clamp)),
      vk::bind(LAGOON_SURFACE_BIND_UW_UP, sampled(luts_.uw_up, samplers_.clamp))};
  if (particles) {
    const gpu::ParticlesPush push = particles_push(scene);
    vk::draw(frame.cmd, pipeline_, bindings, &push, sizeof(push), kCandidates * 6);
  }
  if (!grains_.empty()) {
    const glm::vec4 look(scene.sediment.grain_size_mm * 1e-3f, 0, 0, 0);
    bindings.push_back(vk::bind(LAGOON_SURFACE_BIND_SEDIMENT, frame.slot.sediment));
    vk::draw(frame.cmd, grains_, bindings, &look, sizeof(look),
             LAGOON_MAX_SEDIMENT_PUFFS * LAGOON_SEDIMENT_MAX_GRAINS * 6);
  }
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
