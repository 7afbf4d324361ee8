// Formulas written once in shaders/shared/ and compiled as C++ too: the GPU's evaluation matches the C++
// one, and both match an independent double-precision form of the published shape.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "lagoon_test_shaders/shaders.h"
#include "render/sky_light.h"
#include "shared/sky_shape.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

template <typename T>
std::vector<T> from_bytes(const std::vector<std::byte>& bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

// The sky's shape as docs/rendering.md states it, in double: 0.55 + 1.2(1 − max(y, 0))⁴ + 0.6 max(d·s, 0)¹².
double reference_shape(glm::dvec3 d, glm::dvec3 s) {
  return 0.55 + 1.2 * std::pow(1.0 - std::max(d.y, 0.0), 4) +
         0.6 * std::pow(std::max(glm::dot(d, s), 0.0), 12);
}

std::vector<glm::vec4> random_pairs(uint32_t count) {
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  std::vector<glm::vec4> pairs;
  for (uint32_t i = 0; i < 2 * count; ++i)
    pairs.push_back(glm::vec4(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))), 0));
  return pairs;
}

class SharedFormula : public GpuTest {};

TEST_F(SharedFormula, SkyShapeIsTheSameOnGpuAndCpu) {
  const uint32_t count = 1000;
  const std::vector<glm::vec4> pairs = random_pairs(count);
  const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  vk::Buffer in =
      vk::Buffer::create(ctx(), pairs.size() * sizeof(glm::vec4), usage, vk::MemoryUsage::Device, "in");
  vk::Buffer out = vk::Buffer::create(ctx(), count * 4, usage, vk::MemoryUsage::Device, "out");
  vk::upload_buffer(ctx(), in, vk::as_bytes_of(pairs));
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx(), shaders::gpu_sky_shape_eval_comp);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, eval, {vk::bind(0, in), vk::bind(1, out)}, count, vk::groups_for(eval, {count, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<float> gpu = from_bytes<float>(vk::readback_buffer(ctx(), out));
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 d(pairs[2 * i]), s(pairs[2 * i + 1]);
    const double reference = reference_shape(glm::dvec3(d), glm::dvec3(s));
    ASSERT_NEAR(gpu::sky_shape(d, s), reference, 1e-5 * reference) << "C++ at " << i;
    ASSERT_NEAR(gpu[i], reference, 1e-4 * reference) << "GPU at " << i;
  }
}

TEST(SkyShapeIntegral, MatchesAClosedFormForTheSunBelowTheHorizon) {
  // With the sun straight down, d·s ≤ 0 over the upper hemisphere, so the shape is 0.55 + 1.2(1 − cos θ)⁴ and
  // (1/π)∫ shape cos θ dω = 0.55 + 2.4 ∫₀¹ (1 − μ)⁴ μ dμ = 0.55 + 2.4 / 30.
  EXPECT_NEAR(render::sky_shape_integral(glm::vec3(0, -1, 0)), 0.55 + 2.4 / 30.0, 1e-3);
}

}  // namespace
}  // namespace lagoon::test
