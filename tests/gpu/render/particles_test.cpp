// The suspended particles (seed 002; common/particle_candidate.glsl, common/simplex4.glsl) against what the
// scene asks and an independent reference: the 4-D simplex noise against Gustavson's algorithm written out
// here in double precision; the number of particles per cubic metre against underwater.particles's density;
// their motion between two times against its drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "lagoon_test_shaders/shaders.h"
#include "render/passes/particles_pass.h"
#include "shared/sediment.h"
#include "support/particle_candidates.h"
#include "support/vk_fixture.h"
#include "vk/barriers.h"
#include "vk/pipeline.h"
#include "vk/transfer.h"

namespace lagoon::test {
namespace {

// Simplex noise in 4-D as Gustavson ("Simplex noise demystified", 2005) describes it, in double: skew to the
// hypercubic lattice, find the simplex by ordering the offset's coordinates (largest first; here a sort, not
// the shader's rank counting), sum the five corners' (0.6 - |x|²)⁴ (g · x). The gradients are the shader's
// by definition: an integer hash (lowbias32) of the corner and the seed picks one of the 32 (0, ±1, ±1, ±1).
uint32_t lowbias32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

std::array<double, 4> gradient(std::array<int, 4> corner, uint32_t seed) {
  uint32_t h = lowbias32(uint32_t(corner[0]) ^ lowbias32(seed));
  for (int a = 1; a < 4; ++a) h = lowbias32(h ^ uint32_t(corner[a]));
  std::array<double, 4> g{};
  const int zero = int(h & 3u);
  int bit = 2;
  for (int a = 0; a < 4; ++a)
    if (a != zero) g[a] = ((h >> bit++) & 1u) ? 1.0 : -1.0;
  return g;
}

double reference_simplex4(std::array<double, 4> p, uint32_t seed) {
  const double f4 = (std::sqrt(5.0) - 1) / 4, g4 = (5 - std::sqrt(5.0)) / 20;
  const double skew = (p[0] + p[1] + p[2] + p[3]) * f4;
  std::array<int, 4> cell{};
  for (int a = 0; a < 4; ++a) cell[a] = int(std::floor(p[a] + skew));
  const double unskew = (cell[0] + cell[1] + cell[2] + cell[3]) * g4;
  std::array<double, 4> x0{};
  for (int a = 0; a < 4; ++a) x0[a] = p[a] - (cell[a] - unskew);
  std::array<int, 4> order{0, 1, 2, 3};  // axes by decreasing offset; ties to the lower axis
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return x0[a] > x0[b]; });
  double sum = 0;
  std::array<int, 4> step{};  // the corner's lattice offset from `cell`
  for (int k = 0; k <= 4; ++k) {
    if (k > 0) step[order[k - 1]] = 1;
    std::array<double, 4> x{};
    std::array<int, 4> corner{};
    double r2 = 0;
    for (int a = 0; a < 4; ++a) {
      x[a] = x0[a] - step[a] + k * g4;
      corner[a] = cell[a] + step[a];
      r2 += x[a] * x[a];
    }
    const double t = 0.6 - r2;
    if (t <= 0) continue;
    const std::array<double, 4> g = gradient(corner, seed);
    sum += t * t * t * t * (g[0] * x[0] + g[1] * x[1] + g[2] * x[2] + g[3] * x[3]);
  }
  return 27 * sum;
}

constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
constexpr uint32_t kCandidates = kParticleCandidates;

class Particles : public GpuTest {
 protected:
  std::vector<glm::vec4> candidates(const scene::Scene& scene) { return particle_candidates(ctx(), scene); }
};

TEST_F(Particles, TheSimplexNoiseIsGustavsonsAlgorithm) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-40.0f, 40.0f);
  std::vector<glm::vec4> points(20000);
  for (glm::vec4& p : points) p = {u(rng), u(rng), u(rng), u(rng)};
  for (int i = 0; i < 200; ++i) points[i] = glm::vec4(float(i % 7), float(i / 7 % 5), -float(i % 3), 0.5f);
  const uint32_t count = uint32_t(points.size()), seed = 7;
  vk::Buffer in = vk::Buffer::create(ctx(), count * sizeof(glm::vec4), kUsage, vk::MemoryUsage::Device, "in");
  vk::Buffer out = vk::Buffer::create(ctx(), count * sizeof(float), kUsage, vk::MemoryUsage::Device, "out");
  vk::upload_buffer(ctx(), in, vk::as_bytes_of(points));
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx(), shaders::gpu_simplex4_eval_comp);
  const std::array<uint32_t, 2> push{count, seed};
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, eval, {vk::bind(0, in), vk::bind(1, out)}, push, vk::groups_for(eval, {count, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<float> gpu = from_bytes<float>(vk::readback_buffer(ctx(), out));
  double worst = 0, sum = 0, sum2 = 0, largest = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec4 p = points[i];
    const double ref = reference_simplex4({p.x, p.y, p.z, p.w}, seed);
    worst = std::max(worst, std::abs(gpu[i] - ref));
    sum += ref, sum2 += ref * ref, largest = std::max(largest, std::abs(ref));
  }
  const double mean = sum / count, deviation = std::sqrt(sum2 / count - mean * mean);
  RecordProperty("worst_error", std::to_string(worst));
  RecordProperty("mean_deviation_largest",
                 std::to_string(mean) + " " + std::to_string(deviation) + " " + std::to_string(largest));
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(std::abs(mean), 0.01);  // gradient noise has no bias
  EXPECT_GT(deviation, 0.1);        // and is not flat
  EXPECT_LE(largest, 1.0);          // the 27 keeps it within [-1, 1]
  // Another seed is another field.
  EXPECT_GT(
      std::abs(reference_simplex4({0.3, 1.7, -2.2, 0.9}, 7) - reference_simplex4({0.3, 1.7, -2.2, 0.9}, 8)),
      1e-3);
}

// Camera positions deep under water, far apart: each lattice holds independent clouds of the noise.
scene::Scene deep_scene(float density, glm::vec3 camera) {
  scene::Scene s;
  s.underwater.particles.density_per_m3 = density;
  s.camera.position = camera;
  return s;
}

TEST_F(Particles, TheyAreAsDenseAsTheSceneAsks) {
  for (const float density : {20.0f, 100.0f, 2.0f}) {
    double kept = 0, volume = 0;
    for (int k = 0; k < 12; ++k) {
      scene::Scene s = deep_scene(density, glm::vec3(137.0f * k, -60.0f - 7.0f * k, -91.0f * k));
      s.time_s = 13.0 * k;
      const gpu::ParticlesPush push = render::particles_push(s);
      for (const glm::vec4& c : candidates(s)) kept += c.w;
      volume += double(kCandidates) * push.lattice.w * push.lattice.w * push.lattice.w;
    }
    const double measured = kept / volume;
    RecordProperty("density_" + std::to_string(int(density)), std::to_string(measured));
    EXPECT_NEAR(measured, density, 0.05 * density) << "asked " << density << " per cubic metre";
  }
}

TEST_F(Particles, TheyMoveWithTheDrift) {
  scene::Scene s = deep_scene(20.0f, glm::vec3(3.0f, -30.0f, 5.0f));
  s.underwater.particles.drift_mps = {0.03f, 0.005f, -0.02f};
  s.time_s = 10.0;
  const std::vector<glm::vec4> before = candidates(s);
  const double dt = 0.25;
  s.time_s += dt;
  const std::vector<glm::vec4> after = candidates(s);
  const double cell = render::particles_push(s).lattice.w;
  const glm::dvec3 expected = glm::dvec3(s.underwater.particles.drift_mps) * dt;
  double worst = 0;
  for (uint32_t i = 0; i < kCandidates; ++i) {
    // A candidate that crosses its cell's side comes back in at the other (every cell keeps one).
    glm::dvec3 r = glm::dvec3(after[i]) - glm::dvec3(before[i]) - expected;
    r -= cell * glm::round(r / cell);
    worst = std::max(worst, glm::length(r));
  }
  RecordProperty("worst_error_m", std::to_string(worst));
  EXPECT_LT(worst, 5e-5);  // of a 7.5 mm step; floats at 30 m resolve 2e-6 m
}

// Seed 002 §3.4's sediment particles: the grains of a cloud sample its Gaussian (the same cloud the
// turbidity integrates), as many as the renderer asks, the same each time for the same release.
TEST_F(Particles, SedimentGrainsSampleTheirCloudsGaussian) {
  constexpr uint32_t kClouds = 64, kPer = LAGOON_SEDIMENT_MAX_GRAINS;
  const glm::vec3 centre(2.0f, -5.0f, -3.0f);
  const float sigma = 0.7f;
  std::vector<gpu::SedimentPuffGpu> puffs(kClouds);
  for (uint32_t i = 0; i < kClouds; ++i)
    puffs[i] = {
        .centre_sigma = glm::vec4(centre, sigma),
        .strength = glm::vec4(1.0f, i == 0 ? 10.0f : float(kPer), std::bit_cast<float>(i * 7919u + 1u), 0)};
  vk::Buffer in = vk::Buffer::create(ctx(), kClouds * sizeof(gpu::SedimentPuffGpu), kUsage,
                                     vk::MemoryUsage::Device, "puffs");
  vk::Buffer out = vk::Buffer::create(ctx(), kClouds * kPer * sizeof(glm::vec4), kUsage,
                                      vk::MemoryUsage::Device, "grains");
  vk::upload_buffer(ctx(), in, vk::as_bytes_of(puffs));
  const vk::ComputePipeline eval = vk::ComputePipeline::create(ctx(), shaders::gpu_sediment_grains_eval_comp);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) {
    vk::memory_barrier(cmd, vk::access::kTransferWrite, vk::access::kComputeReadWrite);
    vk::dispatch(cmd, eval, {vk::bind(0, in), vk::bind(1, out)}, kClouds,
                 vk::groups_for(eval, {kClouds * kPer, 1, 1}));
    vk::memory_barrier(cmd, vk::access::kComputeWrite, vk::access::kTransferRead);
  });
  const std::vector<glm::vec4> grains = from_bytes<glm::vec4>(vk::readback_buffer(ctx(), out));
  int first = 0;
  for (uint32_t j = 0; j < kPer; ++j) first += grains[j].w > 0 ? 1 : 0;
  EXPECT_EQ(first, 10) << "the first cloud asks for 10 grains";
  glm::dvec3 sum(0.0), sum2(0.0);
  double n = 0;
  for (uint32_t i = kPer; i < kClouds * kPer; ++i) {
    ASSERT_GT(grains[i].w, 0.0f);
    const glm::dvec3 d = glm::dvec3(grains[i]) - glm::dvec3(centre);
    sum += d, sum2 += d * d, n += 1;
  }
  const glm::dvec3 mean = sum / n, deviation = glm::sqrt(sum2 / n - mean * mean);
  RecordProperty("mean_m",
                 std::to_string(mean.x) + " " + std::to_string(mean.y) + " " + std::to_string(mean.z));
  RecordProperty("deviation_m", std::to_string(deviation.x) + " " + std::to_string(deviation.y) + " " +
                                    std::to_string(deviation.z));
  for (int a = 0; a < 3; ++a) {
    EXPECT_LT(std::abs(mean[a]), 0.06 * sigma) << "axis " << a;  // 3 standard errors of 4032 grains
    EXPECT_NEAR(deviation[a], sigma, 0.05 * sigma) << "axis " << a;
  }
}

}  // namespace
}  // namespace lagoon::test
