#include "render/passes/snell_window_pass.h"

#include "vk/rendering.h"

namespace lagoon::render {

void SnellWindowPass::resize(VkExtent2D extent) {
  color_ = vk::Image::create(ctx_, {.format = color_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                    .debug_name = "snell window"});
  depth_ = vk::Image::create(ctx_, {.format = depth_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                    .debug_name = "snell window depth"});
}

void SnellWindowPass::record(const FrameContext& frame) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "snell window");
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = color_.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                      vk::DepthTarget{.view = depth_.view(), .clear = 1.0f});
  objects_.draw(frame, gpu::MeshMode::Window);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
