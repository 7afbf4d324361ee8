// The colour LUTs of the scene's water under its sun (compute/optics/lut.h, docs/optics.md) as textures
// for the surface pass: x = r axis, y = h axis. With them, the underwater tables (optics/underwater.h) for a
// camera under the water: x = distance d, y = depth z.
#pragma once
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/result.h"
#include "ocean/initial_spectrum.h"
#include "optics/lut.h"
#include "scene/scene.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

struct WaterLuts {
  vk::Image t0, t1;
  glm::vec3 deep_colour{0};
  double r_max_m = 1, h_max_m = 1;
  vk::Image uw_target, uw_down, uw_up;  // RGBA: target (RGB, blur), the water's light down, up (RGB, 1)
  double d_max_m = 1, z_max_m = 1;
  glm::vec4 caustic_share{0};
  glm::vec3 underwater_top{1};  // the target table at (0, 0), which every transmittance divides by
  float scattering_550 = 0, phase_g_550 = 0;  // σ (1/m) and the phase function's g at 550 nm  // the sun's
                                              // direct share of the light at each caustic slice's depth
};

// Fails with the optics model's message (e.g. an unreadable custom water table).
// `spectra`: the ocean's cascade spectra when the caller has built them already (the renderer), else null.
Result<WaterLuts> upload_water_luts(vk::Context& ctx, const scene::Scene& scene,
                                    const std::vector<ocean::CascadeSpectrum>* spectra = nullptr);

// The LUTs' inputs for a scene: its water and sun, and the sea's slopes for eq. 10's wavy surface
// (optics/rough_surface.h; ocean::sea_slope_moments). Every LUT of the renderer, the demo and lagoon lut
// comes from here, so they agree.
Result<optics::LutInputs> scene_lut_inputs(const scene::Scene& scene,
                                           const std::vector<ocean::CascadeSpectrum>* spectra = nullptr);

}  // namespace lagoon::render
