#include "render/gpu_mesh.h"

#include "render/texture_mips.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

GpuMesh upload_mesh(vk::Context& ctx, std::span<const MeshVertex> vertices,
                    std::span<const uint32_t> indices) {
  constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  GpuMesh mesh;
  mesh.vertices =
      vk::Buffer::create(ctx, vertices.size_bytes(), kUsage, vk::MemoryUsage::Device, "mesh vertices");
  mesh.indices =
      vk::Buffer::create(ctx, indices.size_bytes(), kUsage, vk::MemoryUsage::Device, "mesh indices");
  vk::upload_buffer(ctx, mesh.vertices, std::as_bytes(vertices));
  vk::upload_buffer(ctx, mesh.indices, std::as_bytes(indices));
  mesh.index_count = uint32_t(indices.size());
  return mesh;
}

vk::Image upload_texture(vk::Context& ctx, const io::Image8& image, const char* name, bool srgb) {
  vk::Image texture =
      vk::Image::create(ctx, {.format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                              .extent = {image.width, image.height},
                              .mip_levels = 0,
                              .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              .debug_name = name});
  // The mips made on the CPU, not by blits: lavapipe compiles its blitter at a process's first blit
  // (render/texture_mips.h).
  const std::vector<uint8_t> chain = rgba8_mip_chain(image, srgb);
  vk::upload_image_mips(ctx, texture, std::as_bytes(std::span(chain)), VK_IMAGE_LAYOUT_GENERAL,
                        vk::access::kGraphicsSampled);
  return texture;
}

}  // namespace lagoon::render
