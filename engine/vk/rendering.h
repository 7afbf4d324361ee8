// Dynamic rendering (no VkRenderPass/VkFramebuffer objects): begin with attachments, viewport and scissor
// set.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <optional>

namespace lagoon::vk {

struct ColorTarget {
  VkImageView view = VK_NULL_HANDLE;
  std::optional<std::array<float, 4>> clear;  // nullopt = load existing contents
};
struct DepthTarget {
  VkImageView view = VK_NULL_HANDLE;
  std::optional<float> clear = 1.0f;
};

// Color attachments must be in COLOR_ATTACHMENT_OPTIMAL, depth in DEPTH_ATTACHMENT_OPTIMAL.
void begin_rendering(VkCommandBuffer cmd, VkExtent2D extent, std::initializer_list<ColorTarget> colors,
                     std::optional<DepthTarget> depth = std::nullopt);
void end_rendering(VkCommandBuffer cmd);

}  // namespace lagoon::vk
