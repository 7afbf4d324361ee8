// The parts of objects above the water drawn lit into a target of their own (HDR colour, a = coverage, and
// depth) that the water surface looks up. Two instances, one per mesh mode (shared/mesh.h):
// - the reflection (LAGOON_MESH_MIRRORED): mirrored about the mean water level and seen by the main camera;
//   the surface from above reflects it, and the analytic sky where alpha is 0.
// - the Snell's window (LAGOON_MESH_WINDOW): each vertex where a flat surface shows it to a camera under the
//   water (shaders/common/snell_window.glsl); the surface from below looks its refracted rays up in it.
#pragma once
#include <string>

#include "render/frame_context.h"
#include "render/scene_objects.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

class ObjectsPass {
 public:
  ObjectsPass(vk::Context& ctx, const SceneObjects& objects, gpu::MeshMode mode, std::string name,
              VkFormat color_format, VkFormat depth_format)
      : ctx_(ctx),
        objects_(objects),
        mode_(mode),
        name_(std::move(name)),
        color_format_(color_format),
        depth_format_(depth_format) {}

  void resize(VkExtent2D extent);
  // Expects its targets as attachments. With `draw` false it only clears them (render.effects.reflection).
  void record(const FrameContext& frame, bool draw = true) const;

  vk::Target color() const { return color_.target(); }
  vk::Target depth() const { return depth_.target(); }
  const vk::Image& color_image() const { return color_; }

 private:
  vk::Context& ctx_;
  const SceneObjects& objects_;
  gpu::MeshMode mode_;
  std::string name_;  // the GPU timer's and the debug names' label
  VkFormat color_format_, depth_format_;
  vk::Image color_, depth_;
};

}  // namespace lagoon::render
