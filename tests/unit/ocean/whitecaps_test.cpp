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
  EXPECT_EQ(r.onset, 0.7);
  EXPECT_EQ(r.width, 1.0);
}

// The share of a cascade set's texels whose whole-sea Jacobian (each cascade's own, as the CPU step gives
// it, at the cascades' common points: one patch the size of the smallest, where every cascade's texel grid
// is used as is) lies below j.
TEST(Whitecaps, TheOnsetLeavesMonahansShareOfTheSeaBelowHalfFoam) {
  for (double wind : {8.0, 16.0}) {
    OceanParams p;
    p.spectrum.wind_speed_mps = wind;
    p.spectrum.fetch_km = 5000;
    p.cascades = {{400.0, 128}};  // one cascade: its texels are the sea's points
    const std::vector<CascadeSpectrum> spectra = make_cascade_spectra(p);
    const FoamRule rule = foam_rule(p, spectra);
    CpuOceanStep step(p, spectra, cpu_inverse_fft(2));
    step.step(0.0, 0.0);
    const std::vector<double>& nj = step.cascades()[0].normal_jacobian;
    size_t below = 0, n = nj.size() / 4;
    for (size_t i = 0; i < n; ++i) below += nj[4 * i + 3] < rule.onset - 0.5 * rule.width ? 1 : 0;
    const double share = double(below) / double(n);
    EXPECT_NEAR(share / monahan_coverage(wind), 1.0, 0.15) << wind << " m/s: " << share;
    EXPECT_GT(rule.width, 0.0);
    EXPECT_LT(rule.onset, 1.0) << "flat water must not foam";
  }
}

}  // namespace
}  // namespace lagoon::ocean
