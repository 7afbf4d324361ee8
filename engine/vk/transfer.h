// Staging upload and readback for set-up, tests and the CLI's PNG output. Each call submits and waits;
// the per-frame path records its copies into the frame's command buffer instead.
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/image.h"

namespace lagoon::vk {

class Context;

void upload_buffer(Context& ctx, const Buffer& dst, std::span<const std::byte> data, VkDeviceSize offset = 0);
std::vector<std::byte> readback_buffer(Context& ctx, const Buffer& src);

// `texels`: mip 0 of every layer, tightly packed, layer after layer. The previous contents are discarded and
// the image is left in `final_layout`, visible to `final_access`.
void upload_image(Context& ctx, const Image& image, std::span<const std::byte> texels,
                  VkImageLayout final_layout, Access final_access);
// As upload_image, with every mip level given: `chain` holds level 0, 1, ... image.mip_levels() - 1 of every
// layer, each tightly packed (a texture whose mips were made on the CPU, render/texture_mips.h).
void upload_image_mips(Context& ctx, const Image& image, std::span<const std::byte> chain,
                       VkImageLayout final_layout, Access final_access);
// Records a copy of one mip level of every layer (tightly packed) into `staging` (a Readback buffer of at
// least readback_bytes(image, mip)), made visible to the host once `cmd` has completed. The image must be in
// `layout` after `last_writer`; it is returned to `layout`. Lets a frame read its result in its own submit.
VkDeviceSize readback_bytes(const Image& image, uint32_t mip = 0);
void record_readback(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, Access last_writer,
                     const Buffer& staging, uint32_t mip = 0);
// Reads one mip level of every layer (tightly packed). The image must be in `layout` after `last_writer`;
// it is returned to `layout`.
std::vector<std::byte> readback_image(Context& ctx, const Image& image, VkImageLayout layout,
                                      Access last_writer, uint32_t mip = 0);

template <typename T>
std::span<const std::byte> as_bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span<const T>(v));
}

}  // namespace lagoon::vk
