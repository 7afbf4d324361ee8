#include "ocean/gpu/ocean_fft_path.h"

#include <algorithm>
#include <array>
#include <string>

#include "fft/fft_plan.h"
#include "fft/gpu_fft.h"
#include "lagoon_shaders/shaders.h"
#include "shared/fft.h"
#include "shared/ocean.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"
#include "vk/transfer.h"

namespace lagoon::ocean {
namespace {

vk::ImageRef storage(const vk::Image& image) {
  return {image.mip_view(0), VK_IMAGE_LAYOUT_GENERAL};
}

// The assembly's resources, the same for both paths (common/ocean_assemble.glsl).
std::array<vk::Binding, 5> assembly_bindings(const vk::Buffer& fields, const vk::Buffer& twiddles,
                                             const OceanFftBindings& b) {
  return {vk::bind(LAGOON_OCEAN_BIND_FIELDS, fields), vk::bind(LAGOON_OCEAN_BIND_TWIDDLES, twiddles),
          vk::bind(LAGOON_OCEAN_BIND_DISPLACEMENT, storage(*b.displacement)),
          vk::bind(LAGOON_OCEAN_BIND_NORMAL_JACOBIAN, storage(*b.normal_jacobian)),
          vk::bind(LAGOON_OCEAN_BIND_JACOBIAN_TERMS, storage(*b.jacobian_terms))};
}

class StockhamPath : public OceanFftPath {
 public:
  StockhamPath(vk::Context& ctx, uint32_t n, uint32_t cascades)
      : n_(n), fft_(ctx, n, /*inverse=*/true, /*fields=*/4, fft::GpuFft2d::Ends::Fused) {
    const VkDeviceSize bytes = VkDeviceSize(n) * n * 8 * 4 * cascades;
    ping_ = vk::Buffer::create(ctx, bytes, vk::kStorageUsage, vk::MemoryUsage::Device, "ocean fft ping");
    pong_ = vk::Buffer::create(ctx, bytes, vk::kStorageUsage, vk::MemoryUsage::Device, "ocean fft pong");
    const auto first = fft_.pass(0), last = fft_.pass(fft_.pass_count() - 1);
    auto evolve_spec = fft::GpuFft2d::specialisation(n, first.ns, first.radix, false, true);
    auto assemble_spec = fft::GpuFft2d::specialisation(n, last.ns, last.radix, true, true);
    evolve_ = vk::ComputePipeline::create(ctx, shaders::ocean_evolve_fft_comp, evolve_spec);
    assemble_ = vk::ComputePipeline::create(ctx, shaders::ocean_fft_assemble_comp, assemble_spec);
    // The warm-up's variants: made (compiled) only when a warm-up runs.
    evolve_spec.push_back({LAGOON_OCEAN_SPEC_FOAM_ONLY, 1});
    assemble_spec.push_back({LAGOON_OCEAN_SPEC_FOAM_ONLY, 1});
    evolve_foam_ = vk::ComputePipeline::create(ctx, shaders::ocean_evolve_fft_comp, evolve_spec);
    assemble_foam_ = vk::ComputePipeline::create(ctx, shaders::ocean_fft_assemble_comp, assemble_spec);
  }

  void record(VkCommandBuffer cmd, const OceanFftBindings& b, const gpu::OceanPush& push, vk::GpuTimer* timer,
              StepOutputs outputs) const override {
    const bool foam_only = outputs == StepOutputs::FoamOnly;
    const vk::ComputePipeline& evolve = foam_only ? evolve_foam_ : evolve_;
    const vk::ComputePipeline& assemble = foam_only ? assemble_foam_ : assemble_;
    const uint32_t count = push.cascades, passes = uint32_t(fft_.pass_count());
    // The plain passes take the fields four at a time: a foam-only step's 2 per cascade are rounded up (the
    // buffers hold 4 per cascade, and the extra arrays are never read back).
    const uint32_t arrays = foam_only ? (2 * count + 3) / 4 * 4 : 4 * count;
    const auto first = fft_.pass(0), last = fft_.pass(passes - 1);
    const vk::Buffer* src = &ping_;
    const vk::Buffer* dst = &pong_;
    {
      vk::GpuScope s(timer, cmd, "ocean evolve+rows " + std::to_string(n_));
      vk::dispatch(cmd, evolve,
                   {vk::bind(LAGOON_OCEAN_BIND_SPECTRUM, *b.spectrum),
                    vk::bind(LAGOON_OCEAN_BIND_OMEGA, *b.omega), vk::bind(LAGOON_OCEAN_BIND_EVOLVED, ping_)},
                   push, vk::groups_for(evolve, {n_ / first.radix, n_, count}));
      vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
      for (uint32_t i = 1; i + 1 < passes; ++i) {
        fft_.record_pass(cmd, i, *src, *dst, arrays);
        std::swap(src, dst);
      }
    }
    vk::GpuScope s(timer, cmd, "ocean columns+assemble " + std::to_string(n_));
    const auto bindings = assembly_bindings(*src, fft_.twiddles(), b);
    vk::dispatch(cmd, assemble, bindings, &push, sizeof(push),
                 vk::groups_for(assemble, {n_, n_ / last.radix, count}));
  }

 private:
  uint32_t n_;
  fft::GpuFft2d fft_;
  vk::Buffer ping_, pong_;
  vk::ComputePipeline evolve_, assemble_, evolve_foam_, assemble_foam_;
};

class WorkgroupPath : public OceanFftPath {
 public:
  WorkgroupPath(vk::Context& ctx, uint32_t n, uint32_t cascades) : n_(n), lines_(std::max(1u, 1024u / n)) {
    const VkDeviceSize bytes = VkDeviceSize(n) * n * 8 * 4 * cascades;
    fields_ = vk::Buffer::create(ctx, bytes, vk::kStorageUsage, vk::MemoryUsage::Device, "ocean fields");
    const std::vector<float> table = fft::twiddle_table(n);
    twiddles_ = vk::Buffer::create(ctx, table.size() * 4, vk::kStorageUsage, vk::MemoryUsage::Device,
                                   "ocean twiddles");
    vk::upload_buffer(ctx, twiddles_, vk::as_bytes_of(table));
    // As many lines per workgroup as fit 32 KiB of shared memory (4 fields x N complex floats each): every
    // workgroup is then 64 invocations.
    const uint32_t work = n / 16;
    const std::vector<vk::SpecConstant> rows_spec{{LAGOON_FFT_SPEC_GROUP_X, work},
                                                  {LAGOON_FFT_SPEC_GROUP_Y, lines_},
                                                  {LAGOON_FFT_SPEC_INVERSE, 1},
                                                  {LAGOON_FFT_SPEC_N, n},
                                                  {LAGOON_FFT_SPEC_LINES, lines_}};
    const std::vector<vk::SpecConstant> columns_spec{{LAGOON_FFT_SPEC_GROUP_X, lines_},
                                                     {LAGOON_FFT_SPEC_GROUP_Y, work},
                                                     {LAGOON_FFT_SPEC_INVERSE, 1},
                                                     {LAGOON_FFT_SPEC_N, n},
                                                     {LAGOON_FFT_SPEC_LINES, lines_}};
    rows_ = vk::ComputePipeline::create(ctx, shaders::ocean_evolve_rows_comp, rows_spec);
    columns_ = vk::ComputePipeline::create(ctx, shaders::ocean_columns_assemble_comp, columns_spec);
  }

  // A foam-only step is a full one here: on a GPU the whole step costs a few tens of microseconds.
  void record(VkCommandBuffer cmd, const OceanFftBindings& b, const gpu::OceanPush& push, vk::GpuTimer* timer,
              StepOutputs) const override {
    const uint32_t count = push.cascades;
    {
      vk::GpuScope s(timer, cmd, "ocean evolve+rows " + std::to_string(n_));
      vk::dispatch(
          cmd, rows_,
          {vk::bind(LAGOON_OCEAN_BIND_SPECTRUM, *b.spectrum), vk::bind(LAGOON_OCEAN_BIND_OMEGA, *b.omega),
           vk::bind(LAGOON_OCEAN_BIND_ROW_TWIDDLES, twiddles_), vk::bind(LAGOON_OCEAN_BIND_ROWS, fields_)},
          push, {1, n_ / lines_, count});
      vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
    }
    vk::GpuScope s(timer, cmd, "ocean columns+assemble " + std::to_string(n_));
    const auto bindings = assembly_bindings(fields_, twiddles_, b);
    vk::dispatch(cmd, columns_, bindings, &push, sizeof(push), {n_ / lines_, 1, count});
  }

 private:
  uint32_t n_, lines_;
  vk::Buffer fields_, twiddles_;
  vk::ComputePipeline rows_, columns_;
};

}  // namespace

std::unique_ptr<OceanFftPath> make_ocean_fft_path(vk::Context& ctx, FftVariant variant, uint32_t n,
                                                  uint32_t cascades) {
  if (variant == FftVariant::Auto)
    variant = ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? FftVariant::Stockham
                                                                         : FftVariant::Workgroup;
  if (variant == FftVariant::Stockham) return std::make_unique<StockhamPath>(ctx, n, cascades);
  return std::make_unique<WorkgroupPath>(ctx, n, cascades);
}

}  // namespace lagoon::ocean
