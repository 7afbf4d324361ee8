// The measurement of the seed's RGB composites against its spectral eq. 20 (optics/composite_error.h) and the
// colour difference it is measured in (optics/colour_difference.h).
#include <gtest/gtest.h>

#include <cmath>

#include "optics/bottom_spectra.h"
#include "optics/colour_difference.h"
#include "optics/composite_error.h"

namespace lagoon::optics {
namespace {

TEST(ColourDifference, MatchesSharmasCiede2000TestData) {
  // Sharma, Wu & Dalal (2005), Table 1: pairs 1-3 (blue), 7-9 (near neutral, the hue wrap at 0/360),
  // 17-20 (large differences), 25.
  struct Pair {
    glm::dvec3 a, b;
    double expected;
  };
  const Pair pairs[] = {
      {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
      {{50.0, 3.1571, -77.2803}, {50.0, 0.0, -82.7485}, 2.8615},
      {{50.0, 2.8361, -74.0200}, {50.0, 0.0, -82.7485}, 3.4412},
      {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
      {{50.0, -1.0, 2.0}, {50.0, 0.0, 0.0}, 2.3669},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0009}, 7.1792},
      {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
      {{50.0, 2.5, 0.0}, {61.0, -5.0, 29.0}, 22.8977},
      {{50.0, 2.5, 0.0}, {56.0, -27.0, -3.0}, 31.9030},
      {{50.0, 2.5, 0.0}, {58.0, 24.0, 15.0}, 19.4535},
      {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
  };
  for (const Pair& p : pairs) EXPECT_NEAR(delta_e_2000(p.a, p.b), p.expected, 1e-4) << p.expected;
}

TEST(ColourDifference, LabOfSrgbPrimariesAndWhite) {
  const glm::dvec3 white = linear_srgb_to_lab(glm::dvec3(1.0));
  EXPECT_NEAR(white.x, 100.0, 1e-9);
  EXPECT_NEAR(white.y, 0.0, 1e-9);
  EXPECT_NEAR(white.z, 0.0, 1e-9);
  // sRGB red in CIELAB (D65): (53.24, 80.09, 67.20), as every colour reference lists it.
  const glm::dvec3 red = linear_srgb_to_lab({1, 0, 0});
  EXPECT_NEAR(red.x, 53.24, 0.02);
  EXPECT_NEAR(red.y, 80.09, 0.05);
  EXPECT_NEAR(red.z, 67.20, 0.05);
}

LutInputs inputs_for(const char* type) {
  WaterParams params;
  params.type = type;
  params.lut_size = 24;
  auto in = lut_inputs(params, 45.0);
  EXPECT_TRUE(bool(in));
  return *in;
}

TEST(CompositeError, Eq22IsEq20ForAGreyBottom) {
  // With Lagoon's linear Φ and γ = 1, a = ᾱ and T_bottom = ρ(1, 1, 1), so eq. 22 with signed tables is eq. 20
  // exactly; the LUTs as shipped agree wherever neither table had to be clipped to the sRGB gamut.
  Spectrum grey{};
  grey.fill(0.3);
  for (const char* type : {"jerlov-IA", "jerlov-5C"}) {
    const LutInputs in = inputs_for(type);
    auto signed_tables = composite_errors(in, grey, PhiMode::Linear, false);
    ASSERT_TRUE(bool(signed_tables));
    const auto& eq22 = signed_tables->approx[int(Composite::Eq22)];
    for (size_t k = 0; k < eq22.size(); ++k)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(eq22[k][c], signed_tables->exact[k][c], 1e-6) << type << " node " << k;
    auto shipped = composite_errors(in, grey, PhiMode::Linear);
    ASSERT_TRUE(bool(shipped));
    size_t unclipped = 0;
    for (size_t k = 0; k < eq22.size(); ++k) {
      if (shipped->eq22_clipped[k]) continue;
      ++unclipped;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(shipped->approx[int(Composite::Eq22)][k][c], shipped->exact[k][c], 1e-6)
            << type << " node " << k;
    }
    EXPECT_GT(unclipped, 0u) << type;
  }
}

TEST(CompositeError, ColouredBottomsAndTheSeedsToneMappedTablesShowErrors) {
  // The measurement can fail: over a red coralline bottom the RGB product differs from the spectral one, and
  // tone-mapping each table before compositing (the seed's Φ) breaks even a grey bottom (its eq. 19).
  const LutInputs in = inputs_for("jerlov-IB");
  const BottomSpectrum& red = bottom_spectra()[2];
  ASSERT_EQ(red.name, "coralline_algae");
  auto coloured = composite_errors(in, red.reflectance, PhiMode::Linear);
  ASSERT_TRUE(bool(coloured));
  EXPECT_GT(summarise(*coloured, Composite::Eq22).max, 0.5);
  Spectrum grey{};
  grey.fill(0.3);
  auto seed = composite_errors(in, grey, PhiMode::Seed);
  ASSERT_TRUE(bool(seed));
  EXPECT_GT(summarise(*seed, Composite::Eq21).max, 1.0);
}

TEST(BottomSpectra, AreReflectancesOnTheGrid) {
  ASSERT_EQ(bottom_spectra().size(), 5u);
  for (const BottomSpectrum& b : bottom_spectra())
    for (double r : b.reflectance) {
      EXPECT_GE(r, 0.0) << b.name;
      EXPECT_LE(r, 1.0) << b.name;
    }
  // Sand is the brightest of them at 550 nm, the macroalgae the darkest (chlorophyll).
  const int at550 = (550 - kLambdaMinNm) / kLambdaStepNm;
  EXPECT_GT(bottom_spectra()[0].reflectance[at550], 0.25);
  EXPECT_LT(bottom_spectra()[3].reflectance[at550], 0.06);
}

}  // namespace
}  // namespace lagoon::optics
