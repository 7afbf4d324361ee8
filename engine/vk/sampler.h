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
};

Unique<VkSampler> create_sampler(const Context& ctx, const SamplerDesc& desc);

}  // namespace lagoon::vk
