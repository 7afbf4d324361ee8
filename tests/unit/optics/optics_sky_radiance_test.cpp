// The angle-resolved spectral sky (optics/sky_radiance.h, issue 16 item 3): its daylight basis against the
// CIE's D65, its irradiance against the irradiance model the LUTs use, and the shape of a clear sky.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optics/cie.h"
#include "optics/sky_radiance.h"

namespace lagoon::optics {
namespace {

glm::dvec3 towards(double zenith_deg, double azimuth_deg) {
  const double t = zenith_deg * std::numbers::pi / 180, p = azimuth_deg * std::numbers::pi / 180;
  return {std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p)};
}

TEST(DaylightBasis, ReproducesTheCieD65Table) {
  // D65 is S0 + M1 S1 + M2 S2 at its chromaticity (CIE 15:2004); the D65 table is independent data, so a
  // mistyped basis value of 3 or more shows here.
  const Spectrum d65 = daylight_spectrum(0.31271, 0.32902);
  for (int i = 0; i < kSamples; ++i)
    EXPECT_NEAR(d65[i], cie_d65()[i], 0.01 * cie_d65()[i]) << wavelength_nm(i) << " nm";
}

TEST(SkyTurbidity, FollowsPreethamsDefinitionWithBirdsDepths) {
  // τ_R(550) = 1 / (0.55⁴ (115.6406 − 1.335 / 0.55²)) = 0.09816; τ_a(550) = τ500 (1.1)^−α.
  const double tau_r = 1.0 / (std::pow(0.55, 4) * (115.6406 - 1.335 / (0.55 * 0.55)));
  EXPECT_NEAR(tau_r, 0.09816, 1e-4);
  SkyParams hazy;
  hazy.aerosol_optical_depth_500nm = 0.4;
  EXPECT_NEAR(sky_turbidity(hazy), 1.0 + 0.4 * std::pow(1.1, -1.3) / tau_r, 1e-9);
  EXPECT_NEAR(sky_turbidity({}), 1.0 + 0.1 * std::pow(1.1, -1.3) / tau_r, 1e-9);
}

TEST(SkyRadiance, ItsColourShiftLeavesANearlyFlatScaleToBirdsSpectrum) {
  // After the chromaticity shift, Preetham's sky has Bird's colour, so the per-wavelength scale to Bird's
  // E_sky is nearly flat over the visible band: within 10 % of its 550 nm value from 400 to 700 nm.
  for (double tau : {0.1, 0.4}) {
    SkyParams params;
    params.aerosol_optical_depth_500nm = tau;
    const SkyRadiance sky(35.0, params);
    const double at550 = sky.scale()[(550 - kLambdaMinNm) / kLambdaStepNm];
    for (int nm = 400; nm <= 700; nm += 5)
      EXPECT_NEAR(sky.scale()[(nm - kLambdaMinNm) / kLambdaStepNm] / at550, 1.0, 0.10)
          << "tau " << tau << ", " << nm;
  }
}

TEST(SkyRadiance, KeepsEveryDirectionNearTheDaylightLocus) {
  // The horizon of a clear sky is a pale daylight white, not pink: every direction's chromaticity lies within
  // 0.01 of the CIE daylight locus y = −3x² + 2.87x − 0.275.
  const SkyRadiance sky(35.0);
  for (double zenith : {0.0, 30.0, 60.0, 80.0, 89.0})
    for (double azimuth : {0.0, 90.0, 180.0}) {
      const glm::dvec2 xy = chromaticity(spectrum_to_xyz(sky.radiance(towards(zenith, azimuth))));
      EXPECT_NEAR(xy.y, -3 * xy.x * xy.x + 2.87 * xy.x - 0.275, 0.01) << zenith << ", " << azimuth;
    }
}

TEST(SkyRadiance, ItsImageHasTheIrradianceModelsESky) {
  // A 1° image of the sky (90 × 180 cells, as lagoon sky writes it) integrates to clear_sky's E_sky at every
  // wavelength within 1 %: the same light as the LUTs.
  for (double elevation : {5.0, 30.0, 60.0, 85.0}) {
    for (double tau : {0.1, 0.4}) {
      SkyParams params;
      params.aerosol_optical_depth_500nm = tau;
      const SkyRadiance sky(elevation, params);
      const Spectrum image = sky_image_irradiance(sky, 90);
      for (int i = 0; i < kSamples; ++i)
        ASSERT_NEAR(image[i], sky.irradiance().sky[i], 0.01 * sky.irradiance().sky[i])
            << "elevation " << elevation << ", tau " << tau << ", " << wavelength_nm(i) << " nm";
    }
  }
}

TEST(SkyRadiance, IsBrightestNearTheSunAndBrighterAtTheHorizonThanOverhead) {
  const SkyRadiance sky(30.0);  // the seed's Fig. 2: sun 30° above the horizon, i.e. zenith angle 60°
  auto luminance = [&](glm::dvec3 d) { return spectrum_to_xyz(sky.radiance(d)).y; };
  const double near_sun = luminance(towards(55.0, 0.0)), zenith = luminance({0, 1, 0});
  const double opposite_horizon = luminance(towards(88.0, 180.0)),
               opposite_90 = luminance(towards(30.0, 180.0));
  EXPECT_GT(near_sun, 3.0 * zenith);
  EXPECT_GT(opposite_horizon, opposite_90) << "a clear sky brightens towards the horizon";
  // The darkest part of a clear sky lies about 90° from the sun (Preetham's Fig. 6).
  EXPECT_LT(luminance(towards(30.0, 180.0)), luminance(towards(80.0, 0.0)));
}

TEST(SkyRadiance, IsBluerOverheadThanAtTheHorizon) {
  const SkyRadiance sky(45.0);
  auto blue_over_red = [&](glm::dvec3 d) {
    const Spectrum l = sky.radiance(d);
    return l[(450 - kLambdaMinNm) / kLambdaStepNm] / l[(650 - kLambdaMinNm) / kLambdaStepNm];
  };
  EXPECT_GT(blue_over_red({0, 1, 0}), 1.1 * blue_over_red(towards(88.0, 120.0)));
}

TEST(SkyRadiance, HazeWhitensTheSky) {
  // More aerosol: a whiter sky overhead (Preetham's Fig. 7), from both the shape's chromaticity and Bird's
  // spectrum.
  SkyParams hazy;
  hazy.aerosol_optical_depth_500nm = 0.6;
  const SkyRadiance clear(40.0), turbid(40.0, hazy);
  auto blue_over_red = [](const SkyRadiance& s) {
    const Spectrum l = s.radiance({0, 1, 0});
    return l[(450 - kLambdaMinNm) / kLambdaStepNm] / l[(650 - kLambdaMinNm) / kLambdaStepNm];
  };
  EXPECT_GT(turbid.turbidity(), clear.turbidity());
  EXPECT_LT(blue_over_red(turbid), 0.8 * blue_over_red(clear));
}

}  // namespace
}  // namespace lagoon::optics
