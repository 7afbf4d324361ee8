// Where a frame's caustics are computed (render/passes/caustics_pass.h draws them): a window of the sea
// around where the camera looks, its slices' depths and the surface cells whose rays reach it. Plain data
// the frame's uniforms and the renderer read without the pass.
#pragma once
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

#include "scene/scene.h"
#include "shared/caustics.h"

namespace lagoon::render {

// Where this frame's caustics are computed (FrameUniforms::caustics, caustic_depths).
struct CausticsWindow {
  static constexpr float kSizeM = 32.0f;  // the window's side: LAGOON_CAUSTICS_CELLS cells of 12.5 cm
  glm::vec2 origin{0};                    // world xz of the window's corner
  float cell_m = kSizeM / LAGOON_CAUSTICS_CELLS;
  // Cells per side, at most LAGOON_CAUSTICS_CELLS (the map's first cells x cells); 0 = no caustics this frame
  // (switched off, the sun down, or nothing to light).
  uint32_t cells = 0;
  glm::vec4 depths{1.0f, 2.5f, 6.0f, 15.0f};
  // The surface cells whose rays reach the window at some slice: the window shifted towards the sun by where
  // a flat surface sends the rays at each depth, plus LAGOON_CAUSTICS_MARGIN cells on every side. One ray per
  // cell serves every slice, so the cascades are sampled once.
  glm::vec2 source_origin{0};
  glm::uvec2 source_cells{0};
  // Each slice's Gaussian blur, its standard deviation in cells: the rays' angular spread that the splat
  // does not follow (the waves shorter than a cell and the solar disc) over the slice's depth. 0 when
  // render.effects.caustics_blur is off.
  glm::vec4 blur_cells{0.0f};
};
// `sun` towards the sun; `ior` of the water; `unresolved_mss` the mean square slope of the waves shorter than
// a cell (caustic_unresolved_mss); `cells` per side of the same window (LAGOON_CAUSTICS_CELLS, or a power of
// two down to 64 for a picture drawn small: OceanRenderer::set_caustic_cells).
CausticsWindow caustics_window(const scene::Scene& scene, glm::vec3 sun, float ior, float unresolved_mss,
                               uint32_t cells = LAGOON_CAUSTICS_CELLS);

// The standard deviation, in radians per axis, of the refracted sun's direction under the water from what a
// cell's ray leaves out: slopes of mean square `unresolved_mss` tilt the surface's normal by s (per axis
// √(mss/2)), which turns the refracted ray by (1 − cos θa / (n cos θw)) s in the plane of incidence, and the
// solar disc's radius α, α cos θa / (n cos θw) under the water (a uniform disc: α/2 per axis). Spreads
// combined in quadrature. `sun_y` is the sine of the sun's elevation.
double refracted_sun_spread_rad(double sun_y, double ior, double unresolved_mss);

}  // namespace lagoon::render
