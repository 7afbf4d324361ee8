// Float colour targets that a ground-truth frame draws into and reads back (OceanRenderer's
// render_surface_aov and render_underwater_terms): `count` RGBA32F colour images and a depth image of one
// extent, each colour image with its host-visible staging buffer.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

class FloatTargets {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

  FloatTargets(vk::Context& ctx, VkExtent2D extent, uint32_t count, VkFormat depth_format, const char* name);

  vk::Target color(uint32_t i) const { return colors_[i].target(); }
  const vk::Image& color_image(uint32_t i) const { return colors_[i]; }
  vk::Target depth() const { return depth_.target(); }
  // Every colour target and the depth, discarded and made ready as attachments.
  void begin(VkCommandBuffer cmd) const;
  // Copies every colour target (in COLOR_ATTACHMENT_OPTIMAL after colour writes) to its staging buffer.
  void record_readback(VkCommandBuffer cmd) const;
  // Colour target i as read back, rows from the top; after the submission has completed.
  std::vector<glm::vec4> read(uint32_t i) const;

 private:
  VkExtent2D extent_;
  std::vector<vk::Image> colors_;
  std::vector<vk::Buffer> staging_;
  vk::Image depth_;
};

}  // namespace lagoon::render
