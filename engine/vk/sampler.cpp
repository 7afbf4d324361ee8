#include "vk/sampler.h"

#include <algorithm>

#include "vk/check.h"
#include "vk/context.h"

namespace lagoon::vk {

Unique<VkSampler> create_sampler(const Context& ctx, const SamplerDesc& desc) {
  // Enabled, not merely supported: a host's device (Context::adopt) may leave samplerAnisotropy off.
  const bool aniso = desc.max_anisotropy > 1.0f && ctx.enabled_features().samplerAnisotropy;
  const VkSamplerCreateInfo info{
      .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
      .magFilter = desc.filter,
      .minFilter = desc.min_filter == VK_FILTER_MAX_ENUM ? desc.filter : desc.min_filter,
      .mipmapMode = desc.mipmap,
      .addressModeU = desc.address,
      .addressModeV = desc.address_v == VK_SAMPLER_ADDRESS_MODE_MAX_ENUM ? desc.address : desc.address_v,
      .addressModeW = desc.address,
      .anisotropyEnable = aniso ? VK_TRUE : VK_FALSE,
      .maxAnisotropy =
          aniso ? std::min(desc.max_anisotropy, ctx.properties().limits.maxSamplerAnisotropy) : 1.0f,
      .minLod = 0.0f,
      .maxLod = desc.mip_levels ? VK_LOD_CLAMP_NONE : 0.0f,
      .borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK};
  VkSampler sampler;
  VK_CHECK(vkCreateSampler(ctx.device(), &info, nullptr, &sampler));
  return {ctx.device(), sampler};
}

}  // namespace lagoon::vk
