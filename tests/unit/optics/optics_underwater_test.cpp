// The underwater medium tables (optics/underwater.h) against closed forms: grey water (the same χ, σ at every
// wavelength) makes Φ act on a multiple of the white, so every channel must follow Beer–Lambert and the
// delta-Eddington split exactly. Jerlov types are checked against the LUT they must agree with and against
// the blur the issue asks for (turbid water blurs a reef at 10 m, clear water does not).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "optics/underwater.h"

namespace lagoon::optics {
namespace {

// Grey water with the seed's D = 1 unless asked: the closed forms below are the seed's eq. 4 (no path-length
// factor on the diffuse flows).
LutInputs grey_water(double chi, double sigma, double phase_x1, double diffuse_path_factor = 1.0) {
  LutInputs in;
  in.params.diffuse_path_factor = diffuse_path_factor;
  in.water.name = "grey";
  in.water.absorption_per_m.fill(chi);
  in.water.scattering_per_m.fill(sigma);
  in.params.type = "custom";
  in.params.phase = "constant";
  in.params.phase_x1 = phase_x1;
  in.sky = clear_sky(60.0);
  return in;
}

UnderwaterSample at(const LutInputs& in, double d, double z) {
  auto s = underwater_sample(in, d, z);
  EXPECT_TRUE(s) << s.error().message;
  return s ? *s : UnderwaterSample{};
}

void expect_channels_near(glm::dvec3 actual, double expected, double relative, const char* what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected, relative * expected) << what << " channel " << c;
}

TEST(OpticsUnderwater, NonScatteringGreyWaterIsBeerLambertAlongTheRayAndWithDepth) {
  const double chi = 0.2;
  const LutInputs in = grey_water(chi, 0.0, 0.0);
  const UnderwaterSample top = at(in, 0, 0);
  for (double z : {0.0, 3.0, 12.0})
    for (double d : {1.0, 5.0, 20.0}) {
      const UnderwaterSample s = at(in, d, z);
      // Along the ray: exp(−χd). With depth: the four-flow model's flows carry no path-length factor, so
      // without scattering both the direct and the diffuse downwelling light fall as exp(−χz).
      expect_channels_near(s.target / top.target, std::exp(-chi * (d + z)), 1e-9, "target");
      EXPECT_DOUBLE_EQ(s.blur, 0.0);
      // Nothing scatters, so the water adds no light in either direction.
      EXPECT_NEAR(glm::length(s.water_down) + glm::length(s.water_up), 0.0, 1e-12) << d << ", " << z;
    }
}

TEST(OpticsUnderwater, WithAPathLengthFactorTheDiffuseLightFallsFasterThanTheBeam) {
  // Non-scattering grey water with D = 2: the direct beam still falls as exp(−χz), the diffuse light as
  // exp(−2χz). So each channel is f·exp(−χz) + (1 − f)·exp(−2χz) with f its direct share at the surface: f
  // from z = 3 m predicts z = 12 m, and the direct share grows with depth.
  const double chi = 0.2;
  const LutInputs in = grey_water(chi, 0.0, 0.0, 2.0);
  const UnderwaterSample top = at(in, 0, 0);
  const glm::dvec3 r3 = at(in, 0, 3.0).target / top.target, r12 = at(in, 0, 12.0).target / top.target;
  for (int c = 0; c < 3; ++c) {
    const double f = (r3[c] - std::exp(-2 * chi * 3)) / (std::exp(-chi * 3) - std::exp(-2 * chi * 3));
    EXPECT_GT(f, 0.3) << c;
    EXPECT_LT(f, 1.0) << c;
    EXPECT_NEAR(r12[c], f * std::exp(-chi * 12) + (1 - f) * std::exp(-2 * chi * 12), 1e-9) << c;
  }
  EXPECT_GT(at(in, 0, 10.0).direct_share, top.direct_share + 0.1);
}

TEST(OpticsUnderwater, ForwardScatteringStaysOnTheRayBlurredAsDeltaEddingtonSays) {
  // X1 = 2.4: g = 0.8, forward peak f = g² = 0.64. Of σ, 0.64σ stays on the ray (blurred), 0.36σ leaves it.
  const double chi = 0.1, sigma = 0.5, f = 0.64;
  const LutInputs in = grey_water(chi, sigma, 2.4);
  for (double d : {0.5, 2.0, 10.0}) {
    const UnderwaterSample s = at(in, d, 4.0), near = at(in, 0.0, 4.0);
    expect_channels_near(s.target / near.target, std::exp(-(chi + sigma * (1 - f)) * d), 1e-9, "target");
    EXPECT_NEAR(s.blur, 1.0 - std::exp(-sigma * f * d), 1e-9) << d;
  }
  // Isotropic scattering has no forward peak: nothing arrives blurred, all of σ leaves the ray.
  const LutInputs iso = grey_water(chi, sigma, 0.0);
  const UnderwaterSample s = at(iso, 3.0, 4.0), near = at(iso, 0.0, 4.0);
  expect_channels_near(s.target / near.target, std::exp(-(chi + sigma) * 3.0), 1e-9, "isotropic target");
  EXPECT_NEAR(s.blur, 0.0, 1e-12);
}

TEST(OpticsUnderwater, TheWaterAddsLightThatSaturatesWithDistance) {
  const LutInputs in = grey_water(0.1, 0.5, 0.0);
  const double epsilon = 0.6;  // isotropic: nothing of σ stays on the ray
  const UnderwaterSample far = at(in, 500.0, 4.0);
  ASSERT_GT(far.water_down.y, 0.0);
  ASSERT_GT(far.water_up.y, 0.0);
  for (double d : {0.3, 1.0, 4.0}) {
    const UnderwaterSample s = at(in, d, 4.0);
    const double saturation = 1.0 - std::exp(-epsilon * d);
    expect_channels_near(s.water_down / far.water_down, saturation, 1e-9, "down");
    expect_channels_near(s.water_up / far.water_up, saturation, 1e-9, "up");
  }
  // Down-welling light is brighter than up-welling: looking up, the water is brighter than looking down.
  EXPECT_GT(far.water_up.y, far.water_down.y);
}

TEST(OpticsUnderwater, LookingDownFromJustBelowTheSurfaceSeesTheLutsDeepWaterColour) {
  for (const char* type : {"jerlov-I", "jerlov-III", "jerlov-5C", "jerlov-9C"}) {
    WaterParams p;
    p.type = type;
    auto in = lut_inputs(p, 45.0);
    ASSERT_TRUE(in) << in.error().message;
    in->params.lut_size = 2;
    auto lut = build_water_lut(*in);
    ASSERT_TRUE(lut) << lut.error().message;
    const UnderwaterSample s = at(*in, 2000.0, 0.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.water_down[c], lut->deep_colour[c], 1e-6) << type << " " << c;
  }
}

double blur_at_10m(const char* type) {
  WaterParams p;
  p.type = type;
  auto in = lut_inputs(p, 60.0);
  EXPECT_TRUE(in);
  return in ? at(*in, 10.0, 6.0).blur : -1;
}

TEST(OpticsUnderwater, TurbidWaterBlursAReefAtTenMetresClearWaterDoesNot) {
  // Measured: jerlov-I 0.000, IB 0.355, 1C 0.957, 9C 1.000 (of the light from the reef, the share that
  // arrives forward-scattered).
  EXPECT_LT(blur_at_10m("jerlov-I"), 0.05);
  EXPECT_LT(blur_at_10m("jerlov-IB"), 0.5);
  EXPECT_GT(blur_at_10m("jerlov-1C"), 0.9);
  EXPECT_GT(blur_at_10m("jerlov-9C"), 0.99);
}

TEST(OpticsUnderwater, TheSunsDirectShareFallsWithDepthWhereTheWaterScatters) {
  // Without scattering the direct beam and the diffuse light decay alike (no path-length factor): the share
  // stays what the surface let in.
  const LutInputs clear = grey_water(0.2, 0.0, 0.0);
  const double top = at(clear, 0, 0).direct_share;
  EXPECT_GT(top, 0.5);
  EXPECT_LT(top, 1.0);
  for (double z : {2.0, 10.0}) EXPECT_NEAR(at(clear, 0, z).direct_share, top, 1e-9) << z;
  // Scattering turns the beam into diffuse light: the share falls.
  WaterParams p;
  p.type = "jerlov-1C";
  auto in = lut_inputs(p, 60.0);
  ASSERT_TRUE(in);
  const double s1 = at(*in, 0, 1).direct_share, s10 = at(*in, 0, 10).direct_share;
  EXPECT_GT(s1, s10 + 0.1) << s1 << " at 1 m, " << s10 << " at 10 m";
}

TEST(OpticsUnderwater, TableHoldsTheSamplesOnSquaredAxes) {
  WaterParams p;
  p.type = "jerlov-1C";
  auto in = lut_inputs(p, 60.0);
  ASSERT_TRUE(in);
  auto t = build_underwater_table(*in, {.d_count = 9, .z_count = 5, .d_max_m = 80, .z_max_m = 40});
  ASSERT_TRUE(t) << t.error().message;
  ASSERT_EQ(t->target.size(), 9u * 5u * 4u);
  EXPECT_DOUBLE_EQ(t->d_m[4], 80.0 * 0.25);
  EXPECT_DOUBLE_EQ(t->z_m[2], 40.0 * 0.25);
  for (auto [i, j] : {std::pair{0u, 0u}, {4u, 2u}, {8u, 4u}, {3u, 1u}}) {
    const UnderwaterSample s = at(*in, t->d_m[i], t->z_m[j]);
    const float* target = t->at(t->target, i, j, 4);
    const float* down = t->at(t->water_down, i, j, 3);
    const float* up = t->at(t->water_up, i, j, 3);
    for (int c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(target[c], float(s.target[c])) << i << "," << j;
      EXPECT_FLOAT_EQ(down[c], float(s.water_down[c])) << i << "," << j;
      EXPECT_FLOAT_EQ(up[c], float(s.water_up[c])) << i << "," << j;
    }
    EXPECT_FLOAT_EQ(target[3], float(s.blur));
  }
  // Downwelling light dims with depth at a rate between clear ocean's and turbid coast's.
  EXPECT_GT(t->kd_luminance_per_m, 0.05);
  EXPECT_LT(t->kd_luminance_per_m, 0.5);
}

TEST(OpticsUnderwater, RefusesAbsurdAxesAndDistances) {
  const LutInputs in = grey_water(0.1, 0.1, 0.0);
  EXPECT_FALSE(build_underwater_table(in, {.d_count = 1}));
  EXPECT_FALSE(build_underwater_table(in, {.d_max_m = 0}));
  EXPECT_FALSE(build_underwater_table(in, {.z_max_m = INFINITY}));
  EXPECT_FALSE(underwater_sample(in, -1.0, 0.0));
  EXPECT_FALSE(underwater_sample(in, 1.0, NAN));
}

}  // namespace
}  // namespace lagoon::optics
