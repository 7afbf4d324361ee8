// CPU field evaluation: our CPU FFT against FFTW, the real-field packing (Hermitian symmetry), and the
// time derivative against a finite difference.
#include <gtest/gtest.h>

#include <random>

#include "fft/cpu_fft.h"
#include "ocean/band_limit.h"
#include "ocean/spectral_fields.h"
#include "support/fftw_reference.h"

namespace lagoon::test {
namespace {

using ocean::Field;

ocean::OceanParams small_ocean() {
  ocean::OceanParams p;
  p.cascades = {{200.0, 64}};
  return p;
}

TEST(CpuFft, MatchesFftw) {
  for (uint32_t n : {2u, 8u, 64u, 256u, 512u}) {
    for (bool inverse : {false, true}) {
      std::mt19937 rng(n);
      std::normal_distribution<double> g;
      std::vector<std::complex<double>> a(size_t{n} * n * 3);
      for (auto& v : a) v = {g(rng), g(rng)};
      auto b = a;
      fft::CpuFft2d(n, inverse).transform(a, 3, 2);
      fftw_2d(b, int(n), 3, inverse);
      EXPECT_LT(relative_l2(a, b), 1e-13) << n;
    }
  }
}

// A band-limited spectrum fills only some rows: whole groups of the transform's lines are zeros (skipped),
// others mix zero and non-zero rows. Every layout must still be FFTW's transform.
TEST(CpuFft, RowsOfZerosMatchFftw) {
  for (uint32_t n : {16u, 64u, 256u}) {
    std::mt19937 rng(n + 7);
    std::normal_distribution<double> g;
    std::vector<std::complex<double>> a(size_t{n} * n * 2);
    for (uint32_t b = 0; b < 2; ++b)
      for (uint32_t row = 0; row < n; ++row) {
        // The first quarter and the last eighth of the rows, and every fifth row of the rest of batch 1.
        const bool filled = row < n / 4 || row >= n - n / 8 || (b == 1 && row % 5 == 0);
        if (filled)
          for (uint32_t i = 0; i < n; ++i) a[(size_t{b} * n + row) * n + i] = {g(rng), g(rng)};
      }
    auto b = a;
    fft::CpuFft2d(n, true).transform(a, 2, 1);
    fftw_2d(b, int(n), 2, true);
    EXPECT_LT(relative_l2(a, b), 1e-13) << n;
  }
}

// The bodies' query evaluates from the modes listed once (SpectrumModes): the same fields to the bit as the
// evaluation that visits every cell, for a full and a band-limited spectrum, any fields and times.
TEST(SpectralFields, ListedModesGiveTheGridsEvaluationToTheBit) {
  ocean::OceanParams p;
  p.cascades = {{300.0, 64}, {40.0, 32}};
  const ocean::InverseFft2d fft = ocean::cpu_inverse_fft(1);
  const Field fields[] = {Field::Dx, Field::Height, Field::Dz, Field::SlopeX, Field::VelocityY};
  for (uint32_t c = 0; c < 2; ++c)
    for (bool limited : {false, true}) {
      ocean::CascadeSpectrum s = ocean::make_cascade_spectrum(p, c);
      if (limited) s = ocean::band_limited(s, 0.6 * s.band.k_max);
      const ocean::SpectrumModes modes = ocean::list_modes(s);
      EXPECT_LT(modes.index.size(), size_t{s.resolution} * s.resolution) << "the zero modes are not listed";
      for (double t : {0.0, 1.7, 123.4}) {
        const auto want = ocean::evaluate_fields(s, t, fields, fft);
        const auto got = ocean::evaluate_fields(modes, t, fields, fft);
        ASSERT_EQ(got.size(), want.size());
        for (size_t f = 0; f < want.size(); ++f)
          for (size_t i = 0; i < want[f].size(); ++i)
            ASSERT_EQ(got[f][i], want[f][i])
                << "cascade " << c << ", field " << f << ", t " << t << ", " << i;
      }
    }
}

TEST(SpectralFields, HeightIsRealSoPackingTwoFieldsIsExact) {
  const auto params = small_ocean();
  const auto s = ocean::make_cascade_spectrum(params, 0);
  const uint32_t n = s.resolution;
  std::vector<std::complex<double>> h(size_t{n} * n);
  for (uint32_t iz = 0; iz < n; ++iz)
    for (uint32_t ix = 0; ix < n; ++ix)
      h[size_t{iz} * n + ix] = ocean::field_spectrum(s, ix, iz, 2.7, Field::Height);
  fftw_2d(h, int(n), 1, true);
  double re = 0, im = 0;
  for (const auto& v : h) re += v.real() * v.real(), im += v.imag() * v.imag();
  ASSERT_GT(re, 0);
  EXPECT_LT(std::sqrt(im / re), 1e-12) << "h̃(k,t) is not Hermitian: the height would not be real";
}

TEST(SpectralFields, PackedEvaluationEqualsSeparateTransforms) {
  const auto s = ocean::make_cascade_spectrum(small_ocean(), 0);
  const Field fields[] = {Field::Dx, Field::Height, Field::SlopeZ};
  const auto packed = ocean::evaluate_fields(s, 1.1, fields, ocean::cpu_inverse_fft());
  for (size_t f = 0; f < 3; ++f) {
    const Field one[] = {fields[f]};
    const auto alone = ocean::evaluate_fields(s, 1.1, one, ocean::cpu_inverse_fft());
    double diff = 0, ref = 0;
    for (size_t i = 0; i < alone[0].size(); ++i)
      diff += std::pow(alone[0][i] - packed[f][i], 2), ref += std::pow(alone[0][i], 2);
    EXPECT_LT(std::sqrt(diff / ref), 1e-12) << "field " << f;
  }
}

// The lattice evaluation folds the modes onto a smaller spectrum: at every stride-th point it must give the
// full evaluation's values (here through FFTW, independent of the folding and of our FFT).
TEST(SpectralFields, TheLatticeHoldsTheFullGridsValuesAtItsPoints) {
  const auto s = ocean::make_cascade_spectrum(small_ocean(), 0);
  const uint32_t n = s.resolution;
  std::vector<std::complex<double>> h(size_t{n} * n);
  for (uint32_t iz = 0; iz < n; ++iz)
    for (uint32_t ix = 0; ix < n; ++ix)
      h[size_t{iz} * n + ix] = ocean::field_spectrum(s, ix, iz, 2.7, Field::DxDz);
  fftw_2d(h, int(n), 1, true);
  const Field fields[] = {Field::DxDz};
  for (uint32_t stride : {2u, 4u, 16u}) {
    const auto lattice = ocean::evaluate_fields_on_lattice(s, 2.7, fields, ocean::cpu_inverse_fft(), stride);
    const uint32_t m = n / stride;
    ASSERT_EQ(lattice[0].size(), size_t{m} * m);
    double diff = 0, ref = 0;
    for (uint32_t j = 0; j < m; ++j)
      for (uint32_t i = 0; i < m; ++i) {
        const double full = h[size_t{j * stride} * n + i * stride].real();
        diff += std::pow(lattice[0][size_t{j} * m + i] - full, 2), ref += full * full;
      }
    ASSERT_GT(ref, 0);
    EXPECT_LT(std::sqrt(diff / ref), 1e-12) << "stride " << stride;
  }
}

TEST(SpectralFields, VelocityIsTheTimeDerivative) {
  const auto s = ocean::make_cascade_spectrum(small_ocean(), 0);
  const Field fields[] = {Field::Dx, Field::Height, Field::VelocityX, Field::VelocityY};
  const double t = 3.0, dt = 1e-4;
  const auto now = ocean::evaluate_fields(s, t, fields, ocean::cpu_inverse_fft());
  const auto before = ocean::evaluate_fields(s, t - dt, fields, ocean::cpu_inverse_fft());
  const auto after = ocean::evaluate_fields(s, t + dt, fields, ocean::cpu_inverse_fft());
  for (int f : {0, 1}) {
    double diff = 0, ref = 0;
    for (size_t i = 0; i < now[0].size(); ++i) {
      const double fd = (after[f][i] - before[f][i]) / (2 * dt);
      diff += std::pow(fd - now[f + 2][i], 2);
      ref += std::pow(now[f + 2][i], 2);
    }
    EXPECT_LT(std::sqrt(diff / ref), 1e-5) << (f == 0 ? "vx" : "vy");
  }
}

}  // namespace
}  // namespace lagoon::test
