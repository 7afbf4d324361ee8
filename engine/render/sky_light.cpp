#include "render/sky_light.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>

#include "optics/cie.h"
#include "optics/colour.h"
#include "optics/lut.h"
#include "optics/sky_radiance.h"
#include "render/camera.h"

namespace lagoon::render {
namespace {

// The sky model for one sun elevation and atmosphere, kept while those stay the same: building it fits
// Preetham's turbidity (a few milliseconds), and frame_uniforms asks for it every frame.
std::shared_ptr<const optics::SkyRadiance> sky_model_for(double elevation, const optics::SkyParams& params) {
  static std::mutex mutex;
  static double last_elevation = -1000;
  static optics::SkyParams last_params;
  static std::shared_ptr<const optics::SkyRadiance> last;
  const std::lock_guard lock(mutex);
  const bool same = last && last_elevation == elevation &&
                    last_params.aerosol_optical_depth_500nm == params.aerosol_optical_depth_500nm &&
                    last_params.angstrom_alpha == params.angstrom_alpha &&
                    last_params.ozone_cm == params.ozone_cm &&
                    last_params.surface_pressure_hpa == params.surface_pressure_hpa;
  if (!same) {
    last = std::make_shared<const optics::SkyRadiance>(elevation, params);
    last_elevation = elevation;
    last_params = params;
  }
  return last;
}

}  // namespace

SkyLight sky_light(const scene::Sun& sun, const optics::SkyParams& params) {
  SkyLight light;
  light.sun_direction = sun_direction(sun);
  light.sun_elevation_deg = sun.elevation_deg;
  // Colours relative to the light above the water; below the horizon use a low sun's colours, dimmed.
  const double elevation = std::max<double>(sun.elevation_deg, 2.0);
  const std::shared_ptr<const optics::SkyRadiance> shared_model = sky_model_for(elevation, params);
  const optics::SkyRadiance& model = *shared_model;
  const optics::SkyIrradiance& sky = model.irradiance();
  const optics::Spectrum white = optics::downwelling_white(sky);
  const double cos_zenith = std::sin(elevation * 3.14159265358979323846 / 180.0);
  const glm::dvec3 sun_h = optics::adapted_linear_srgb(sky.sun, white);  // sun on a horizontal surface
  const glm::dvec3 sky_h = optics::adapted_linear_srgb(sky.sky, white);
  const double night =
      sun.elevation_deg >= 2.0 ? 1.0 : std::clamp((sun.elevation_deg + 6.0) / 8.0, 0.02, 1.0);
  const double scale = sun.intensity * night;
  light.light_scale = float(scale);
  light.sun_irradiance = glm::vec3(sun_h / cos_zenith * scale);
  light.sky_radiance = glm::vec3(sky_h * scale);
  // B_k as a uniform sky's radiance in white units: π B_k through Φ, like E_sky above.
  light.sky_model = model.coefficients();
  glm::vec4* basis[3] = {&light.sky_model.basis0, &light.sky_model.basis1, &light.sky_model.basis2};
  for (int k = 0; k < 3; ++k) {
    optics::Spectrum pi_b = model.basis_radiance(k);
    for (double& v : pi_b) v *= 3.14159265358979323846;
    *basis[k] = glm::vec4(glm::vec3(optics::adapted_linear_srgb(pi_b, white) * scale), basis[k]->w);
  }
  // E = L·Ω for the disc: L = E_normal / Ω, times π because white units are E_d/π.
  const double disc_solid_angle = 6.8e-5;
  light.sun_disc_radiance = glm::vec3(sun_h / cos_zenith * scale * 3.14159265358979323846 / disc_solid_angle);
  if (sun.elevation_deg < -0.5) light.sun_irradiance = light.sun_disc_radiance = glm::vec3(0);
  return light;
}

double reference_illuminance_lux(const scene::Sun& sun, const optics::SkyParams& params) {
  const std::shared_ptr<const optics::SkyRadiance> model =
      sky_model_for(std::max<double>(sun.elevation_deg, 2.0), params);
  return 683.0 * optics::spectrum_to_xyz(optics::downwelling_white(model->irradiance())).y;
}

}  // namespace lagoon::render
