// CPU field evaluation: our CPU FFT against FFTW, the real-field packing (Hermitian symmetry), and the
// time derivative against a finite difference.
#include <gtest/gtest.h>

#include <random>

#include "fft/cpu_fft.h"
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
