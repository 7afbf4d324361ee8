// Fills mips 1..n-1 of an image from mip 0 by successive linear blits (all layers).
#pragma once
#include "vk/barriers.h"
#include "vk/image.h"

namespace lagoon::vk {

// The image stays in `layout` (GENERAL or TRANSFER-compatible layouts); mip 0 was last written by
// `last_writer`; afterwards every mip is visible to `next_reader`.
void generate_mipmaps(VkCommandBuffer cmd, const Image& image, VkImageLayout layout, Access last_writer,
                      Access next_reader);

}  // namespace lagoon::vk
