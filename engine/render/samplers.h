// The samplers the passes share, created once per renderer.
#pragma once
#include "vk/context.h"
#include "vk/handle.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

struct Samplers {
  vk::Unique<VkSampler> repeat;   // tiling textures (cascades, albedo); isotropic on every device
  vk::Unique<VkSampler> clamp;    // screen-space targets and LUTs
  vk::Unique<VkSampler> nearest;  // depth read back as a texture

  static Samplers create(const vk::Context& ctx);
};

// `image` as sampled by a pass (GENERAL layout, vk/barriers.h ImageUse::Sampled).
inline vk::ImageRef sampled(const vk::Image& image, VkSampler sampler) {
  return {image.view(), VK_IMAGE_LAYOUT_GENERAL, sampler};
}

}  // namespace lagoon::render
