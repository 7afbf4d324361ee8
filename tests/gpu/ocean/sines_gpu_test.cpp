// Model sines on the GPU (docs/models.md): a scene's own waves are summed directly, and the step's layer at
// every texel equals eqs. 2-3 for the exact waves (less the mean level), written out here, to 1e-5 m.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/gpu/gpu_ocean.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using SinesGpu = GpuTest;

// Eq. 2 for one wave at S, less its mean level C(2p, p)/4^p.
double sine_wave(double amplitude, double s, int p) {
  double mean = 1;
  for (int j = 1; j <= p; ++j) mean *= double(p + j) / double(j) / 4.0;
  return amplitude * (std::pow(0.5 * (1 + std::sin(s)), p) - mean);
}

TEST_F(SinesGpu, TheStepHoldsTheSumOfTheExactSinesAtEveryTexel) {
  ocean::OceanParams params;
  params.model = ocean::SurfaceModel::Sines;
  params.choppiness = 0;
  params.cascades = {{200, 128}, {20, 128}};
  struct Wave {
    double a, length, direction, phase;
    int p;
  };
  const Wave waves[] = {{0.6, 37, 20, 0, 3}, {0.2, 9.3, -40, 50, 1}, {0.05, 1.9, 75, -120, 2}};
  params.sines.waves.clear();
  for (const Wave& w : waves)
    params.sines.waves.push_back({w.a, w.length, w.direction, uint32_t(w.p), w.phase});
  auto gpu = ocean::GpuOcean::create(ctx(), params);
  ASSERT_TRUE(gpu) << gpu.error().message;
  const double t = 2.9;
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
  const ocean::CascadeReadback big = (*gpu)->read_cascade(0);
  double worst = 0, largest = 0, horizontal = 0;
  constexpr double kRad = std::numbers::pi / 180;
  for (uint32_t j = 0; j < 128; ++j)
    for (uint32_t i = 0; i < 128; ++i) {
      const size_t a = (size_t(j) * 128 + i) * 4;
      const double x = 1.5625 * i, z = 1.5625 * j;
      double exact = 0;
      for (const Wave& w : waves) {
        // Compass: clockwise from north (-z) toward east (+x); deep water ω = sqrt(g k).
        const double k = 2 * std::numbers::pi / w.length, omega = std::sqrt(9.81 * k);
        const double s = k * (x * std::sin(w.direction * kRad) - z * std::cos(w.direction * kRad)) -
                         omega * t + w.phase * kRad;
        exact += sine_wave(w.a, s, w.p);
      }
      worst = std::max(worst, std::abs(big.displacement[a + 1] - exact));
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
