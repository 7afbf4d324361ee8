// The colour LUTs: limits of the model, the colours the Jerlov types must have, and eq. 22 reproducing
// eq. 20 where its assumptions hold.
#include "optics/lut.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/colour.h"
#include "optics/four_flow.h"

namespace lagoon::optics {
namespace {

LutInputs inputs(const std::string& type, double albedo = 0.3, double gamma = 1.0) {
  WaterParams p;
  p.type = type;
  p.bottom_albedo = albedo;
  p.lut_gamma = gamma;
  p.lut_size = 16;
  auto in = lut_inputs(p, 45.0);
  EXPECT_TRUE(in) << in.error().message;
  return *in;
}

WaterLut build(const LutInputs& in) {
  auto lut = build_water_lut(in);
  EXPECT_TRUE(lut) << lut.error().message;
  return *lut;
}

const float* t0_at(const WaterLut& lut, uint32_t i, uint32_t j) {
  return &lut.t0[(size_t{i} * lut.h_count + j) * 4];
}
const float* t1_at(const WaterLut& lut, uint32_t i, uint32_t j) {
  return &lut.t1[(size_t{i} * lut.h_count + j) * 3];
}

TEST(OpticsLut, ShallowWaterShowsTheBottomDeepWaterHidesIt) {
  const WaterLut lut = build(inputs("jerlov-III"));
  const uint32_t last = lut.r_count - 1;
  EXPECT_GT(t0_at(lut, 0, 0)[3], 0.999f) << "a at r = h = 0";
  EXPECT_LT(t0_at(lut, last, last)[3], 1e-3f) << "a at r_max, h_max";
  // a falls as the path gets longer, along both axes.
  for (uint32_t i = 1; i < lut.r_count; ++i) {
    EXPECT_LE(t0_at(lut, i, 3)[3], t0_at(lut, i - 1, 3)[3]);
    EXPECT_LE(t0_at(lut, 3, i)[3], t0_at(lut, 3, i - 1)[3]);
  }
}

TEST(OpticsLut, DeepWaterColourDoesNotDependOnTheBottom) {
  WaterLut dark = build(inputs("jerlov-9C", 0.0)), bright = build(inputs("jerlov-9C", 1.0));
  const uint32_t deep = dark.h_count - 1;  // 30 m of turbid coastal water
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(t1_at(dark, 0, deep)[c], t1_at(bright, 0, deep)[c], 1e-6 + 1e-4 * t1_at(bright, 0, deep)[c]);
    EXPECT_NEAR(dark.deep_colour[c], bright.deep_colour[c], 1e-9);
  }
  // ...while in shallow water the bottom's albedo shows in the water colour.
  EXPECT_GT(t1_at(bright, 0, 2)[1], 1.5 * t1_at(dark, 0, 2)[1]);
}

TEST(OpticsLut, ClearOceanIsBlueTurbidCoastalIsGreenBrown) {
  const glm::dvec3 clear = build(inputs("jerlov-I")).deep_colour;
  EXPECT_GT(clear.b, clear.g);
  EXPECT_GT(clear.g, clear.r);
  const glm::dvec3 turbid = build(inputs("jerlov-9C")).deep_colour;
  EXPECT_GT(turbid.g, turbid.b);
  EXPECT_GT(turbid.r, 0.5 * turbid.b) << "9C should be brownish, not blue-green";
  // Every type gives a finite, non-negative colour with some light in it.
  for (const std::string& name : water_type_names()) {
    const glm::dvec3 c = build(inputs(name)).deep_colour;
    EXPECT_GT(c.r + c.g + c.b, 1e-4) << name;
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k]) && c[k] >= 0) << name;
  }
}

// With γ = 1 and a spectrally flat bottom, eq. 22 is eq. 20 exactly, because Φ (before clipping) is linear.
TEST(OpticsLut, Eq22ReproducesEq20ForAGreyBottom) {
  const LutInputs in = inputs("jerlov-1C", 0.3, 1.0);
  const double grey = 0.4;
  for (auto [r, h] : {std::pair{0.5, 0.7}, {3.0, 2.0}, {12.0, 6.0}}) {
    auto e = explain_lut_point(in, r, h);
    ASSERT_TRUE(e) << e.error().message;
    Spectrum refr{}, white{};
    for (int i = 0; i < kSamples; ++i) {
      const auto& w = e->spectral[i];
      const double at_bottom = w.bottom_flows[0] + w.bottom_flows[2];
      refr[i] = w.alpha_l * grey * at_bottom + (1 - w.alpha_l) * w.surface_flows[3];
      white[i] = w.e_sun + w.e_sky;
    }
    const glm::dvec3 direct = adapted_linear_srgb(refr, white);
    const glm::dvec3 via_luts = e->a * e->t0 * grey + (1 - e->a) * e->t1;
    for (int c = 0; c < 3; ++c) {
      if (direct[c] <= 1e-6) continue;  // clipped to the gamut in the LUT
      EXPECT_NEAR(via_luts[c], direct[c], 1e-9 + 1e-6 * direct[c]) << "r " << r << " h " << h;
    }
  }
}

// Eq. 23 with γ ≠ 1: the LUT's a(r, h) is 1 − (1 − ᾱ)^γ, with ᾱ Bouguer's transmission e^{−ε l} along
// l = √(r² + h²) averaged over 380–780 nm (trapezoids on the 5 nm grid), recomputed here from the water's
// χ and σ at each grid point. The points are where ᾱ is mid-range, so a γ ignored or misapplied shows.
TEST(OpticsLut, Eq23GivesTheBottomsShareWithItsGamma) {
  for (double gamma : {0.4, 2.5}) {
    const LutInputs in = inputs("jerlov-1C", 0.3, gamma);
    const WaterLut lut = build(in);
    int mid_range = 0;
    for (uint32_t i = 0; i < lut.r_count; i += 3)
      for (uint32_t j = 1; j < lut.h_count; j += 2) {
        const double r = lut.r_m[i], h = lut.h_m[j], l = std::hypot(r, h);
        auto e = explain_lut_point(in, r, h);
        ASSERT_TRUE(e) << e.error().message;
        double integral = 0;
        for (size_t k = 0; k + 1 < e->spectral.size(); ++k) {
          const auto &w0 = e->spectral[k], &w1 = e->spectral[k + 1];
          integral += 0.5 * (std::exp(-(w0.chi + w0.sigma) * l) + std::exp(-(w1.chi + w1.sigma) * l)) *
                      (w1.wavelength_nm - w0.wavelength_nm);
        }
        ASSERT_DOUBLE_EQ(e->spectral.back().wavelength_nm - e->spectral.front().wavelength_nm, 400.0);
        const double mean = integral / 400.0, expected = 1.0 - std::pow(1.0 - mean, gamma);
        EXPECT_NEAR(t0_at(lut, i, j)[3], expected, 1e-6 + 1e-5 * expected)
            << "gamma " << gamma << " r " << r << " h " << h << " mean transmission " << mean;
        mid_range += std::abs(expected - mean) > 0.01 ? 1 : 0;
      }
    EXPECT_GE(mid_range, 6) << "gamma " << gamma << ": too few points where gamma changes a";
  }
}

TEST(OpticsLut, SimilarityScalingKeepsTheTransportCoefficient) {
  for (double x1 : {1.5, 2.0, 2.77}) {
    const SimilarScattering s = similarity_scaled(0.2, x1);
    EXPECT_EQ(s.phase_x1, kMaxModelX1);
    EXPECT_NEAR(s.scattering_per_m * (1 - s.phase_x1 / 3), 0.2 * (1 - x1 / 3), 1e-15);
  }
  EXPECT_EQ(similarity_scaled(0.2, 0.5).scattering_per_m, 0.2);
}

TEST(OpticsLut, UnknownWaterTypeListsTheAcceptedNames) {
  WaterParams p;
  p.type = "jerlov-IV";
  auto in = lut_inputs(p, 45.0);
  ASSERT_FALSE(in);
  EXPECT_NE(in.error().message.find("jerlov-IB"), std::string::npos) << in.error().message;
}

TEST(OpticsLut, SunBelowTheHorizonStillGivesColours) {
  WaterParams p;
  p.lut_size = 8;
  auto in = lut_inputs(p, -5.0);
  ASSERT_TRUE(in);
  auto lut = build_water_lut(*in);
  ASSERT_TRUE(lut);
  EXPECT_GT(lut->deep_colour.b, 0.0);
}

}  // namespace
}  // namespace lagoon::optics
