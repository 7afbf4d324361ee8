// Model sines through the FFT ocean's cascades (ocean/sines.h, docs/models.md): the GPU's summed height at
// every texel of the large cascade equals eqs. 2-3 evaluated directly (less the mean level) to 1e-5 m.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/gpu/gpu_ocean.h"
#include "ocean/sines.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using SinesGpu = GpuTest;

TEST_F(SinesGpu, TheCascadesHoldTheSumOfSinesAtEveryTexel) {
  ocean::OceanParams params;
  params.model = ocean::SurfaceModel::Sines;
  params.choppiness = 0;
  params.cascades = {{200, 128}, {20, 128}};
  params.sines.waves = {{0.6, 37, 20, 3, 0}, {0.2, 9.3, -40, 1, 50}, {0.05, 1.9, 75, 2, -120}};
  const auto lattice = ocean::sines_lattice(params);
  ASSERT_EQ(lattice.size(), 3u);
  EXPECT_EQ(lattice[0].wave.cascade, 0);
  EXPECT_EQ(lattice[1].wave.cascade, 0);
  EXPECT_EQ(lattice[2].wave.cascade, 1);
  auto gpu = ocean::GpuOcean::create(ctx(), params);
  ASSERT_TRUE(gpu) << gpu.error().message;
  const double t = 2.9;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
  const ocean::CascadeReadback big = (*gpu)->read_cascade(0), small = (*gpu)->read_cascade(1);
  double worst = 0, largest = 0, horizontal = 0;
  for (uint32_t j = 0; j < 128; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      // Texel (i, j) of the 200 m cascade lies at 1.5625 (i, j) m: texel 10 (i, j) of the 20 m one.
      const size_t a = (size_t(j) * 128 + i) * 4, b = (size_t((10 * j) % 128) * 128 + (10 * i) % 128) * 4;
      const double h = big.displacement[a + 1] + small.displacement[b + 1];
      const double exact = ocean::sines_height(params, t, 1.5625 * i, 1.5625 * j);
      worst = std::max(worst, std::abs(h - exact));
      largest = std::max(largest, std::abs(exact));
      horizontal = std::max(
          {horizontal, double(std::abs(big.displacement[a])), double(std::abs(big.displacement[a + 2]))});
    }
  RecordProperty("worst_height_error_m", std::to_string(worst));
  EXPECT_GT(largest, 0.3);
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(horizontal, 0.0) << "the sines move the surface only vertically";
}

}  // namespace
}  // namespace lagoon::test
