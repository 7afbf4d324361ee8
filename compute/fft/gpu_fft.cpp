#include "fft/gpu_fft.h"

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
  return {{0, 8}, {1, 8},  {2, radix}, {3, columns ? 1u : 0u}, {4, inverse ? 1u : 0u},
          {5, n}, {6, ns}, {8, fields}};
}

GpuFft2d::GpuFft2d(vk::Context& ctx, uint32_t n, bool inverse, uint32_t fields)
    : ctx_(ctx), n_(n), inverse_(inverse), fields_(fields), radices_(stockham_radices(n)) {
  if (!is_supported_size(n))
    vk::throw_usage_error("GpuFft2d: size " + std::to_string(n) + " is not a power of two in [64, 1024]");
  const std::vector<float> table = twiddle_table(n);
  twiddles_ = vk::Buffer::create(ctx, table.size() * sizeof(float),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 vk::MemoryUsage::Device, "fft twiddles");
  vk::upload_buffer(ctx, twiddles_, vk::as_bytes_of(table));
  for (size_t i = 0; i < pass_count(); ++i) {
    const Pass p = pass(i);
    pipelines_.push_back(vk::ComputePipeline::create(
        ctx, shaders::fft_fft_pass_comp, specialisation(n, p.ns, p.radix, p.columns, inverse, fields)));
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
  if (batches % fields_ != 0)
    vk::throw_usage_error("GpuFft2d: batches must be a multiple of the fields per group");
  const uint32_t groups = batches / fields_;
  const gpu::FftPush push{.batches = groups};
  const uint32_t butterflies = n_ / p.radix;
  // Each invocation: two butterflies of a row, or one butterfly of two columns (fft_pass.comp).
  const std::array<uint32_t, 3> threads =
      p.columns ? std::array{n_ / 2, butterflies, groups} : std::array{butterflies / 2, n_, groups};
  vk::dispatch(cmd, pipeline, {vk::bind(0, src), vk::bind(1, dst), vk::bind(2, twiddles_)}, push,
               vk::groups_for(pipeline, threads));
  vk::memory_barrier(cmd, vk::access::kComputeReadWrite, vk::access::kComputeReadWrite);
}

const vk::Buffer& GpuFft2d::record(VkCommandBuffer cmd, const vk::Buffer& a, const vk::Buffer& b,
                                   uint32_t batches) const {
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
