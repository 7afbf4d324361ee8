// The dynamic wave layer on the GPU (issue 14; the CPU reference and the physics: ocean/dynamic_layer.h).
// A step: forward FFT of the state h + i dh/dt (fft/gpu_fft.h), the exact evolution of every mode toward the
// sources' depression (shaders/ocean/dynamic_evolve.comp: the modes in pairs k, -k, then the Nyquist lines),
// the inverse FFT, and the absorbing border with the foam trails and the renderer's fields
// (dynamic_sponge.comp). Records only; never submits.
#pragma once
#include <glm/vec2.hpp>
#include <span>
#include <vector>

#include "fft/gpu_fft.h"
#include "ocean/dynamic_layer.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/pipeline.h"

namespace lagoon::ocean {

class DynamicLayerGpu {
 public:
  // Steps recorded between two waits on the GPU: each has its own sources in a ring of this many.
  static constexpr uint32_t kStepsInFlight = 512;

  // Starts at rest. Throws (vk::throw_usage_error) when params.n is not a supported FFT size.
  DynamicLayerGpu(vk::Context& ctx, const DynamicLayerParams& params);

  void set_window(glm::ivec2 origin) { origin_ = origin; }
  glm::ivec2 window() const { return origin_; }
  // Records the state back to rest (and the fields to zero).
  void record_clear(VkCommandBuffer cmd);
  // Records one step of dt seconds. At most kStepsInFlight steps may be recorded before the GPU has run the
  // first of them (their sources share a ring). Fields::Keep leaves the fields image as it was (the steps of
  // a catch-up but its last: cheaper, and nothing draws them).
  enum class Fields { Write, Keep };
  void record_step(VkCommandBuffer cmd, double dt, std::span<const WakeSource> sources,
                   Fields fields = Fields::Write);

  // (h, dh/dx, dh/dz, foam) per cell, R32G32B32A32 n x n in GENERAL, world cell (a, b) at texel (a mod n,
  // b mod n): sample it with repeat addressing at uv = (x, z) / (n · cell) + 0.5 / n. Visible to compute
  // reads after a step; a sampling pass needs its own barrier.
  const vk::Image& fields() const { return fields_; }
  // h + i dh/dt per storage index, as the CPU reference's state() (for tests and export).
  const vk::Buffer& state() const { return state_; }
  // The foam trails' coverage (float per storage index), as the CPU reference's foam().
  const vk::Buffer& foam() const { return foam_[foam_current_]; }
  const DynamicLayerParams& params() const { return params_; }

  // Everything a run of steps leaves that a later step or a draw reads (h + i dh/dt, the current foam, the
  // fields), so that a cache can file it (render/wakes_cache.h): write_state() puts back exactly what
  // read_state() read, and the steps after it are the same bits. Waits for the device. write_state() is
  // false when `state` is not this layer's size.
  std::vector<float> read_state(vk::Context& ctx) const;
  // Its size: n² values of h + i dh/dt (two floats), of foam and of fields (four).
  size_t state_floats() const { return size_t(params_.n) * params_.n * (2 + 1 + 4); }
  bool write_state(vk::Context& ctx, std::span<const float> state);

 private:
  DynamicLayerParams params_;
  fft::GpuFft2d forward_, inverse_;
  vk::ComputePipeline evolve_, evolve_nyquist_, sponge_, sponge_no_fields_;
  vk::Buffer state_, scratch_, sources_;
  vk::Buffer foam_[2];  // ping-pong: a step spreads the trails from one into the other
  uint32_t foam_current_ = 0;
  vk::Image fields_;
  glm::ivec2 origin_{0};
  uint32_t next_slot_ = 0;  // in the sources ring
};

}  // namespace lagoon::ocean
