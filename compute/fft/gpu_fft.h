// Batched 2-D complex FFT of N x N arrays on the GPU: log16(N) Stockham passes along rows, then along
// columns, ping-ponging between two buffers. Records only; never submits.
#pragma once
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"

namespace lagoon::fft {

class GpuFft2d {
 public:
  // n: supported size (fft_plan.h); inverse: exp(+2πi kn/N) without 1/N scaling (as FFTW_BACKWARD).
  // fields: arrays per batch group that one invocation transforms together, sharing its twiddles (the
  // ocean's 4 packed fields); record()'s `batches` must then be a multiple of it.
  // Ends::Fused: the caller records the first and last passes itself (the ocean fuses evolution and
  // assembly into them), so their pipelines are not built and record() is unavailable; record_pass() the
  // rest.
  enum class Ends { Own, Fused };
  GpuFft2d(vk::Context& ctx, uint32_t n, bool inverse, uint32_t fields = 1, Ends ends = Ends::Own);

  // Transforms `batches` arrays of vec2 in `a` (row-major, array after array) using `b` as scratch. Returns
  // the buffer holding the result (a when the pass count is even, which it is for every supported n).
  // Expects `a` written before by a compute shader or transfer; leaves the result visible to compute reads.
  const vk::Buffer& record(VkCommandBuffer cmd, const vk::Buffer& a, const vk::Buffer& b,
                           uint32_t batches) const;

  // Pass i of pass_count(): row passes first, then column passes.
  struct Pass {
    uint32_t radix = 0;
    uint32_t ns = 1;  // Stockham stride
    bool columns = false;
  };
  size_t pass_count() const { return 2 * radices_.size(); }
  Pass pass(size_t index) const;
  // Records pass `index` alone (for callers that fuse their own first or last pass), with a barrier after it.
  void record_pass(VkCommandBuffer cmd, size_t index, const vk::Buffer& src, const vk::Buffer& dst,
                   uint32_t batches) const;

  uint32_t size() const { return n_; }
  size_t pipeline_count() const;  // the pipelines built: pass_count(), or 2 fewer with Ends::Fused
  const vk::Buffer& twiddles() const { return twiddles_; }

  // The pipeline of one pass: shared with the ocean's fused passes through the same specialisation scheme.
  static std::vector<vk::SpecConstant> specialisation(uint32_t n, uint32_t ns, uint32_t radix, bool columns,
                                                      bool inverse, uint32_t fields = 1);

 private:
  vk::Context& ctx_;
  uint32_t n_;
  bool inverse_;
  uint32_t fields_;
  Ends ends_;
  std::vector<uint32_t> radices_;
  vk::Buffer twiddles_;
  std::vector<vk::ComputePipeline> pipelines_;  // one per pass
};

}  // namespace lagoon::fft
