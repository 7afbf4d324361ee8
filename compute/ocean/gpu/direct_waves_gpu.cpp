#include "ocean/gpu/direct_waves_gpu.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "lagoon_shaders/shaders.h"
#include "ocean/direct_waves.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/transfer.h"

namespace lagoon::ocean {

DirectWavesGpu::DirectWavesGpu(vk::Context& ctx, const OceanParams& params, const GerstnerSurface& surface)
    : params_(params),
      n_(params.cascades.front().resolution),
      count_(uint32_t(surface.size())),
      pipeline_(vk::ComputePipeline::create(ctx, shaders::ocean_direct_waves_comp,
                                            std::array{vk::SpecConstant{LAGOON_SPEC_DIRECT_WAVES, 1}})) {
  std::vector<gpu::DirectWaveGpu> waves = direct_waves_gpu(surface);
  if (waves.size() > LAGOON_DIRECT_MAX_WAVES)
    vk::throw_usage_error("DirectWavesGpu: more than " + std::to_string(LAGOON_DIRECT_MAX_WAVES) + " waves");
  waves.resize(std::max<size_t>(waves.size(), 1));  // a buffer cannot be empty
  waves_ = vk::Buffer::create(ctx, waves.size() * sizeof(gpu::DirectWaveGpu),
                              (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT), vk::MemoryUsage::Device,
                              "direct waves");
  vk::upload_buffer(ctx, waves_, vk::as_bytes_of(waves));
}

void DirectWavesGpu::record(VkCommandBuffer cmd, double time_s, double dt_s, bool reset_foam,
                            const LayerTarget& target, vk::GpuTimer* timer) const {
  vk::GpuScope scope(timer, cmd, "direct waves");
  const gpu::DirectWavesPush push{.n = n_,
                                  .layer = target.layer,
                                  .count = count_,
                                  .reset_foam = reset_foam ? 1u : 0u,
                                  .spacing = float(params_.cascades.front().patch_size_m / n_),
                                  .time_s = float(time_s),
                                  .foam_threshold = float(params_.foam.threshold),
                                  .foam_decay = float(std::exp(-params_.foam.decay_per_s * dt_s))};
  auto storage = [](const vk::Image* image) {
    return vk::ImageRef{image->mip_view(0), VK_IMAGE_LAYOUT_GENERAL};
  };
  vk::dispatch(cmd, pipeline_,
               {vk::bind(LAGOON_DIRECT_BIND_WAVES, waves_),
                vk::bind(LAGOON_DIRECT_BIND_DISPLACEMENT, storage(target.displacement)),
                vk::bind(LAGOON_DIRECT_BIND_NORMAL_JACOBIAN, storage(target.normal_jacobian)),
                vk::bind(LAGOON_DIRECT_BIND_JACOBIAN_TERMS, storage(target.jacobian_terms))},
               push, vk::groups_for(pipeline_, {n_, n_, 1}));
}

}  // namespace lagoon::ocean
