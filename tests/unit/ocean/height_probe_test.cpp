// HeightProbe (compute/ocean/height_probe.h): the height of the displaced surface above one point from the
// largest modes only, against the exact sum of every mode (tests/support/direct_sum.h) with the displacement
// inverted in double, and against WaveQuery on a shipped scene's cascades.
#include "ocean/height_probe.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "ocean/direct_waves.h"
#include "ocean/random_sea.h"
#include "ocean/wave_query.h"
#include "scene/scene.h"
#include "scene/scene_io.h"
#include "support/direct_sum.h"

namespace lagoon::test {
namespace {

// The exact height of the surface point displaced to (x, z): the rest point by fixed-point iteration on the
// full sums of Dx and Dz, then the full sum of the height there.
double exact_height(const std::vector<ocean::CascadeSpectrum>& spectra, double choppiness, double t, double x,
                    double z) {
  glm::dvec2 p(x, z);
  for (int i = 0; i < 40; ++i) {
    const glm::dvec2 d(direct_sum(spectra, ocean::Field::Dx, t, p.x, p.y),
                       direct_sum(spectra, ocean::Field::Dz, t, p.x, p.y));
    const glm::dvec2 next = glm::dvec2(x, z) - choppiness * d;
    if (glm::length(next - p) < 1e-9) break;
    p = next;
  }
  return direct_sum(spectra, ocean::Field::Height, t, p.x, p.y);
}

TEST(HeightProbe, MatchesTheExactSumWithinItsBound) {
  ocean::OceanParams params;
  params.choppiness = 1.0;
  params.cascades = {{200.0, 64}, {30.0, 64}};
  const auto spectra = ocean::make_cascade_spectra(params);
  const ocean::HeightProbe probe(params, spectra, 0.01);
  EXPECT_LT(probe.modes(), 2u * 64 * 64) << "no mode was left out";
  double worst = 0, spread = 0;
  for (int i = 0; i < 12; ++i) {
    const double t = 3.0 + 1.7 * i, x = 23.1 * i - 40.0, z = 7.3 * i * i - 90.0;
    const double exact = exact_height(spectra, params.choppiness, t, x, z);
    const ocean::HeightProbe::Answer answer = probe.height(t, x, z);
    EXPECT_TRUE(answer.converged);
    EXPECT_LE(std::abs(answer.height - exact), answer.error_bound_m) << "point " << i;
    worst = std::max(worst, std::abs(answer.height - exact));
    spread = std::max(spread, std::abs(exact));
  }
  EXPECT_LE(probe.height(0, 0, 0).error_bound_m, 0.01);
  EXPECT_GT(spread, 0.3) << "a sea too calm to tell anything";
  std::printf("HeightProbe: %zu of %d modes, worst error %.2e m, bound %.2e m, heights up to %.2f m\n",
              probe.modes(), 2 * 64 * 64, worst, probe.height(0, 0, 0).error_bound_m, spread);
}

TEST(HeightProbe, AgreesWithWaveQueryOnTheShippedScenes) {
  for (const char* name : {"default", "open-ocean"}) {
    SCOPED_TRACE(name);
    auto s = scene::load_scene(std::string(LAGOON_SOURCE_DIR) + "/scenes/" + name + ".json", {});
    ASSERT_TRUE(s) << s.error().message;
    const auto spectra = ocean::make_cascade_spectra(s->ocean);
    const ocean::HeightProbe probe(s->ocean, spectra, 0.01);
    ocean::WaveQuery query(s->ocean, spectra);
    // Over the default scene's floor, the cascades read where their lattices have moved, as the camera's
    // side of the water asks (world/camera_medium.h).
    const auto floor = ocean::sea_over_floor(s->ocean, ocean::random_sea(s->ocean, spectra));
    EXPECT_EQ(floor != nullptr, std::string(name) == "default");
    double worst = 0, probe_ms = 0;
    for (int i = 0; i < 6; ++i) {
      const double t = 2.0 + 0.9 * i, x = 13.0 * i, z = -5.0 * i;
      const auto start = std::chrono::steady_clock::now();
      ocean::HeightProbe::Answer answer = probe.height(t, x, z, floor.get());
      if (floor) answer.height *= floor->ground({x, z}).y;
      probe_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      const ocean::WaveSample sample = query.sample(t, x, z);
      EXPECT_LE(std::abs(answer.height - sample.height), answer.error_bound_m + sample.error_bound_m);
      worst = std::max(worst, std::abs(answer.height - sample.height));
    }
    std::printf("%s: %zu modes kept, bound %.3f m, worst difference from WaveQuery %.2e m, %.2f ms a query\n",
                name, probe.modes(), probe.height(0, 0, 0).error_bound_m, worst, probe_ms / 6);
  }
}

}  // namespace
}  // namespace lagoon::test
