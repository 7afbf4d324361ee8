// OceanRenderer::render_underwater_terms: the underwater view's image formation terms
// (shaders/render/underwater_terms.frag) in a frame of their own, for the dataset's ground truth.
#include "render/camera.h"
#include "render/float_targets.h"
#include "render/ocean_renderer.h"
#include "render/passes/caustics_pass.h"
#include "render/passes/objects_pass.h"
#include "render/passes/refraction_pass.h"
#include "render/passes/underwater_pass.h"
#include "vk/barriers.h"

namespace lagoon::render {

OceanRenderer::UnderwaterTerms OceanRenderer::render_underwater_terms(const scene::Scene& scene) {
  static_assert(UnderwaterPass::kTermsFormat == FloatTargets::kFormat);
  const VkExtent2D extent{scene.render.width, scene.render.height};
  resize(extent);
  const FloatTargets terms(ctx_, extent, 3, kDepthFormat, "underwater terms");  // clean, T, backscatter
  prepare(scene);
  const CausticsWindow caustics = caustics_window(scene, sun_direction(scene.sun), float(scene.water.ior));
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    using enum vk::ImageUse;
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, caustics);
    record_time_steps(frame);
    caustics_->record(frame, caustics);
    vk::use(cmd, {refraction_->albedo(), refraction_->depth()}, Discard, Attachment);
    refraction_->record(frame);
    vk::use(cmd, {refraction_->albedo(), refraction_->depth()}, Attachment, Sampled);
    terms.begin(cmd);
    underwater_->record_terms(
        frame,
        {refraction_->albedo_image(), refraction_->depth_image(), caustics_->map(), window_->color_image()},
        {terms.color(0), terms.color(1), terms.color(2)}, terms.depth());
    terms.record_readback(cmd);
  });
  return {.width = extent.width,
          .height = extent.height,
          .clean = terms.read(0),
          .transmission = terms.read(1),
          .backscatter = terms.read(2)};
}

}  // namespace lagoon::render
