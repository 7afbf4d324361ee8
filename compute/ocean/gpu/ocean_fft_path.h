// The two ways the ocean step runs its transforms (both tested against the CPU reference on lavapipe):
//  - Stockham: evolve fused into the first radix-16 pass, assembly fused into the last, plain passes in
//    between; global memory only. Best on CPU devices (lavapipe), where shared memory and barriers are slow.
//  - Workgroup: each line's whole FFT in one workgroup through shared memory, so one dispatch per axis
//    (evolve + rows, columns + assembly). Best on GPUs.
// Measured on lavapipe (3 x 256²): Stockham ~69 ms, Workgroup ~116 ms (see the issue notes).
#pragma once
#include <memory>

#include "shared/ocean.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/gpu_timer.h"
#include "vk/image.h"

namespace lagoon::ocean {

enum class FftVariant { Auto, Stockham, Workgroup };

struct OceanFftBindings {
  const vk::Buffer* spectrum = nullptr;  // vec4 (h0(k), conj(h0(-k))) per k, cascade after cascade
  const vk::Buffer* omega = nullptr;     // float ω(k)
  const vk::Image* displacement = nullptr;
  const vk::Image* normal_jacobian = nullptr;
  const vk::Image* jacobian_terms = nullptr;
};

// What a step brings to its time: everything, or (a warm-up's steps) only the foam in displacement.w; the
// displacement's other channels and the other images are then left for the next full step.
enum class StepOutputs { All, FoamOnly };

class OceanFftPath {
 public:
  virtual ~OceanFftPath() = default;
  // Records evolve -> inverse 2-D FFT of the 4 packed fields -> assembly into mip 0 of the images (GENERAL).
  // FoamOnly: the 2 fields the Jacobian needs (a path may do the full step instead).
  virtual void record(VkCommandBuffer cmd, const OceanFftBindings& bindings, const gpu::OceanPush& push,
                      vk::GpuTimer* timer, StepOutputs outputs = StepOutputs::All) const = 0;
};

// Auto picks Stockham on CPU devices and Workgroup elsewhere.
std::unique_ptr<OceanFftPath> make_ocean_fft_path(vk::Context& ctx, FftVariant variant, uint32_t n,
                                                  uint32_t cascades);

}  // namespace lagoon::ocean
