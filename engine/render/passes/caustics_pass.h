// Caustics: the sun's light focused by the displaced surface onto horizontal planes at a few depths
// (shared/caustics.h), in a window of the sea around where the camera looks. Each frame, every source cell's
// refracted sun ray is splatted where it lands (shaders/caustics/splat.comp), then blurred by what the rays
// leave out (blur_rows.comp along x, render/caustics_window.h) and resolved into a map of irradiance relative
// to a flat sea (resolve.comp, along z) that the floor's shading multiplies the direct sunlight
// by, from above (ocean_surface.frag) and below (underwater_medium.frag). Energy is conserved by
// construction: every ray carries the same share of the flat-surface irradiance.
#pragma once
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "render/caustics_window.h"
#include "render/frame_context.h"
#include "render/samplers.h"
#include "render/surface_fields.h"
#include "scene/scene.h"
#include "shared/caustics.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::render {

class CausticsPass {
 public:
  CausticsPass(vk::Context& ctx, const SurfaceFields& fields, const Samplers& samplers);

  // Computes the map for `window` (nothing when it has no cells) and makes it ready for fragment shaders.
  void record(const FrameContext& frame, const CausticsWindow& window) const;

  // LAGOON_CAUSTICS_SLICES layers of LAGOON_CAUSTICS_CELLS² irradiance ratios (R32F, GENERAL layout), of
  // which a frame's window uses the first cells² (CausticsWindow::cells).
  const vk::Image& map() const { return map_; }
  // For tests: the last frame's map read back, [slice][row z][column x] over the whole image (a coarser
  // frame's cells are its first cells x cells), relative to a flat sea.
  std::vector<float> read_map(vk::Context& ctx) const;

 private:
  const SurfaceFields& fields_;
  const Samplers& samplers_;
  vk::ComputePipeline splat_, blur_rows_, resolve_;
  vk::Buffer accum_, rows_;
  vk::Image map_;
};

}  // namespace lagoon::render
