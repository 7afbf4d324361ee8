#include "render/passes/waterline_pass.h"

#include "lagoon_shaders/shaders.h"
#include "render/surface_fields.h"
#include "shared/shoaling.h"
#include "shared/surface.h"
#include "vk/rendering.h"

namespace lagoon::render {

WaterlinePass::WaterlinePass(vk::Context& ctx, const SurfaceFields& fields, const Samplers& samplers,
                             VkFormat color_format, VkFormat depth_format)
    : ctx_(ctx),
      fields_(fields),
      samplers_(samplers),
      color_format_(color_format),
      depth_format_(depth_format),
      composite_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_fullscreen_vert,
                                                    .fragment = &shaders::render_waterline_frag,
                                                    .color_formats = {color_format},
                                                    .depth_format = depth_format,
                                                    .depth_test = true,
                                                    .depth_write = true,
                                                    .depth_compare = VK_COMPARE_OP_ALWAYS,
                                                    .alpha_blend = true,
                                                    .spec = with_surface_field_specs({}, fields)})) {}

void WaterlinePass::resize(VkExtent2D extent) {
  const VkImageUsageFlags sampled = VK_IMAGE_USAGE_SAMPLED_BIT;
  color_ = vk::Image::create(ctx_, {.format = color_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | sampled,
                                    .debug_name = "waterline: frame from below"});
  depth_ = vk::Image::create(ctx_, {.format = depth_format_,
                                    .extent = extent,
                                    .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | sampled,
                                    .debug_name = "waterline: depth from below"});
}

void WaterlinePass::record(const FrameContext& frame, vk::Target color, vk::Target depth) const {
  vk::GpuScope scope(frame.timer(), frame.cmd, "waterline");
  vk::begin_rendering(frame.cmd, frame.extent, {{.view = color.view}},
                      vk::DepthTarget{.view = depth.view, .clear = {}});
  // Only the displacement of the cascades (the vertex stage's array, without the normals), the wakes and the
  // floor's transformation table.
  std::vector<vk::Binding> bindings{
      vk::bind(LAGOON_SURFACE_BIND_FRAME, frame.uniforms()),
      vk::bind(LAGOON_SURFACE_BIND_BELOW_COLOR, sampled(color_, samplers_.nearest)),
      vk::bind(LAGOON_SURFACE_BIND_BELOW_DEPTH, sampled(depth_, samplers_.nearest))};
  for (const vk::Binding& b : surface_field_bindings(fields_, samplers_))
    if (b.binding == LAGOON_SURFACE_BIND_DISPLACEMENT || b.binding == LAGOON_SURFACE_BIND_WAKES ||
        b.binding == LAGOON_SURFACE_BIND_SHOALING)
      bindings.push_back(b);
  vk::draw(frame.cmd, composite_, bindings, nullptr, 0, 3);
  vk::end_rendering(frame.cmd);
}

}  // namespace lagoon::render
