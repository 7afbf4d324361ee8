// Model gerstner on the GPU (docs/models.md). A scene's own waves are summed directly: the step's layer at
// every texel equals eq. 11 in double precision (GerstnerSurface) for the exact waves, each with its own
// steepness. Waves sampled from the spectrum go through the cascades on their lattice, and there the FFT
// equals the direct sum of those lattice waves to 1e-5 m.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/packing.hpp>
#include <numbers>

#include "ocean/gerstner.h"
#include "ocean/gpu/gpu_ocean.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

ocean::OceanParams gerstner_ocean() {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Gerstner;
  p.choppiness = 0.9;
  p.cascades = {{200, 128}, {20, 128}};
  // The first two with their own steepness, the third with choppiness.
  p.gerstner.waves = {{0.6, 37, 20, 30, 0.95}, {0.2, 9.3, -40, 100, 0.2}, {0.03, 1.7, 75, 10}};
  return p;
}

// The scene's waves written out here as eq. 11 takes them (not through the code under test).
ocean::GerstnerParams exact_waves() {
  constexpr double kRad = std::numbers::pi / 180;
  return {.waves = {{0.6, 37, 20, 30 * kRad, 0.95},
                    {0.2, 9.3, -40, 100 * kRad, 0.2},
                    {0.03, 1.7, 75, 10 * kRad, 0.9}},
          .limit_steepness = false};
}

using GerstnerGpu = GpuTest;

TEST_F(GerstnerGpu, TheStepHoldsEquationElevenOfTheExactWavesAtEveryTexel) {
  const ocean::OceanParams params = gerstner_ocean();
  auto gpu = ocean::GpuOcean::create(ctx(), params);
  ASSERT_TRUE(gpu) << gpu.error().message;
  ASSERT_NE((*gpu)->direct_waves(), nullptr);
  const double t = 3.7;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
  const ocean::CascadeReadback big = (*gpu)->read_cascade(0), small = (*gpu)->read_cascade(1);
  const ocean::GerstnerSurface cpu(exact_waves());
  double worst = 0, worst_jacobian = 0, largest = 0, second = 0;
  for (uint32_t j = 0; j < 128; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      const size_t a = (size_t(j) * 128 + i) * 4;
      const glm::dvec3 gpu_d(big.displacement[a], big.displacement[a + 1], big.displacement[a + 2]);
      const glm::dvec2 x0 = 1.5625 * glm::dvec2(i, j);  // texel (i, j) of the 200 m cascade
      const ocean::GerstnerPoint p = cpu.at_rest(x0, t);
      const glm::dvec3 cpu_d = p.position - glm::dvec3(x0.x, 0, x0.y);
      worst = std::max(worst, glm::length(gpu_d - cpu_d));
      largest = std::max(largest, glm::length(cpu_d));
      const double jxx = big.jacobian_terms[a], jzz = big.jacobian_terms[a + 1],
                   jxz = big.jacobian_terms[a + 2];
      worst_jacobian = std::max(worst_jacobian, std::abs((1 + jxx) * (1 + jzz) - jxz * jxz - p.jacobian));
      second = std::max(
          {second, double(std::abs(small.displacement[a])), double(std::abs(small.displacement[a + 1]))});
    }
  RecordProperty("worst_displacement_error_m", std::to_string(worst));
  RecordProperty("worst_jacobian_error", std::to_string(worst_jacobian));
  EXPECT_GT(largest, 0.5);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worst_jacobian, 3e-3);  // the terms are half floats
  EXPECT_EQ(second, 0.0) << "the other cascades hold still water";
}

TEST_F(GerstnerGpu, WavesFromTheSpectrumGoThroughTheCascadesAndEqualTheirDirectSum) {
  ocean::OceanParams params = gerstner_ocean();
  params.choppiness = 0.5;
  params.gerstner.spectrum_waves = 24;
  std::vector<int> cascade_of;
  const auto waves = ocean::lattice_gerstner_waves(params, &cascade_of);
  ASSERT_EQ(waves.size(), 24u);
  auto gpu = ocean::GpuOcean::create(ctx(), params);
  ASSERT_TRUE(gpu) << gpu.error().message;
  ASSERT_EQ((*gpu)->direct_waves(), nullptr);
  const double t = 3.7;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
  const ocean::CascadeReadback big = (*gpu)->read_cascade(0), small = (*gpu)->read_cascade(1);
  const ocean::GerstnerSurface cpu(ocean::gerstner_params(params));
  double worst = 0, largest = 0;
  for (uint32_t j = 0; j < 128; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      // Texel (i, j) of the 200 m cascade rests at 1.5625 (i, j) m: texel 10 (i, j) of the 20 m one.
      const size_t a = (size_t(j) * 128 + i) * 4, b = (size_t((10 * j) % 128) * 128 + (10 * i) % 128) * 4;
      const glm::dvec3 gpu_d(big.displacement[a] + small.displacement[b],
                             big.displacement[a + 1] + small.displacement[b + 1],
                             big.displacement[a + 2] + small.displacement[b + 2]);
      const glm::dvec2 x0 = 1.5625 * glm::dvec2(i, j);
      const glm::dvec3 cpu_d = cpu.at_rest(x0, t).position - glm::dvec3(x0.x, 0, x0.y);
      worst = std::max(worst, glm::length(gpu_d - cpu_d));
      largest = std::max(largest, glm::length(cpu_d));
    }
  RecordProperty("worst_displacement_error_m", std::to_string(worst));
  EXPECT_GT(largest, 0.2);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace lagoon::test
