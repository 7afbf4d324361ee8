// The frame's light, derived from the optics model's clear sky (compute/optics/sky.h) through the same
// spectrum-to-RGB operator Φ as the water-colour LUTs, so sky, sun, objects and water agree.
//
// Units ("white units"): radiance relative to that of a white Lambertian surface lit by the sun and sky
// above the water (E_d/π). The LUT colours are already in these units; the post pass tone-maps them.
#pragma once
#include <glm/vec3.hpp>

#include "optics/sky.h"
#include "scene/scene.h"
#include "shared/sky_model.h"

namespace lagoon::render {

inline constexpr double kSunDiscRadiusRad = 0.00465;  // the solar disc's angular radius seen from the Earth

struct SkyLight {
  glm::vec3 sun_direction{0, 1, 0};  // unit vector towards the sun
  // Irradiance from the sun on a surface facing it, and radiance of a uniform sky with the model's E_sky,
  // both in white units (a white Lambertian surface facing up receives sun·cos Z + sky·1 → radiance 1).
  glm::vec3 sun_irradiance{0};
  glm::vec3 sky_radiance{0};
  // The sky's radiance by direction (shared/sky_model.h, optics/sky_radiance.h) in white units: its
  // cosine-weighted integral over the sky, divided by π, is sky_radiance.
  gpu::SkyModelGpu sky_model{};
  glm::vec3 sun_disc_radiance{0};  // radiance of the solar disc (0.53°), for the sky pass
  float sun_elevation_deg = 0;
  // The light above the water relative to that of the LUTs' sun (sun.intensity, dimmed after sunset): the
  // LUT colours are ratios to that light, so the water's own light scales with it.
  float light_scale = 1;
};

SkyLight sky_light(const scene::Sun& sun, const optics::SkyParams& params = {});

// The illuminance (lux) of the light above the water the white units refer to, E_sun + E_sky on a horizontal
// surface (the sun clamped to 2° as for the colours): 683 lm/W times the CIE-Y integral of the optics model's
// spectra. A lamp's irradiance in white units is its lux over this.
double reference_illuminance_lux(const scene::Sun& sun, const optics::SkyParams& params = {});

}  // namespace lagoon::render
