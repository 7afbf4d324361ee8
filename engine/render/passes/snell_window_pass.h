// Objects above the water as seen from below through Snell's window (docs/rendering.md, "Under the
// surface"): each is drawn where a flat surface shows it to the camera, refraction and all
// (shaders/common/snell_window.glsl). The surface from below (ocean_surface_below.frag) looks its own
// refracted rays up in this picture, as the surface from above looks up the reflection pass's. Drawn only
// when the camera is under the water or at the waterline.
#pragma once
#include "render/frame_context.h"
#include "render/scene_objects.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

class SnellWindowPass {
 public:
  SnellWindowPass(vk::Context& ctx, const SceneObjects& objects, VkFormat color_format, VkFormat depth_format)
      : ctx_(ctx), objects_(objects), color_format_(color_format), depth_format_(depth_format) {}

  void resize(VkExtent2D extent);
  // Expects its targets as attachments. rgb = radiance, a = coverage (0 where the sky is seen).
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
