// Counts, on the GPU, the texels of the ocean's outputs (mip 0 of every cascade's displacement, normal and
// Jacobian-term textures) that hold NaN or Inf. `lagoon soak` records it after every step, so no step goes
// unchecked and nothing is read back but one counter.
#pragma once
#include <cstdint>

#include "ocean/gpu/gpu_ocean.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"

namespace lagoon::ocean {

class FieldCheck {
 public:
  explicit FieldCheck(vk::Context& ctx);

  // Adds the non-finite texels of `ocean`'s current fields to the running count. Record it after
  // GpuOcean::record_step in the same or a later command buffer.
  void record(VkCommandBuffer cmd, const GpuOcean& ocean);
  // The count since the last take(), once the recorded command buffers have completed; resets it.
  uint64_t take();

 private:
  vk::ComputePipeline pipeline_;
  vk::Buffer count_;
};

}  // namespace lagoon::ocean
