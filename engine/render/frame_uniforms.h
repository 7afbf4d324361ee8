// The per-frame constants every pass reads (shaders/shared/frame.h), computed on the CPU from the scene,
// the camera, the ocean and the water's LUTs.
#pragma once
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "ocean/gpu/gpu_ocean.h"
#include "render/caustics_window.h"
#include "render/surface_grid.h"
#include "render/water_luts.h"
#include "scene/scene.h"
#include "shared/frame.h"

namespace lagoon::render {

// What the surface shader needs of the ocean's statistics; fixed with the ocean, so computed once.
struct OceanShading {
  glm::vec4 cascade_mss{0};        // mean square slope of each drawn cascade (ocean/slope_statistics.h)
  float subgrid_mss = 0;           // ... of the waves shorter than the last drawn cascade, down to 1 cm
  float caustic_mss = 0;           // ... of the waves the caustic map's cells do not resolve (its blur)
  DisplacementBound bound;         // 6σ of the whole ocean's displacement plus a metre, for culling
  float significant_height_m = 0;  // H_s = 4σ of the drawn cascades' height
};
OceanShading ocean_shading(const ocean::GpuOcean& ocean);
// The mean square slope of the waves a caustic map of `cell_m` cells does not resolve (its blur).
float caustic_unresolved_mss(const ocean::GpuOcean& ocean, float cell_m);

struct FrameInputs {
  const scene::Scene& scene;
  VkExtent2D extent{};
  const ocean::GpuOcean& ocean;
  const OceanShading& shading;
  const WaterLuts& luts;
  const SurfaceGrid& grid;
  const glm::mat4& view_proj;
  float reach_m = 0;  // how far the surface mesh reaches from the camera
  uint32_t light_count = 0;
  bool under_water = false;
  const CausticsWindow& caustics;
  glm::vec4 wakes_window{0.0f};                      // WakesPass::window()
  glm::vec4 submerged_rect{1.0f, 1.0f, 0.0f, 0.0f};  // SceneObjects::submerged_screen_rect (empty: none)
};
gpu::FrameUniforms frame_uniforms(const FrameInputs& in);

// The scene's point lights (at most LAGOON_MAX_LIGHTS) into `out`; returns how many were written.
uint32_t write_point_lights(const scene::Scene& scene, const std::vector<scene::PointLight>& more,
                            gpu::PointLightGpu* out);

}  // namespace lagoon::render
