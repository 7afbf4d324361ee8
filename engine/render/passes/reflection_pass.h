// Planar reflection: what is above the water, mirrored about the mean water level, seen by the main camera.
// Alpha marks where something was drawn; elsewhere the surface reflects the analytic sky.
#pragma once
#include "render/frame_context.h"
#include "render/scene_objects.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

class ReflectionPass {
 public:
  ReflectionPass(vk::Context& ctx, const SceneObjects& objects, VkFormat color_format, VkFormat depth_format)
      : ctx_(ctx), objects_(objects), color_format_(color_format), depth_format_(depth_format) {}

  void resize(VkExtent2D extent);
  // Expects its targets as attachments. With render.effects.reflection off it only clears them.
  void record(const FrameContext& frame) const;

  vk::Target color() const { return color_.target(); }
  vk::Target depth() const { return depth_.target(); }
  const vk::Image& color_image() const { return color_; }

 private:
  vk::Context& ctx_;
  const SceneObjects& objects_;
  VkFormat color_format_, depth_format_;
  vk::Image color_, depth_;
};

}  // namespace lagoon::render
