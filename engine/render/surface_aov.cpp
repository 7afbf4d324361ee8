// OceanRenderer::render_surface_aov: the surface pass's ground-truth variant in a frame of its own, and the
// scene's meshes in the same targets when asked.
#include "render/float_targets.h"
#include "render/ocean_renderer.h"
#include "render/passes/surface_pass.h"
#include "vk/barriers.h"
#include "vk/rendering.h"

namespace lagoon::render {

OceanRenderer::SurfaceAov OceanRenderer::render_surface_aov(const scene::Scene& scene, bool with_objects) {
  static_assert(SurfacePass::kAovFormat == FloatTargets::kFormat &&
                SceneObjects::kGroundTruthFormat == FloatTargets::kFormat);
  const VkExtent2D extent{scene.render.width, scene.render.height};
  const FloatTargets targets(ctx_, extent, 2, kDepthFormat, "aov");  // normal and foam, world point
  prepare(scene);
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, CausticsWindow{});
    record_time_steps(frame);
    targets.begin(cmd);
    surface_->record_aov(frame, targets.color(0), targets.color(1), targets.depth());
    if (with_objects) {
      vk::use(cmd, {targets.color(0), targets.color(1), targets.depth()}, vk::ImageUse::Attachment,
              vk::ImageUse::Attachment);
      vk::begin_rendering(cmd, extent, {{.view = targets.color(0).view}, {.view = targets.color(1).view}},
                          vk::DepthTarget{.view = targets.depth().view, .clear = std::nullopt});
      objects_->draw_ground_truth(frame);
      vk::end_rendering(cmd);
    }
    targets.record_readback(cmd);
  });
  return {.width = extent.width,
          .height = extent.height,
          .normal_foam = targets.read(0),
          .world = targets.read(1)};
}

}  // namespace lagoon::render
