// The keyed random numbers and the initial spectrum h0(k): variance against the continuous spectrum, band
// layout, determinism and loop quantisation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "ocean/dispersion.h"
#include "ocean/initial_spectrum.h"
#include "ocean/random.h"
#include "ocean/spectrum.h"

namespace lagoon::ocean {
namespace {

TEST(OceanRandom, SameKeySameNumbersDifferentKeysDiffer) {
  EXPECT_EQ(gaussian_pair(7, 1, -3, 12), gaussian_pair(7, 1, -3, 12));
  const std::complex<double> base = gaussian_pair(7, 1, -3, 12);
  EXPECT_NE(base, gaussian_pair(8, 1, -3, 12));
  EXPECT_NE(base, gaussian_pair(7, 2, -3, 12));
  EXPECT_NE(base, gaussian_pair(7, 1, 3, 12));
  EXPECT_NE(base, gaussian_pair(7, 1, -3, -12));
  EXPECT_NE(base, gaussian_pair(7, 1, 12, -3));
  EXPECT_NE(gaussian_pair(0, 0, 0, 0), gaussian_pair(0, 0, 0, 1));
}

TEST(OceanRandom, StandardNormalMoments) {
  // 10^5 keys: the mean's standard error is 1/√n = 0.0032, the variance's √(2/n) = 0.0045; allow 4 σ.
  const int side = 316;
  double sum_r = 0, sum_i = 0, sum_rr = 0, sum_ii = 0, sum_ri = 0, n = 0, beyond_2 = 0;
  for (int mz = -side / 2; mz < side / 2; ++mz)
    for (int mx = -side / 2; mx < side / 2; ++mx) {
      const std::complex<double> z = gaussian_pair(42, 0, mx, mz);
      sum_r += z.real(), sum_i += z.imag(), sum_rr += z.real() * z.real(), sum_ii += z.imag() * z.imag();
      sum_ri += z.real() * z.imag(), n += 1;
      beyond_2 += (std::fabs(z.real()) > 2.0);
    }
  const double tol_mean = 4.0 / std::sqrt(n), tol_var = 4.0 * std::sqrt(2.0 / n);
  EXPECT_NEAR(sum_r / n, 0.0, tol_mean);
  EXPECT_NEAR(sum_i / n, 0.0, tol_mean);
  EXPECT_NEAR(sum_rr / n, 1.0, tol_var);
  EXPECT_NEAR(sum_ii / n, 1.0, tol_var);
  EXPECT_NEAR(sum_ri / n, 0.0, tol_mean);
  // Gaussian tails: P(|ξ| > 2) = 0.0455 (binomial σ ≈ 0.00066).
  EXPECT_NEAR(beyond_2 / n, 0.0455, 0.003);
}

TEST(OceanInitialSpectrum, BandsAreDisjointContiguousAndQuarterNyquist) {
  OceanParams p;
  p.cascades = {{2000.0, 512}, {250.0, 256}, {40.0, 128}, {9.0, 64}};
  const std::vector<CascadeBand> bands = cascade_bands(p);
  ASSERT_EQ(bands.size(), 4u);
  EXPECT_EQ(bands[0].k_min, 0.0);
  for (size_t c = 0; c < bands.size(); ++c) {
    EXPECT_DOUBLE_EQ(bands[c].k_max,
                     std::numbers::pi * p.cascades[c].resolution / (2.0 * p.cascades[c].patch_size_m));
    EXPECT_LT(bands[c].k_min, bands[c].k_max);
    if (c > 0) {
      EXPECT_EQ(bands[c].k_min, bands[c - 1].k_max);
    }
    // The shortest wave carried spans 4 texels: 2π/k_max = 4 L/N.
    EXPECT_NEAR(2.0 * std::numbers::pi / bands[c].k_max,
                4.0 * p.cascades[c].patch_size_m / p.cascades[c].resolution, 1e-12);
  }
}

size_t index_of(int mx, int mz, int n) {
  return static_cast<size_t>(mz < 0 ? mz + n : mz) * n + (mx < 0 ? mx + n : mx);
}

TEST(OceanInitialSpectrum, ZeroOutsideTheBandAndAtTheOrigin) {
  const OceanParams p;
  for (uint32_t c = 0; c < 3; ++c) {
    const CascadeSpectrum s = make_cascade_spectrum(p, c);
    const int n = static_cast<int>(s.resolution);
    ASSERT_EQ(s.h0.size(), static_cast<size_t>(n) * n);
    ASSERT_EQ(s.omega.size(), static_cast<size_t>(n) * n);
    EXPECT_EQ(s.h0[0], std::complex<float>(0.0f, 0.0f));
    size_t inside = 0;
    for (int mz = -n / 2; mz < n / 2; ++mz)
      for (int mx = -n / 2; mx < n / 2; ++mx) {
        const double k = 2.0 * std::numbers::pi / s.patch_size_m * std::hypot(mx, mz);
        const size_t i = index_of(mx, mz, n);
        if (k == 0.0 || k < s.band.k_min || k >= s.band.k_max) {
          ASSERT_EQ(s.h0[i], std::complex<float>(0.0f, 0.0f)) << c << " " << mx << " " << mz;
          ASSERT_EQ(s.omega[i], 0.0f);
        } else {
          ++inside;
          EXPECT_GT(s.omega[i], 0.0f);
        }
      }
    EXPECT_GT(inside, static_cast<size_t>(n * n / 10)) << c;
  }
  EXPECT_EQ(make_cascade_spectrum(p, 3).resolution, 0u);
}

// ∫∫ Ψ over the annulus [ka, kb): Simpson in ln k, trapezoid in θ.
double band_integral(const DirectionalSpectrum& psi, double ka, double kb) {
  ka = std::max(ka, 1e-4);
  const int nk = 1000, nt = 360;
  const double u0 = std::log(ka), h = (std::log(kb) - u0) / nk, dt = 2.0 * std::numbers::pi / nt;
  double sum = 0.0;
  for (int i = 0; i <= nk; ++i) {
    const double k = std::exp(u0 + i * h);
    double ring = 0.0;
    for (int j = 0; j < nt; ++j) ring += psi(k * std::cos(j * dt), k * std::sin(j * dt));
    sum += ((i == 0 || i == nk) ? 1.0 : (i % 2 ? 4.0 : 2.0)) * ring * dt * k * k;
  }
  return sum * h / 3.0;
}

// Var η carried by a cascade: the mean over seeds of Σ_k (|h0(k)|² + |h0(-k)|²) must equal Σ_k Ψ(k) Δk²
// (the expected variance of the surface) and the continuous ∫Ψ over the band. With Tessendorf's naive
// 1/√2 scaling (√2 more amplitude) the ratio would be 2.
void check_variance(OceanParams p, uint32_t cascade, double continuum_tolerance) {
  const DirectionalSpectrum psi(p);
  double expected = 0.0, integral = 0.0;
  std::vector<double> totals;
  for (uint32_t seed = 1; seed <= 64; ++seed) {
    p.seed = seed;
    const CascadeSpectrum s = make_cascade_spectrum(p, cascade);
    const int n = static_cast<int>(s.resolution);
    const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
    double total = 0.0;
    for (int mz = -n / 2 + 1; mz < n / 2; ++mz)
      for (int mx = -n / 2 + 1; mx < n / 2; ++mx) {
        total += std::norm(std::complex<double>(s.h0[index_of(mx, mz, n)])) +
                 std::norm(std::complex<double>(s.h0[index_of(-mx, -mz, n)]));
        if (seed == 1) {
          const double k = dk * std::hypot(mx, mz);
          if (k > 0.0 && k >= s.band.k_min && k < s.band.k_max) expected += psi(mx * dk, mz * dk) * dk * dk;
        }
      }
    if (seed == 1) integral = band_integral(psi, s.band.k_min, s.band.k_max);
    totals.push_back(total);
  }
  double mean = 0.0, var = 0.0;
  for (double t : totals) mean += t / totals.size();
  for (double t : totals) var += (t - mean) * (t - mean) / (totals.size() - 1);
  const double standard_error = std::sqrt(var / totals.size());
  std::printf("cascade %u: mean Σ|h0|² %.6g  Σ Ψ Δk² %.6g  ∫Ψ %.6g  (standard error %.2f %%)\n", cascade,
              mean, expected, integral, 100.0 * standard_error / mean);
  ASSERT_GT(expected, 0.0);
  EXPECT_LT(standard_error, 0.05 * expected);  // the statistical check below is sharp enough to see a ×2
  EXPECT_NEAR(mean, expected, std::max(4.0 * standard_error, 0.01 * expected));
  EXPECT_NEAR(mean, integral, 0.05 * integral);
  EXPECT_NEAR(expected, integral, continuum_tolerance * integral);
}

TEST(OceanInitialSpectrum, VarianceMatchesTheSpectrum) {
  OceanParams p;  // JONSWAP, cos-2s, U = 10 m/s, 100 km fetch; peak wavelength ≈ 60 m
  check_variance(p, 0, 0.05);
  check_variance(p, 1, 0.05);
  p.spectrum.type = SpectrumType::Tma;
  p.spectrum.spreading = Spreading::DonelanBanner;
  p.spectrum.swell = 0.6;
  p.depth_m = 15.0;
  p.spectrum.wind_direction_deg = 123.0;
  check_variance(p, 0, 0.05);
}

TEST(OceanInitialSpectrum, AmplitudeIsKeyedGaussianTimesHalfSqrtPsiDk) {
  OceanParams p;
  p.seed = 99;
  const CascadeSpectrum s = make_cascade_spectrum(p, 1);
  const DirectionalSpectrum psi(p);
  const int n = static_cast<int>(s.resolution);
  const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
  for (int mz = -n / 2; mz < n / 2; ++mz)
    for (int mx = -n / 2; mx < n / 2; ++mx) {
      const double k = dk * std::hypot(mx, mz);
      if (k < s.band.k_min || k >= s.band.k_max) continue;
      const std::complex<double> expected =
          gaussian_pair(99, 1, mx, mz) * std::sqrt(psi(mx * dk, mz * dk)) * dk / 2.0;
      const std::complex<double> got(s.h0[index_of(mx, mz, n)]);
      ASSERT_NEAR(std::abs(got - expected), 0.0, 1e-6 * std::abs(expected) + 1e-30) << mx << " " << mz;
    }
}

TEST(OceanInitialSpectrum, DeterministicAndKeyedByMode) {
  OceanParams p;
  const CascadeSpectrum a = make_cascade_spectrum(p, 0), b = make_cascade_spectrum(p, 0);
  ASSERT_EQ(a.h0.size(), b.h0.size());
  EXPECT_EQ(0, std::memcmp(a.h0.data(), b.h0.data(), a.h0.size() * sizeof(a.h0[0])));
  EXPECT_EQ(0, std::memcmp(a.omega.data(), b.omega.data(), a.omega.size() * sizeof(a.omega[0])));
  // Halving the resolution keeps every mode both grids carry: the random numbers are keyed, not streamed.
  p.cascades[0].resolution = 128;
  const CascadeSpectrum half = make_cascade_spectrum(p, 0);
  const int n = 128;
  size_t compared = 0;
  for (int mz = -n / 2; mz < n / 2; ++mz)
    for (int mx = -n / 2; mx < n / 2; ++mx) {
      const double k = 2.0 * std::numbers::pi / half.patch_size_m * std::hypot(mx, mz);
      if (k == 0.0 || k >= half.band.k_max) continue;
      ASSERT_EQ(half.h0[index_of(mx, mz, n)], a.h0[index_of(mx, mz, 256)]) << mx << " " << mz;
      ++compared;
    }
  EXPECT_GT(compared, 2000u);
  // A different seed changes the phases.
  p.cascades[0].resolution = 256;
  p.seed = 2;
  const CascadeSpectrum other = make_cascade_spectrum(p, 0);
  EXPECT_NE(0, std::memcmp(a.h0.data(), other.h0.data(), a.h0.size() * sizeof(a.h0[0])));
}

TEST(OceanInitialSpectrum, OmegaFollowsDispersionAndLoopQuantisation) {
  OceanParams p;
  p.depth_m = 20.0;
  const CascadeSpectrum free = make_cascade_spectrum(p, 1);
  p.loop_period_s = 30.0;
  const CascadeSpectrum looped = make_cascade_spectrum(p, 1);
  const double step = 2.0 * std::numbers::pi / 30.0;
  const int n = static_cast<int>(free.resolution);
  for (int mz = -n / 2; mz < n / 2; ++mz)
    for (int mx = -n / 2; mx < n / 2; ++mx) {
      const size_t i = index_of(mx, mz, n);
      if (free.omega[i] == 0.0f) continue;
      const double k = 2.0 * std::numbers::pi / free.patch_size_m * std::hypot(mx, mz);
      const double w0 = std::sqrt(9.81 * k * std::tanh(20.0 * k) * (1.0 + k * k * 0.074 / (1000.0 * 9.81)));
      ASSERT_NEAR(free.omega[i], w0, 1e-6 * w0);
      const double cycles = looped.omega[i] / step;
      ASSERT_NEAR(cycles, std::round(cycles), 1e-5);
      ASSERT_LE(looped.omega[i], free.omega[i] * (1.0 + 1e-6));
      ASSERT_GT(looped.omega[i], free.omega[i] - step * (1.0 + 1e-6));
    }
  EXPECT_EQ(0, std::memcmp(free.h0.data(), looped.h0.data(), free.h0.size() * sizeof(free.h0[0])));
}

}  // namespace
}  // namespace lagoon::ocean
