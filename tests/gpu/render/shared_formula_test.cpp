// Formulas written once in shaders/shared/ and compiled as C++ too: the GPU's evaluation matches the C++
// one, and both match an independent double-precision form of the published shape.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "lagoon_test_shaders/shaders.h"
#include "render/dfg_table.h"
#include "render/sky_light.h"
#include "shared/pbr.h"
#include "shared/sky_model.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

// Preetham et al. (1999) as they print it, in double: Perez F(θ, γ) for Y, x, y (x, y shifted by Lagoon's
// (Δx, Δy), optics/sky_radiance.h), the CIE daylight M1, M2, and the radiance Σ_k w_k B_k with
// w = F_Y (1, M1, M2) / (Y0 + M1 Y1 + M2 Y2).
double perez(glm::dvec4 abcd, double e, double cos_theta, double gamma) {
  return (1 + abcd.x * std::exp(abcd.y / cos_theta)) *
         (1 + abcd.z * std::exp(abcd.w * gamma) + e * std::cos(gamma) * std::cos(gamma));
}

glm::dvec3 reference_rgb(const gpu::SkyModelGpu& m, glm::dvec3 d, glm::dvec3 s) {
  const double cos_theta = std::max(d.y, 0.01);
  const glm::dvec3 above = glm::normalize(glm::dvec3(d.x, cos_theta, d.z));
  const double gamma = std::acos(std::clamp(glm::dot(above, s), -1.0, 1.0));
  const double lum = perez(m.perez_lum, m.perez_e.x, cos_theta, gamma);
  const double x = m.zenith.x * perez(m.perez_x, m.perez_e.y, cos_theta, gamma) + m.zenith.z;
  const double y = m.zenith.y * perez(m.perez_y, m.perez_e.z, cos_theta, gamma) + m.zenith.w;
  const double den = 0.0241 + 0.2562 * x - 0.7341 * y;
  const double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / den,
               m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / den;
  const double scale = lum / (m.basis0.w + m1 * m.basis1.w + m2 * m.basis2.w);
  return scale * (glm::dvec3(m.basis0) + m1 * glm::dvec3(m.basis1) + m2 * glm::dvec3(m.basis2));
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

TEST_F(SharedFormula, SkyModelIsTheSameOnGpuAndCpu) {
  const uint32_t count = 1000;
  std::vector<glm::vec4> pairs = random_pairs(count);
  for (uint32_t i = 0; i < count; ++i) pairs[2 * i + 1].y = std::abs(pairs[2 * i + 1].y);  // sun above
  const render::SkyLight light = render::sky_light({.elevation_deg = 35.0f, .azimuth_deg = 120.0f});
  const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  vk::Buffer in =
      vk::Buffer::create(ctx(), pairs.size() * sizeof(glm::vec4), usage, vk::MemoryUsage::Device, "in");
  vk::Buffer model =
      vk::Buffer::create(ctx(), sizeof(gpu::SkyModelGpu), usage, vk::MemoryUsage::Device, "model");
  vk::Buffer out =
      vk::Buffer::create(ctx(), count * sizeof(glm::vec4), usage, vk::MemoryUsage::Device, "out");
  vk::upload_buffer(ctx(), in, vk::as_bytes_of(pairs));
  vk::upload_buffer(ctx(), model, vk::as_bytes_of(std::vector<gpu::SkyModelGpu>{light.sky_model}));
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx(), shaders::gpu_sky_model_eval_comp);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, eval, {vk::bind(0, in), vk::bind(1, model), vk::bind(2, out)}, count,
                 vk::groups_for(eval, {count, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<glm::vec4> gpu = from_bytes<glm::vec4>(vk::readback_buffer(ctx(), out));
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 d(pairs[2 * i]), s(pairs[2 * i + 1]);
    const glm::dvec3 reference = reference_rgb(light.sky_model, glm::dvec3(d), glm::dvec3(s));
    const glm::vec3 cpu = gpu::sky_model_rgb(light.sky_model, d, s);
    for (int c = 0; c < 3; ++c) {
      ASSERT_GT(reference[c], 0.0) << "a clear sky is never black or negative, at " << i;
      ASSERT_NEAR(cpu[c], reference[c], 2e-5 * reference[c]) << "C++ at " << i << " channel " << c;
      ASSERT_NEAR(gpu[i][c], reference[c], 1e-3 * reference[c]) << "GPU at " << i << " channel " << c;
    }
  }
}

TEST_F(SharedFormula, PbrBrdfIsTheSameOnGpuAndCpu) {
  // shared/pbr.h as the mesh shader compiles it against the C++ the unit tests check (pbr_brdf_test.cpp).
  const uint32_t count = 1000;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> cases;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 n(0, 1, 0);
    const glm::vec3 v = glm::normalize(glm::vec3(u(rng) - 0.5f, 0.05f + u(rng), u(rng) - 0.5f));
    const glm::vec3 l = glm::normalize(glm::vec3(u(rng) - 0.5f, 0.05f + u(rng), u(rng) - 0.5f));
    const float roughness = u(rng);
    const glm::vec2 ab = render::dfg_table().lookup(v.y, roughness);
    cases.insert(cases.end(), {glm::vec4(n, roughness), glm::vec4(v, ab.x), glm::vec4(l, ab.y),
                               glm::vec4(u(rng), u(rng), u(rng), u(rng))});
  }
  const auto usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  vk::Buffer in =
      vk::Buffer::create(ctx(), cases.size() * sizeof(glm::vec4), usage, vk::MemoryUsage::Device, "in");
  vk::Buffer out =
      vk::Buffer::create(ctx(), 2 * count * sizeof(glm::vec4), usage, vk::MemoryUsage::Device, "out");
  vk::upload_buffer(ctx(), in, vk::as_bytes_of(cases));
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx(), shaders::gpu_pbr_eval_comp);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, eval, {vk::bind(0, in), vk::bind(1, out)}, count, vk::groups_for(eval, {count, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<glm::vec4> gpu = from_bytes<glm::vec4>(vk::readback_buffer(ctx(), out));
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec4* c = &cases[4 * i];
    const glm::vec2 ab(c[1].w, c[2].w);
    const glm::vec3 brdf = gpu::pbr_brdf_cos(glm::vec3(c[0]), glm::vec3(c[1]), glm::vec3(c[2]),
                                             glm::vec3(c[3]), c[3].w, c[0].w, ab);
    const glm::vec3 env =
        gpu::pbr_environment(ab, glm::vec3(c[3]), c[3].w, {0.7f, 0.8f, 0.9f}, {0.5f, 0.6f, 0.7f});
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(gpu[2 * i][k], brdf[k], 1e-3f * brdf[k] + 1e-6f) << "BRDF at " << i << " channel " << k;
      ASSERT_NEAR(gpu[2 * i + 1][k], env[k], 1e-4f * env[k] + 1e-6f)
          << "environment at " << i << " channel " << k;
    }
  }
}

TEST(SkyModelIntegral, IsTheUniformSkyOfTheSameIrradiance) {
  // (1/π) ∫ L cos θ dω over the sky, in white units, is the uniform sky of the optics model's E_sky
  // (sky_light.sky_radiance, Φ(E_sky)): the image and the LUTs see the same light (issue 16, 1 %).
  for (float elevation : {5.0f, 30.0f, 60.0f, 89.0f}) {
    const render::SkyLight light = render::sky_light({.elevation_deg = elevation, .azimuth_deg = 40.0f});
    const int n = 90;
    const double pi = 3.14159265358979323846, dt = pi / 2 / n, dp = 2 * pi / (2 * n);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * dt;
      for (int j = 0; j < 2 * n; ++j) {
        const double p = (j + 0.5) * dp;
        const glm::vec3 d(std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p));
        sum += glm::dvec3(gpu::sky_model_rgb(light.sky_model, d, light.sun_direction)) * std::cos(t) *
               std::sin(t) * dt * dp;
      }
    }
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sum[c] / pi, light.sky_radiance[c], 0.01 * light.sky_radiance[c])
          << "elevation " << elevation << " channel " << c;
  }
}

}  // namespace
}  // namespace lagoon::test
