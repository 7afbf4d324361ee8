#include "render/passes/objects_pass.h"

#include "vk/rendering.h"

namespace lagoon::render {

void ObjectsPass::resize(VkExtent2D extent) {
  color_ = vk::Image::create(ctx_, {.format = color_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                    .debug_name = name_.c_str()});
  depth_ = vk::Image::create(ctx_, {.format = depth_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                    .debug_name = (name_ + " depth").c_str()});
}

void ObjectsPass::record(const FrameContext& frame, bool draw) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, name_);
  vk::begin_rendering(frame.cmd, frame.extent,
                      {{.view = color_.view(), .clear = std::array{0.f, 0.f, 0.f, 0.f}}},
                      vk::DepthTarget{.view = depth_.view(), .clear = 1.0f});
  if (draw) objects_.draw(frame, mode_);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
