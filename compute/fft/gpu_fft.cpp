#include "fft/gpu_fft.h"

#include <algorithm>

#include "fft/fft_plan.h"
#include "lagoon_shaders/shaders.h"
#include "shared/fft.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/transfer.h"

namespace lagoon::fft {

std::vector<vk::SpecConstant> GpuFft2d::specialisation(uint32_t n, uint32_t ns, uint32_t radix, bool columns,
                                                       bool inverse, uint32_t fields) {
  // 8 x 8 workgroups: neighbouring lanes read neighbouring elements in both directions (see fft_pass.comp).
  return {{LAGOON_FFT_SPEC_GROUP_X, 8},
          {LAGOON_FFT_SPEC_GROUP_Y, 8},
          {LAGOON_FFT_SPEC_RADIX, radix},
          {LAGOON_FFT_SPEC_COLUMNS, columns ? 1u : 0u},
          {LAGOON_FFT_SPEC_INVERSE, inverse ? 1u : 0u},
          {LAGOON_FFT_SPEC_N, n},
          {LAGOON_FFT_SPEC_NS, ns},
          {LAGOON_FFT_SPEC_FIELDS, fields}};
}

GpuFft2d::GpuFft2d(vk::Context& ctx, uint32_t n, bool inverse, uint32_t fields, Ends ends)
    : ctx_(ctx), n_(n), inverse_(inverse), fields_(fields), ends_(ends), radices_(stockham_radices(n)) {
  if (!is_supported_size(n))
    vk::throw_usage_error("GpuFft2d: size " + std::to_string(n) + " is not a power of two in [64, 1024]");
  const std::vector<float> table = twiddle_table(n);
  twiddles_ = vk::Buffer::create(ctx, table.size() * sizeof(float),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 vk::MemoryUsage::Device, "fft twiddles");
  vk::upload_buffer(ctx, twiddles_, vk::as_bytes_of(table));
  for (size_t i = 0; i < pass_count(); ++i) {
    const Pass p = pass(i);
    // The caller's fused passes replace the first and the last: compiling them would be wasted work.
    const bool fused = ends == Ends::Fused && (i == 0 || i + 1 == pass_count());
    pipelines_.push_back(
        fused ? vk::ComputePipeline{}
              : vk::ComputePipeline::create(ctx, shaders::fft_fft_pass_comp,
                                            specialisation(n, p.ns, p.radix, p.columns, inverse, fields)));
  }
}

GpuFft2d::Pass GpuFft2d::pass(size_t index) const {
  const size_t per_axis = radices_.size();
  Pass p{.radix = radices_[index % per_axis], .ns = 1, .columns = index >= per_axis};
  for (size_t i = 0; i < index % per_axis; ++i) p.ns *= radices_[i];
  return p;
}

void GpuFft2d::record_pass(VkCommandBuffer cmd, size_t index, const vk::Buffer& src, const vk::Buffer& dst,
                           uint32_t batches) const {
  const Pass p = pass(index);
  const vk::ComputePipeline& pipeline = pipelines_.at(index);
  if (pipeline.empty())
    vk::throw_usage_error("GpuFft2d: pass " + std::to_string(index) +
                          " is fused by the caller (Ends::Fused)");
  if (batches % fields_ != 0)
    vk::throw_usage_error("GpuFft2d: batches must be a multiple of the fields per group");
  const uint32_t groups = batches / fields_;
  const gpu::FftPush push{.batches = groups};
  const uint32_t butterflies = n_ / p.radix;
  // Each invocation: two butterflies of a row, or one butterfly of two columns (fft_pass.comp).
  const std::array<uint32_t, 3> threads =
      p.columns ? std::array{n_ / 2, butterflies, groups} : std::array{butterflies / 2, n_, groups};
  vk::dispatch(cmd, pipeline,
               {vk::bind(LAGOON_FFT_BIND_SRC, src), vk::bind(LAGOON_FFT_BIND_DST, dst),
                vk::bind(LAGOON_FFT_BIND_TWIDDLES, twiddles_)},
               push, vk::groups_for(pipeline, threads));
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
}

size_t GpuFft2d::pipeline_count() const {
  return size_t(std::count_if(pipelines_.begin(), pipelines_.end(),
                              [](const vk::ComputePipeline& p) { return !p.empty(); }));
}

const vk::Buffer& GpuFft2d::record(VkCommandBuffer cmd, const vk::Buffer& a, const vk::Buffer& b,
                                   uint32_t batches) const {
  if (ends_ == Ends::Fused)
    vk::throw_usage_error("GpuFft2d::record: the first and last passes are the caller's");
  const VkDeviceSize bytes = VkDeviceSize(batches) * n_ * n_ * 8;
  if (a.size() < bytes || b.size() < bytes) vk::throw_usage_error("GpuFft2d::record: buffers too small");
  const vk::Buffer* src = &a;
  const vk::Buffer* dst = &b;
  vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kComputeRead);
  for (size_t i = 0; i < pass_count(); ++i) {
    record_pass(cmd, i, *src, *dst, batches);
    std::swap(src, dst);
  }
  return *src;
}

}  // namespace lagoon::fft
