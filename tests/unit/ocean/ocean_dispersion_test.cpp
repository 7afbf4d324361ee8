// Dispersion relation against its physical limits (deep, shallow, capillary), a finite-difference group
// velocity and the loop quantisation of seed formula 10.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/dispersion.h"
#include "support/reference_math.h"

namespace lagoon::ocean {
namespace {

using test::kG;

TEST(OceanDispersion, DeepWaterLimitIsSqrtGk) {
  // kD >= 100: tanh(kD) = 1 to double precision.
  for (double k : {0.1, 1.0, 10.0}) {
    EXPECT_NEAR(omega_finite_depth(k, 1000.0), std::sqrt(kG * k), 1e-12 * std::sqrt(kG * k)) << k;
    EXPECT_DOUBLE_EQ(omega_deep(k), std::sqrt(kG * k));
    EXPECT_NEAR(omega(DispersionModel{1000.0, false, 0.0}, k), std::sqrt(kG * k), 1e-12 * std::sqrt(kG * k));
  }
}

TEST(OceanDispersion, ShallowWaterLimitIsKSqrtGD) {
  // kD = 1e-3: tanh x = x (1 - x²/3 ...), so ω = k sqrt(gD) to a relative 2e-7; waves are non-dispersive.
  const double depth = 2.0, k = 5e-4;
  const double expected = k * std::sqrt(kG * depth);
  EXPECT_NEAR(omega_finite_depth(k, depth), expected, 1e-6 * expected);
  EXPECT_NEAR(domega_dk(DispersionModel{depth, false, 0.0}, k), std::sqrt(kG * depth),
              1e-6 * std::sqrt(kG * depth));
  EXPECT_LT(omega_finite_depth(k, depth), 0.1 * omega_deep(k));  // far below the deep-water value
  EXPECT_DOUBLE_EQ(domega_dk(DispersionModel{depth, true, 0.0}, 0.0), std::sqrt(kG * depth));
}

TEST(OceanDispersion, CapillaryTermNegligibleForLongWavesDominantForShort) {
  // λ = 10 m: k²/k_m² ~ 3e-6 with k_m² = ρg/σ ≈ 1.33e5 rad²/m².
  const double k_long = 2.0 * std::numbers::pi / 10.0;
  EXPECT_NEAR(omega_capillary(k_long) / omega_deep(k_long), 1.0, 5e-6);
  // λ = 1 mm: pure capillary waves, ω² = σk³/ρ (gravity adds k_m²/k² ~ 0.3 %).
  const double k_short = 2.0 * std::numbers::pi / 1e-3;
  const double capillary_only = std::sqrt(0.074 * k_short * k_short * k_short / 1000.0);
  EXPECT_NEAR(omega_capillary(k_short) / capillary_only, 1.0, 0.01);
  EXPECT_GT(omega_capillary(k_short), 10.0 * omega_deep(k_short));
  // The ocean's model combines both: finite depth and surface tension.
  const DispersionModel model{5.0, true, 0.0};
  for (double k : {0.01, 0.3, 40.0, 2000.0}) {
    const double expected = std::sqrt(kG * k * std::tanh(5.0 * k) * (1.0 + k * k * 0.074 / (1000.0 * kG)));
    EXPECT_NEAR(omega(model, k), expected, 1e-12 * expected) << k;
  }
}

TEST(OceanDispersion, GroupVelocityMatchesFiniteDifference) {
  for (double depth : {0.5, 10.0, 4000.0}) {
    for (bool capillary : {false, true}) {
      const DispersionModel model{depth, capillary, 0.0};
      for (double k : {1e-3, 0.05, 0.7, 3.0, 90.0, 400.0, 3000.0}) {
        const double h = 1e-5 * k;
        const double fd = (omega(model, k + h) - omega(model, k - h)) / (2.0 * h);
        EXPECT_NEAR(domega_dk(model, k), fd, 1e-7 * fd)
            << "D " << depth << " k " << k << " cap " << capillary;
      }
    }
  }
}

TEST(OceanDispersion, DeepGravityGroupVelocityIsHalfThePhaseVelocity) {
  const DispersionModel model{1e4, false, 0.0};
  for (double k : {0.05, 1.0}) EXPECT_NEAR(domega_dk(model, k), 0.5 * std::sqrt(kG / k), 1e-9);
}

TEST(OceanDispersion, LoopQuantisationGivesWholeCyclesPerPeriod) {
  const double period = 20.0, step = 2.0 * std::numbers::pi / period;
  const DispersionModel looped{30.0, true, period}, free{30.0, true, 0.0};
  for (double k : {0.003, 0.02, 0.1, 0.77, 5.0, 123.0}) {
    const double w = omega(looped, k), w0 = omega(free, k);
    const double cycles = w / step;
    EXPECT_NEAR(cycles, std::round(cycles), 1e-9) << k;
    EXPECT_LE(w, w0);
    EXPECT_GT(w, w0 - step);
    EXPECT_NEAR(std::cos(w * period), 1.0, 1e-9);  // every wave is back in phase after T
  }
  EXPECT_EQ(omega(looped, 1e-4), 0.0);  // ω0 < 2π/T: the longest waves freeze rather than break the loop
  EXPECT_EQ(quantise_omega(1.234, 0.0), 1.234);
}

TEST(OceanDispersion, ModelFromParams) {
  OceanParams p;
  p.depth_m = 12.5;
  p.loop_period_s = 40.0;
  const DispersionModel m = dispersion_for(p);
  EXPECT_EQ(m.depth_m, 12.5);
  EXPECT_TRUE(m.capillary);
  EXPECT_EQ(m.loop_period_s, 40.0);
  EXPECT_EQ(omega(m, 0.0), 0.0);
  EXPECT_EQ(omega(m, -1.0), 0.0);
}

}  // namespace
}  // namespace lagoon::ocean
