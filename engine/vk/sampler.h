// Samplers. Ocean textures repeat (tiling patches); screen-space lookups clamp.
#pragma once
#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace lagoon::vk {

class Context;

struct SamplerDesc {
  VkFilter filter = VK_FILTER_LINEAR;
  VkSamplerMipmapMode mipmap = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  VkSamplerAddressMode address = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  float max_anisotropy = 1.0f;  // > 1 only takes effect when the device supports anisotropic filtering
  // Where a texture's axes or its magnification and minification differ (glTF samplers): MAX_ENUM = as
  // `address` / `filter`.
  VkSamplerAddressMode address_v = VK_SAMPLER_ADDRESS_MODE_MAX_ENUM;
  VkFilter min_filter = VK_FILTER_MAX_ENUM;
  bool mip_levels = true;  // false: only the base level is sampled (glTF minFilter NEAREST or LINEAR)
};

Unique<VkSampler> create_sampler(const Context& ctx, const SamplerDesc& desc);

}  // namespace lagoon::vk
