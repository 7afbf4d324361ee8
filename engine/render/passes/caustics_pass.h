// Caustics: the sun's light focused by the displaced surface onto horizontal planes at a few depths
// (shared/caustics.h), in a window of the sea around where the camera looks. Each frame, every source cell's
// refracted sun ray is splatted where it lands (shaders/caustics/splat.comp), then resolved into a map of
// irradiance relative to a flat sea (resolve.comp) that the floor's shading multiplies the direct sunlight
// by, from above (ocean_surface.frag) and below (underwater_medium.frag). Energy is conserved by
// construction: every ray carries the same share of the flat-surface irradiance.
#pragma once
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

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

// Where this frame's caustics are computed (FrameUniforms::caustics, caustic_depths).
struct CausticsWindow {
  glm::vec2 origin{0};  // world xz of the window's corner
  float cell_m = 0.125f;
  uint32_t cells = 0;  // 0 = no caustics this frame (switched off, the sun down, or nothing to light)
  glm::vec4 depths{1.0f, 2.5f, 6.0f, 15.0f};
  // The surface cells whose rays reach the window at some slice: the window shifted towards the sun by where
  // a flat surface sends the rays at each depth, plus LAGOON_CAUSTICS_MARGIN cells on every side. One ray per
  // cell serves every slice, so the cascades are sampled once.
  glm::vec2 source_origin{0};
  glm::uvec2 source_cells{0};
};
// `sun` towards the sun; `ior` of the water.
CausticsWindow caustics_window(const scene::Scene& scene, glm::vec3 sun, float ior);

class CausticsPass {
 public:
  CausticsPass(vk::Context& ctx, const SurfaceFields& fields, const Samplers& samplers);

  // Computes the map for `window` (nothing when it has no cells) and makes it ready for fragment shaders.
  void record(const FrameContext& frame, const CausticsWindow& window) const;

  // LAGOON_CAUSTICS_SLICES layers of LAGOON_CAUSTICS_CELLS² irradiance ratios (R32F, GENERAL layout).
  const vk::Image& map() const { return map_; }
  // For tests: the last frame's map read back, [slice][row z][column x], relative to a flat sea.
  std::vector<float> read_map(vk::Context& ctx) const;

 private:
  const SurfaceFields& fields_;
  const Samplers& samplers_;
  vk::ComputePipeline splat_, resolve_;
  vk::Buffer accum_;
  vk::Image map_;
};

}  // namespace lagoon::render
