// The window's swapchain: images to present, recreated on resize or when the surface reports it out of
// date. B8G8R8A8/R8G8B8A8 UNORM so that the renderer's display-referred output (gamma already applied) is
// shown unchanged, and usable as a copy source for screenshots.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/context.h"
#include "vk/handle.h"

namespace lagoon {

class Swapchain {
 public:
  // `extent` is the window's framebuffer size (clamped to what the surface allows); with `vsync` off the
  // swapchain prefers MAILBOX, then IMMEDIATE, and falls back to FIFO (the only mode every driver has).
  // Replaces `previous` (which must be idle) when given.
  Swapchain(vk::Context& ctx, VkExtent2D extent, bool vsync, Swapchain* previous = nullptr);
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  VkSwapchainKHR handle() const { return swapchain_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  VkPresentModeKHR present_mode() const { return present_mode_; }
  uint32_t min_image_count() const { return min_images_; }
  uint32_t image_count() const { return uint32_t(images_.size()); }
  VkImage image(uint32_t i) const { return images_[i]; }
  VkImageView view(uint32_t i) const { return views_[i]; }
  // Signalled when image i has been rendered; waited on by its present. One per image, so a semaphore is
  // never reused while a present may still wait on it.
  VkSemaphore rendered(uint32_t i) const { return rendered_[i]; }

 private:
  vk::Context& ctx_;
  vk::Unique<VkSwapchainKHR> swapchain_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  uint32_t min_images_ = 2;
  std::vector<VkImage> images_;  // owned by the swapchain
  std::vector<vk::Unique<VkImageView>> views_;
  std::vector<vk::Unique<VkSemaphore>> rendered_;
};

}  // namespace lagoon
