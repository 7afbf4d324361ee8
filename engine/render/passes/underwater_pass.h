// The frame for a camera under the water (docs/rendering.md, "Under the surface"): the floor and submerged
// objects seen through the water, or the water itself where the view meets nothing (underwater_medium.frag),
// then the surface from below with Snell's window and total internal reflection (ocean_surface_below.frag).
// Light and colour come from the underwater tables (optics/underwater.h) of the scene's water.
#pragma once
#include <array>

#include "render/frame_context.h"
#include "render/samplers.h"
#include "render/surface_fields.h"
#include "render/water_luts.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class UnderwaterPass {
 public:
  // The refraction pass's output: what is under the water, as albedo (a = coverage) and depth.
  struct Inputs {
    const vk::Image& refraction_albedo;
    const vk::Image& refraction_depth;
    const vk::Image& caustics;  // the caustic pass's map
    const vk::Image& window;    // objects above the water, as seen through Snell's window (objects_pass.h)
  };

  UnderwaterPass(vk::Context& ctx, const SurfaceFields& fields, const WaterLuts& luts,
                 const Samplers& samplers, VkFormat color_format, VkFormat depth_format);

  // Into `color` and `depth` as attachments; every pixel is written.
  void record(const FrameContext& frame, const Inputs& in, vk::Target color, vk::Target depth) const;

  // The view's image formation terms for the ground truth (shaders/render/underwater_terms.frag), without the
  // surface: clean, transmission and backscatter into three kTermsFormat targets, and `depth`.
  static constexpr VkFormat kTermsFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  void record_terms(const FrameContext& frame, const Inputs& in, const std::array<vk::Target, 3>& terms,
                    vk::Target depth);

 private:
  std::vector<vk::Binding> table_bindings(const FrameContext& frame) const;
  std::vector<vk::Binding> medium_bindings(const FrameContext& frame, const Inputs& in) const;

  const SurfaceFields& fields_;
  const WaterLuts& luts_;
  const Samplers& samplers_;
  // [0]: without light shafts, [1]: with (render.effects.shafts), as a specialisation constant.
  std::array<vk::GraphicsPipeline, 2> surface_;
  // [shafts][lamps]: also without or with the lamps' light (LAGOON_SURFACE_SPEC_LAMPS).
  std::array<std::array<vk::GraphicsPipeline, 2>, 2> medium_;
  // The same for record_terms(), made on first use.
  std::array<std::array<vk::GraphicsPipeline, 2>, 2> terms_;
  vk::Context& ctx_;
  VkFormat depth_format_;
  bool sediment_;
};

}  // namespace lagoon::render
