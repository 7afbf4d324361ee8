// The water surface: the above-water parts of objects, then the clipmap mesh displaced by the cascades,
// shaded with Fresnel between the reflection and the refracted light through the colour LUTs (eq. 22), foam
// and glints, tone-mapped into the displayed frame (shaders/render/ocean_surface.*). Also draws the
// surface's ground-truth AOVs (ocean_surface_aov.frag). render.shading's classic modes replace the shading
// with seed 001's Blinn-Phong (ocean_surface_classic.*).
#pragma once
#include <array>
#include <vector>

#include "render/frame_context.h"
#include "render/samplers.h"
#include "render/scene_objects.h"
#include "render/surface_fields.h"
#include "render/water_luts.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class SurfacePass {
 public:
  // The refraction and reflection passes' outputs, as sampled images.
  struct Inputs {
    const vk::Image& refraction_albedo;
    const vk::Image& refraction_depth;
    const vk::Image& reflection;
    const vk::Image& caustics;  // the caustic pass's map
  };

  SurfacePass(vk::Context& ctx, const SurfaceFields& fields, const SceneObjects& objects,
              const WaterLuts& luts, const Samplers& samplers, VkFormat color_format, VkFormat depth_format);

  // Into `color` and `depth` as attachments, cleared first.
  void record(const FrameContext& frame, const Inputs& in, vk::Target color, vk::Target depth) const;
  // The surface's shading normal and foam, and its world point, into two RGBA32F attachments (no objects).
  void record_aov(const FrameContext& frame, vk::Target normal_foam, vk::Target world, vk::Target depth);

  static constexpr VkFormat kAovFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

 private:
  vk::Context& ctx_;
  const SurfaceFields& fields_;
  const SceneObjects& objects_;
  const WaterLuts& luts_;
  const Samplers& samplers_;
  VkFormat color_format_, depth_format_;
  // Variants with the lamps' light under the water (bit 0, LAGOON_SURFACE_SPEC_LAMPS) and the caustics
  // (bit 1, LAGOON_SURFACE_SPEC_CAUSTICS) compiled in or out.
  std::array<vk::GraphicsPipeline, 8> surface_;  // by lamps (1), caustics (2), submerged objects (4)
  vk::GraphicsPipeline aov_;                     // created on first use
  // render.shading's classic modes (ocean_surface_classic.*): blinn-phong, gouraud, flat, created on first
  // use.
  const vk::GraphicsPipeline& classic(scene::Shading shading) const;
  mutable std::array<vk::GraphicsPipeline, 3> classic_;
};

}  // namespace lagoon::render
