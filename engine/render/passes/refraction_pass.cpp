#include "render/passes/refraction_pass.h"

#include "vk/rendering.h"

namespace lagoon::render {

void RefractionPass::resize(VkExtent2D extent) {
  const VkImageUsageFlags sampled = VK_IMAGE_USAGE_SAMPLED_BIT;
  albedo_ = vk::Image::create(ctx_, {.format = color_format_,
                                     .extent = extent,
                                     .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | sampled,
                                     .debug_name = "refraction albedo"});
  depth_ = vk::Image::create(ctx_, {.format = depth_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | sampled,
                                    .debug_name = "refraction depth"});
}

void RefractionPass::record(const FrameContext& frame) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "refraction");
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = albedo_.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                      vk::DepthTarget{.view = depth_.view(), .clear = 1.0f});
  objects_.draw_floor(frame);
  objects_.draw(frame, gpu::MeshMode::Refraction);  // their submerged parts
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
