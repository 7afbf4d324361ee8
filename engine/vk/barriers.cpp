#include "vk/barriers.h"

namespace lagoon::vk {

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
