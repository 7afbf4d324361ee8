#include "render/float_targets.h"

#include <cstring>
#include <string>

#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {

FloatTargets::FloatTargets(vk::Context& ctx, VkExtent2D extent, uint32_t count, VkFormat depth_format,
                           const char* name)
    : extent_(extent) {
  for (uint32_t i = 0; i < count; ++i) {
    colors_.push_back(vk::Image::create(
        ctx, {.format = kFormat,
              .extent = extent,
              .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
              .debug_name = name}));
    staging_.push_back(vk::Buffer::create(ctx, vk::readback_bytes(colors_.back()),
                                          VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUsage::Readback, name));
  }
  depth_ = vk::Image::create(ctx, {.format = depth_format,
                                   .extent = extent,
                                   .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                   .debug_name = name});
}

void FloatTargets::begin(VkCommandBuffer cmd) const {
  for (const vk::Image& image : colors_)
    vk::use(cmd, {image.target()}, vk::ImageUse::Discard, vk::ImageUse::Attachment);
  vk::use(cmd, {depth_.target()}, vk::ImageUse::Discard, vk::ImageUse::Attachment);
}

void FloatTargets::record_readback(VkCommandBuffer cmd) const {
  for (size_t i = 0; i < colors_.size(); ++i)
    vk::record_readback(cmd, colors_[i], VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        vk::access::kColorAttachmentWrite, staging_[i]);
}

std::vector<glm::vec4> FloatTargets::read(uint32_t i) const {
  staging_[i].invalidate();
  std::vector<glm::vec4> values(size_t{extent_.width} * extent_.height);
  std::memcpy(values.data(), staging_[i].mapped(), values.size() * sizeof(glm::vec4));
  return values;
}

}  // namespace lagoon::render
