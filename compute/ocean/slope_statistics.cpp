#include "ocean/slope_statistics.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "ocean/short_waves.h"
#include "ocean/spectrum.h"

namespace lagoon::ocean {

double mean_square_slope(const CascadeSpectrum& s) {
  const uint32_t n = s.resolution;
  const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
  double sum = 0;
  for (uint32_t iz = 0; iz < n; ++iz) {
    const double kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
    for (uint32_t ix = 0; ix < n; ++ix) {
      const double kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
      sum += (kx * kx + kz * kz) * std::norm(std::complex<double>(s.h0[size_t{iz} * n + ix]));
    }
  }
  return 2.0 * sum;
}

double height_variance(const CascadeSpectrum& s) {
  double sum = 0;
  for (const std::complex<float>& h : s.h0) sum += std::norm(std::complex<double>(h));
  return 2.0 * sum;
}

double spectrum_mean_square_slope(const OceanParams& params, double k_from, double k_to) {
  if (!(k_to > k_from) || k_from <= 0) return 0;
  const DirectionalSpectrum spectrum(params);
  // Trapezoid in ln k: the integrand k²Ψ(k)·k varies slowly there (the saturation range gives k^0).
  constexpr int kSteps = 512;
  const double a = std::log(k_from), b = std::log(k_to), step = (b - a) / kSteps;
  double sum = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const double k = std::exp(a + i * step);
    const double f = k * k * spectrum.omnidirectional(k) * k;
    sum += (i == 0 || i == kSteps) ? 0.5 * f : f;
  }
  return sum * step;
}

SlopeMoments slope_moments(const CascadeSpectrum& s, double k_from) {
  const uint32_t n = s.resolution;
  const double dk = 2.0 * std::numbers::pi / s.patch_size_m;
  SlopeMoments m;
  for (uint32_t iz = 0; iz < n; ++iz) {
    const double kz = dk * (iz < n / 2 ? double(iz) : double(iz) - n);
    for (uint32_t ix = 0; ix < n; ++ix) {
      const double kx = dk * (ix < n / 2 ? double(ix) : double(ix) - n);
      if (kx * kx + kz * kz < k_from * k_from) continue;
      const double a = 2.0 * std::norm(std::complex<double>(s.h0[size_t{iz} * n + ix]));
      m.xx += kx * kx * a;
      m.zz += kz * kz * a;
      m.xz += kx * kz * a;
    }
  }
  return m;
}

SlopeMoments spectrum_slope_moments(const OceanParams& params, double k_from, double k_to) {
  SlopeMoments m;
  if (!(k_to > k_from) || k_from <= 0) return m;
  const DirectionalSpectrum spectrum(params);
  // Ψ is a density in (kx, kz): ∫∫ k_i k_j Ψ k dk dθ, trapezoid in ln k (one more k) and uniform in θ.
  constexpr int kSteps = 512, kAngles = 128;
  const double a = std::log(k_from), b = std::log(k_to), step = (b - a) / kSteps;
  const double dtheta = 2 * std::numbers::pi / kAngles;
  for (int i = 0; i <= kSteps; ++i) {
    const double k = std::exp(a + i * step), end = (i == 0 || i == kSteps) ? 0.5 : 1.0;
    for (int j = 0; j < kAngles; ++j) {
      const double theta = dtheta * j, kx = k * std::cos(theta), kz = k * std::sin(theta);
      const double w = end * spectrum(kx, kz) * k * k * step * dtheta;
      m.xx += kx * kx * w;
      m.zz += kz * kz * w;
      m.xz += kx * kz * w;
    }
  }
  return m;
}

SlopeMoments sea_slope_moments(const OceanParams& params) {
  std::vector<CascadeSpectrum> spectra;
  for (uint32_t c = 0; c < params.cascades.size(); ++c) spectra.push_back(make_cascade_spectrum(params, c));
  return sea_slope_moments(params, spectra);
}

SlopeMoments sea_slope_moments(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra) {
  SlopeMoments m;
  for (const CascadeSpectrum& s : spectra) {
    const SlopeMoments one = slope_moments(s);
    m.xx += one.xx, m.zz += one.zz, m.xz += one.xz;
  }
  if (params.model == SurfaceModel::Fft) {
    const SlopeMoments rest = short_wave_slope_moments(params, cascade_bands(params).back().k_max);
    m.xx += rest.xx, m.zz += rest.zz, m.xz += rest.xz;
  }
  return m;
}

SlopeMoments unresolved_slope_moments(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra,
                                      size_t drawn, double k_from) {
  drawn = std::min(drawn, spectra.size());
  SlopeMoments m;
  if (drawn == 0) return m;
  for (size_t c = 0; c < drawn; ++c) {
    const SlopeMoments one = slope_moments(spectra[c], k_from);
    m.xx += one.xx, m.zz += one.zz, m.xz += one.xz;
  }
  const double beyond = std::max(cascade_bands(params)[drawn - 1].k_max, k_from);
  const SlopeMoments rest = params.model == SurfaceModel::Fft
                                ? short_wave_slope_moments(params, beyond)
                                : spectrum_slope_moments(params, beyond, kCapillaryCutoffK);
  m.xx += rest.xx, m.zz += rest.zz, m.xz += rest.xz;
  return m;
}

}  // namespace lagoon::ocean
