// OceanRenderer::render_underwater_terms: the underwater view's image formation terms
// (shaders/render/underwater_terms.frag) in a frame of their own, for the dataset's ground truth (the steps:
// render/frame_steps.cpp).
#include <string>

#include "render/camera.h"
#include "render/float_targets.h"
#include "render/ocean_renderer.h"
#include "render/passes/underwater_pass.h"

namespace lagoon::render {

OceanRenderer::UnderwaterTerms OceanRenderer::render_underwater_terms(const scene::Scene& scene) {
  static_assert(UnderwaterPass::kTermsFormat == FloatTargets::kFormat);
  const VkExtent2D extent{scene.render.width, scene.render.height};
  resize(extent);
  const FloatTargets terms(ctx_, extent, 3, kDepthFormat, "underwater terms");  // clean, T, backscatter
  prepare(scene);
  const CausticsWindow caustics =
      caustics_window(scene, sun_direction(scene.sun), float(scene.water.ior), caustic_mss_, caustic_cells_);
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, caustics);
    // A dataset draws the terms right after the picture of the same frame: its caustic map and refraction
    // are still there (~40 % of this frame on lavapipe).
    const std::string key = views_key(scene, frame.camera_side, extent);
    record_frame(frame, {.kind = FrameKind::UnderwaterTerms,
                         .caustics = caustics,
                         .floats = &terms,
                         .views_drawn = key == views_drawn_for_});
    views_drawn_for_ = key;
    terms.record_readback(cmd);
  });
  remember_pipelines();
  return {.width = extent.width,
          .height = extent.height,
          .clean = terms.read(0),
          .transmission = terms.read(1),
          .backscatter = terms.read(2)};
}

}  // namespace lagoon::render
