// Where a frame's caustics are computed (render/passes/caustics_pass.h draws them): a window of the sea
// around where the camera looks, its slices' depths and the surface cells whose rays reach it. Plain data
// the frame's uniforms and the renderer read without the pass.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

#include "scene/scene.h"

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

}  // namespace lagoon::render
