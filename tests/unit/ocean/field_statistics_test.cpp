// What lagoon compare measures (ocean/field_statistics.h), against closed forms: one lattice wave A cos(k·x)
// has Hs = 4 A / sqrt(2), its own wavevector as the peak, correlation 1 one patch away and -1 half a
// wavelength away; the FFT ocean's field, averaged over seeds, carries the target spectrum's band energies.
#include "ocean/field_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/initial_spectrum.h"
#include "ocean/spectral_fields.h"

namespace lagoon::test {
namespace {

ocean::HeightGrid wave(uint32_t n, double patch, int mx, int mz, double amplitude) {
  ocean::HeightGrid g{.n = n, .patch_m = patch, .height = std::vector<double>(size_t{n} * n)};
  const double dk = 2 * std::numbers::pi / patch, texel = patch / n;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i)
      g.height[size_t{j} * n + i] = amplitude * std::cos(dk * (mx * i + mz * j) * texel + 0.3);
  return g;
}

TEST(FieldStatistics, OneWaveHasItsClosedForms) {
  const std::vector<ocean::HeightGrid> grids{wave(128, 200, 3, 5, 0.7)};
  EXPECT_NEAR(ocean::significant_height(grids), 4 * 0.7 / std::sqrt(2.0), 1e-9);
  const glm::dvec2 k = ocean::peak_wavevector(ocean::mode_energy(grids.front()));
  const double dk = 2 * std::numbers::pi / 200;
  EXPECT_NEAR(k.x, 3 * dk, 1e-12);
  EXPECT_NEAR(k.y, 5 * dk, 1e-12);
  EXPECT_NEAR(ocean::tiling_correlation(grids, 200), 1.0, 1e-9);
  // Half a wavelength along x is half a wave along z too only for an axis wave.
  const std::vector<ocean::HeightGrid> axis{wave(128, 200, 4, 0, 0.7)};
  EXPECT_NEAR(ocean::tiling_correlation(axis, 25), 0.5 * (-1.0 + 1.0), 1e-6);  // x: -1, z: +1 (constant)
}

TEST(FieldStatistics, TheFftOceansBandsCarryTheTargetsEnergy) {
  ocean::OceanParams p;
  p.cascades = {{300, 128}};
  std::vector<double> measured, target;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    p.seed = uint32_t(seed);
    const ocean::CascadeSpectrum s = ocean::make_cascade_spectrum(p, 0);
    const ocean::Field height = ocean::Field::Height;
    auto fields = ocean::evaluate_fields(s, 0.0, std::span(&height, 1), ocean::cpu_inverse_fft(1));
    ocean::HeightGrid g{.n = 128, .patch_m = 300, .height = fields[0]};
    const ocean::BandEnergies b =
        ocean::band_energies(ocean::mode_energy(g), p, 2 * std::numbers::pi / 300, s.band.k_max, 8);
    measured.resize(b.measured.size()), target = b.target;
    for (size_t i = 0; i < b.measured.size(); ++i) measured[i] += b.measured[i] / seeds;
  }
  double diff = 0, norm = 0;
  for (size_t i = 0; i < target.size(); ++i)
    diff += std::pow(measured[i] - target[i], 2), norm += target[i] * target[i];
  RecordProperty("band_energy_error_8_seeds", std::to_string(std::sqrt(diff / norm)));
  EXPECT_LT(std::sqrt(diff / norm), 0.2);  // 0.137 with these seeds
  // A field with sqrt(2) times the amplitude has twice the energy: the error is 1.
  diff = 0;
  for (size_t i = 0; i < target.size(); ++i) diff += std::pow(2 * measured[i] - target[i], 2);
  EXPECT_GT(std::sqrt(diff / norm), 0.8);
}

}  // namespace
}  // namespace lagoon::test
