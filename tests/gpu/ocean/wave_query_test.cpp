// WaveQuery against the GPU's fields: at surface points the GPU computed (rest lattice points common to
// every cascade, displaced), the query must give the GPU's height within its stated bound.
#include "ocean/wave_query.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>

#include "ocean/gpu/gpu_ocean.h"
#include "support/direct_sum.h"
#include "support/vk_fixture.h"

namespace lagoon::test {
namespace {

class WaveQueryTest : public GpuTest {};

TEST(CatmullRom, ErrorGrowsWithFrequencyAndVanishesAtZero) {
  EXPECT_LT(ocean::catmull_rom_exponential_error(0.0), 1e-12);
  EXPECT_LT(ocean::catmull_rom_exponential_error(0.1), ocean::catmull_rom_exponential_error(0.5));
  EXPECT_LT(ocean::catmull_rom_exponential_error(M_PI / 2), 0.15);  // 4 texels per wave: ~12 %
  EXPECT_NEAR(ocean::catmull_rom_lebesgue_constant(), 1.25, 0.01);
}

TEST_F(WaveQueryTest, MatchesGpuFieldsWithinItsBound) {
  ocean::OceanParams params;
  params.choppiness = 0.8;
  params.cascades = {{512.0, 128}, {64.0, 128}, {8.0, 128}};
  const double t = 4.5;
  ocean::GpuOcean gpu_ocean(ctx(), params);
  ctx().submit_and_wait([&](VkCommandBuffer cmd) { gpu_ocean.record_step(cmd, t, 0.0); });
  std::vector<ocean::CascadeReadback> fields;
  for (uint32_t c = 0; c < 3; ++c) fields.push_back(gpu_ocean.read_cascade(c));

  // Rest points on the coarsest grid are texel centres of every cascade (512/128 = 8·(64/128) = 64·(8/128)).
  std::vector<glm::dvec2> queries;
  std::vector<double> expected;
  const double texel0 = 512.0 / 128;
  for (int j = 0; j < 128; j += 3)
    for (int i = 0; i < 128; i += 5) {
      const glm::dvec2 rest(i * texel0, j * texel0);
      glm::dvec2 displaced = rest;
      double height = 0;
      for (uint32_t c = 0; c < 3; ++c) {
        const double texel = params.cascades[c].patch_size_m / 128;
        const int x = int(std::lround(rest.x / texel)) & 127, z = int(std::lround(rest.y / texel)) & 127;
        const float* d = &fields[c].displacement[(size_t(z) * 128 + x) * 4];
        displaced += glm::dvec2(d[0], d[2]);
        height += d[1];
      }
      queries.push_back(displaced);
      expected.push_back(height);
    }
  ocean::WaveQuery query(params, gpu_ocean.spectra());
  const auto samples = query.sample(t, queries);
  double worst = 0, rms = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    ASSERT_TRUE(samples[i].converged) << i;
    const double error = std::abs(samples[i].height - expected[i]);
    worst = std::max(worst, error);
    rms += error * error;
    ASSERT_LE(error, samples[i].error_bound_m) << "point " << i;
  }
  rms = std::sqrt(rms / samples.size());
  const double bound = samples[0].error_bound_m;
  // The bound must be useful, not just true: below a tenth of the significant wave height.
  double hs = 0;
  for (double h : expected) hs += h * h;
  hs = 4 * std::sqrt(hs / expected.size());
  EXPECT_LT(bound, 0.1 * hs) << "bound " << bound << " m vs Hs " << hs << " m";
  RecordProperty("worst_error_m", std::to_string(worst));
  RecordProperty("rms_error_m", std::to_string(rms));
  RecordProperty("bound_m", std::to_string(bound));
  std::printf("WaveQuery vs GPU: %zu points, worst %.2e m, rms %.2e m, bound %.2e m, Hs %.2f m\n",
              samples.size(), worst, rms, bound, hs);
}

// Off the grids, against the exact sum of every mode: interpolation error within the stated bound, and
// normal and velocity right. No choppiness, so the rest point is the query point.
TEST(WaveQueryExact, ArbitraryPointsWithinTheBound) {
  ocean::OceanParams params;
  params.choppiness = 0;
  params.cascades = {{400.0, 64}, {40.0, 64}};
  ocean::WaveQuery query(params);
  std::vector<ocean::CascadeSpectrum> spectra;
  for (uint32_t c = 0; c < 2; ++c) spectra.push_back(ocean::make_cascade_spectrum(params, c));
  const double t = 7.25;
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 60; ++i) points.push_back({37.3 * i + 0.17 * i * i, 11.9 * i - 0.31 * i * i});
  const auto samples = query.sample(t, points);
  double worst = 0, worst_normal = 0, worst_velocity = 0, hs = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double x = points[i].x, z = points[i].y;
    const double h = direct_sum(spectra, ocean::Field::Height, t, x, z);
    const double sx = direct_sum(spectra, ocean::Field::SlopeX, t, x, z);
    const double sz = direct_sum(spectra, ocean::Field::SlopeZ, t, x, z);
    const double vy = direct_sum(spectra, ocean::Field::VelocityY, t, x, z);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(-sx, 1, -sz));
    const double error = std::abs(samples[i].height - h);
    ASSERT_LE(error, samples[i].error_bound_m) << "point " << i;
    worst = std::max(worst, error);
    worst_normal = std::max(worst_normal, glm::length(samples[i].normal - normal));
    worst_velocity = std::max(worst_velocity, std::abs(samples[i].velocity.y - vy));
    hs += h * h;
  }
  hs = 4 * std::sqrt(hs / points.size());
  const double bound = samples[0].error_bound_m;
  EXPECT_LT(bound, 0.1 * hs) << "the bound " << bound << " m is too loose to be useful (Hs " << hs << " m)";
  EXPECT_LT(query.worst_case_bound_m(), 10 * hs);
  EXPECT_LT(worst_normal, 0.05);
  EXPECT_LT(worst_velocity, 0.1 * hs);
  std::printf(
      "WaveQuery vs exact sum: worst height error %.3e m, bound %.3e m (rigorous %.3e m), Hs %.2f m, "
      "worst normal error %.3f, worst vertical velocity error %.3e m/s\n",
      worst, bound, query.worst_case_bound_m(), hs, worst_normal, worst_velocity);
}

}  // namespace
}  // namespace lagoon::test
