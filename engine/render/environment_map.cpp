#include "render/environment_map.h"

#include <cmath>
#include <cstring>
#include <span>

#include "render/cached_tables.h"
#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::render {
namespace {

constexpr float kSeaF0 = 0.0211f;  // ((1.34 − 1) / (1.34 + 1))²: a flat sea's reflectance at normal incidence

struct Source {
  std::vector<glm::vec3> dir;
  std::vector<float> solid_angle;               // dω of the texel
  std::vector<glm::vec3> radiance_solid_angle;  // L · dω
};

Source sample_source(const gpu::SkyModelGpu& sky, glm::vec3 sun, uint32_t width, uint32_t height) {
  Source s;
  const float dphi = 2.0f * LAGOON_PBR_PI / float(width), dtheta = LAGOON_PBR_PI / float(height);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const glm::vec2 uv((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const glm::vec3 d = gpu::env_direction(uv);
      const float d_omega = dphi * dtheta * std::sin(LAGOON_PBR_PI * uv.y);
      s.dir.push_back(d);
      s.solid_angle.push_back(d_omega);
      s.radiance_solid_angle.push_back(environment_radiance(sky, sun, d) * d_omega);
    }
  }
  return s;
}

// The radiance around `r` averaged over the GGX lobe of `alpha` (n = v = r: weight D(r·h) (r·l) dω, with
// r·h = sqrt((1 + r·l) / 2)).
glm::vec3 convolve_ggx(const Source& s, glm::vec3 r, float alpha) {
  glm::vec3 sum(0.0f);
  float weight = 0.0f;
  for (size_t i = 0; i < s.dir.size(); ++i) {
    const float c = glm::dot(r, s.dir[i]);
    if (c <= 0.0f) continue;
    const float w = gpu::pbr_d_ggx(std::sqrt(0.5f * (1.0f + c)), alpha) * c;
    sum += w * s.radiance_solid_angle[i];
    weight += w * s.solid_angle[i];
  }
  return weight > 0.0f ? sum / weight : glm::vec3(0.0f);
}

// The irradiance over π around n.
glm::vec3 irradiance_over_pi(const Source& s, glm::vec3 n) {
  glm::vec3 sum(0.0f);
  for (size_t i = 0; i < s.dir.size(); ++i)
    sum += std::max(glm::dot(n, s.dir[i]), 0.0f) * s.radiance_solid_angle[i];
  return sum / LAGOON_PBR_PI;
}

}  // namespace

glm::vec3 environment_radiance(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, glm::vec3 dir) {
  if (dir.y >= 0.0f) return gpu::sky_model_rgb(sky, dir, sun_dir);
  const glm::vec3 mirrored(dir.x, -dir.y, dir.z);
  const float m = 1.0f - (-dir.y);
  const float fresnel = kSeaF0 + (1.0f - kSeaF0) * m * m * m * m * m;
  return fresnel * gpu::sky_model_rgb(sky, mirrored, sun_dir);
}

EnvironmentLayers prefilter_environment(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, uint32_t width,
                                        uint32_t height) {
  EnvironmentLayers out{width, height, {}};
  out.texels.reserve(size_t(LAGOON_ENV_LAYERS) * width * height);
  const Source src = sample_source(sky, sun_dir, width, height);
  for (uint32_t layer = 0; layer < LAGOON_ENV_LAYERS; ++layer) {
    for (uint32_t y = 0; y < height; ++y) {
      for (uint32_t x = 0; x < width; ++x) {
        const glm::vec3 r =
            gpu::env_direction({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)});
        glm::vec3 value(0.0f);
        if (layer == 0) {
          value = environment_radiance(sky, sun_dir, r);
        } else if (layer < LAGOON_ENV_SPECULAR_LAYERS) {
          const float roughness = float(layer) / float(LAGOON_ENV_SPECULAR_LAYERS - 1);
          value = convolve_ggx(src, r, roughness * roughness);
        } else {
          value = irradiance_over_pi(src, r);
        }
        out.texels.emplace_back(value, 1.0f);
      }
    }
  }
  return out;
}

EnvironmentMap::EnvironmentMap(vk::Context& ctx)
    : ctx_(ctx),
      image_(vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                     .extent = {kWidth, kHeight},
                                     .layers = LAGOON_ENV_LAYERS,
                                     .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                     .debug_name = "environment"})) {}

void EnvironmentMap::update(const SkyLight& light) {
  if (valid_ && std::memcmp(&sky_, &light.sky_model, sizeof(sky_)) == 0 && sun_ == light.sun_direction)
    return;
  sky_ = light.sky_model;
  sun_ = light.sun_direction;
  const EnvironmentLayers layers = cached_environment(sky_, sun_, kWidth, kHeight);
  if (valid_) ctx_.wait_idle();  // frames in flight may still sample the old layers
  vk::upload_image(ctx_, image_, std::as_bytes(std::span(layers.texels)), VK_IMAGE_LAYOUT_GENERAL,
                   vk::access::kGraphicsSampled);
  valid_ = true;
}

}  // namespace lagoon::render
