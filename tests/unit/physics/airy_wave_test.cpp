// Linear wave theory's pressure under a regular wave (physics/airy_wave.h, issue 33): the dispersion
// relation, the head at the surface and on the floor against their closed forms, and the wave's force on a
// half-submerged sphere against a quadrature of linear theory's pressure over the exact hemisphere, which
// the quasi-static approximation (the height above each point) doubles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/airy_wave.h"
#include "physics/hydrostatics.h"
#include "physics/sphere_mesh.h"
#include "support/reference_math.h"

namespace lagoon::test {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(AiryWave, DispersionInDeepAndShallowWater) {
  const physics::AiryWave deep{.amplitude = 0.5, .wavenumber = 0.1, .gravity = kG};
  EXPECT_NEAR(deep.angular_frequency(), std::sqrt(kG * 0.1), 1e-12);
  physics::AiryWave shallow = deep;
  shallow.depth = 3.0;
  EXPECT_NEAR(shallow.angular_frequency(), std::sqrt(kG * 0.1 * std::tanh(0.3)), 1e-12);
  // Nearly the shallow-water speed sqrt(g d) when the wave is long against the depth.
  EXPECT_NEAR(shallow.angular_frequency() / 0.1, std::sqrt(kG * 3.0), 0.02 * std::sqrt(kG * 3.0));
}

TEST(AiryWave, ThePressureHeadIsTheHeightAtTheSurfaceAndFadesBelow) {
  const double k = 2 * kPi / 40.0, a = 0.8;
  const physics::AiryWave deep{.amplitude = a, .wavenumber = k, .gravity = kG};
  for (double x : {0.0, 7.0, 13.0, 29.0}) {
    const double eta = deep.height(x, 0, 1.5);
    EXPECT_NEAR(deep.pressure_head(x, eta, 0, 1.5), eta, 1e-12) << "no pressure at the surface, x " << x;
    // Below it, Wheeler-stretched: η·e^{k(y − η)}.
    EXPECT_NEAR(deep.pressure_head(x, -6.0, 0, 1.5), eta * std::exp(k * (-6.0 - eta)), 1e-12);
  }
  // Under the crest 6 m down the wave's pressure is e^{-k·6.8} = 0.34 of its height: the quasi-static
  // approximation would say all of it.
  EXPECT_NEAR(deep.pressure_head(0, -6.0, 0, 0) / a, std::exp(-k * 6.8), 1e-12);
  // Finite depth: the head on the floor under a crest is a / cosh(kd) (the bottom-pressure formula), and a
  // very deep floor is deep water (but for Wheeler's stretch d/(d + η), 1e-4 here).
  physics::AiryWave shallow = deep;
  shallow.depth = 5.0;
  EXPECT_NEAR(shallow.pressure_head(0, -5.0, 0, 0), a / std::cosh(k * 5.0), 1e-12);
  shallow.depth = 1e4;
  EXPECT_NEAR(shallow.pressure_head(3, -6.0, 0, 0.7), deep.pressure_head(3, -6.0, 0, 0.7), 1e-4 * 0.26);
}

// Linear theory's wave force upwards on the fixed hemisphere r < R, y < 0 under a wave a·cos(kx):
// ρ·g·a·∫ e^{k y} cos(k x) n_down dS, by the midpoint rule in (θ from the bottom, φ).
double hemisphere_wave_force(double rho, double a, double k, double radius) {
  const int nt = 400, np = 800;
  double sum = 0;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double theta = 0.5 * kPi * (i + 0.5) / nt, phi = 2 * kPi * (j + 0.5) / np;
      const double x = radius * std::sin(theta) * std::cos(phi), y = -radius * std::cos(theta);
      sum += std::exp(k * y) * std::cos(k * x) * std::cos(theta) * radius * radius * std::sin(theta);
    }
  return rho * kG * a * sum * (0.5 * kPi / nt) * (2 * kPi / np);
}

TEST(Hydrostatics, TheWavesPressureOnADeepHullFadesAsLinearTheorySays) {
  // The IEA OES Task 10 sphere (R = 5 m, half submerged) under the crest of a 30 m wave (kR = 1.05, its
  // heave resonance), 1 cm high so that the waterline hardly moves.
  const double rho = 1000.0, radius = 5.0, k = 2 * kPi / 30.0, a = 0.01;
  const physics::TriangleMesh hull = physics::uv_sphere(radius, 48);
  const physics::AiryWave wave{.amplitude = a, .wavenumber = k, .gravity = kG};
  const physics::WaterHeight still = [](double, double) { return 0.0; };
  const physics::WaterHeight height = [&](double x, double z) { return wave.height(x, z, 0); };
  const physics::PressureHead head = [&](double x, double y, double z) {
    return wave.pressure_head(x, y, z, 0);
  };
  const double rest = physics::hydrostatic_wrench(hull.vertices, hull.indices, still, {}, rho, kG).force.y;
  const double linear =
      physics::hydrostatic_wrench(hull.vertices, hull.indices, height, {}, rho, kG, 1e300, head).force.y -
      rest;
  const double quasi_static =
      physics::hydrostatic_wrench(hull.vertices, hull.indices, height, {}, rho, kG).force.y - rest;
  const double expected = hemisphere_wave_force(rho, a, k, radius);
  RecordProperty("linear_over_expected", std::to_string(linear / expected));
  RecordProperty("quasi_static_over_expected", std::to_string(quasi_static / expected));
  EXPECT_NEAR(linear, expected, 0.03 * expected);
  // What the head adds: the height above each point alone pushes twice as hard (1.99 ×).
  EXPECT_GT(quasi_static, 1.4 * expected);
}

}  // namespace
}  // namespace lagoon::test
