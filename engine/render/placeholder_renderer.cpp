#include "render/placeholder_renderer.h"

#include <algorithm>
#include <cstring>

#include "lagoon_shaders/shaders.h"
#include "render/camera.h"
#include "shared/placeholder_frame.h"
#include "vk/barriers.h"
#include "vk/rendering.h"
#include "vk/transfer.h"

namespace lagoon::render {

PlaceholderRenderer::PlaceholderRenderer(vk::Context& ctx)
    : ctx_(ctx),
      sky_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_placeholder_sky_vert,
                                              .fragment = &shaders::render_placeholder_sky_frag,
                                              .color_formats = {kColorFormat},
                                              .depth_format = kDepthFormat})),
      grid_(vk::GraphicsPipeline::create(ctx, {.vertex = &shaders::render_placeholder_grid_vert,
                                               .fragment = &shaders::render_placeholder_grid_frag,
                                               .color_formats = {kColorFormat},
                                               .depth_format = kDepthFormat,
                                               .depth_test = true,
                                               .depth_write = true})),
      frame_(vk::Buffer::create(ctx, sizeof(gpu::PlaceholderFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                vk::MemoryUsage::Upload, "placeholder frame")),
      timer_(ctx) {}

io::Image8 PlaceholderRenderer::render(const scene::Scene& scene, std::vector<vk::PassTime>* timings) {
  const VkExtent2D extent{scene.render.width, scene.render.height};
  vk::Image color =
      vk::Image::create(ctx_, {.format = kColorFormat,
                               .extent = extent,
                               .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                               .debug_name = "placeholder color"});
  vk::Image depth = vk::Image::create(ctx_, {.format = kDepthFormat,
                                             .extent = extent,
                                             .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                             .debug_name = "placeholder depth"});

  const CameraMatrices cam = camera_matrices(scene.camera, float(extent.width) / float(extent.height));
  const gpu::PlaceholderFrame frame{.view_proj = cam.view_proj,
                                    .inv_view_proj = glm::inverse(cam.view_proj),
                                    .camera_pos = glm::vec4(scene.camera.position, 1.0f),
                                    .sun_dir = glm::vec4(sun_direction(scene.sun), scene.sun.intensity),
                                    .grid = glm::vec4(std::min(0.8f * scene.camera.far_m, kGridHalfExtentM),
                                                      float(kGridVertsPerSide), scene.time_s, 0.0f),
                                    .post = glm::vec4(scene.render.exposure, scene.render.gamma, 0.0f, 0.0f)};
  std::memcpy(frame_.mapped(), &frame, sizeof(frame));
  frame_.flush();

  ctx_.submit_and_wait([&](VkCommandBuffer cmd) {
    timer_.reset(cmd);
    vk::image_barrier(cmd, color.handle(), color.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kColorAttachmentWrite);
    vk::image_barrier(cmd, depth.handle(), depth.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, vk::access::kNone,
                      vk::access::kDepthAttachment);
    // One timing scope for the whole pass: tilers such as lavapipe rasterise a pass's draws when it ends,
    // so timestamps between draws of one pass would not mean anything.
    vk::GpuScope scope(timer_, cmd, "surface+sky");
    vk::begin_rendering(cmd, extent, {{.view = color.view(), .clear = std::array{0.f, 0.f, 0.f, 1.f}}},
                        vk::DepthTarget{.view = depth.view(), .clear = 1.0f});
    const vk::BufferRef frame_ref{frame_.handle()};
    vk::draw(cmd, sky_, {vk::bind(0, frame_ref)}, 3);
    const uint32_t quads = (kGridVertsPerSide - 1) * (kGridVertsPerSide - 1);
    vk::draw(cmd, grid_, {vk::bind(0, frame_ref)}, quads * 6);
    vk::end_rendering(cmd);
  });
  if (timings) *timings = timer_.results();

  const std::vector<std::byte> texels = vk::readback_image(
      ctx_, color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, vk::access::kColorAttachmentWrite);
  io::Image8 image;
  image.width = extent.width;
  image.height = extent.height;
  image.rgba.resize(texels.size());
  std::memcpy(image.rgba.data(), texels.data(), texels.size());
  return image;
}

}  // namespace lagoon::render
