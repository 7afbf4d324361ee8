// Fresnel terms and the flat-surface coefficients of the four-flow model (seed eqs. 6–7): ranges, energy
// sums, closed-form limits, and the hemisphere averages against a brute-force integration.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/fresnel.h"
#include "optics/surface.h"

namespace lagoon::optics {
namespace {

constexpr double kWater = 1.333;

// ∫0^1 R(μ) 2μ dμ by composite Simpson. From the dense side R = 1 up to the critical cosine μc and then falls
// like sqrt(μ − μc): integrate [μc, 1] in t with μ = μc + (1 − μc) t², which makes the integrand smooth.
double brute_force_hemispherical(double n_from, double n_to) {
  const double ratio = n_to / n_from;
  const double mu_c = n_from > n_to ? std::sqrt(1.0 - ratio * ratio) : 0.0;
  const int n = 20000;
  const double h = 1.0 / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double t = i * h, mu = mu_c + (1.0 - mu_c) * t * t, dmu_dt = 2.0 * (1.0 - mu_c) * t;
    const double weight = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    sum += weight * fresnel_reflectance(n_from, n_to, mu) * 2.0 * mu * dmu_dt;
  }
  return mu_c * mu_c + sum * h / 3.0;
}

TEST(SurfaceFresnel, NormalIncidenceAndLimits) {
  for (double n : {1.0, 1.333, 1.5, 2.4}) {
    const double expected = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1));
    EXPECT_NEAR(fresnel_reflectance(1.0, n, 1.0), expected, 1e-15) << n;
    EXPECT_NEAR(fresnel_reflectance(n, 1.0, 1.0), expected, 1e-15) << n;
    EXPECT_DOUBLE_EQ(refracted_cos(1.0, n, 1.0), 1.0);
  }
  EXPECT_DOUBLE_EQ(fresnel_reflectance(1.0, kWater, 0.0), 1.0);  // grazing
  // Total internal reflection beyond the critical angle (sin θc = 1/n).
  const double cos_c = std::sqrt(1.0 - 1.0 / (kWater * kWater));
  EXPECT_DOUBLE_EQ(fresnel_reflectance(kWater, 1.0, cos_c * 0.999), 1.0);
  EXPECT_DOUBLE_EQ(refracted_cos(kWater, 1.0, cos_c * 0.999), 0.0);
  EXPECT_LT(fresnel_reflectance(kWater, 1.0, cos_c * 1.001), 1.0);
  // Snell: n1 sin θ1 = n2 sin θ2, and reciprocity R(1 → n, θ) = R(n → 1, θt).
  for (double c : {0.05, 0.3, 0.7, 0.99}) {
    const double ct = refracted_cos(1.0, kWater, c);
    EXPECT_NEAR(std::sqrt(1 - c * c), kWater * std::sqrt(1 - ct * ct), 1e-14);
    EXPECT_NEAR(fresnel_reflectance(1.0, kWater, c), fresnel_reflectance(kWater, 1.0, ct), 1e-14);
    EXPECT_DOUBLE_EQ(fresnel_reflectance(1.0, kWater, -c), fresnel_reflectance(1.0, kWater, c));
  }
}

TEST(SurfaceFresnel, HemisphericalMatchesBruteForce) {
  for (double n : {1.1, 1.333, 1.5}) {
    EXPECT_NEAR(fresnel_hemispherical(1.0, n), brute_force_hemispherical(1.0, n), 1e-10) << n;
    EXPECT_NEAR(fresnel_hemispherical(n, 1.0), brute_force_hemispherical(n, 1.0), 1e-10) << n;
  }
  EXPECT_EQ(fresnel_hemispherical(1.0, 1.0), 0.0);
}

TEST(SurfaceCoefficientsTest, RangesAndEnergySums) {
  for (double zenith_deg = 0; zenith_deg <= 100; zenith_deg += 2.5) {
    const SurfaceCoefficients c = surface_coefficients(kWater, zenith_deg * std::numbers::pi / 180);
    for (double v : {c.t_dd, c.r_dd, c.t_df, c.r_df, c.t_ff, c.r_ff, c.rw_dd, c.rw_df, c.rw_ff, c.tw_ff}) {
      EXPECT_GE(v, 0.0) << zenith_deg;
      EXPECT_LE(v, 1.0) << zenith_deg;
    }
    EXPECT_NEAR(c.t_dd + c.r_dd + c.t_df + c.r_df, 1.0, 1e-15) << zenith_deg;  // eq. 6
    EXPECT_NEAR(c.r_ff + c.t_ff, 1.0, 1e-15);                                  // eq. 6
    EXPECT_NEAR(c.rw_ff + c.tw_ff, 1.0, 1e-15);
    EXPECT_EQ(c.t_df, 0.0);
    EXPECT_EQ(c.r_df, 0.0);
    EXPECT_EQ(c.rw_df, 0.0);
    // The upward beam meets the surface at the refracted sun angle: reciprocity makes that Fresnel term
    // r_dd (evaluated from below it is ill-conditioned near the critical angle, i.e. for a low sun).
    EXPECT_EQ(c.rw_dd, c.r_dd);
    if (zenith_deg < 89) {
      const double mu_t = refracted_cos(1.0, kWater, std::cos(zenith_deg * std::numbers::pi / 180));
      EXPECT_NEAR(c.rw_dd, fresnel_reflectance(kWater, 1.0, mu_t), 1e-9) << zenith_deg;
    }
  }
}

TEST(SurfaceCoefficientsTest, ValuesForWater) {
  const SurfaceCoefficients c = surface_coefficients(kWater, 0.0);
  EXPECT_NEAR(c.r_dd, std::pow(0.333 / 2.333, 2), 1e-15);  // 0.0204
  // Uniform sky over a flat water surface: 0.0664 (literature: ≈ 0.066).
  EXPECT_NEAR(c.r_ff, 0.066406, 1e-6);
  // Uniform upwelling radiance from below, total internal reflection included: 1 − t_ff/n² = 0.4746.
  EXPECT_NEAR(c.rw_ff, 0.474591, 1e-6);
  EXPECT_NEAR(c.rw_ff, 1.0 - c.t_ff / (kWater * kWater), 1e-14);
}

TEST(SurfaceCoefficientsTest, SunAtAndBelowHorizon) {
  EXPECT_NEAR(surface_coefficients(kWater, std::numbers::pi / 2).t_dd, 0.0, 1e-12);
  EXPECT_LT(surface_coefficients(kWater, std::numbers::pi / 2 - 1e-3).t_dd,
            0.01);  // t_dd ∝ cos θ near grazing
  const SurfaceCoefficients below = surface_coefficients(kWater, 1.7);
  EXPECT_EQ(below.t_dd, 0.0);
  EXPECT_EQ(below.r_dd, 1.0);
  // t_dd falls monotonically with the zenith angle.
  double previous = 2.0;
  for (double z = 0; z < std::numbers::pi / 2; z += 0.01) {
    const double t = surface_coefficients(kWater, z).t_dd;
    EXPECT_LE(t, previous);
    previous = t;
  }
}

TEST(SurfaceBottom, Lambertian) {
  const BottomCoefficients b = lambertian_bottom(0.3);
  EXPECT_EQ(b.r_dd, 0.0);
  EXPECT_EQ(b.r_df, 0.3);
  EXPECT_EQ(b.r_ff, 0.3);
}

}  // namespace
}  // namespace lagoon::optics
