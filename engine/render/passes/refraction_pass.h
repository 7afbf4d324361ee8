// Refraction: the floor and the submerged parts of objects, as albedo (a = coverage) and depth, for the
// surface pass to light through the water with the colour LUTs (seed 000's eq. 22).
#pragma once
#include "render/frame_context.h"
#include "render/scene_objects.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

class RefractionPass {
 public:
  RefractionPass(vk::Context& ctx, const SceneObjects& objects, VkFormat color_format, VkFormat depth_format)
      : ctx_(ctx), objects_(objects), color_format_(color_format), depth_format_(depth_format) {}

  void resize(VkExtent2D extent);
  // Expects its targets as attachments (vk/barriers.h ImageUse::Attachment).
  void record(const FrameContext& frame) const;

  vk::Target albedo() const { return albedo_.target(); }
  vk::Target depth() const { return depth_.target(); }
  const vk::Image& albedo_image() const { return albedo_; }
  const vk::Image& depth_image() const { return depth_; }

 private:
  vk::Context& ctx_;
  const SceneObjects& objects_;
  VkFormat color_format_, depth_format_;
  vk::Image albedo_, depth_;
};

}  // namespace lagoon::render
