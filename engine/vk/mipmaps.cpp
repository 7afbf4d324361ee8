#include "vk/mipmaps.h"

#include <algorithm>

namespace lagoon::vk {

void generate_mipmaps(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, Access last_writer,
                      Access next_reader) {
  const VkImageAspectFlags aspect = image.aspect();
  const uint32_t layers = image.layers();
  image_barrier(cmd, image.handle(), {aspect, 0, 1, 0, layers}, layout, layout, last_writer,
                access::kTransferRead);
  int32_t w = int32_t(image.extent().width), h = int32_t(image.extent().height);
  for (uint32_t mip = 1; mip < image.mip_levels(); ++mip) {
    const int32_t nw = std::max(1, w / 2), nh = std::max(1, h / 2);
    // The destination mip's previous contents are discarded, but the last frame's readers must be done.
    image_barrier(cmd, image.handle(), {aspect, mip, 1, 0, layers}, layout, layout, next_reader,
                  access::kTransferWrite);
    const VkImageBlit blit{.srcSubresource = {aspect, mip - 1, 0, layers},
                           .srcOffsets = {{0, 0, 0}, {w, h, 1}},
                           .dstSubresource = {aspect, mip, 0, layers},
                           .dstOffsets = {{0, 0, 0}, {nw, nh, 1}}};
    vkCmdBlitImage(cmd, image.handle(), layout, image.handle(), layout, 1, &blit, VK_FILTER_LINEAR);
    image_barrier(cmd, image.handle(), {aspect, mip, 1, 0, layers}, layout, layout, access::kTransferWrite,
                  access::kTransferRead);
    w = nw;
    h = nh;
  }
  image_barrier(cmd, image.handle(), image.all_subresources(), layout, layout,
                {access::kTransferRead.stage | access::kTransferWrite.stage, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                next_reader);
}

}  // namespace lagoon::vk
