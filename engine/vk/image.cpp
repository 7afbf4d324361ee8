#include "vk/image.h"

#include <algorithm>
#include <bit>
#include <string>

#include "vk/check.h"
#include "vk/context.h"
#include "vk/memory.h"

namespace lagoon::vk {

bool is_depth_format(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

uint32_t format_texel_size(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_UNORM:
      return 1;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_D32_SFLOAT:
      return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      throw_usage_error("format_texel_size: unsupported format " + std::to_string(format));
  }
}

Image Image::create(const Context& ctx, const ImageDesc& desc) {
  Image img;
  img.format_ = desc.format;
  img.extent_ = desc.extent;
  img.layers_ = desc.layers;
  img.mip_levels_ =
      desc.mip_levels != 0
          ? desc.mip_levels
          : static_cast<uint32_t>(std::bit_width(std::max(desc.extent.width, desc.extent.height)));
  img.aspect_ = is_depth_format(desc.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
  const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                               .imageType = VK_IMAGE_TYPE_2D,
                               .format = desc.format,
                               .extent = {desc.extent.width, desc.extent.height, 1},
                               .mipLevels = img.mip_levels_,
                               .arrayLayers = desc.layers,
                               .samples = VK_SAMPLE_COUNT_1_BIT,
                               .tiling = VK_IMAGE_TILING_OPTIMAL,
                               .usage = desc.usage,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                               .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
  VkImage image;
  VK_CHECK(vkCreateImage(ctx.device(), &info, nullptr, &image));
  img.image_ = Unique<VkImage>(ctx.device(), image);
  ctx.set_name(image, VK_OBJECT_TYPE_IMAGE, desc.debug_name);

  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(ctx.device(), image, &req);
  const VkMemoryAllocateInfo alloc{
      .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
      .allocationSize = req.size,
      .memoryTypeIndex = ctx.find_memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
  const std::string what = "image " + std::string(desc.debug_name ? desc.debug_name : "(unnamed)") + " " +
                           std::to_string(desc.extent.width) + "x" + std::to_string(desc.extent.height) +
                           (desc.layers > 1 ? "x" + std::to_string(desc.layers) + " layers" : std::string());
  VkDeviceMemory mem = allocate_memory(ctx, alloc, what);
  img.memory_ = Unique<VkDeviceMemory>(ctx.device(), mem);
  VK_CHECK(vkBindImageMemory(ctx.device(), image, mem, 0));

  const VkImageViewType view_type =
      desc.layers > 1 || desc.array_view ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  auto make_view = [&](uint32_t base_mip, uint32_t mip_count) {
    const VkImageViewCreateInfo view_info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = view_type,
        .format = desc.format,
        .subresourceRange = {img.aspect_, base_mip, mip_count, 0, desc.layers}};
    VkImageView view;
    VK_CHECK(vkCreateImageView(ctx.device(), &view_info, nullptr, &view));
    return Unique<VkImageView>(ctx.device(), view);
  };
  img.view_ = make_view(0, img.mip_levels_);
  const bool per_mip_views = img.mip_levels_ > 1 && (desc.usage & VK_IMAGE_USAGE_STORAGE_BIT);
  if (per_mip_views)
    for (uint32_t m = 0; m < img.mip_levels_; ++m) img.mip_views_.push_back(make_view(m, 1));
  return img;
}

}  // namespace lagoon::vk
