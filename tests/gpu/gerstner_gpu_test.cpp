// Model gerstner through the FFT ocean's cascades (ocean/gerstner.h, docs/models.md): the GPU's summed
// displacement and Jacobian at every texel of the large cascade equal eq. 11 evaluated in double precision
// (GerstnerSurface) for the lattice waves.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/packing.hpp>

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
  p.gerstner.waves = {{0.6, 37, 20, 30}, {0.2, 9.3, -40, 100}, {0.03, 1.7, 75, 10}};
  return p;
}

using GerstnerGpu = GpuTest;

TEST_F(GerstnerGpu, TheCascadesHoldEquationElevenAtEveryTexel) {
  const ocean::OceanParams params = gerstner_ocean();
  std::vector<int> cascade_of;
  const auto waves = ocean::lattice_gerstner_waves(params, &cascade_of);
  EXPECT_EQ(cascade_of, (std::vector<int>{0, 0, 1}));
  for (size_t i = 0; i < waves.size(); ++i)  // moved to the lattice by less than half a lattice step
    EXPECT_NEAR(waves[i].wavelength_m, params.gerstner.waves[i].wavelength_m,
                0.05 * params.gerstner.waves[i].wavelength_m);
  auto gpu = ocean::GpuOcean::create(ctx(), params);
  ASSERT_TRUE(gpu) << gpu.error().message;
  const double t = 3.7;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
  const ocean::CascadeReadback big = (*gpu)->read_cascade(0), small = (*gpu)->read_cascade(1);
  const ocean::GerstnerSurface cpu(ocean::gerstner_params(params));
  double worst = 0, worst_jacobian = 0, largest = 0;
  for (uint32_t j = 0; j < 128; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      // Texel (i, j) of the 200 m cascade rests at 1.5625 (i, j) m: texel 10 (i, j) of the 20 m one.
      const size_t a = (size_t(j) * 128 + i) * 4, b = (size_t((10 * j) % 128) * 128 + (10 * i) % 128) * 4;
      const glm::dvec3 gpu_d(big.displacement[a] + small.displacement[b],
                             big.displacement[a + 1] + small.displacement[b + 1],
                             big.displacement[a + 2] + small.displacement[b + 2]);
      const glm::dvec2 x0 = 1.5625 * glm::dvec2(i, j);
      const ocean::GerstnerPoint p = cpu.at_rest(x0, t);
      const glm::dvec3 cpu_d = p.position - glm::dvec3(x0.x, 0, x0.y);
      worst = std::max(worst, glm::length(gpu_d - cpu_d));
      largest = std::max(largest, glm::length(cpu_d));
      const double jxx = big.jacobian_terms[a] + small.jacobian_terms[b],
                   jzz = big.jacobian_terms[a + 1] + small.jacobian_terms[b + 1],
                   jxz = big.jacobian_terms[a + 2] + small.jacobian_terms[b + 2];
      worst_jacobian = std::max(worst_jacobian, std::abs((1 + jxx) * (1 + jzz) - jxz * jxz - p.jacobian));
    }
  RecordProperty("worst_displacement_error_m", std::to_string(worst));
  RecordProperty("worst_jacobian_error", std::to_string(worst_jacobian));
  EXPECT_GT(largest, 0.5);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worst_jacobian, 3e-3);  // the terms are half floats
}

}  // namespace
}  // namespace lagoon::test
