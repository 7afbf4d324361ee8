#include "ocean/sines.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>

#include "ocean/dispersion.h"
#include "ocean/gerstner.h"

namespace lagoon::ocean {

std::vector<std::complex<double>> sine_power_coefficients(uint32_t p) {
  // A DFT of 64 samples is exact for a trigonometric polynomial of degree p < 32.
  constexpr int kSamples = 64;
  std::vector<std::complex<double>> c(p + 1, 0.0);
  for (int j = 0; j < kSamples; ++j) {
    const double s = 2 * std::numbers::pi * j / kSamples;
    const double g = std::pow(0.5 * (1 + std::sin(s)), double(p));
    for (uint32_t m = 0; m <= p; ++m) c[m] += g * std::polar(1.0 / kSamples, -double(m) * s);
  }
  return c;
}

std::vector<SineWaveSpec> sines_wave_specs(const OceanParams& params) {
  const uint32_t n = params.sines.spectrum_waves;
  if (n == 0) return params.sines.waves;
  std::vector<SineWaveSpec> out;
  for (const GerstnerWaveSpec& w : spectrum_wave_specs(params, n))
    out.push_back({2 * w.amplitude_m, w.wavelength_m, w.direction_deg, 1, w.phase_deg});
  return out;
}

std::vector<SineLattice> sines_lattice(const OceanParams& params) {
  // Not the FFT's bands (they only share the random spectrum out between cascades): the largest patch, so the
  // wave moves least on its lattice, whose grid still gives the highest harmonic 4 texels per wavelength.
  const std::vector<CascadeBand> bands = cascade_bands(params);
  std::vector<SineLattice> out;
  for (const SineWaveSpec& w : sines_wave_specs(params)) {
    const glm::dvec2 k = wave_vector(w.wavelength_m, w.direction_deg);
    SineLattice l;
    l.wave.k = k;
    l.harmonics_held = false;
    for (size_t c = 0; c < params.cascades.size() && !l.harmonics_held; ++c) {
      const double dk = 2 * std::numbers::pi / params.cascades[c].patch_size_m;
      const glm::dvec2 m = glm::round(k / dk);
      const double length = glm::length(m * dk);
      if (length > 0 && double(w.steepness) * length < bands[c].k_max) {
        l.wave = {int(c), glm::ivec2(m), m * dk};
        l.harmonics_held = true;
      }
    }
    l.omega = quantise_omega(gerstner_omega(params.sines.dispersion, glm::length(l.wave.k), params.depth_m),
                             params.loop_period_s);
    out.push_back(l);
  }
  return out;
}

CascadeSpectrum sines_cascade_spectrum(const OceanParams& params, uint32_t cascade) {
  CascadeSpectrum out = empty_cascade_spectrum(params, cascade);
  if (out.resolution == 0) return out;
  const uint32_t n = out.resolution;
  const std::vector<SineLattice> lattice = sines_lattice(params);
  const std::vector<SineWaveSpec> waves = sines_wave_specs(params);
  for (size_t i = 0; i < lattice.size(); ++i) {
    const SineLattice& l = lattice[i];
    if (l.wave.cascade != int(cascade) || !l.harmonics_held) continue;
    const SineWaveSpec& w = waves[i];
    const std::vector<std::complex<double>> c = sine_power_coefficients(w.steepness);
    const double phase = w.phase_deg * std::numbers::pi / 180;
    // h̃(K, t) = h0(K) e^{-iΩt} + conj(h0(-K)) e^{iΩt}: h0(m k) = A c_m gives A c_m e^{i m (k·x - ωt)}, and
    // its conjugate at -m k the term c_{-m}; together A (g(S) - c_0) with S = k·x - ω t.
    for (uint32_t m = 1; m <= w.steepness; ++m) {
      const long mx = long(m) * l.wave.mode.x, mz = long(m) * l.wave.mode.y;
      out.h0[mode_index(n, mx, mz)] += std::complex<float>(w.amplitude_m * c[m] * std::polar(1.0, m * phase));
      out.omega[mode_index(n, mx, mz)] = float(m * l.omega);
      out.omega[mode_index(n, -mx, -mz)] = float(m * l.omega);
    }
  }
  return out;
}

double sines_height(const OceanParams& params, double t, double x, double z) {
  const std::vector<SineLattice> lattice = sines_lattice(params);
  const std::vector<SineWaveSpec> waves = sines_wave_specs(params);
  const bool exact = params.sines.spectrum_waves == 0;  // summed directly (direct_waves.h): no lattice
  double h = 0;
  for (size_t i = 0; i < lattice.size(); ++i) {
    const SineWaveSpec& w = waves[i];
    glm::dvec2 k = lattice[i].wave.k;
    double omega = lattice[i].omega;
    if (exact) {
      k = wave_vector(w.wavelength_m, w.direction_deg);
      omega = quantise_omega(gerstner_omega(params.sines.dispersion, glm::length(k), params.depth_m),
                             params.loop_period_s);
    }
    const double s = glm::dot(k, glm::dvec2(x, z)) - omega * t + w.phase_deg * std::numbers::pi / 180;
    h += w.amplitude_m *
         (std::pow(0.5 * (1 + std::sin(s)), double(w.steepness)) - sine_profile_mean(w.steepness));
  }
  return h;
}

}  // namespace lagoon::ocean
