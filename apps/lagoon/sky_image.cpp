#include "sky_image.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "core/compass.h"

namespace lagoon::cli {
namespace {

// The direction of pixel (x, y): the compass azimuth φ measured clockwise from the sun's, the sun at
// φ = 180° (the middle column).
glm::dvec3 pixel_direction(const render::SkyLight& light, int x, int y, int width, int height) {
  const double theta = (y + 0.5) / height * std::numbers::pi / 2;
  const double sun_azimuth = compass::azimuth_of({light.sun_direction.x, light.sun_direction.z});
  const double phi = sun_azimuth + (x + 0.5) / width * 2 * std::numbers::pi - std::numbers::pi;
  const glm::dvec2 across = std::sin(theta) * compass::toward(phi);
  return {across.x, std::cos(theta), across.y};
}

}  // namespace

SkyImage sky_image(const render::SkyLight& light, int width) {
  SkyImage image{.width = width, .height = width / 4};
  const size_t n = size_t(image.width) * image.height;
  image.rgb.resize(n * 3);
  image.sky_luminance.resize(n);
  image.solid_angle.resize(n);
  const double d_theta = std::numbers::pi / 2 / image.height, d_phi = 2 * std::numbers::pi / image.width;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::dvec3 dir = pixel_direction(light, x, y, image.width, image.height);
      const glm::vec3 rgb = gpu::sky_model_rgb(light.sky_model, glm::vec3(dir), light.sun_direction);
      const size_t i = size_t(y) * image.width + x;
      for (int c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgb[c];
      image.sky_luminance[i] = optics::linear_srgb_luminance(glm::dvec3(rgb));
      image.solid_angle[i] = std::sin((y + 0.5) * d_theta) * d_theta * d_phi;
    }
  return image;
}

optics::ToneMapParams fit_tone_map(const SkyImage& image) {
  double log_sum = 0, omega = 0;
  std::vector<size_t> order(image.sky_luminance.size());
  std::iota(order.begin(), order.end(), size_t{0});
  for (size_t i = 0; i < order.size(); ++i) {
    log_sum += std::log(std::max(image.sky_luminance[i], 1e-6)) * image.solid_angle[i];
    omega += image.solid_angle[i];
  }
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return image.sky_luminance[a] > image.sky_luminance[b]; });
  double brightest = image.sky_luminance[order.front()], covered = 0;
  for (size_t i : order) {  // the luminance above which 1 % of the sky's solid angle lies
    covered += image.solid_angle[i];
    brightest = image.sky_luminance[i];
    if (covered >= 0.01 * omega) break;
  }
  optics::ToneMapParams params;
  params.world_adaptation_luminance = std::exp(log_sum / omega);
  const optics::ToneMapCurve curve = optics::tone_map_curve(params);
  params.white_luminance = curve.m * std::pow(brightest / curve.world_adaptation, curve.exponent);
  return params;
}

io::Image8 sky_png(const SkyImage& image, const render::SkyLight& light,
                   const optics::ToneMapParams& params) {
  io::Image8 png{.width = uint32_t(image.width), .height = uint32_t(image.height)};
  png.rgba.resize(size_t{png.width} * png.height * 4);
  const double cos_disc = std::cos(0.00465);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const size_t i = size_t(y) * image.width + x;
      glm::dvec3 rgb(image.rgb[i * 3], image.rgb[i * 3 + 1], image.rgb[i * 3 + 2]);
      // The disc is smaller than a pixel: a pixel holds the sun if the sun's centre lies in it.
      const glm::dvec3 dir = pixel_direction(light, x, y, image.width, image.height);
      const double half_pixel = std::numbers::pi / image.width;
      if (glm::dot(dir, glm::dvec3(light.sun_direction)) > std::min(cos_disc, std::cos(half_pixel * 1.5)))
        rgb += glm::dvec3(light.sun_disc_radiance);
      const glm::dvec3 shown = optics::encode_srgb(optics::tone_map(rgb, params));
      uint8_t* p = png.pixel(uint32_t(x), uint32_t(y));
      for (int c = 0; c < 3; ++c) p[c] = uint8_t(std::lround(std::clamp(shown[c], 0.0, 1.0) * 255));
      p[3] = 255;
    }
  return png;
}

}  // namespace lagoon::cli
