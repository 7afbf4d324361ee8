// Directional spreading: normalisation by quadrature, symmetry, width ordering and closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/spreading.h"

namespace lagoon::ocean {
namespace {

// Composite Simpson over θ in [-π, π] with n intervals (fine enough for Donelan-Banner lobes 1e-3 rad wide).
template <typename F>
double integrate_theta(F&& f, int n = 1 << 16) {
  const double h = 2.0 * std::numbers::pi / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i)
    sum += ((i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0)) * f(-std::numbers::pi + i * h);
  return sum * h / 3.0;
}

SpreadingModel model_of(Spreading type, double swell, double s_peak = 12.0) {
  return SpreadingModel{type, 0.9, s_peak, swell};
}

TEST(OceanSpreading, EveryModelIntegratesToOne) {
  for (Spreading type : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner}) {
    for (double swell : {0.0, 0.05, 0.3, 0.7, 1.0}) {
      const SpreadingModel m = model_of(type, swell);
      for (double r : {0.3, 0.5, 0.6, 0.9, 1.0, 1.3, 1.7, 3.0, 10.0, 50.0}) {
        const double w = r * m.peak_omega;
        const double total = integrate_theta([&](double t) { return spreading(m, w, t); });
        EXPECT_NEAR(total, 1.0, 2e-4) << to_string(type) << " swell " << swell << " ω/ω_p " << r;
      }
    }
  }
  // Very directional cos-2s (s = 500) stays finite and normalised (lgamma, not Γ).
  const SpreadingModel narrow = model_of(Spreading::Cos2s, 0.0, 500.0);
  EXPECT_NEAR(integrate_theta([&](double t) { return spreading(narrow, 0.9, t); }), 1.0, 1e-6);
}

TEST(OceanSpreading, Cos2sNormalisationClosedForms) {
  EXPECT_NEAR(cos2s_normalisation(0.0), 1.0 / (2.0 * std::numbers::pi), 1e-14);  // isotropic
  EXPECT_NEAR(cos2s_normalisation(1.0), 1.0 / std::numbers::pi, 1e-14);          // ∫ cos²(θ/2) dθ = π
  EXPECT_NEAR(cos2s_normalisation(2.0), 4.0 / (3.0 * std::numbers::pi), 1e-14);  // ∫ cos⁴(θ/2) dθ = 3π/4
  // Laplace: cos^(2s)(θ/2) ≈ exp(-sθ²/4) for large s, so Q ≈ sqrt(s/(4π)) (1 + O(1/s)).
  EXPECT_NEAR(cos2s_normalisation(2000.0) / std::sqrt(2000.0 / (4.0 * std::numbers::pi)), 1.0, 2e-4);
  EXPECT_TRUE(std::isfinite(cos2s_normalisation(1e6)));
}

TEST(OceanSpreading, SymmetricAboutTheWind) {
  for (Spreading type : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner}) {
    const SpreadingModel m = model_of(type, 0.4);
    for (double w : {0.5, 0.9, 2.0})
      for (double t : {0.1, 0.7, 1.5, 2.5, 3.1}) EXPECT_DOUBLE_EQ(spreading(m, w, t), spreading(m, w, -t));
    // θ wraps: 2π + θ is θ.
    EXPECT_NEAR(spreading(m, 0.9, 0.3 + 2.0 * std::numbers::pi), spreading(m, 0.9, 0.3), 1e-12);
  }
}

// ∫ D θ² dθ: the angular variance about the wind.
double angular_variance(const SpreadingModel& m, double w) {
  return integrate_theta([&](double t) { return spreading(m, w, t) * t * t; });
}

TEST(OceanSpreading, LargerCos2sExponentIsNarrower) {
  const SpreadingModel wide = model_of(Spreading::Cos2s, 0.0, 2.0),
                       narrow = model_of(Spreading::Cos2s, 0.0, 40.0);
  EXPECT_GT(spreading(narrow, 0.9, 0.0), spreading(wide, 0.9, 0.0));
  EXPECT_LT(spreading(narrow, 0.9, 1.2), spreading(wide, 0.9, 1.2));
  EXPECT_LT(angular_variance(narrow, 0.9), 0.2 * angular_variance(wide, 0.9));
  // Large s: variance of exp(-sθ²/4) is 2/s.
  EXPECT_NEAR(angular_variance(narrow, 0.9), 2.0 / 40.0, 0.1 * 2.0 / 40.0);
}

TEST(OceanSpreading, SwellIncreasesDirectionality) {
  for (Spreading type : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner}) {
    for (double r : {0.8, 1.0, 2.0}) {
      const double w = 0.9 * r;
      double previous = 1e9;
      for (double swell : {0.0, 0.3, 0.6, 1.0}) {
        const double v = angular_variance(model_of(type, swell), w);
        EXPECT_LT(v, previous) << to_string(type) << " swell " << swell;
        previous = v;
      }
    }
  }
  EXPECT_NEAR(swell_exponent(0.9, 0.9, 1.0), 16.0 * std::tanh(1.0), 1e-12);
  EXPECT_NEAR(swell_exponent(0.9, 0.9, 0.5), 4.0 * std::tanh(1.0), 1e-12);
  EXPECT_EQ(swell_exponent(0.9, 0.9, 0.0), 0.0);
}

TEST(OceanSpreading, Cos2HasNoWavesAgainstTheWind) {
  const SpreadingModel m = model_of(Spreading::Cos2, 0.0);
  EXPECT_NEAR(spreading(m, 1.0, 0.0), 2.0 / std::numbers::pi, 1e-14);
  EXPECT_EQ(spreading(m, 1.0, 0.5 * std::numbers::pi + 1e-3), 0.0);
  EXPECT_EQ(spreading(m, 1.0, std::numbers::pi), 0.0);
  EXPECT_EQ(spreading(model_of(Spreading::Cos2, 1.0), 1.0, -2.0), 0.0);
}

TEST(OceanSpreading, MitsuyasuExponent) {
  // U = 10 m/s, PM peak ω_p = 2π 0.13 g/U: U/c_p = ω_p U/g = 0.8168, s_p = 11.5 · 0.8168^-2.5 = 19.1.
  SpectrumParams s;
  s.type = SpectrumType::PiersonMoskowitz;
  s.spreading = Spreading::Cos2s;
  const SpreadingModel m = spreading_for(s);
  EXPECT_NEAR(m.s_peak, 11.5 * std::pow(2.0 * std::numbers::pi * 0.13, -2.5), 1e-9);
  EXPECT_NEAR(m.s_peak, 19.1, 0.05);
  EXPECT_NEAR(cos2s_exponent(m, m.peak_omega), m.s_peak, 1e-12);
  EXPECT_NEAR(cos2s_exponent(m, 0.5 * m.peak_omega), m.s_peak / 32.0, 1e-9);
  EXPECT_NEAR(cos2s_exponent(m, 4.0 * m.peak_omega), m.s_peak / 32.0, 1e-9);
  // Directionality peaks at the spectral peak.
  EXPECT_LT(angular_variance(m, m.peak_omega), angular_variance(m, 0.7 * m.peak_omega));
  EXPECT_LT(angular_variance(m, m.peak_omega), angular_variance(m, 1.5 * m.peak_omega));
}

TEST(OceanSpreading, DonelanBannerBeta) {
  // Banner's high-frequency branch meets Donelan's at ω/ω_p = 1.6 (to 0.1 %), and tends to 10^-0.4.
  EXPECT_NEAR(donelan_banner_beta(1.6), 2.28 * std::pow(1.6, -1.3), 0.001 * 2.28 * std::pow(1.6, -1.3));
  EXPECT_NEAR(donelan_banner_beta(1e6), std::pow(10.0, -0.4), 1e-3);
  EXPECT_NEAR(donelan_banner_beta(0.95), 2.28 * std::pow(0.95, -1.3), 1e-12);
  EXPECT_NEAR(donelan_banner_beta(0.9), 2.61 * std::pow(0.9, 1.3), 1e-12);
  EXPECT_LE(donelan_banner_beta(1e-3), 1e4);
  // Narrowest near the peak: the angular width grows away from it.
  const SpreadingModel m = model_of(Spreading::DonelanBanner, 0.0);
  EXPECT_LT(angular_variance(m, m.peak_omega), angular_variance(m, 3.0 * m.peak_omega));
}

TEST(OceanSpreading, NonPositiveOmegaIsIsotropic) {
  for (Spreading type : {Spreading::Cos2, Spreading::Cos2s, Spreading::DonelanBanner})
    EXPECT_NEAR(spreading(model_of(type, 0.5), 0.0, 1.0), 1.0 / (2.0 * std::numbers::pi), 1e-15);
}

}  // namespace
}  // namespace lagoon::ocean
