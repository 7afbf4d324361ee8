// The sum of sines (ocean/sines.h; seed 001 eqs. 1-3, issue 15): an integer power of a sine is exactly its
// few harmonics, and WaveQuery of model sines answers the direct sum of eq. 2 within its bound.
#include "ocean/sines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/wave_query.h"

namespace lagoon::test {
namespace {

TEST(Sines, APowerOfASineIsItsHarmonics) {
  for (uint32_t p = 1; p <= 8; ++p) {
    const auto c = ocean::sine_power_coefficients(p);
    ASSERT_EQ(c.size(), p + 1);
    double mean = 1;  // C(2p, p) / 4^p, the mean of sin^(2p)
    for (uint32_t j = 1; j <= p; ++j) mean *= double(p + j) / j / 4;
    EXPECT_NEAR(c[0].real(), mean, 1e-14) << p;
    for (double s : {0.1, 1.3, 2.9, 4.4, 6.0}) {
      std::complex<double> sum = c[0];
      for (uint32_t m = 1; m <= p; ++m) sum += 2.0 * (c[m] * std::polar(1.0, m * s)).real();
      EXPECT_NEAR(sum.real(), std::pow(0.5 * (1 + std::sin(s)), double(p)), 1e-13) << p << " at " << s;
    }
  }
}

TEST(Sines, WaveQueryOfModelSinesAnswersTheDirectSum) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Sines;
  p.choppiness = 0;
  p.cascades = {{200, 128}, {20, 128}};
  p.sines.waves = {{0.6, 37, 20, 3, 33}, {0.2, 9.3, -40, 1, 0}, {0.05, 1.9, 75, 2, 200}};
  ocean::WaveQuery query(p);
  double worst = 0, bound = 0, largest = 0;
  for (int i = 0; i < 40; ++i) {
    const double x = -50 + 2.71 * i, z = 13 - 1.93 * i, t = 0.37 * i;
    const double exact = ocean::sines_height(p, t, x, z);
    const ocean::WaveSample s = query.sample(t, x, z);
    worst = std::max(worst, std::abs(s.height - exact));
    largest = std::max(largest, std::abs(exact));
    bound = s.error_bound_m;
  }
  RecordProperty("worst_height_error_m", std::to_string(worst));
  RecordProperty("bound_m", std::to_string(bound));
  EXPECT_GT(largest, 0.3);
  EXPECT_LE(worst, bound + 1e-12);  // the waves are summed directly: bound 0, rounding only
  EXPECT_LT(worst, 0.01);
}

TEST(Sines, EachWaveOscillatesAtItsLawsFrequencyOnTheLattice) {
  // One wave on the 200 m lattice: its fundamental has the deep-water ω = sqrt(g k) of its lattice k (its
  // harmonics m k get m ω, so the whole shape travels at ω/k).
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Sines;
  p.choppiness = 0;
  p.cascades = {{200, 128}};
  p.sines.waves = {{0.5, 40, 90, 3}};
  const auto l = ocean::sines_lattice(p)[0];
  const double k = std::hypot(l.wave.k.x, l.wave.k.y);
  EXPECT_NEAR(l.omega / k, std::sqrt(9.81 / k), 1e-12);
  EXPECT_NEAR(2 * std::numbers::pi / k, 40.0, 0.2);  // 200 m / 5 on the lattice
}

// Sines sampled from the spectrum: the surface's variance Σ (A/2)²/2 is the spectrum's over the sampled band
// (PM written out and integrated by Simpson; 3 % allowed), and the direct sum and the cascades agree on it.
TEST(Sines, SinesSampledFromTheSpectrumCarryItsEnergy) {
  ocean::OceanParams p;
  p.model = ocean::SurfaceModel::Sines;
  p.choppiness = 0;
  p.spectrum.type = ocean::SpectrumType::PiersonMoskowitz;
  p.spectrum.wind_speed_mps = 9;
  p.sines.spectrum_waves = 32;
  const auto waves = ocean::sines_wave_specs(p);
  ASSERT_EQ(waves.size(), 32u);
  double variance = 0;
  for (const auto& w : waves) {
    EXPECT_EQ(w.steepness, 1u);
    variance += 0.5 * std::pow(0.5 * w.amplitude_m, 2);
  }
  const double g = 9.81, wp = 2 * std::numbers::pi * 0.13 * g / 9, lo = 0.6 * wp, hi = 4 * wp;
  const auto pm = [&](double w) {
    return 0.0081 * g * g / std::pow(w, 5) * std::exp(-1.25 * std::pow(wp / w, 4));
  };
  double band = 0;
  const int n = 20000;
  for (int i = 0; i <= n; ++i) band += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * pm(lo + (hi - lo) * i / n);
  band *= (hi - lo) / n / 3;
  RecordProperty("hs_sampled_m", std::to_string(4 * std::sqrt(variance)));
  RecordProperty("hs_of_band_m", std::to_string(4 * std::sqrt(band)));
  EXPECT_NEAR(variance, band, 0.06 * band);  // 3 % in Hs
  ocean::WaveQuery query(p);
  for (double x : {3.0, -41.5})
    EXPECT_LE(std::abs(query.sample(1.5, x, 7).height - ocean::sines_height(p, 1.5, x, 7)),
              query.sample(1.5, x, 7).error_bound_m);
}

}  // namespace
}  // namespace lagoon::test
