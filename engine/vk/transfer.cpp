#include "vk/transfer.h"

#include <algorithm>
#include <cstring>

#include "vk/check.h"
#include "vk/context.h"

namespace lagoon::vk {
namespace {

VkDeviceSize mip_bytes(const Image& image, uint32_t mip) {
  const uint32_t w = std::max(1u, image.extent().width >> mip),
                 h = std::max(1u, image.extent().height >> mip);
  return VkDeviceSize(w) * h * format_texel_size(image.format()) * image.layers();
}

VkBufferImageCopy mip_copy(const Image& image, uint32_t mip) {
  return {.bufferOffset = 0,
          .imageSubresource = {image.aspect(), mip, 0, image.layers()},
          .imageExtent = {std::max(1u, image.extent().width >> mip),
                          std::max(1u, image.extent().height >> mip), 1}};
}

}  // namespace

void upload_buffer(Context& ctx, const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset) {
  if (offset + data.size() > dst.size()) throw_usage_error("upload_buffer: data does not fit the buffer");
  if (data.empty()) return;
  if (dst.host_visible()) {
    std::memcpy(dst.mapped() + offset, data.data(), data.size());
    dst.flush();
    return;
  }
  Buffer staging =
      Buffer::create(ctx, data.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload, "staging");
  std::memcpy(staging.mapped(), data.data(), data.size());
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{.srcOffset = 0, .dstOffset = offset, .size = data.size()};
    vkCmdCopyBuffer(cmd, staging.handle(), dst.handle(), 1, &region);
  });
}

std::vector<std::byte> readback_buffer(Context& ctx, const Buffer& src) {
  std::vector<std::byte> out(src.size());
  if (src.host_visible()) {
    src.invalidate();
    std::memcpy(out.data(), src.mapped(), out.size());
    return out;
  }
  Buffer staging =
      Buffer::create(ctx, src.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "readback");
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{.size = src.size()};
    vkCmdCopyBuffer(cmd, src.handle(), staging.handle(), 1, &region);
    buffer_barrier(cmd, staging.handle(), access::kTransferWrite, access::kHostRead);
  });
  staging.invalidate();
  std::memcpy(out.data(), staging.mapped(), out.size());
  return out;
}

namespace {

// Levels 0 .. levels - 1 from `texels` (packed level after level) into the image.
void upload_levels(Context& ctx, const Image& image, std::span<const std::byte> texels, uint32_t levels,
                   VkImageLayout final_layout, Access final_access) {
  std::vector<VkBufferImageCopy> regions;
  VkDeviceSize offset = 0;
  for (uint32_t m = 0; m < levels; ++m) {
    VkBufferImageCopy region = mip_copy(image, m);
    region.bufferOffset = offset;
    regions.push_back(region);
    offset += mip_bytes(image, m);
  }
  if (texels.size() != offset) throw_usage_error("upload_image: texel data does not match the image size");
  Buffer staging =
      Buffer::create(ctx, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload, "staging");
  std::memcpy(staging.mapped(), texels.data(), texels.size());
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    const VkImageSubresourceRange range = image.all_subresources();
    image_barrier(cmd, image.handle(), range, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                  access::kNone, access::kTransferWrite);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(regions.size()), regions.data());
    image_barrier(cmd, image.handle(), range, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, final_layout,
                  access::kTransferWrite, final_access);
  });
}

}  // namespace

void upload_image(Context& ctx, const Image& image, std::span<const std::byte> texels,
                  VkImageLayout final_layout, Access final_access) {
  upload_levels(ctx, image, texels, 1, final_layout, final_access);
}

void upload_image_mips(Context& ctx, const Image& image, std::span<const std::byte> chain,
                       VkImageLayout final_layout, Access final_access) {
  upload_levels(ctx, image, chain, image.mip_levels(), final_layout, final_access);
}

VkDeviceSize readback_bytes(const Image& image, uint32_t mip) {
  return mip_bytes(image, mip);
}

void record_readback(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, Access last_writer,
                     const Buffer& staging, uint32_t mip) {
  const VkImageSubresourceRange range = image.all_subresources();
  image_barrier(cmd, image.handle(), range, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, last_writer,
                access::kTransferRead);
  const VkBufferImageCopy region = mip_copy(image, mip);
  vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1,
                         &region);
  image_barrier(cmd, image.handle(), range, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                access::kTransferRead, last_writer);
  buffer_barrier(cmd, staging.handle(), access::kTransferWrite, access::kHostRead);
}

std::vector<std::byte> readback_image(Context& ctx, const Image& image, VkImageLayout layout,
                                      Access last_writer, uint32_t mip) {
  const VkDeviceSize size = mip_bytes(image, mip);
  Buffer staging =
      Buffer::create(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "readback");
  ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { record_readback(cmd, image, layout, last_writer, staging, mip); });
  staging.invalidate();
  std::vector<std::byte> out(size);
  std::memcpy(out.data(), staging.mapped(), size);
  return out;
}

}  // namespace lagoon::vk
