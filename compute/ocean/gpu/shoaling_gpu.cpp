#include "ocean/gpu/shoaling_gpu.h"

#include <vector>

#include "vk/transfer.h"

namespace lagoon::ocean {

ShoalingGpu::ShoalingGpu(vk::Context& ctx, const Shoaling* shoaling) : active_(shoaling != nullptr) {
  std::vector<glm::vec4> texels(1, glm::vec4(0.0f));
  if (active_) {
    const std::vector<glm::dvec4>& table = shoaling->table();
    texels.assign(table.begin(), table.end());
    const DepthProfile& floor = shoaling->floor();
    axis_ = glm::vec4(float(floor.origin.x), float(floor.origin.y), float(floor.axis.x), float(floor.axis.y));
    grid_ = glm::vec4(float(floor.spacing_m), float(floor.columns()), float(floor.rows),
                      float(shoaling->lattice_layer(0)));
    for (size_t c = 0; c < shoaling->lattice_count(); ++c)
      lattice_.push_back(glm::vec4(shoaling->lattice_wave(c)));
  }
  table_ = vk::Buffer::create(ctx, texels.size() * sizeof(glm::vec4), vk::kStorageUsage,
                              vk::MemoryUsage::Device, "shoaling table");
  vk::upload_buffer(ctx, table_, vk::as_bytes_of(texels));
}

}  // namespace lagoon::ocean
