// A 2-D image (optionally layered and mipmapped) with its memory and a view of all mips and layers.
#pragma once
#include <vulkan/vulkan.h>

#include <vector>

#include "vk/handle.h"

namespace lagoon::vk {

class Context;

struct ImageDesc {
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkExtent2D extent{1, 1};
  uint32_t mip_levels = 1;  // 0 = full chain down to 1x1
  uint32_t layers = 1;      // > 1 gives a 2D_ARRAY view (e.g. one layer per ocean cascade)
  bool array_view = false;  // a 2D_ARRAY view even for one layer (shaders that declare image2DArray)
  VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
  const char* debug_name = nullptr;
};

// An image as render passes see it (vk/barriers.h use(), vk/rendering.h): Lagoon's own or a host's.
struct Target {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

class Image {
 public:
  Image() = default;
  static Image create(const Context& ctx, const ImageDesc& desc);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  // View of one mip level (all layers), e.g. to write a mip in a compute pass.
  VkImageView mip_view(uint32_t level) const {
    return mip_views_.empty() ? view_.get() : mip_views_.at(level).get();
  }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t mip_levels() const { return mip_levels_; }
  uint32_t layers() const { return layers_; }
  VkImageAspectFlags aspect() const { return aspect_; }
  Target target() const { return {image_, view_, aspect_}; }
  VkImageSubresourceRange all_subresources() const { return {aspect_, 0, mip_levels_, 0, layers_}; }

 private:
  Unique<VkImage> image_;
  Unique<VkDeviceMemory> memory_;
  Unique<VkImageView> view_;
  std::vector<Unique<VkImageView>> mip_views_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  uint32_t mip_levels_ = 1;
  uint32_t layers_ = 1;
  VkImageAspectFlags aspect_ = VK_IMAGE_ASPECT_COLOR_BIT;
};

// Bytes per texel of the uncompressed formats Lagoon uses (throws for others).
uint32_t format_texel_size(VkFormat format);
bool is_depth_format(VkFormat format);

}  // namespace lagoon::vk
