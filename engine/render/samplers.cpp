#include "render/samplers.h"

#include "vk/sampler.h"

namespace lagoon::render {

Samplers Samplers::create(const vk::Context& ctx) {
  // Anisotropic filtering is cheap in GPU hardware but runs in software on CPU devices.
  const bool cpu = ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  return {.repeat = vk::create_sampler(
              ctx, {.address = VK_SAMPLER_ADDRESS_MODE_REPEAT, .max_anisotropy = cpu ? 1.0f : 8.0f}),
          .clamp = vk::create_sampler(ctx, {.address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE}),
          .nearest = vk::create_sampler(ctx, {.filter = VK_FILTER_NEAREST,
                                              .mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                              .address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE})};
}

}  // namespace lagoon::render
