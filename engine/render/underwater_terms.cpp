// OceanRenderer::render_underwater_terms: the underwater view's image formation terms
// (shaders/render/underwater_terms.frag) in a frame of their own, for the dataset's ground truth.
#include <cstring>

#include "render/camera.h"
#include "render/ocean_renderer.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

OceanRenderer::UnderwaterTerms OceanRenderer::render_underwater_terms(const scene::Scene& scene) {
  const VkExtent2D extent{scene.render.width, scene.render.height};
  resize(extent);
  auto target = [&](VkFormat format, VkImageUsageFlags usage, const char* name) {
    return vk::Image::create(ctx_, {.format = format, .extent = extent, .usage = usage, .debug_name = name});
  };
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  const std::array<vk::Image, 3> terms = {target(UnderwaterPass::kTermsFormat, usage, "terms clean"),
                                          target(UnderwaterPass::kTermsFormat, usage, "terms transmission"),
                                          target(UnderwaterPass::kTermsFormat, usage, "terms backscatter")};
  const vk::Image depth = target(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "terms depth");
  std::array<vk::Buffer, 3> staging;
  for (size_t i = 0; i < 3; ++i)
    staging[i] = vk::Buffer::create(ctx_, vk::readback_bytes(terms[i]), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    vk::MemoryUsage::Readback, "terms readback");
  prepare(scene);
  const CausticsWindow caustics = caustics_window(scene, sun_direction(scene.sun), float(scene.water.ior));
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    using enum vk::ImageUse;
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, caustics);
    ocean_step_->record(frame);
    wakes_->record(frame);
    caustics_->record(frame, caustics);
    vk::use(cmd, {refraction_->albedo(), refraction_->depth()}, Discard, Attachment);
    refraction_->record(frame);
    vk::use(cmd, {refraction_->albedo(), refraction_->depth()}, Attachment, Sampled);
    vk::use(cmd, {terms[0].target(), terms[1].target(), terms[2].target(), depth.target()}, Discard,
            Attachment);
    underwater_->record_terms(
        frame,
        {refraction_->albedo_image(), refraction_->depth_image(), caustics_->map(), window_->color_image()},
        {terms[0].target(), terms[1].target(), terms[2].target()}, depth.target());
    for (size_t i = 0; i < 3; ++i)
      vk::record_readback(cmd, terms[i], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          vk::access::kColorAttachmentWrite, staging[i]);
  });
  UnderwaterTerms out{.width = extent.width, .height = extent.height};
  for (auto [buffer, values] : {std::pair{&staging[0], &out.clean},
                                {&staging[1], &out.transmission},
                                {&staging[2], &out.backscatter}}) {
    buffer->invalidate();
    values->resize(size_t{extent.width} * extent.height);
    std::memcpy(values->data(), buffer->mapped(), values->size() * sizeof(glm::vec4));
  }
  return out;
}

}  // namespace lagoon::render
