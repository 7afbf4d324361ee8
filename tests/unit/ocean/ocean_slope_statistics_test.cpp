// Mean square slope: the sampled cascade's sum against the slopes of its own CPU field (Parseval, an
// independent path through the FFT), the continuous spectrum's integral against the sampled cascade, and the
// total against Cox & Munk's measured glitter slopes.
#include <gtest/gtest.h>

#include <cmath>

#include "ocean/short_waves.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectral_fields.h"

namespace lagoon::test {
namespace {

using ocean::Field;

ocean::OceanParams ocean_with(std::vector<ocean::CascadeParams> cascades, double wind = 10.0) {
  ocean::OceanParams p;
  p.spectrum.wind_speed_mps = wind;
  p.cascades = std::move(cascades);
  return p;
}

TEST(SlopeStatistics, CascadeSumEqualsTheFieldsMeanSquareSlope) {
  const auto params = ocean_with({{200.0, 128}, {20.0, 128}});
  for (uint32_t c = 0; c < 2; ++c) {
    const auto s = ocean::make_cascade_spectrum(params, c);
    const Field slopes[] = {Field::SlopeX, Field::SlopeZ};
    double field_mss = 0;
    const double times[] = {0.0, 3.7, 11.2};
    for (double t : times) {
      const auto f = ocean::evaluate_fields(s, t, slopes, ocean::cpu_inverse_fft());
      double sum = 0;
      for (size_t i = 0; i < f[0].size(); ++i) sum += f[0][i] * f[0][i] + f[1][i] * f[1][i];
      field_mss += sum / double(f[0].size()) / std::size(times);
    }
    const double mss = ocean::mean_square_slope(s);
    ASSERT_GT(mss, 0) << c;
    EXPECT_NEAR(field_mss / mss, 1.0, 0.02) << "cascade " << c;
  }
}

TEST(SlopeStatistics, HeightVarianceEqualsTheFieldsVariance) {
  const auto params = ocean_with({{200.0, 128}, {20.0, 128}});
  for (uint32_t c = 0; c < 2; ++c) {
    const auto s = ocean::make_cascade_spectrum(params, c);
    const Field height[] = {Field::Height};
    double field_var = 0;
    const double times[] = {0.0, 3.7, 11.2};
    for (double t : times) {
      const auto f = ocean::evaluate_fields(s, t, height, ocean::cpu_inverse_fft());
      double sum = 0;
      for (double h : f[0]) sum += h * h;
      field_var += sum / double(f[0].size()) / std::size(times);
    }
    ASSERT_GT(ocean::height_variance(s), 0) << c;
    EXPECT_NEAR(field_var / ocean::height_variance(s), 1.0, 0.02) << "cascade " << c;
  }
}

TEST(SlopeStatistics, SpectrumIntegralMatchesTheSampledBand) {
  const auto params = ocean_with({{200.0, 256}, {20.0, 256}});
  const auto bands = ocean::cascade_bands(params);
  // Cascade 1's band holds many modes, so its sampled sum is close to its expectation.
  const auto s = ocean::make_cascade_spectrum(params, 1);
  const double integral = ocean::spectrum_mean_square_slope(params, bands[1].k_min, bands[1].k_max);
  EXPECT_NEAR(ocean::mean_square_slope(s) / integral, 1.0, 0.05);
  EXPECT_EQ(ocean::spectrum_mean_square_slope(params, 5.0, 5.0), 0.0);
  EXPECT_EQ(ocean::spectrum_mean_square_slope(params, 5.0, 1.0), 0.0);
}

TEST(SlopeStatistics, UnresolvedSlopesAreTheSpectrumBeyondTheCut) {
  // A cut inside cascade 1's band: its sampled modes beyond it against the continuous spectrum's integral,
  // plus Elfouhaily's short waves beyond the band (the glint's).
  const auto params = ocean_with({{200.0, 256}, {20.0, 256}});
  const auto bands = ocean::cascade_bands(params);
  const std::vector<ocean::CascadeSpectrum> spectra{ocean::make_cascade_spectrum(params, 0),
                                                    ocean::make_cascade_spectrum(params, 1)};
  const double cut = std::sqrt(bands[1].k_min * bands[1].k_max);
  const ocean::SlopeMoments band = ocean::spectrum_slope_moments(params, cut, bands[1].k_max);
  const ocean::SlopeMoments rest = ocean::short_wave_slope_moments(params, bands[1].k_max);
  const ocean::SlopeMoments m = ocean::unresolved_slope_moments(params, spectra, 2, cut);
  EXPECT_NEAR((m.xx + m.zz) / (band.xx + band.zz + rest.xx + rest.zz), 1.0, 0.05);
  EXPECT_NEAR(m.xx / (band.xx + rest.xx), 1.0, 0.05);  // along the wind, not only in sum
  // Beyond every cascade only the short waves are left; with cascade 1 not drawn, the glint's short waves
  // stand for its band beyond the cut.
  const double far = 2 * bands[1].k_max;
  const ocean::SlopeMoments beyond = ocean::unresolved_slope_moments(params, spectra, 2, far);
  const ocean::SlopeMoments short_only = ocean::short_wave_slope_moments(params, far);
  EXPECT_DOUBLE_EQ(beyond.xx + beyond.zz, short_only.xx + short_only.zz);
  const ocean::SlopeMoments one = ocean::unresolved_slope_moments(params, spectra, 1, cut);
  const ocean::SlopeMoments after_first = ocean::short_wave_slope_moments(params, cut);
  EXPECT_NEAR((one.xx + one.zz) / (after_first.xx + after_first.zz), 1.0, 1e-9);
}

TEST(SlopeStatistics, TotalIsWithinCoxAndMunksRange) {
  // Bounds tight enough to catch a factor √2 in either direction.
  // Cox & Munk (1954), clean surface: mss = 0.003 + 5.12e-3 U ± 0.004, U at 12.5 m (about U10 here).
  // At 15 m/s the JONSWAP tail gives 0.62 of Cox & Munk (breaking and spray steepen real seas), so only
  // moderate winds are held to it.
  for (double wind : {5.0, 10.0}) {
    const auto params = ocean_with({{1000.0, 256}}, wind);
    const double mss = ocean::spectrum_mean_square_slope(params, 1e-3, ocean::kCapillaryCutoffK);
    const double cox_munk = 0.003 + 5.12e-3 * wind;
    EXPECT_GT(mss, 0.65 * cox_munk) << wind;
    EXPECT_LT(mss, 1.4 * cox_munk) << wind;
  }
}

}  // namespace
}  // namespace lagoon::test
