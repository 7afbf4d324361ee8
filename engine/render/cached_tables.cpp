#include "render/cached_tables.h"

#include <span>

#include "result_fingerprint.h"

namespace lagoon::render {

io::ResultKey table_key(std::string_view kind) {
  io::ResultKey key(kind);
  key.add("code", LAGOON_RESULT_FINGERPRINT);
  return key;
}

EnvironmentLayers cached_environment(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, uint32_t width,
                                     uint32_t height) {
  static_assert(sizeof(gpu::SkyModelGpu) == 8 * 16, "a new field of the sky model must join the key");
  const auto* floats = reinterpret_cast<const float*>(&sky);
  std::vector<double> model(floats, floats + sizeof(sky) / sizeof(float));
  io::ResultKey key = table_key("environment");
  key.add("sky_model", model)
      .add("sun_x", sun_dir.x)
      .add("sun_y", sun_dir.y)
      .add("sun_z", sun_dir.z)
      .add("width", width)
      .add("height", height);
  const io::ResultCache cache = io::ResultCache::from_environment();
  const size_t texels_count = size_t{width} * height * LAGOON_ENV_LAYERS;
  if (auto texels = cache.load_vector<glm::vec4>(key, texels_count))
    return EnvironmentLayers{.width = width, .height = height, .texels = std::move(*texels)};
  EnvironmentLayers layers = prefilter_environment(sky, sun_dir, width, height);
  cache.store_vector(key, layers.texels);
  return layers;
}

}  // namespace lagoon::render
