// The initial (t = 0) Fourier amplitudes h0(k) and frequencies ω(k) of each FFT cascade: what the GPU
// evolves every frame as h(k, t) = h0(k) e^{-iωt} + conj(h0(-k)) e^{+iωt} (spectral_fields.h), so the
// component h0(k) e^{i(k·x - ωt)} travels along k, i.e. downwind where Ψ puts its energy. Tessendorf writes
// e^{+iωt}; the sign does not change any variance below.
#pragma once
#include <complex>
#include <cstdint>
#include <vector>

#include "ocean/ocean_params.h"

namespace lagoon::ocean {

struct CascadeBand {
  double k_min = 0, k_max = 0;  // rad/m: the cascade carries |k| in [k_min, k_max)
};

// Disjoint, contiguous bands: cascade 0 starts at 0; each k_max = π N/(2L) so every wave a cascade carries
// spans >= 4 texels (no aliasing of the displaced, sharpened crests); cascade c starts where c-1 ends.
// Cascades are given largest patch first; validate() rejects sets whose bands would be empty or unreachable
// (an empty band here has k_max = k_min).
std::vector<CascadeBand> cascade_bands(const OceanParams& params);

struct CascadeSpectrum {
  uint32_t resolution = 0;  // N
  double patch_size_m = 0;  // L
  CascadeBand band;
  // N*N each, row-major [iz * N + ix]; element i along an axis is mode m = (i < N/2 ? i : i - N),
  // k = 2π m / L.
  std::vector<std::complex<float>> h0;  // h0(k), m; 0 outside the band and at k = 0
  std::vector<float> omega;             // ω(k) in rad/s (quantised when looping); 0 outside the band
};

// The spectrum of params.cascades[cascade]; an empty CascadeSpectrum (resolution 0) when the index is out
// of range or the cascade has no size (run validate() first). Deterministic: bit-identical for equal params
// whatever the thread count. Takes a few ms per 256² cascade (rows are spread over up to 8 threads).
CascadeSpectrum make_cascade_spectrum(const OceanParams& params, uint32_t cascade);
// The cascade's size and band with h0 and ω all zero, for a model to fill; resolution 0 when the index is out
// of range or the cascade has no size.
CascadeSpectrum empty_cascade_spectrum(const OceanParams& params, uint32_t cascade);
// Every cascade's, in order.
std::vector<CascadeSpectrum> make_cascade_spectra(const OceanParams& params);

}  // namespace lagoon::ocean
