// Seed 000 eq. 10 (optics/rough_surface.h): the surface coefficients averaged over the sea's facets, over a
// generated patch's normals (the document's way) and over the Gaussian slope distribution of the spectrum's
// slope moments (issue 16). The two agree within 1 %; both are the flat surface's exactly at zero slope; and
// the waves move the coefficients by more than that, so the agreement is a check that can fail.
#include "optics/rough_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/initial_spectrum.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectral_fields.h"

namespace lagoon::test {
namespace {

using optics::SurfaceCoefficients;
constexpr double kWater = 1.333;

// Toward a sun at a compass azimuth (clockwise from north, -z, as the wind's direction): 30 is downwind of
// the test sea's wind, 120 across it.
glm::dvec3 sun_at(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * std::numbers::pi / 180, a = azimuth_deg * std::numbers::pi / 180;
  return {std::sin(z) * std::sin(a), std::cos(z), -std::sin(z) * std::cos(a)};
}

void expect_same(const SurfaceCoefficients& a, const SurfaceCoefficients& b) {
  EXPECT_EQ(a.r_dd, b.r_dd);
  EXPECT_EQ(a.t_dd, b.t_dd);
  EXPECT_EQ(a.r_ff, b.r_ff);
  EXPECT_EQ(a.t_ff, b.t_ff);
  EXPECT_EQ(a.rw_ff, b.rw_ff);
  EXPECT_EQ(a.rw_dd, b.rw_dd);
}

TEST(RoughSurface, AtZeroSlopeBothAreTheFlatSurface) {
  const std::vector<glm::dvec2> still(64, glm::dvec2(0));
  for (double zenith : {0.0, 40.0, 80.0}) {
    const SurfaceCoefficients flat = optics::surface_coefficients(kWater, zenith * std::numbers::pi / 180);
    expect_same(optics::patch_surface_coefficients(kWater, sun_at(zenith, 30), still), flat);
    expect_same(optics::gaussian_surface_coefficients(kWater, sun_at(zenith, 30), {}), flat);
    expect_same(optics::wavy_surface_coefficients(kWater, zenith * std::numbers::pi / 180, {}), flat);
  }
}

// The slopes of a 12 m/s sea on a 256² grid over the first patch (two cascades summed, at t = 0), and the
// slope moments of the same cascades' amplitudes.
struct Sea {
  std::vector<glm::dvec2> slopes;
  optics::SlopeCovariance covariance;
};

Sea sea() {
  ocean::OceanParams p;
  p.spectrum.wind_speed_mps = 12;
  p.spectrum.wind_direction_deg = 30;
  p.cascades = {{250, 256}, {25, 256}};
  Sea out;
  std::vector<std::vector<std::vector<double>>> fields;
  for (uint32_t c = 0; c < 2; ++c) {
    const ocean::CascadeSpectrum s = ocean::make_cascade_spectrum(p, c);
    const ocean::Field wanted[] = {ocean::Field::SlopeX, ocean::Field::SlopeZ};
    fields.push_back(ocean::evaluate_fields(s, 0.0, wanted, ocean::cpu_inverse_fft(2)));
    const ocean::SlopeMoments m = ocean::slope_moments(s);
    out.covariance.xx += m.xx, out.covariance.zz += m.zz, out.covariance.xz += m.xz;
  }
  // Point (i, j) of the first grid; the second cascade's texel under it (25 m patch: 10.24 of its texels per
  // texel of the first, so the points sample it all).
  for (uint32_t j = 0; j < 256; ++j)
    for (uint32_t i = 0; i < 256; ++i) {
      const size_t a = size_t{j} * 256 + i;
      const size_t b = size_t((j * 1024 / 100) % 256) * 256 + (i * 1024 / 100) % 256;
      out.slopes.push_back({fields[0][0][a] + fields[1][0][b], fields[0][1][a] + fields[1][1][b]});
    }
  return out;
}

TEST(RoughSurface, ThePatchAndTheGaussianAgreeWithinOnePercent) {
  const Sea s = sea();
  RecordProperty("mean_square_slope", std::to_string(s.covariance.mean_square()));
  for (double zenith : {10.0, 45.0, 70.0})
    for (double azimuth : {30.0, 120.0}) {
      const glm::dvec3 sun = sun_at(zenith, azimuth);
      const SurfaceCoefficients patch = optics::patch_surface_coefficients(kWater, sun, s.slopes);
      const SurfaceCoefficients gauss = optics::gaussian_surface_coefficients(kWater, sun, s.covariance);
      const SurfaceCoefficients flat = optics::surface_coefficients(kWater, zenith * std::numbers::pi / 180);
      for (auto [name, member] : {std::pair{"r_dd", &SurfaceCoefficients::r_dd},
                                  {"t_dd", &SurfaceCoefficients::t_dd},
                                  {"r_ff", &SurfaceCoefficients::r_ff},
                                  {"t_ff", &SurfaceCoefficients::t_ff},
                                  {"rw_ff", &SurfaceCoefficients::rw_ff},
                                  {"tw_ff", &SurfaceCoefficients::tw_ff}}) {
        EXPECT_NEAR(patch.*member, gauss.*member, 0.01 * gauss.*member)
            << name << " at zenith " << zenith << ", azimuth " << azimuth << " (flat: " << flat.*member
            << ")";
      }
    }
  // The check can fail: slopes √2 times too steep (the covariance doubled) move r_dd at a low sun by more
  // than 1 %.
  optics::SlopeCovariance doubled = s.covariance;
  doubled.xx *= 2, doubled.zz *= 2, doubled.xz *= 2;
  const glm::dvec3 low = sun_at(70, 30);
  const SurfaceCoefficients patch = optics::patch_surface_coefficients(kWater, low, s.slopes);
  const SurfaceCoefficients steep = optics::gaussian_surface_coefficients(kWater, low, doubled);
  RecordProperty("r_dd_70_patch", std::to_string(patch.r_dd));
  RecordProperty("r_dd_70_doubled", std::to_string(steep.r_dd));
  EXPECT_GT(std::abs(steep.r_dd - patch.r_dd), 0.01 * patch.r_dd);
  // Near grazing the facets tilted toward the sun reflect far less than the flat mirror.
  const SurfaceCoefficients grazing = optics::patch_surface_coefficients(kWater, sun_at(85, 30), s.slopes);
  const SurfaceCoefficients mirror = optics::surface_coefficients(kWater, 85 * std::numbers::pi / 180);
  RecordProperty("r_dd_85_flat", std::to_string(mirror.r_dd));
  RecordProperty("r_dd_85_patch", std::to_string(grazing.r_dd));
  EXPECT_LT(grazing.r_dd, 0.9 * mirror.r_dd);
}

}  // namespace
}  // namespace lagoon::test
