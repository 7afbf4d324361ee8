// OceanRenderer::render_surface_aov: the surface pass's ground-truth variant in a frame of its own, and the
// scene's meshes in the same targets when asked (the steps: render/frame_steps.cpp).
#include "render/float_targets.h"
#include "render/ocean_renderer.h"
#include "render/passes/surface_pass.h"

namespace lagoon::render {

OceanRenderer::SurfaceAov OceanRenderer::render_surface_aov(const scene::Scene& scene, bool with_objects) {
  static_assert(SurfacePass::kAovFormat == FloatTargets::kFormat &&
                SceneObjects::kGroundTruthFormat == FloatTargets::kFormat);
  const VkExtent2D extent{scene.render.width, scene.render.height};
  const FloatTargets targets(ctx_, extent, 2, kDepthFormat, "aov");  // normal and foam, world point
  prepare(scene);
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, CausticsWindow{});
    record_frame(frame, {.kind = FrameKind::SurfaceAov, .floats = &targets, .objects = with_objects});
    targets.record_readback(cmd);
  });
  remember_pipelines();
  return {.width = extent.width,
          .height = extent.height,
          .normal_foam = targets.read(0),
          .world = targets.read(1)};
}

}  // namespace lagoon::render
