#include "vk/barriers.h"

#include <vector>

namespace lagoon::vk {
namespace {

struct UseState {
  VkImageLayout layout;
  Access access;
};

UseState state_of(ImageUse use, VkImageAspectFlags aspect) {
  const bool depth = (aspect & VK_IMAGE_ASPECT_DEPTH_BIT) != 0;
  switch (use) {
    case ImageUse::Discard:
      return {VK_IMAGE_LAYOUT_UNDEFINED, access::kNone};
    case ImageUse::Attachment:
      return depth ? UseState{VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, access::kDepthAttachment}
                   : UseState{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, access::kColorAttachmentWrite};
    case ImageUse::Sampled:
      return {VK_IMAGE_LAYOUT_GENERAL, access::kGraphicsSampled};
  }
  return {VK_IMAGE_LAYOUT_UNDEFINED, access::kNone};
}

}  // namespace

void use(VkCommandBuffer cmd, std::initializer_list<Target> targets, ImageUse from, ImageUse to) {
  std::vector<VkImageMemoryBarrier2> barriers;
  for (const Target& t : targets) {
    const UseState a = state_of(from, t.aspect), b = state_of(to, t.aspect);
    barriers.push_back(
        {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
         .srcStageMask = a.access.stage,
         .srcAccessMask = a.access.access,
         .dstStageMask = b.access.stage,
         .dstAccessMask = b.access.access,
         .oldLayout = a.layout,
         .newLayout = b.layout,
         .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
         .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
         .image = t.image,
         .subresourceRange = {t.aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS}});
  }
  const VkDependencyInfo dep{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                             .imageMemoryBarrierCount = uint32_t(barriers.size()),
                             .pImageMemoryBarriers = barriers.data()};
  vkCmdPipelineBarrier2(cmd, &dep);
}

void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageSubresourceRange range,
                   VkImageLayout old_layout, VkImageLayout new_layout, Access src, Access dst) {
  const VkImageMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                                      .srcStageMask = src.stage,
                                      .srcAccessMask = src.access,
                                      .dstStageMask = dst.stage,
                                      .dstAccessMask = dst.access,
                                      .oldLayout = old_layout,
                                      .newLayout = new_layout,
                                      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                      .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                      .image = image,
                                      .subresourceRange = range};
  const VkDependencyInfo dep{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                             .imageMemoryBarrierCount = 1,
                             .pImageMemoryBarriers = &barrier};
  vkCmdPipelineBarrier2(cmd, &dep);
}

void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, Access src, Access dst) {
  const VkBufferMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
                                       .srcStageMask = src.stage,
                                       .srcAccessMask = src.access,
                                       .dstStageMask = dst.stage,
                                       .dstAccessMask = dst.access,
                                       .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                       .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                                       .buffer = buffer,
                                       .offset = 0,
                                       .size = VK_WHOLE_SIZE};
  const VkDependencyInfo dep{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                             .bufferMemoryBarrierCount = 1,
                             .pBufferMemoryBarriers = &barrier};
  vkCmdPipelineBarrier2(cmd, &dep);
}

void memory_barrier(VkCommandBuffer cmd, Access src, Access dst) {
  const VkMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                 .srcStageMask = src.stage,
                                 .srcAccessMask = src.access,
                                 .dstStageMask = dst.stage,
                                 .dstAccessMask = dst.access};
  const VkDependencyInfo dep{
      .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1, .pMemoryBarriers = &barrier};
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace lagoon::vk
