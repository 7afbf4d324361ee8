// Perlin noise as a surface model (ocean/perlin.h; seed 001 §1.1.1, issue 15): each octave's variance is
// persistence² of the one before, the field tiles on the first cascade's patch, and through the cascades the
// surface at t = 0 is the noise less its mean, with zero mean.
#include "ocean/perlin.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ocean/wave_query.h"

namespace lagoon::test {
namespace {

ocean::OceanParams perlin_ocean() {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Perlin;
  p.choppiness = 0;
  p.cascades = {{200, 256}};
  p.perlin = {.amplitude_m = 0.8, .cells = 8, .octaves = 4, .persistence = 0.6, .lacunarity = 2};
  return p;
}

TEST(Perlin, EachOctavesVarianceIsPersistenceSquaredOfThePrevious) {
  const ocean::OceanParams p = perlin_ocean();
  double variance[4] = {};
  const int n = 512;
  for (uint32_t o = 0; o < 4; ++o) {
    double sum = 0, sum2 = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double h = ocean::perlin_octave(p, o, 200.0 * (i + 0.37) / n, 200.0 * (j + 0.61) / n);
        sum += h;
        sum2 += h * h;
      }
    variance[o] = sum2 / (n * n) - std::pow(sum / (n * n), 2);
  }
  for (uint32_t o = 0; o + 1 < 4; ++o) {
    RecordProperty("variance_ratio_" + std::to_string(o), std::to_string(variance[o + 1] / variance[o]));
    EXPECT_NEAR(variance[o + 1] / variance[o], 0.36, 0.05 * 0.36) << "octave " << o;
  }
}

TEST(Perlin, TheFieldTilesOnThePatch) {
  const ocean::OceanParams p = perlin_ocean();
  for (double x : {0.3, 17.7, 123.4})
    for (double z : {-5.5, 66.1}) {
      EXPECT_NEAR(ocean::perlin_height(p, x + 200, z), ocean::perlin_height(p, x, z), 1e-12);
      EXPECT_NEAR(ocean::perlin_height(p, x, z - 400), ocean::perlin_height(p, x, z), 1e-12);
    }
  EXPECT_GT(std::abs(ocean::perlin_height(p, 17.7, 66.1) - ocean::perlin_height(p, 117.7, 66.1)), 1e-3);
}

TEST(Perlin, ThroughTheCascadesTheSurfaceIsTheNoiseLessItsMean) {
  const ocean::OceanParams p = perlin_ocean();
  ocean::WaveQuery query(p);
  // The mean over the cascade's grid, which the model takes out.
  double mean = 0;
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i)
      mean += ocean::perlin_height(p, 200.0 * i / 256, 200.0 * j / 256) / (256 * 256);
  double worst = 0, grid_mean = 0;
  for (int j = 0; j < 256; j += 5)
    for (int i = 0; i < 256; i += 3) {
      const double x = 200.0 * i / 256, z = 200.0 * j / 256;  // grid points: no interpolation error
      worst =
          std::max(worst, std::abs(query.sample(0.0, x, z).height - (ocean::perlin_height(p, x, z) - mean)));
    }
  for (int j = 0; j < 256; ++j)
    for (int i = 0; i < 256; ++i)
      grid_mean += query.sample(0.0, 200.0 * i / 256, 200.0 * j / 256).height / (256 * 256);
  RecordProperty("worst_height_error_m", std::to_string(worst));
  EXPECT_LT(worst, 1e-6);
  EXPECT_NEAR(grid_mean, 0.0, 1e-9);
  EXPECT_GT(std::abs(mean), 0.0);
}

}  // namespace
}  // namespace lagoon::test
