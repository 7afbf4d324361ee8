// The spectral -> RGB operator (von Kries adaptation, sRGB, tone mapping) and the clear-sky model.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "optics/cie.h"
#include "optics/colour.h"
#include "optics/csv_table.h"
#include "optics/sky.h"

namespace lagoon::optics {
namespace {

glm::dvec3 d65_xyz_unit_y() {
  const glm::dvec3 xyz = spectrum_to_xyz(cie_d65());
  return xyz / xyz.y;
}

void expect_near(glm::dvec3 actual, glm::dvec3 expected, double tolerance) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

Spectrum global(const SkyIrradiance& s) {
  Spectrum g;
  for (int i = 0; i < kSamples; ++i) g[i] = s.sun[i] + s.sky[i];
  return g;
}

double band_integral(const Spectrum& f) {
  double sum = 0.0;
  for (double v : f) sum += v * kLambdaStepNm;
  return sum;
}

TEST(OpticsColour, VonKriesMatrixIsHuntPointerEstevez) {
  const glm::dmat3& m = xyz_to_lms();
  // Math row 1, column 0 (glm is column-major: m[column][row]). The seed's eq. 15 prints -0.023.
  EXPECT_DOUBLE_EQ(m[0][1], -0.2263);
  EXPECT_DOUBLE_EQ(m[0][0], 0.40024);
  EXPECT_DOUBLE_EQ(m[2][2], 0.91822);
  expect_near(m * d65_xyz_unit_y(), glm::dvec3(1.0), 1e-3);
}

TEST(OpticsColour, SrgbMatrixMapsD65ToWhite) {
  expect_near(xyz_to_linear_srgb() * d65_xyz_unit_y(), glm::dvec3(1.0), 1e-3);
  EXPECT_DOUBLE_EQ(xyz_to_linear_srgb()[0][0], 3.2409699419);  // the *_exact row, not the IEC print
  const glm::dmat3 product = linear_srgb_to_xyz() * xyz_to_linear_srgb();
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0 : 0.0, 1e-8);
  EXPECT_NEAR(linear_srgb_luminance(glm::dvec3(1.0)), 1.0, 1e-9);
}

TEST(OpticsColour, WhiteAdaptedToItselfIsOne) {
  expect_near(adapted_linear_srgb(cie_d65(), cie_d65()), glm::dvec3(1.0), 1e-9);
  // Any spectrum adapted to itself, e.g. the clear sky at 30° or a bluish one.
  Spectrum bluish;
  for (int i = 0; i < kSamples; ++i) bluish[i] = std::exp(-(wavelength_nm(i) - 450.0) / 80.0);
  expect_near(adapted_linear_srgb(bluish, bluish), glm::dvec3(1.0), 1e-9);
  const Spectrum sky = global(clear_sky(30.0));
  expect_near(adapted_linear_srgb(sky, sky), glm::dvec3(1.0), 1e-9);
}

TEST(OpticsColour, ProportionalToTheWhiteIsNeutralGrey) {
  const Spectrum white = global(clear_sky(45.0));
  for (double k : {0.02, 0.37, 3.0}) {
    Spectrum f = white;
    for (double& v : f) v *= k;
    expect_near(adapted_linear_srgb(f, white), glm::dvec3(k), 1e-9 * k);
  }
  Spectrum d65_grey = cie_d65();
  for (double& v : d65_grey) v *= 0.18;
  expect_near(adapted_linear_srgb(d65_grey, cie_d65()), glm::dvec3(0.18), 1e-10);
}

TEST(OpticsColour, AdaptationRemovesTheIlluminantCast) {
  // A surface of flat reflectance under a warm white looks grey to an observer adapted to that white,
  // but blue-ish water reflectance stays blue.
  const Spectrum white = global(clear_sky(20.0));
  Spectrum water = white;
  for (int i = 0; i < kSamples; ++i) water[i] *= 0.05 * std::exp(-(wavelength_nm(i) - 400.0) / 100.0);
  const glm::dvec3 rgb = adapted_linear_srgb(water, white);
  EXPECT_GT(rgb.b, rgb.g);
  EXPECT_GT(rgb.g, rgb.r);
  const glm::dvec3 raw = adapted_linear_srgb(white, cie_d65());  // not adapted: the warm cast shows
  EXPECT_GT(raw.r, raw.b);
}

TEST(OpticsColour, NoLightGivesBlack) {
  Spectrum zero{};
  EXPECT_EQ(adapted_linear_srgb(cie_d65(), zero), glm::dvec3(0.0));
  EXPECT_EQ(adapted_linear_srgb(zero, cie_d65()), glm::dvec3(0.0));
}

TEST(OpticsToneMap, MonotonicFromZeroToAtMostOne) {
  const ToneMapParams p;
  EXPECT_EQ(tone_map_luminance(0.0, p), 0.0);
  EXPECT_EQ(tone_map_luminance(-1.0, p), 0.0);
  double previous = 0.0;
  for (double L = 1e-6; L < 1e6; L *= 1.05) {
    const double v = tone_map_luminance(L, p);
    EXPECT_GE(v, previous) << L;
    EXPECT_LE(v, 1.0) << L;
    previous = v;
  }
  EXPECT_EQ(tone_map_luminance(1e9, p), 1.0);
  // Strictly increasing below the clip.
  EXPECT_LT(tone_map_luminance(0.5, p), tone_map_luminance(0.51, p));
}

TEST(OpticsToneMap, WhiteMapsToAboutPointEight) {
  const double white = tone_map_luminance(1.0);
  EXPECT_GT(white, 0.75);
  EXPECT_LT(white, 0.85);
  // Dark water colours stay close to proportional (the exponent γ_w/γ_d is about 1.06).
  EXPECT_NEAR(tone_map_luminance(0.03) / white, 0.03 / 0.8, 0.01);
  // The world adaptation luminance scales the input.
  EXPECT_NEAR(tone_map_luminance(0.5, {.world_adaptation_luminance = 0.5}), white, 1e-12);
}

TEST(OpticsToneMap, ToneMapKeepsTheHueAndClamps) {
  const glm::dvec3 rgb(0.1, 0.2, 0.4);
  const glm::dvec3 out = tone_map(rgb);
  EXPECT_NEAR(out.g / out.r, 2.0, 1e-12);
  EXPECT_NEAR(out.b / out.r, 4.0, 1e-12);
  EXPECT_NEAR(linear_srgb_luminance(out), tone_map_luminance(linear_srgb_luminance(rgb)), 1e-12);
  expect_near(tone_map(glm::dvec3(50.0)), glm::dvec3(1.0), 1e-9);
  EXPECT_EQ(tone_map(glm::dvec3(0.0)), glm::dvec3(0.0));
  const glm::dvec3 saturated = tone_map(glm::dvec3(-0.1, 0.3, 2.0));
  EXPECT_EQ(saturated.r, 0.0);
  EXPECT_EQ(saturated.b, 1.0);
}

TEST(OpticsToneMap, SrgbTransferFunction) {
  EXPECT_EQ(encode_srgb(glm::dvec3(0.0)), glm::dvec3(0.0));
  expect_near(encode_srgb(glm::dvec3(1.0)), glm::dvec3(1.0), 1e-12);
  EXPECT_NEAR(encode_srgb(glm::dvec3(0.5)).r, 1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055, 1e-12);
  EXPECT_NEAR(encode_srgb(glm::dvec3(0.002)).r, 12.92 * 0.002, 1e-12);
  // Continuous at the linear/power junction.
  EXPECT_NEAR(encode_srgb(glm::dvec3(0.0031308)).r, encode_srgb(glm::dvec3(0.0031309)).r, 1e-5);
  expect_near(encode_srgb(glm::dvec3(-1.0, 2.0, 0.0)), glm::dvec3(0.0, 1.0, 0.0), 1e-12);
}

TEST(OpticsSky, ExtraterrestrialBinsPreserveTheIntegral) {
  const CsvTable t = embedded_table_or_abort("astm_g173_380_780.csv");
  const std::vector<double> nm = numbers_or_abort(t, "wavelength_nm");
  const std::vector<double> e = numbers_or_abort(t, "extraterrestrial_W_m2_nm");
  double raw = 0.0;  // trapezoid over the 0.5/1 nm data
  for (std::size_t j = 0; j + 1 < nm.size(); ++j) raw += 0.5 * (e[j] + e[j + 1]) * (nm[j + 1] - nm[j]);
  const Spectrum& h0 = extraterrestrial_irradiance();
  double binned = 0.0;  // the end bins are half width
  for (int i = 0; i < kSamples; ++i) binned += h0[i] * (i == 0 || i == kSamples - 1 ? 2.5 : 5.0);
  EXPECT_NEAR(binned, raw, 1e-9 * raw);
  EXPECT_NEAR(h0[sample_index(500)], 1.9, 0.2);  // ~1.9 W m⁻² nm⁻¹ in the green
}

TEST(OpticsSky, NoSunBelowTheHorizon) {
  for (double e : {-30.0, -5.0, -0.1, 0.0}) {
    const SkyIrradiance s = clear_sky(e);
    EXPECT_EQ(s.sun_elevation_deg, e);
    for (int i = 0; i < kSamples; ++i) {
      EXPECT_EQ(s.sun[i], 0.0) << e;
      EXPECT_GE(s.sky[i], 0.0) << e;
      EXPECT_TRUE(std::isfinite(s.sky[i]));
    }
  }
}

TEST(OpticsSky, IrradianceGrowsWithElevation) {
  double previous_sun = 0.0, previous_total = 0.0;
  for (double e = 1.0; e <= 90.0; e += 1.0) {
    const SkyIrradiance s = clear_sky(e);
    const double sun = band_integral(s.sun), total = sun + band_integral(s.sky);
    EXPECT_GT(sun, previous_sun) << e;
    EXPECT_GT(total, previous_total) << e;
    previous_sun = sun, previous_total = total;
  }
}

TEST(OpticsSky, GlobalIrradianceAt60DegreesIsPlausible) {
  const SkyIrradiance s = clear_sky(60.0);
  const double sun = band_integral(s.sun), sky = band_integral(s.sky);
  RecordProperty("sun_W_m2", std::to_string(sun));
  RecordProperty("sky_W_m2", std::to_string(sky));
  // Clear sky, 380-780 nm: about 400-550 W m⁻² global (this model: 513, of which sky 69).
  EXPECT_GT(sun + sky, 400.0);
  EXPECT_LT(sun + sky, 550.0);
  EXPECT_GT(sky, 0.08 * (sun + sky));
  EXPECT_LT(sky, 0.25 * (sun + sky));
}

TEST(OpticsSky, TheSkyIsBlue) {
  const SkyIrradiance s = clear_sky(60.0);
  const auto share = [&](int nm) {
    return s.sky[sample_index(nm)] / (s.sun[sample_index(nm)] + s.sky[sample_index(nm)]);
  };
  EXPECT_GT(share(450), 1.5 * share(650));
  const glm::dvec2 sky_xy = chromaticity(spectrum_to_xyz(s.sky));
  EXPECT_LT(sky_xy.x, 0.29);  // the diffuse sky alone is well on the blue side of D65
}

TEST(OpticsSky, DaylightIsNearD65) {
  const glm::dvec2 d65 = chromaticity(spectrum_to_xyz(cie_d65()));
  const glm::dvec2 xy = chromaticity(spectrum_to_xyz(global(clear_sky(60.0))));
  EXPECT_LT(glm::length(xy - d65), 0.02) << xy.x << " " << xy.y;
}

TEST(OpticsSky, ParametersActInTheRightDirection) {
  const double clean = band_integral(clear_sky(40.0).sun);
  const double hazy = band_integral(clear_sky(40.0, {.aerosol_optical_depth_500nm = 0.5}).sun);
  EXPECT_LT(hazy, clean);
  const SkyIrradiance more_ozone = clear_sky(40.0, {.ozone_cm = 0.5});
  const SkyIrradiance base = clear_sky(40.0);
  EXPECT_LT(more_ozone.sun[sample_index(600)], base.sun[sample_index(600)]);
  EXPECT_DOUBLE_EQ(more_ozone.sun[sample_index(400)], base.sun[sample_index(400)]);  // no Chappuis absorption
  const SkyIrradiance high = clear_sky(40.0, {.surface_pressure_hpa = 700.0});
  EXPECT_LT(high.sky[sample_index(400)],
            base.sky[sample_index(400)]);  // less Rayleigh scattering at altitude
}

}  // namespace
}  // namespace lagoon::optics
