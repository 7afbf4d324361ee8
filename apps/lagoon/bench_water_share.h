// lagoon bench render's water colour share (issue 16; seed 000 claims the water takes at most 25 % of a
// frame): the scene's frames with the physical shading and with render.shading = blinn-phong, alternated
// round by round so the machine's drift hits both alike. The difference is the colour part of the surface
// pass (Fresnel, the LUTs, reflection and refraction lookups, foam, haze); the LUT build is timed apart, as
// it runs once per change of water, sun or sea, not per frame.
#pragma once
#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "vk/context.h"

namespace lagoon::cli {

struct WaterShare {
  nlohmann::json rows;      // Google Benchmark-style entries (ms)
  double share = 0;         // median of the per-round water colour / physical frame
  double per_frame_ms = 0;  // median of the per-round differences (a difference: noise can make it < 0)
};

// Prints the figures and returns them for the JSON report.
WaterShare bench_water_share(vk::Context& ctx, const scene::Scene& scene, int rounds);

}  // namespace lagoon::cli
