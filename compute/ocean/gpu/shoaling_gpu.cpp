#include "ocean/gpu/shoaling_gpu.h"

#include <vector>

#include "vk/barriers.h"
#include "vk/transfer.h"

namespace lagoon::ocean {

ShoalingGpu::ShoalingGpu(vk::Context& ctx, const Shoaling* shoaling) : active_(shoaling != nullptr) {
  const uint32_t width = active_ ? uint32_t(shoaling->floor().columns()) : 1;
  const uint32_t height = active_ ? uint32_t(shoaling->floor().rows) : 1;
  const uint32_t layers = active_ ? uint32_t(1 + shoaling->wave_count()) : 1;
  std::vector<float> texels(size_t(width) * height * layers * 4, 0.0f);
  if (active_) {
    const std::vector<glm::dvec4>& table = shoaling->table();
    for (size_t i = 0; i < table.size(); ++i)
      for (int c = 0; c < 4; ++c) texels[i * 4 + c] = float(table[i][c]);
    const DepthProfile& floor = shoaling->floor();
    axis_ = glm::vec4(float(floor.origin.x), float(floor.origin.y), float(floor.axis.x), float(floor.axis.y));
    grid_ = glm::vec4(float(floor.spacing_m), float(width), float(height), 0.0f);
  }
  table_ = vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                   .extent = {width, height},
                                   .layers = layers,
                                   .array_view = true,
                                   .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                   .debug_name = "shoaling table"});
  // Read by the surface's vertex and fragment shaders and by the caustics' compute pass.
  const vk::Access readers{VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
  vk::upload_image(ctx, table_, std::as_bytes(std::span(texels)), VK_IMAGE_LAYOUT_GENERAL, readers);
}

}  // namespace lagoon::ocean
