#include "ocean/gpu/dynamic_layer_gpu.h"

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/compass.h"
#include "lagoon_shaders/shaders.h"
#include "shared/dynamic_layer.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/transfer.h"

namespace lagoon::ocean {
namespace {

// One step's sources: a multiple of 256 bytes, the largest uniform-buffer offset alignment Vulkan allows.
constexpr VkDeviceSize kSlotBytes = sizeof(gpu::DynamicSource) * LAGOON_DYNAMIC_MAX_SOURCES;
static_assert(kSlotBytes % 256 == 0);
constexpr std::array<vk::SpecConstant, 1> kNyquistLines{{{LAGOON_DYNAMIC_SPEC_NYQUIST, 1}}};
constexpr std::array<vk::SpecConstant, 1> kNoFields{{{LAGOON_DYNAMIC_SPEC_FIELDS, 0}}};

gpu::DynamicSource to_gpu(const WakeSource& s, double period) {
  // A whole period changes no phase of the grid's modes; within one, float phases stay accurate.
  const glm::dvec2 centre = s.centre - period * glm::floor(s.centre / period);
  return {.centre = glm::vec2(centre),
          .velocity = glm::vec2(s.velocity),
          .sigma = glm::vec2(s.sigma),
          .along = glm::vec2(compass::toward(s.heading)),
          .depression = float(s.depression),
          .depth = float(s.depth),
          .foam_per_s = float(s.foam_per_s)};
}

}  // namespace

DynamicLayerGpu::DynamicLayerGpu(vk::Context& ctx, const DynamicLayerParams& params)
    : params_(params),
      forward_(ctx, params.n, false),
      inverse_(ctx, params.n, true),
      evolve_(vk::ComputePipeline::create(ctx, shaders::ocean_dynamic_evolve_comp)),
      evolve_nyquist_(vk::ComputePipeline::create(ctx, shaders::ocean_dynamic_evolve_comp, kNyquistLines)),
      sponge_(vk::ComputePipeline::create(ctx, shaders::ocean_dynamic_sponge_comp)),
      sponge_no_fields_(vk::ComputePipeline::create(ctx, shaders::ocean_dynamic_sponge_comp, kNoFields)) {
  const VkDeviceSize bytes = VkDeviceSize(params.n) * params.n * 2 * sizeof(float);
  state_ = vk::Buffer::create(ctx, bytes, (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                              vk::MemoryUsage::Device, "dynamic layer state");
  scratch_ = vk::Buffer::create(ctx, bytes, (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                                vk::MemoryUsage::Device, "dynamic layer scratch");
  for (vk::Buffer& foam : foam_)
    foam = vk::Buffer::create(ctx, bytes / 2, (vk::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT),
                              vk::MemoryUsage::Device, "dynamic layer foam");
  sources_ = vk::Buffer::create(ctx, kSlotBytes * kStepsInFlight, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                vk::MemoryUsage::Upload, "dynamic layer sources");
  fields_ =
      vk::Image::create(ctx, {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                              .extent = {params.n, params.n},
                              .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                              .debug_name = "dynamic layer fields"});
  ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, fields_.handle(), fields_.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_GENERAL, vk::access::kNone, vk::access::kTransferWrite);
    record_clear(cmd);
  });
}

void DynamicLayerGpu::record_clear(VkCommandBuffer cmd) {
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kTransferWrite);
  vkCmdFillBuffer(cmd, state_.handle(), 0, VK_WHOLE_SIZE, 0);
  for (const vk::Buffer& foam : foam_) vkCmdFillBuffer(cmd, foam.handle(), 0, VK_WHOLE_SIZE, 0);
  const VkClearColorValue zero{};
  const VkImageSubresourceRange range = fields_.all_subresources();
  vkCmdClearColorImage(cmd, fields_.handle(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &range);
  vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
}

void DynamicLayerGpu::record_step(VkCommandBuffer cmd, double dt, std::span<const WakeSource> sources,
                                  Fields fields) {
  if (sources.size() > LAGOON_DYNAMIC_MAX_SOURCES)
    vk::throw_usage_error("DynamicLayerGpu: more than " + std::to_string(LAGOON_DYNAMIC_MAX_SOURCES) +
                          " sources in one step");
  const VkDeviceSize offset = VkDeviceSize(next_slot_) * kSlotBytes;
  next_slot_ = (next_slot_ + 1) % kStepsInFlight;
  auto* slot = reinterpret_cast<gpu::DynamicSource*>(static_cast<std::byte*>(sources_.mapped()) + offset);
  const double period = params_.n * params_.cell_m;
  // Those that leave foam first: the sponge pass loops over them only (lavapipe runs both sides of an `if`,
  // but leaves a loop when it ends).
  uint32_t foam_sources = 0;
  for (const WakeSource& s : sources)
    if (s.foam_per_s > 0) slot[foam_sources++] = to_gpu(s, period);
  for (size_t i = 0, next = foam_sources; i < sources.size(); ++i)
    if (!(sources[i].foam_per_s > 0)) slot[next++] = to_gpu(sources[i], period);
  sources_.flush();
  const gpu::DynamicPush push{
      .origin = origin_,
      .n = params_.n,
      .source_count = uint32_t(sources.size()),
      .cell = float(params_.cell_m),
      .dt = float(dt),
      .substeps = dynamic_substeps(dt, sources),
      .gravity = float(params_.gravity),
      .depth = float(params_.depth_m),
      .decay_per_s = float(params_.decay_per_s),
      .sponge_cells = float(params_.sponge_m / params_.cell_m),
      .sponge_per_s = float(params_.sponge_per_s),
      .foam_sources = foam_sources,
      .foam_decay = float(foam_decay_factor(params_.foam_lifetime_s, dt)),
      .foam_spread = float(foam_spread_factor(params_.foam_spread_m2_s, params_.cell_m, dt))};
  const vk::BufferRef step_sources{sources_.handle(), offset, kSlotBytes};
  const std::array<uint32_t, 3> cells{params_.n, params_.n, 1};
  // The state is in state_; each transform returns its result in the buffer it was given.
  forward_.record(cmd, state_, scratch_, 1);
  const std::array<vk::Binding, 3> spectral{vk::bind(LAGOON_DYNAMIC_BIND_SPECTRUM, state_),
                                            vk::bind(LAGOON_DYNAMIC_BIND_EVOLVED, scratch_),
                                            vk::bind(LAGOON_DYNAMIC_BIND_SOURCES, step_sources)};
  // The pairs k, -k (half the grid), and the Nyquist lines: disjoint writes, no barrier between them.
  vk::dispatch(cmd, evolve_, spectral, &push, sizeof(push),
               vk::groups_for(evolve_, {params_.n, params_.n / 2, 1}));
  vk::dispatch(cmd, evolve_nyquist_, spectral, &push, sizeof(push),
               vk::groups_for(evolve_nyquist_, {2 * params_.n, 1, 1}));
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
  inverse_.record(cmd, scratch_, state_, 1);
  const vk::ComputePipeline& sponge = fields == Fields::Write ? sponge_ : sponge_no_fields_;
  vk::dispatch(cmd, sponge,
               {vk::bind(LAGOON_DYNAMIC_BIND_RAW, scratch_), vk::bind(LAGOON_DYNAMIC_BIND_STATE, state_),
                vk::bind(LAGOON_DYNAMIC_BIND_SOURCES, step_sources),
                vk::bind(LAGOON_DYNAMIC_BIND_FOAM_IN, foam_[foam_current_]),
                vk::bind(LAGOON_DYNAMIC_BIND_FOAM, foam_[1 - foam_current_]),
                vk::bind(LAGOON_DYNAMIC_BIND_FIELDS, vk::ImageRef{fields_.view(), VK_IMAGE_LAYOUT_GENERAL})},
               push, vk::groups_for(sponge, cells));
  foam_current_ = 1 - foam_current_;
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
}

std::vector<float> DynamicLayerGpu::read_state(vk::Context& ctx) const {
  const vk::Access writer{VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT};
  std::vector<float> out;
  for (const std::vector<std::byte>& bytes :
       {vk::readback_buffer(ctx, state_), vk::readback_buffer(ctx, foam_[foam_current_]),
        vk::readback_image(ctx, fields_, VK_IMAGE_LAYOUT_GENERAL, writer)}) {
    const size_t at = out.size();
    out.resize(at + bytes.size() / sizeof(float));
    std::memcpy(out.data() + at, bytes.data(), bytes.size() / sizeof(float) * sizeof(float));
  }
  return out;
}

bool DynamicLayerGpu::write_state(vk::Context& ctx, std::span<const float> state) {
  const size_t n2 = size_t(params_.n) * params_.n;
  if (state.size() != state_floats()) return false;
  vk::upload_buffer(ctx, state_, std::as_bytes(state.subspan(0, 2 * n2)));
  vk::upload_buffer(ctx, foam_[foam_current_], std::as_bytes(state.subspan(2 * n2, n2)));
  // Read by the next step's compute passes and sampled by the frame's.
  const vk::Access next{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
  vk::upload_image(ctx, fields_, std::as_bytes(state.subspan(3 * n2, 4 * n2)), VK_IMAGE_LAYOUT_GENERAL, next);
  return true;
}

}  // namespace lagoon::ocean
