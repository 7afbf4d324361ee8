#include "ocean/gpu/springs_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "lagoon_shaders/shaders.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/transfer.h"

namespace lagoon::ocean {
namespace {

// Why a time cannot be reached in one call, with the numbers and the fix.
std::string springs_catch_up_message(const SpringsParams& p, double time_s, uint64_t steps) {
  char text[320];
  std::snprintf(
      text, sizeof text,
      "model springs: reaching t = %.6g s takes %llu steps of %.6g s, more than the %llu one call may "
      "take; step through time, or choose a time below %.6g s",
      time_s, (unsigned long long)steps, p.step_s, (unsigned long long)kSpringsMaxCatchUpSteps,
      double(kSpringsMaxCatchUpSteps) * p.step_s);
  return text;
}

}  // namespace

SpringsGpu::SpringsGpu(vk::Context& ctx, const OceanParams& params)
    : params_(params),
      n_(params.cascades.front().resolution),
      step_(vk::ComputePipeline::create(ctx, shaders::ocean_springs_step_comp)),
      assemble_(vk::ComputePipeline::create(ctx, shaders::ocean_springs_assemble_comp)) {
  const VkDeviceSize bytes = VkDeviceSize(n_) * n_ * 2 * sizeof(float);
  state_[0] = vk::Buffer::create(ctx, bytes, (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                                 vk::MemoryUsage::Device, "springs state 0");
  state_[1] = vk::Buffer::create(ctx, bytes, (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                                 vk::MemoryUsage::Device, "springs state 1");
  std::vector<gpu::SpringExcitation> excitations = springs_excitations(params);
  if (excitations.size() > LAGOON_SPRINGS_MAX_EXCITATIONS)
    vk::throw_usage_error("SpringsGpu: more than " + std::to_string(LAGOON_SPRINGS_MAX_EXCITATIONS) +
                          " drops and gusts");
  excitation_count_ = uint32_t(excitations.size());
  excitations.resize(std::max<size_t>(excitations.size(), 1));  // a buffer cannot be empty
  excitations_ = vk::Buffer::create(ctx, excitations.size() * sizeof(gpu::SpringExcitation),
                                    (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                                    vk::MemoryUsage::Device, "springs excitations");
  vk::upload_buffer(ctx, excitations_, vk::as_bytes_of(excitations));
  ctx.submit_and_wait([&](VkCommandBuffer cmd) { record_clear(cmd); });
}

void SpringsGpu::record_clear(VkCommandBuffer cmd) {
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kTransferWrite);
  for (const vk::Buffer& b : state_) vkCmdFillBuffer(cmd, b.handle(), 0, VK_WHOLE_SIZE, 0);
  vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
  steps_ = 0;
}

gpu::SpringsPush SpringsGpu::push(uint64_t step) const {
  const SpringsParams& s = params_.springs;
  const double spacing = params_.cascades.front().patch_size_m / n_;
  return {.n = n_,
          .step = uint32_t(step),
          .excitations = excitation_count_,
          .layer = 0,
          .spacing = float(spacing),
          .dt = float(s.step_s),
          .mass = float(s.mass_kg),
          .stiffness = float(s.stiffness_n_per_m),
          .damping = float(s.damping_kg_per_s),
          .rest = float(s.rest_length * spacing),
          .boundary_amplitude = float(s.boundary_amplitude_m),
          .boundary_omega = float(2 * std::numbers::pi / s.boundary_period_s),
          .behind_s = 0,
          .foam_threshold = float(params_.foam.threshold),
          .foam_decay = 1,
          .reset_foam = 0};
}

void SpringsGpu::record(VkCommandBuffer cmd, double time_s, double dt_s, bool reset_foam,
                        const LayerTarget& target, vk::GpuTimer* timer) {
  time_s = std::max(time_s, 0.0);  // the grid rests before t = 0, as SpringGrid::surface_at
  const uint64_t wanted = springs_steps_for(params_.springs, time_s);
  if (wanted < steps_) record_clear(cmd);
  if (wanted - steps_ > kSpringsMaxCatchUpSteps)
    vk::throw_usage_error(springs_catch_up_message(params_.springs, time_s, wanted - steps_));
  const std::array<uint32_t, 3> nodes{n_, n_, 1};
  {
    vk::GpuScope scope(timer, cmd, "springs steps");
    for (; steps_ < wanted; ++steps_) {
      vk::dispatch(cmd, step_,
                   {vk::bind(LAGOON_SPRINGS_BIND_STATE_IN, state_[steps_ % 2]),
                    vk::bind(LAGOON_SPRINGS_BIND_STATE_OUT, state_[(steps_ + 1) % 2]),
                    vk::bind(LAGOON_SPRINGS_BIND_EXCITATIONS, excitations_)},
                   push(steps_), vk::groups_for(step_, nodes));
      vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
    }
  }
  vk::GpuScope scope(timer, cmd, "springs assemble");
  gpu::SpringsPush p = push(steps_);
  p.layer = target.layer;
  p.behind_s = float(double(steps_) * params_.springs.step_s - time_s);
  p.foam_decay = float(std::exp(-params_.foam.decay_per_s * dt_s));
  p.reset_foam = reset_foam ? 1u : 0u;
  auto storage = [](const vk::Image* image) {
    return vk::ImageRef{image->mip_view(0), VK_IMAGE_LAYOUT_GENERAL};
  };
  vk::dispatch(cmd, assemble_,
               {vk::bind(LAGOON_SPRINGS_BIND_STATE_IN, state_[steps_ % 2]),
                vk::bind(LAGOON_SPRINGS_BIND_DISPLACEMENT, storage(target.displacement)),
                vk::bind(LAGOON_SPRINGS_BIND_NORMAL_JACOBIAN, storage(target.normal_jacobian)),
                vk::bind(LAGOON_SPRINGS_BIND_JACOBIAN_TERMS, storage(target.jacobian_terms))},
               p, vk::groups_for(assemble_, nodes));
}

}  // namespace lagoon::ocean
