// One-line barriers at pass boundaries (synchronization2). Stages and accesses are explicit so the
// validation layer's synchronization checks can tell us when a pass forgot one.
#pragma once
#include <vulkan/vulkan.h>

#include <initializer_list>

#include "vk/image.h"

namespace lagoon::vk {

struct Access {
  VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// Common points of use.
namespace access {
inline constexpr Access kNone{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
inline constexpr Access kTransferWrite{
    VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT,
    VK_ACCESS_2_TRANSFER_WRITE_BIT};
inline constexpr Access kTransferRead{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                                      VK_ACCESS_2_TRANSFER_READ_BIT};
inline constexpr Access kComputeRead{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
inline constexpr Access kComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr Access kComputeReadWrite{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr Access kGraphicsSampled{
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr Access kColorAttachmentWrite{
    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT};
inline constexpr Access kDepthAttachment{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
inline constexpr Access kHostRead{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
inline constexpr Access kHostWrite{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT};
// Everything: for a frame that must start after all work submitted before it.
inline constexpr Access kAllCommands{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                                     VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
}  // namespace access

// How a pass uses an image. use() derives layouts and accesses from it, so the frame states each hand-over
// between passes in one line (engine/render/frame_steps.cpp, each step of the frame).
enum class ImageUse {
  Discard,     // contents not needed (UNDEFINED): before a target's first pass in a frame
  Attachment,  // COLOR_ or DEPTH_ATTACHMENT_OPTIMAL (by the image's aspect): drawn into, depth-tested
  Sampled,     // GENERAL, read by vertex and fragment shaders
};
// One barrier for all `targets`: what `from` wrote becomes visible to `to`, with the layout change.
void use(VkCommandBuffer cmd, std::initializer_list<Target> targets, ImageUse from, ImageUse to);

void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageSubresourceRange range,
                   VkImageLayout old_layout, VkImageLayout new_layout, Access src, Access dst);
void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, Access src, Access dst);
void memory_barrier(VkCommandBuffer cmd, Access src, Access dst);

}  // namespace lagoon::vk
