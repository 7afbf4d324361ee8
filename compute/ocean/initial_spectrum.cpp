#include "ocean/initial_spectrum.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <system_error>
#include <thread>

#include "ocean/direct_waves.h"
#include "ocean/dispersion.h"
#include "ocean/gerstner.h"
#include "ocean/perlin.h"
#include "ocean/random.h"
#include "ocean/sines.h"
#include "ocean/spectrum.h"

namespace lagoon::ocean {

std::vector<CascadeBand> cascade_bands(const OceanParams& params) {
  std::vector<CascadeBand> bands;
  double k_min = 0.0;
  for (const CascadeParams& c : params.cascades) {
    const double k_max = std::numbers::pi * c.resolution / (2.0 * c.patch_size_m);
    bands.push_back({k_min, std::max(k_min, k_max)});
    k_min = bands.back().k_max;
  }
  return bands;
}

namespace {

// Fills rows iz = first, first + stride, ... of `out`.
//
// Amplitude scaling. The surface is η(x, t) = Σ_k h(k, t) e^{ik·x} with
// h(k, t) = h0(k) e^{∓iωt} + conj(h0(-k)) e^{±iωt} (either sign), and h0 of different k independent. We want
// the discrete sum to carry the spectrum's variance: Var η = Σ_k E|h(k)|² should equal Σ_k Ψ(k) Δk² ≈ ∫ Ψ d²k
// over the band (Δk = 2π/L, Ψ in m⁴, Δk² in rad²/m², so Ψ Δk² is m²). Since E|h(k)|² = E|h0(k)|² +
// E|h0(-k)|², each h0 must have E|h0(k)|² = Ψ(k) Δk² / 2. gaussian_pair gives ξr + iξi with E|ξr + iξi|² = 2,
// hence
//   h0(k) = (ξr + iξi) · sqrt(Ψ(k)) · Δk / 2.
// Tessendorf's h0 = (ξr + iξi) sqrt(P(k)) / √2 with P = Ψ Δk² would give E|h0|² = Ψ Δk², i.e. twice the
// variance (√2 too much amplitude), because the conj(h0(-k)) term already doubles what each mode carries.
// (Both terms matter: E|h(k)|² = E|h0(k)|² + E|h0(-k)|² holds because h0(k) and h0(-k) are independent.)
void fill_rows(const OceanParams& params, uint32_t cascade, const DirectionalSpectrum& spectrum,
               const DispersionModel& dispersion, int first, int stride, CascadeSpectrum& out) {
  const int n = static_cast<int>(out.resolution);
  const double dk = 2.0 * std::numbers::pi / out.patch_size_m;
  for (int iz = first; iz < n; iz += stride) {
    const int mz = iz < n / 2 ? iz : iz - n;
    for (int ix = 0; ix < n; ++ix) {
      const int mx = ix < n / 2 ? ix : ix - n;
      const double kx = mx * dk, kz = mz * dk;
      const double k = std::hypot(kx, kz);
      if (k == 0.0 || k < out.band.k_min || k >= out.band.k_max) continue;  // stays 0
      const double amplitude = std::sqrt(spectrum(kx, kz)) * dk * 0.5;
      const std::complex<double> h0 = gaussian_pair(params.seed, cascade, mx, mz) * amplitude;
      const size_t i = static_cast<size_t>(iz) * n + ix;
      out.h0[i] = {static_cast<float>(h0.real()), static_cast<float>(h0.imag())};
      out.omega[i] = static_cast<float>(omega(dispersion, k));
    }
  }
}

}  // namespace

std::vector<CascadeSpectrum> make_cascade_spectra(const OceanParams& params) {
  std::vector<CascadeSpectrum> out;
  for (uint32_t c = 0; c < params.cascades.size(); ++c) out.push_back(make_cascade_spectrum(params, c));
  return out;
}

CascadeSpectrum empty_cascade_spectrum(const OceanParams& params, uint32_t cascade) {
  CascadeSpectrum out;
  if (cascade >= params.cascades.size()) return out;
  const CascadeParams& c = params.cascades[cascade];
  if (c.resolution == 0 || !(c.patch_size_m > 0.0) || !std::isfinite(c.patch_size_m)) return out;
  out.resolution = c.resolution;
  out.patch_size_m = c.patch_size_m;
  out.band = cascade_bands(params)[cascade];
  const size_t count = static_cast<size_t>(c.resolution) * c.resolution;
  out.h0.assign(count, {0.0f, 0.0f});
  out.omega.assign(count, 0.0f);
  return out;
}

CascadeSpectrum make_cascade_spectrum(const OceanParams& params, uint32_t cascade) {
  CascadeSpectrum out = empty_cascade_spectrum(params, cascade);
  if (out.resolution == 0) return out;
  if (evaluated_directly(params)) return out;  // summed where drawn (direct_waves.h), not in the spectrum
  if (params.model == SurfaceModel::Gerstner) return gerstner_cascade_spectrum(params, cascade);
  if (params.model == SurfaceModel::Sines) return sines_cascade_spectrum(params, cascade);
  if (params.model == SurfaceModel::Perlin) return perlin_cascade_spectrum(params, cascade);
  if (params.model == SurfaceModel::Springs) return out;  // stepped in space, not in the spectrum (springs.h)
  const CascadeParams& c = params.cascades[cascade];

  const DirectionalSpectrum spectrum(params);
  const DispersionModel dispersion = dispersion_for(params);
  // Every element depends only on its own mode, so splitting rows between threads cannot change the result.
  const int rows = static_cast<int>(c.resolution);
  const int threads = std::min({std::max(1, static_cast<int>(std::thread::hardware_concurrency())), 8, rows});
  std::vector<std::thread> workers;
  int started = 1;  // stride slot 0 is the calling thread's
  try {
    for (; started < threads; ++started)
      workers.emplace_back(fill_rows, std::cref(params), cascade, std::cref(spectrum), std::cref(dispersion),
                           started, threads, std::ref(out));
  } catch (const std::system_error&) {
    // No more threads: the calling thread takes the slots that did not start.
  }
  fill_rows(params, cascade, spectrum, dispersion, 0, threads, out);
  for (int slot = started; slot < threads; ++slot)
    fill_rows(params, cascade, spectrum, dispersion, slot, threads, out);
  for (std::thread& w : workers) w.join();
  return out;
}

}  // namespace lagoon::ocean
