#include "render/sky_light.h"

#include <algorithm>
#include <cmath>

#include "optics/colour.h"
#include "render/camera.h"
#include "shared/sky_shape.h"

namespace lagoon::render {

SkyLight sky_light(const scene::Sun& sun, const optics::SkyParams& params) {
  SkyLight light;
  light.sun_direction = sun_direction(sun);
  light.sun_elevation_deg = sun.elevation_deg;
  // Colours relative to the light above the water; below the horizon use a low sun's colours, dimmed.
  const double elevation = std::max<double>(sun.elevation_deg, 2.0);
  const optics::SkyIrradiance sky = optics::clear_sky(elevation, params);
  optics::Spectrum white{};
  for (int i = 0; i < optics::kSamples; ++i) white[i] = sky.sun[i] + sky.sky[i];
  const double cos_zenith = std::sin(elevation * 3.14159265358979323846 / 180.0);
  const glm::dvec3 sun_h = optics::adapted_linear_srgb(sky.sun, white);  // sun on a horizontal surface
  const glm::dvec3 sky_h = optics::adapted_linear_srgb(sky.sky, white);
  const double night =
      sun.elevation_deg >= 2.0 ? 1.0 : std::clamp((sun.elevation_deg + 6.0) / 8.0, 0.02, 1.0);
  const double scale = sun.intensity * night;
  light.light_scale = float(scale);
  light.sun_irradiance = glm::vec3(sun_h / cos_zenith * scale);
  light.sky_radiance = glm::vec3(sky_h * scale);
  // E = L·Ω for the disc: L = E_normal / Ω, times π because white units are E_d/π.
  const double disc_solid_angle = 6.8e-5;
  light.sun_disc_radiance = glm::vec3(sun_h / cos_zenith * scale * 3.14159265358979323846 / disc_solid_angle);
  if (sun.elevation_deg < -0.5) light.sun_irradiance = light.sun_disc_radiance = glm::vec3(0);
  return light;
}

double sky_shape_integral(glm::vec3 sun_direction) {
  constexpr double kPi = 3.14159265358979323846;
  const int steps_theta = 64, steps_phi = 128;
  double sum = 0;
  for (int i = 0; i < steps_theta; ++i) {
    const double theta = (i + 0.5) * (kPi / 2) / steps_theta;
    for (int j = 0; j < steps_phi; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / steps_phi;
      const glm::vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      sum += double(gpu::sky_shape(dir, sun_direction)) * std::cos(theta) * std::sin(theta);
    }
  }
  return sum * (kPi / 2 / steps_theta) * (2 * kPi / steps_phi) / kPi;
}

}  // namespace lagoon::render
