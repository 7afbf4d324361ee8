// The light around an object, pre-filtered for the glTF BRDF (shared/pbr.h): the frame's spectral sky
// (shared/sky_model.h, the one the water reflects) above the horizon and, below it, that sky as a flat sea
// reflects it (Fresnel, ior 1.34; the water's own upwelling light is left out, a few per cent of the sky's).
// The sun is not in it: objects take the sun as a directional light through the exact BRDF.
//
// Layers (equirectangular, shared/pbr.h env_direction): LAGOON_ENV_SPECULAR_LAYERS of radiance convolved
// with the GGX lobe of roughness 0, 1/4, ..., 1 around the mirror direction (Karis' n = v = r assumption),
// then the irradiance over π. Computed on the CPU when the sun or the atmosphere changes.
#pragma once
#include <glm/glm.hpp>

#include <vector>

#include "render/sky_light.h"
#include "shared/pbr.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::render {

struct EnvironmentLayers {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec4> texels;  // LAGOON_ENV_LAYERS layers of width × height, rgb (a = 1)
  glm::vec3 at(uint32_t layer, uint32_t x, uint32_t y) const {
    return glm::vec3(texels[(size_t(layer) * height + y) * width + x]);
  }
};

// The radiance arriving from `dir` (unit) in white units, as the layers see it.
glm::vec3 environment_radiance(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, glm::vec3 dir);

EnvironmentLayers prefilter_environment(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, uint32_t width = 64,
                                        uint32_t height = 32);

// The layers on the GPU (an RGBA32F 2D array), refreshed when the sky they were made from changes.
class EnvironmentMap {
 public:
  explicit EnvironmentMap(vk::Context& ctx);
  // Re-filters and uploads when `light` differs from the last call's sky (waits for the device first:
  // frames in flight may be sampling the old layers).
  void update(const SkyLight& light);
  const vk::Image& image() const { return image_; }

 private:
  static constexpr uint32_t kWidth = 64, kHeight = 32;
  vk::Context& ctx_;
  vk::Image image_;
  gpu::SkyModelGpu sky_{};
  glm::vec3 sun_{0.0f};
  bool valid_ = false;
};

}  // namespace lagoon::render
