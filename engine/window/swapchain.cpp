#include "window/swapchain.h"

#include <algorithm>
#include <stdexcept>

#include "vk/check.h"

namespace lagoon {
namespace {

VkSurfaceFormatKHR pick_format(VkPhysicalDevice gpu, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data()));
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  throw std::runtime_error("the window's surface offers no B8G8R8A8 or R8G8B8A8 UNORM format");
}

VkPresentModeKHR pick_present_mode(VkPhysicalDevice gpu, VkSurfaceKHR surface, bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, modes.data()));
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;
}

// currentExtent is the window's size unless the surface lets the swapchain choose (0xFFFFFFFF).
VkExtent2D choose_extent(const VkSurfaceCapabilitiesKHR& caps, VkExtent2D window) {
  if (caps.currentExtent.width != UINT32_MAX) return caps.currentExtent;
  return {std::clamp(window.width, caps.minImageExtent.width, caps.maxImageExtent.width),
          std::clamp(window.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
}

// One more than the minimum (at least 2), so the CPU need not wait for the compositor to release an image.
uint32_t choose_image_count(const VkSurfaceCapabilitiesKHR& caps) {
  const uint32_t count = std::max(caps.minImageCount + 1, 2u);
  return caps.maxImageCount > 0 ? std::min(count, caps.maxImageCount) : count;
}

// Opaque where the compositor allows it; some (Wayland, Android) offer only the other modes.
VkCompositeAlphaFlagBitsKHR pick_composite_alpha(const VkSurfaceCapabilitiesKHR& caps) {
  for (VkCompositeAlphaFlagBitsKHR a :
       {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
        VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
    if (caps.supportedCompositeAlpha & a) return a;
  return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
}

vk::Unique<VkImageView> make_view(VkDevice device, VkImage image, VkFormat format) {
  const VkImageViewCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                   .image = image,
                                   .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                   .format = format,
                                   .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
  return {device, view};
}

vk::Unique<VkSemaphore> make_semaphore(VkDevice device) {
  const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  return {device, semaphore};
}

}  // namespace

Swapchain::Swapchain(vk::Context& ctx, VkExtent2D extent, bool vsync, Swapchain* previous) : ctx_(ctx) {
  const VkPhysicalDevice gpu = ctx.physical_device();
  const VkSurfaceKHR surface = ctx.surface();
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, surface, &caps));
  extent_ = choose_extent(caps, extent);
  const VkSurfaceFormatKHR format = pick_format(gpu, surface);
  format_ = format.format;
  present_mode_ = pick_present_mode(gpu, surface, vsync);
  min_images_ = choose_image_count(caps);
  // Copies in (the rendered frame) and out (screenshots), and the UI drawn on top.
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if ((caps.supportedUsageFlags & usage) != usage)
    throw std::runtime_error("the window's surface cannot be copied to and from (transfer usage missing)");
  if (extent_.width == 0 || extent_.height == 0)
    throw std::runtime_error("cannot create a swapchain for a minimised window (0 x 0)");
  const VkSwapchainCreateInfoKHR info{.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
                                      .surface = surface,
                                      .minImageCount = min_images_,
                                      .imageFormat = format.format,
                                      .imageColorSpace = format.colorSpace,
                                      .imageExtent = extent_,
                                      .imageArrayLayers = 1,
                                      .imageUsage = usage,
                                      .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                      .preTransform = caps.currentTransform,
                                      .compositeAlpha = pick_composite_alpha(caps),
                                      .presentMode = present_mode_,
                                      .clipped = VK_TRUE,
                                      .oldSwapchain = previous ? previous->handle() : VK_NULL_HANDLE};
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(ctx.device(), &info, nullptr, &swapchain));
  swapchain_ = vk::Unique<VkSwapchainKHR>(ctx.device(), swapchain);

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(ctx.device(), swapchain, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(ctx.device(), swapchain, &count, images_.data()));
  // A semaphore per image, so one is never reused while a present may still wait on it.
  for (VkImage image : images_) {
    views_.push_back(make_view(ctx.device(), image, format_));
    rendered_.push_back(make_semaphore(ctx.device()));
  }
}

}  // namespace lagoon
