// Model perlin on the GPU (ocean/perlin.h): at t = 0 the cascade's height is the noise less its mean, and at
// a later time it is what the CPU's evaluation of the same modes (WaveQuery) gives, to 1e-5 m.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/gpu/gpu_ocean.h"
#include "ocean/perlin.h"
#include "ocean/wave_query.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

using PerlinGpu = GpuTest;

TEST_F(PerlinGpu, TheCascadeHoldsTheNoiseAndEvolvesItLikeTheCpu) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Perlin;
  p.choppiness = 0;
  p.cascades = {{200, 128}};
  p.perlin = {.amplitude_m = 0.8, .cells = 8, .octaves = 3, .persistence = 0.5, .lacunarity = 2};
  ocean::WaveQuery query(p);
  double mean = 0;
  for (int j = 0; j < 128; ++j)
    for (int i = 0; i < 128; ++i)
      mean += ocean::perlin_height(p, 200.0 * i / 128, 200.0 * j / 128) / (128 * 128);
  for (double t : {0.0, 2.5}) {
    auto gpu = ocean::GpuOcean::create(ctx(), p);
    ASSERT_TRUE(gpu) << gpu.error().message;
    ctx().submit_and_wait([&](VkCommandBuffer cmd) { (*gpu)->record_step(cmd, t, 0.0); });
    const ocean::CascadeReadback r = (*gpu)->read_cascade(0);
    double worst = 0;
    for (int j = 0; j < 128; j += 3)
      for (int i = 0; i < 128; i += 2) {
        const double x = 200.0 * i / 128, z = 200.0 * j / 128;
        const double expected = t == 0 ? ocean::perlin_height(p, x, z) - mean : query.sample(t, x, z).height;
        worst = std::max(worst, std::abs(r.displacement[(size_t(j) * 128 + i) * 4 + 1] - expected));
      }
    RecordProperty("worst_height_error_m_t" + std::to_string(int(t * 10)), std::to_string(worst));
    EXPECT_LT(worst, 1e-5) << "t = " << t;
  }
}

}  // namespace
}  // namespace lagoon::test
