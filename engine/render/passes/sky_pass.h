// The analytic sky (shaders/render/sky.frag, common/light.glsl), drawn last at the far plane and
// depth-tested: it is shaded only where nothing else was drawn.
#pragma once
#include "render/frame_context.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class SkyPass {
 public:
  SkyPass(vk::Context& ctx, VkFormat color_format, VkFormat depth_format);
  // Into `color` and `depth` as attachments, keeping what is there.
  void record(const FrameContext& frame, vk::Target color, vk::Target depth) const;

 private:
  vk::GraphicsPipeline pipeline_;
};

}  // namespace lagoon::render
