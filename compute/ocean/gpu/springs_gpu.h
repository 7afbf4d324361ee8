// Model springs on the GPU (issue 15, docs/models.md): the Hooke grid of ocean/springs.h stepped in a compute
// pass (shaders/ocean/springs_step.comp, one dispatch per step, ping-pong state buffers), and its picture
// written into the first cascade's layer of the ocean's images (springs_assemble.comp). GpuOcean runs it in
// place of the FFT when the model is springs. Records only; the caller submits.
#pragma once
#include <cstdint>

#include "ocean/ocean_params.h"
#include "ocean/springs.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::ocean {

// Where a model that replaces the FFT writes (springs, direct waves): mip 0 of the ocean's images, one
// array layer.
struct LayerTarget {
  const vk::Image* displacement = nullptr;
  const vk::Image* normal_jacobian = nullptr;
  const vk::Image* jacobian_terms = nullptr;
  uint32_t layer = 0;
};

class SpringsGpu {
 public:
  SpringsGpu(vk::Context& ctx, const OceanParams& params);

  // Steps to `time_s` (from rest again when it lies before the state's step) and writes the picture.
  // Throws vk::UsageError when that needs more than kSpringsMaxCatchUpSteps steps.
  void record(VkCommandBuffer cmd, double time_s, double dt_s, bool reset_foam, const LayerTarget& target,
              vk::GpuTimer* timer);
  uint64_t steps() const { return steps_; }

 private:
  void record_clear(VkCommandBuffer cmd);
  gpu::SpringsPush push(uint64_t step) const;

  OceanParams params_;
  uint32_t n_;
  vk::ComputePipeline step_, assemble_;
  vk::Buffer state_[2];  // vec2 (height, velocity) per node; state_[steps_ % 2] is current
  vk::Buffer excitations_;
  uint32_t excitation_count_ = 0;
  uint64_t steps_ = 0;
};

}  // namespace lagoon::ocean
