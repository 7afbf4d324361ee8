// The step of models gerstner and sines with their own waves (ocean/direct_waves.h): their sum at every
// texel of the first cascade's grid (shaders/ocean/direct_waves.comp), written as the FFT ocean writes its
// layer, foam by the same law. It replaces the FFT, which has nothing to transform: the renderer sums the
// waves where it draws; this layer is what export, `lagoon compare`'s statistics and read-backs see. Records
// only; the caller submits.
#pragma once
#include "ocean/gerstner.h"
#include "ocean/gpu/springs_gpu.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/pipeline.h"

namespace lagoon::ocean {

class DirectWavesGpu {
 public:
  DirectWavesGpu(vk::Context& ctx, const OceanParams& params, const GerstnerSurface& surface);

  // Writes the layer at `time_s`; `dt_s` decays the last step's foam (none with reset_foam).
  void record(VkCommandBuffer cmd, double time_s, double dt_s, bool reset_foam, const LayerTarget& target,
              vk::GpuTimer* timer) const;

 private:
  OceanParams params_;
  uint32_t n_, count_;
  vk::ComputePipeline pipeline_;
  vk::Buffer waves_;
};

}  // namespace lagoon::ocean
