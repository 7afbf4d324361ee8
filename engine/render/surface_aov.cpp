// OceanRenderer::render_surface_aov: the surface pass's ground-truth variant in a frame of its own, and the
// scene's meshes in the same targets when asked.
#include <cstring>

#include "render/ocean_renderer.h"
#include "vk/barriers.h"
#include "vk/rendering.h"
#include "vk/transfer.h"

namespace lagoon::render {

OceanRenderer::SurfaceAov OceanRenderer::render_surface_aov(const scene::Scene& scene, bool with_objects) {
  const VkExtent2D extent{scene.render.width, scene.render.height};
  auto target = [&](VkFormat format, VkImageUsageFlags usage, const char* name) {
    return vk::Image::create(ctx_, {.format = format, .extent = extent, .usage = usage, .debug_name = name});
  };
  const VkImageUsageFlags out = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  const vk::Image normal = target(SurfacePass::kAovFormat, out, "aov normal"),
                  world = target(SurfacePass::kAovFormat, out, "aov world"),
                  depth = target(kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "aov depth");
  auto staging = [&](const vk::Image& image) {
    return vk::Buffer::create(ctx_, vk::readback_bytes(image), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                              vk::MemoryUsage::Readback, "aov readback");
  };
  const vk::Buffer normal_out = staging(normal), world_out = staging(world);
  prepare(scene);
  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    const FrameContext frame = begin_frame(cmd, scene, extent, 0, CausticsWindow{});
    ocean_step_->record(frame);
    wakes_->record(frame);
    vk::use(cmd, {normal.target(), world.target(), depth.target()}, vk::ImageUse::Discard,
            vk::ImageUse::Attachment);
    surface_->record_aov(frame, normal.target(), world.target(), depth.target());
    if (with_objects) {
      vk::use(cmd, {normal.target(), world.target(), depth.target()}, vk::ImageUse::Attachment,
              vk::ImageUse::Attachment);
      vk::begin_rendering(cmd, extent, {{.view = normal.view()}, {.view = world.view()}},
                          vk::DepthTarget{.view = depth.view(), .clear = std::nullopt});
      objects_->draw_ground_truth(frame);
      vk::end_rendering(cmd);
    }
    for (auto [image, buffer] : {std::pair{&normal, &normal_out}, {&world, &world_out}})
      vk::record_readback(cmd, *image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                          vk::access::kColorAttachmentWrite, *buffer);
  });
  SurfaceAov aov{.width = extent.width, .height = extent.height};
  for (auto [buffer, values] : {std::pair{&normal_out, &aov.normal_foam}, {&world_out, &aov.world}}) {
    buffer->invalidate();
    values->resize(size_t{extent.width} * extent.height);
    std::memcpy(values->data(), buffer->mapped(), values->size() * sizeof(glm::vec4));
  }
  return aov;
}

}  // namespace lagoon::render
