#include "render/passes/reflection_pass.h"

#include "vk/rendering.h"

namespace lagoon::render {

void ReflectionPass::resize(VkExtent2D extent) {
  color_ = vk::Image::create(ctx_, {.format = color_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                    .debug_name = "reflection"});
  depth_ = vk::Image::create(
      ctx_, {.format = depth_format_,
             .extent = extent,
             .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
             .debug_name = "reflection depth"});
}

void ReflectionPass::record(const FrameContext& frame) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "reflection");
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = color_.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                      vk::DepthTarget{.view = depth_.view(), .clear = 1.0f});
  if (frame.scene.render.effects.reflection) objects_.draw(frame, gpu::MeshMode::Mirrored);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
