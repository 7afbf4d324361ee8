// Where the sea makes foam (ocean/whitecaps.h): Monahan & O'Muircheartaigh's coverage law, the threshold
// rule a scene that sets foam.threshold keeps, and the coverage rule's onset against the sea's own Jacobian
// computed here independently (CPU reference step, ocean/cpu_step.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ocean/cpu_step.h"
#include "ocean/initial_spectrum.h"
#include "ocean/whitecaps.h"

namespace lagoon::ocean {
namespace {

TEST(Whitecaps, MonahanCoverageIsThePapersLaw) {
  // W = 3.84e-6 U^3.41: 7.3 % at 18 m/s (issue 33), 1 % at 10 m/s.
  EXPECT_NEAR(monahan_coverage(18.0), 0.0733, 0.0005);
  EXPECT_NEAR(monahan_coverage(10.0), 0.00987, 0.0001);
  EXPECT_EQ(monahan_coverage(0.0), 0.0);
}

TEST(Whitecaps, TheThresholdRuleIsTheSeeds) {
  OceanParams p;
  p.foam.coverage = FoamCoverage::Threshold;
  p.foam.threshold = 0.7;
  const FoamRule r = foam_rule(p, make_cascade_spectra(p));
  EXPECT_EQ(r.whole.onset, 0.7);
  EXPECT_EQ(r.whole.width, 1.0);
  ASSERT_EQ(r.cascades.size(), p.cascades.size());
  for (const FoamRamp& c : r.cascades) {
    EXPECT_EQ(c.onset, 0.7);
    EXPECT_EQ(c.width, 1.0);
  }
}

// The coverage rule's onset is set from a prediction (Rice's crossing rate of the fading foam's boundary,
// whitecaps.cpp); here the foam is stepped instead, by the CPU reference step (ocean/cpu_step.h) for 12 s at
// 10 Hz, and its share at least ½ counted over the last 4 s. Two cascades: each keeps its own foam, and
// the sea is white where either is.
TEST(Whitecaps, SteppedFoamCoversMonahansShareOfTheSea) {
  for (double wind : {8.0, 16.0}) {
    OceanParams p;
    p.spectrum.wind_speed_mps = wind;
    p.spectrum.fetch_km = 5000;
    p.cascades = {{400.0, 128}, {40.0, 128}};
    const std::vector<CascadeSpectrum> spectra = make_cascade_spectra(p);
    const FoamRule rule = foam_rule(p, spectra);
    ASSERT_EQ(rule.cascades.size(), 2u);
    for (const FoamRamp& c : rule.cascades) {
      EXPECT_LT(c.onset, 1.0) << "flat water must not foam";
      EXPECT_GT(c.width, 0.0);
    }
    EXPECT_LT(rule.whole.onset, -1.0) << "the FFT ocean's whitecaps are the cascades' own";
    CpuOceanStep step(p, spectra, cpu_inverse_fft(2));
    double white = 0, counted = 0, own[2] = {0, 0};
    for (int i = 0; i <= 120; ++i) {
      step.step(0.1 * i, i == 0 ? 0.0 : 0.1);
      if (i < 80) continue;
      // The sea's points: the 400 m cascade's texels, each with the 40 m cascade's texel it lies on.
      const std::vector<double>& big = step.cascades()[0].displacement;
      const std::vector<double>& small = step.cascades()[1].displacement;
      for (uint32_t z = 0; z < 128; ++z)
        for (uint32_t x = 0; x < 128; ++x) {
          const double b = big[4 * (size_t(z) * 128 + x) + 3];
          const double s = small[4 * (size_t((z * 10) % 128) * 128 + (x * 10) % 128) + 3];
          white += std::max(b, s) >= 0.5 ? 1 : 0;
          own[0] += b >= 0.5 ? 1 : 0;
          own[1] += s >= 0.5 ? 1 : 0;
          ++counted;
        }
    }
    // Each cascade whitens an equal share: the long waves break too, not only the short ones.
    const double each = 1 - std::sqrt(1 - monahan_coverage(wind));
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(own[c] / counted / each, 1.0, 0.5) << wind << " m/s, cascade " << c;
    const double share = white / counted;
    EXPECT_NEAR(share / monahan_coverage(wind), 1.0, 0.35) << wind << " m/s: " << share;
  }
}

}  // namespace
}  // namespace lagoon::ocean
