// A lens cutting the water surface (world/camera_medium.h CameraSide::Waterline): the frame is drawn from
// above into the frame's targets and from below into this pass's own, then shaders/render/waterline.frag
// puts the pixels whose near-plane point is under the displaced surface from the second over the first,
// with a thin meniscus along the split.
#pragma once
#include "render/frame_context.h"
#include "render/samplers.h"
#include "render/surface_fields.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class WaterlinePass {
 public:
  WaterlinePass(vk::Context& ctx, const SurfaceFields& fields, const Samplers& samplers,
                VkFormat color_format, VkFormat depth_format);

  void resize(VkExtent2D extent);
  // Where the frame from below is drawn (as attachments), then read (as sampled images) by record().
  vk::Target below_color() const { return color_.target(); }
  vk::Target below_depth() const { return depth_.target(); }

  // Over `color` and `depth` (attachments holding the frame from above).
  void record(const FrameContext& frame, vk::Target color, vk::Target depth) const;

 private:
  vk::Context& ctx_;
  const SurfaceFields& fields_;
  const Samplers& samplers_;
  VkFormat color_format_, depth_format_;
  vk::GraphicsPipeline composite_;
  vk::Image color_, depth_;
};

}  // namespace lagoon::render
