// The sea without its short waves (ocean/band_limit.h, WaveQueryOptions): what the bodies' buoyancy samples.
// A band-limited, heights-only WaveQuery answers the direct sum of exactly the modes below the cut (modes
// filtered here from the full spectra, independently of band_limited's smaller grids) within its bound, and
// its heights-only answers equal the full query's with the same cut.
#include "ocean/band_limit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ocean/local_heights.h"
#include "ocean/wave_query.h"
#include "support/direct_sum.h"
#include "support/shipped_scene.h"

namespace lagoon::test {
namespace {

// The spectra with every mode at |k| >= k_cut set to zero, on their own grids.
std::vector<ocean::CascadeSpectrum> filtered(std::vector<ocean::CascadeSpectrum> spectra, double k_cut) {
  for (ocean::CascadeSpectrum& s : spectra) {
    const uint32_t n = s.resolution;
    const double dk = 2 * std::numbers::pi / s.patch_size_m;
    for (uint32_t iz = 0; iz < n; ++iz)
      for (uint32_t ix = 0; ix < n; ++ix) {
        const double mx = ix < n / 2 ? double(ix) : double(ix) - n,
                     mz = iz < n / 2 ? double(iz) : double(iz) - n;
        if (dk * std::hypot(mx, mz) >= k_cut) s.h0[size_t(iz) * n + ix] = 0;
      }
  }
  return spectra;
}

TEST(BandLimit, TheHarboursSeaForBuoyancyOnSmallerGrids) {
  const scene::Scene s = shipped_scene("harbour");
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  const double k_cut = ocean::lattice_wavenumber({});  // 2 m waves and longer
  EXPECT_NEAR(k_cut, std::numbers::pi, 1e-12);
  // 400 m: all its band (k < 1.0) on 256²; 60 m: k up to π (30 modes) on 128²; 8 m: nothing that long.
  EXPECT_EQ(ocean::band_limited(spectra[0], k_cut).resolution, 256u);
  EXPECT_EQ(ocean::band_limited(spectra[1], k_cut).resolution, 128u);
  EXPECT_EQ(ocean::band_limited(spectra[2], k_cut).resolution, 0u);
}

TEST(BandLimit, AHeightsOnlyQueryAnswersTheSumOfTheLongWaves) {
  // Heights at rest = at the point, and the deep sea's (its lattices not moved over the floor).
  scene::Scene s = shipped_scene("harbour", {"ocean.choppiness=0", "ocean.shoaling=false"});
  const auto spectra = ocean::make_cascade_spectra(s.ocean);
  const double k_cut = ocean::lattice_wavenumber({});
  ocean::WaveQuery cut(s.ocean, spectra, {.max_wavenumber = k_cut, .heights_only = true});
  ocean::WaveQuery cut_full(s.ocean, spectra, {.max_wavenumber = k_cut});
  const auto reference = filtered(spectra, k_cut);
  const double t = 7.3;
  double worst = 0, bound = 0, short_waves = 0;
  for (int i = 0; i < 24; ++i) {
    const double x = -31.7 + 5.3 * i, z = 12.9 - 3.1 * i;
    const ocean::WaveSample a = cut.sample(t, x, z), b = cut_full.sample(t, x, z);
    EXPECT_NEAR(a.height, b.height, 1e-12);
    const double exact = direct_sum(reference, ocean::Field::Height, t, x, z);
    worst = std::max(worst, std::abs(a.height - exact));
    bound = a.error_bound_m;
    short_waves = std::max(short_waves, std::abs(direct_sum(spectra, ocean::Field::Height, t, x, z) - exact));
  }
  RecordProperty("worst_error_m", std::to_string(worst));
  RecordProperty("bound_m", std::to_string(bound));
  RecordProperty("largest_short_wave_part_m", std::to_string(short_waves));
  EXPECT_LE(worst, bound);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(short_waves, 5 * worst) << "the cut left out nothing measurable";
}

}  // namespace
}  // namespace lagoon::test
