// Upload -> compute -> readback, checked against the same arithmetic on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "lagoon_test_shaders/shaders.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/check.h"
#include "vk/pipeline.h"
#include "vk/sampler.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

class ComputeRoundTrip : public GpuTest {};

std::vector<float> random_floats(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> dist(-10.0f, 10.0f);
  std::vector<float> v(n);
  for (float& f : v) f = dist(rng);
  return v;
}

// Whether `got` is a float evaluation of a*x + y. The reference is exact in double (a*x of two floats is
// exact there). A conformant device may round a*x and then the sum (error <= 0.5 ulp(a*x) + 0.5 ulp(sum))
// or fuse them into one FMA (error <= 0.5 ulp(sum)), so both lie within 1.5 float epsilons of
// max(|a*x|, |y|) (|sum| <= 2 max); two epsilons leaves a margin and is still ~1e-6 relative, far below
// what a wrong formula such as a*x - y or a*(x + y) is off by.
bool is_saxpy(float got, float a, float x, float y) {
  const double ax = double(a) * double(x);
  const double reference = ax + double(y);
  const double scale = std::max(std::abs(ax), std::abs(double(y)));
  return std::abs(double(got) - reference) <= 2.0 * std::numeric_limits<float>::epsilon() * scale;
}

TEST(SaxpyTolerance, AdmitsRoundingAndFmaButNotWrongFormulas) {
  const std::vector<float> x = random_floats(1000, 1), y = random_floats(1000, 2);
  const float a = 2.5f;
  int separate = 0, fused = 0, minus = 0, factored = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const float product = a * x[i];
    separate += is_saxpy(product + y[i], a, x[i], y[i]);
    fused += is_saxpy(std::fma(a, x[i], y[i]), a, x[i], y[i]);
    minus += is_saxpy(product - y[i], a, x[i], y[i]);
    factored += is_saxpy(a * (x[i] + y[i]), a, x[i], y[i]);
  }
  EXPECT_EQ(separate, 1000);
  EXPECT_EQ(fused, 1000);
  EXPECT_EQ(minus, 0);
  EXPECT_EQ(factored, 0);
}

TEST_F(ComputeRoundTrip, SaxpyMatchesCpuThroughDeviceLocalBuffers) {
  const uint32_t n = 10007;  // not a multiple of the workgroup size: the bounds check matters
  const float a = 2.5f;
  const std::vector<float> x = random_floats(n, 1), y = random_floats(n, 2);
  const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  vk::Buffer bx = vk::Buffer::create(ctx(), n * 4, usage, vk::MemoryUsage::Device, "x");
  vk::Buffer by = vk::Buffer::create(ctx(), n * 4, usage, vk::MemoryUsage::Device, "y");
  vk::upload_buffer(ctx(), bx, vk::as_bytes_of(x));
  vk::upload_buffer(ctx(), by, vk::as_bytes_of(y));

  const vk::ComputePipeline saxpy = vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp);
  EXPECT_EQ(saxpy.local_size()[0], 64u);
  struct Push {
    float a;
    uint32_t n;
  } push{a, n};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, saxpy, {vk::bind(0, bx), vk::bind(1, by)}, push, vk::groups_for(saxpy, {n, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<float> result = from_bytes<float>(vk::readback_buffer(ctx(), by));
  ASSERT_EQ(result.size(), n);
  for (uint32_t i = 0; i < n; ++i)
    ASSERT_TRUE(is_saxpy(result[i], a, x[i], y[i]))
        << "at " << i << ": " << result[i] << ", expected " << double(a) * x[i] + y[i];
}

TEST_F(ComputeRoundTrip, StorageImageArraySamplerAndSpecializedWorkgroup) {
  const uint32_t w = 37, h = 23, layers = 3;
  vk::Image dst =
      vk::Image::create(ctx(), {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                .extent = {w, h},
                                .layers = layers,
                                .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                .debug_name = "dst"});
  // Source image for the sampler: distinct RGBA32F values uploaded from the CPU.
  std::vector<float> src_texels(size_t{w} * h * 4);
  for (size_t i = 0; i < src_texels.size(); ++i) src_texels[i] = float(i % 251) * 0.5f;
  vk::Image src =
      vk::Image::create(ctx(), {.format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                .extent = {w, h},
                                .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                .debug_name = "src"});
  vk::upload_image(ctx(), src, vk::as_bytes_of(src_texels), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   vk::access::kComputeRead);
  // Nearest filtering at texel centres must return the texels exactly.
  vk::Unique<VkSampler> sampler =
      vk::create_sampler(ctx(), {.filter = VK_FILTER_NEAREST,
                                 .mipmap = VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                 .address = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE});
  vk::Buffer sampled = vk::Buffer::create(ctx(), size_t{w} * h * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          vk::MemoryUsage::Readback, "sampled");

  const vk::SpecConstant spec[] = {{0, 8}, {1, 4}};
  const vk::ComputePipeline pass = vk::ComputePipeline::create(ctx(), shaders::gpu_image_gradient_comp, spec);
  EXPECT_EQ(pass.local_size()[0], 8u);
  EXPECT_EQ(pass.local_size()[1], 4u);
  struct Push {
    float scale[4];
    uint32_t size[4];
  } push{{1.0f, 2.0f, 3.0f, 0.5f}, {w, h, layers, 0}};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::image_barrier(cmd, dst.handle(), dst.all_subresources(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_GENERAL, vk::access::kNone, vk::access::kComputeWrite);
    vk::dispatch(cmd, pass,
                 {vk::bind(0, vk::ImageRef{dst.view(), VK_IMAGE_LAYOUT_GENERAL}),
                  vk::bind(1, vk::ImageRef{src.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler}),
                  vk::bind(2, sampled)},
                 push, vk::groups_for(pass, {w, h, layers}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kHostRead);
  });
  const std::vector<float> texels =
      from_bytes<float>(vk::readback_image(ctx(), dst, VK_IMAGE_LAYOUT_GENERAL, vk::access::kComputeWrite));
  ASSERT_EQ(texels.size(), size_t{w} * h * layers * 4);
  // Exact on any device: each value is a small integer times 1, 2, 3 or 0.5, a single correctly rounded
  // multiplication whose result is representable (no sum that an FMA could change).
  for (uint32_t z = 0; z < layers; ++z)
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        const float* t = &texels[((size_t{z} * h + y) * w + x) * 4];
        ASSERT_EQ(t[0], float(x) * 1.0f);
        ASSERT_EQ(t[1], float(y) * 2.0f);
        ASSERT_EQ(t[2], float(z) * 3.0f);
        ASSERT_EQ(t[3], float(x * y) * 0.5f);
      }
  // Nearest filtering at texel centres returns a stored texel unchanged, so these are exact too.
  sampled.invalidate();
  const std::span<const float> got = sampled.mapped_as<const float>();
  for (size_t i = 0; i < src_texels.size(); ++i) ASSERT_EQ(got[i], src_texels[i]) << "at " << i;
}

TEST_F(ComputeRoundTrip, WrongBindingsAreReportedWithTheShaderName) {
  const vk::ComputePipeline saxpy = vk::ComputePipeline::create(ctx(), shaders::gpu_saxpy_comp);
  vk::Buffer b = vk::Buffer::create(ctx(), 64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUsage::Upload);
  struct Push {
    float a;
    uint32_t n;
  } push{1.0f, 16};
  struct TooBig {
    float values[16];
  } too_big{};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    // One binding missing.
    try {
      vk::dispatch(cmd, saxpy, {vk::bind(0, b)}, push, {1, 1, 1});
      ADD_FAILURE() << "missing binding accepted";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("gpu/saxpy.comp"), std::string::npos) << e.what();
    }
    // An image where the shader declares a buffer.
    try {
      vk::dispatch(cmd, saxpy, {vk::bind(0, b), vk::bind(1, vk::ImageRef{})}, push, {1, 1, 1});
      ADD_FAILURE() << "image for a buffer binding accepted";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("binding 1"), std::string::npos) << e.what();
    }
    // Push constants of the wrong size.
    try {
      vk::dispatch(cmd, saxpy, {vk::bind(0, b), vk::bind(1, b)}, too_big, {1, 1, 1});
      ADD_FAILURE() << "oversized push constants accepted";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("push constants"), std::string::npos) << e.what();
    }
  });
}

}  // namespace
}  // namespace lagoon::test
