// The GPU FFT against FFTW in double precision, for every supported size and both directions.
#include "fft/gpu_fft.h"

#include <gtest/gtest.h>

#include <random>

#include "fft/fft_plan.h"
#include "support/fftw_reference.h"
#include "support/vk_fixture.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

class GpuFftTest : public GpuTest, public ::testing::WithParamInterface<std::tuple<uint32_t, bool>> {};

TEST(FftPlan, RadicesMultiplyToTheSizeInTwoPasses) {
  for (uint32_t n = 64; n <= 1024; n *= 2) {
    uint32_t product = 1;
    for (uint32_t r : fft::stockham_radices(n)) product *= r;
    EXPECT_EQ(product, n);
    EXPECT_EQ(fft::stockham_radices(n).size(), 2u) << n;
  }
  EXPECT_EQ(fft::stockham_radices(256), (std::vector<uint32_t>{16, 16}));
  EXPECT_EQ(fft::stockham_radices(512), (std::vector<uint32_t>{32, 16}));
  EXPECT_EQ(fft::stockham_radices(1024), (std::vector<uint32_t>{32, 32}));
  EXPECT_FALSE(fft::is_supported_size(96));
  EXPECT_FALSE(fft::is_supported_size(2048));
  EXPECT_TRUE(fft::is_supported_size(64));
}

TEST_P(GpuFftTest, MatchesFftwDouble) {
  const auto [n, inverse] = GetParam();
  const int batches = n <= 256 ? 5 : 2;
  std::mt19937 rng(n + inverse);
  std::normal_distribution<float> gauss;
  std::vector<float> input(size_t{2} * n * n * batches);
  for (float& v : input) v = gauss(rng);

  const VkDeviceSize bytes = input.size() * sizeof(float);
  const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                     VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  vk::Buffer a = vk::Buffer::create(ctx(), bytes, usage, vk::MemoryUsage::Device, "fft a");
  vk::Buffer b = vk::Buffer::create(ctx(), bytes, usage, vk::MemoryUsage::Device, "fft b");
  vk::upload_buffer(ctx(), a, vk::as_bytes_of(input));
  fft::GpuFft2d fft(ctx(), n, inverse);
  const vk::Buffer* result = nullptr;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeRead);
    result = &fft.record(cmd, a, b, uint32_t(batches));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<std::byte> raw = vk::readback_buffer(ctx(), *result);
  std::vector<std::complex<double>> gpu(input.size() / 2), ref(input.size() / 2);
  const float* f = reinterpret_cast<const float*>(raw.data());
  for (size_t i = 0; i < gpu.size(); ++i) {
    gpu[i] = {f[2 * i], f[2 * i + 1]};
    ref[i] = {input[2 * i], input[2 * i + 1]};
  }
  fftw_2d(ref, int(n), batches, inverse);
  const double error = relative_l2(gpu, ref);
  // Single precision with log2(N) rounding stages: ~1e-7..1e-6. A wrong twiddle or index gives O(1).
  EXPECT_LT(error, 1e-5) << "n = " << n << (inverse ? " inverse" : " forward");
}

INSTANTIATE_TEST_SUITE_P(
    Sizes, GpuFftTest, ::testing::Combine(::testing::Values(64u, 128u, 256u, 512u, 1024u), ::testing::Bool()),
    [](const auto& info) {
      return std::to_string(std::get<0>(info.param)) + (std::get<1>(info.param) ? "_inverse" : "_forward");
    });

}  // namespace
}  // namespace lagoon::test
