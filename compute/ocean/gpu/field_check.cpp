#include "ocean/gpu/field_check.h"

#include <cstring>

#include "lagoon_shaders/shaders.h"
#include "shared/ocean.h"
#include "vk/barriers.h"

namespace lagoon::ocean {

FieldCheck::FieldCheck(vk::Context& ctx)
    : pipeline_(vk::ComputePipeline::create(ctx, shaders::ocean_field_check_comp)),
      count_(vk::Buffer::create(ctx, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                vk::MemoryUsage::Readback, "field check count")) {
  std::memset(count_.mapped(), 0, sizeof(uint32_t));
  count_.flush();
}

void FieldCheck::record(VkCommandBuffer cmd, const GpuOcean& ocean) {
  vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kComputeRead);
  for (uint32_t c = 0; c < ocean.cascade_count(); ++c) {
    const CascadeTextures t = ocean.cascade(c);
    auto mip0 = [](const vk::Image* image) {
      return vk::ImageRef{image->mip_view(0), VK_IMAGE_LAYOUT_GENERAL};
    };
    const int32_t layer = int32_t(t.layer);
    vk::dispatch(cmd, pipeline_,
                 {vk::bind(LAGOON_CHECK_BIND_FIELDS, mip0(t.displacement)),
                  vk::bind(LAGOON_CHECK_BIND_FIELDS + 1, mip0(t.normal_jacobian)),
                  vk::bind(LAGOON_CHECK_BIND_FIELDS + 2, mip0(t.jacobian_terms)),
                  vk::bind(LAGOON_CHECK_BIND_COUNT, count_)},
                 layer, vk::groups_for(pipeline_, {t.resolution, t.resolution, 1}));
  }
  vk::buffer_barrier(cmd, count_.handle(), vk::access::kComputeReadWrite, vk::access::kHostRead);
}

uint64_t FieldCheck::take() {
  count_.invalidate();
  uint32_t count = 0;
  std::memcpy(&count, count_.mapped(), sizeof count);
  std::memset(count_.mapped(), 0, sizeof count);
  count_.flush();
  return count;
}

}  // namespace lagoon::ocean
