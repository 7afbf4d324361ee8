#include "render/passes/sky_pass.h"

#include "lagoon_shaders/shaders.h"
#include "shared/frame.h"
#include "vk/rendering.h"

namespace lagoon::render {

SkyPass::SkyPass(vk::Context& ctx, VkFormat color_format, VkFormat depth_format)
    // At the far plane (fullscreen.vert's z = 1), drawn where the depth buffer is still clear.
    : pipeline_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_fullscreen_vert,
                                                   .fragment = &shaders::render_sky_frag,
                                                   .color_formats = {color_format},
                                                   .depth_format = depth_format,
                                                   .depth_test = true,
                                                   .depth_write = false,
                                                   .depth_compare = VK_COMPARE_OP_EQUAL})) {}

void SkyPass::record(const FrameContext& frame, vk::Target color, vk::Target depth) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "sky");
  vk::begin_rendering(frame.cmd, frame.extent, {{.view = color.view}},
                      vk::DepthTarget{.view = depth.view, .clear = {}});
  vk::draw(frame.cmd, pipeline_, {vk::bind(LAGOON_SKY_BIND_FRAME, frame.uniforms())}, 3);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
