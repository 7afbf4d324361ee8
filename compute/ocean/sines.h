// The sum of sines (issue 15; seed 001 §1.1.2, eqs. 1-3) through the FFT ocean's cascades:
//   height = Σ_i A_i ((1 + sin S_i)/2)^p_i,   S_i = k_i (x·dir_i) - ω_i t   (eqs. 1-3)
// An integer power of a sine is a trigonometric polynomial of degree p: harmonics m k, m ω for m = 0..p, so
// each wave is p modes of its cascade (h0(m k) = A c_m, ω = m ω), and the renderer, foam, WaveQuery, probe
// and export run unchanged. The mean level Σ A c_0 is left out (the document offsets it away too). Points
// move only vertically: the model needs choppiness 0.
#pragma once
#include <complex>
#include <vector>

#include "ocean/cascade_lattice.h"
#include "ocean/initial_spectrum.h"

namespace lagoon::ocean {

// c_m, m = 0..p, of ((1 + sin S)/2)^p = Σ_{m=-p..p} c_m e^{i m S} (c_{-m} = conj(c_m)); c_0 = C(2p, p) / 4^p.
std::vector<std::complex<double>> sine_power_coefficients(uint32_t p);

// The waves model sines uses: sines.waves, or with spectrum_waves = N, N plain sines (steepness 1) carrying
// the spectrum's energy (ocean/gerstner.h's sampling; A = twice the sampled amplitude, since eq. 2's
// A (1 + sin S)/2 swings by A/2).
std::vector<SineWaveSpec> sines_wave_specs(const OceanParams& params);

// Each wave on the lattice of the largest patch whose grid holds all its harmonics (4 texels per wavelength);
// harmonics_held is false when no cascade does.
struct SineLattice {
  LatticeWave wave;
  double omega = 0;  // of the fundamental, rad/s (quantised by loop_period_s)
  bool harmonics_held = true;
};
std::vector<SineLattice> sines_lattice(const OceanParams& params);

CascadeSpectrum sines_cascade_spectrum(const OceanParams& params, uint32_t cascade);

// Eqs. 2-3 evaluated at (x, z) and t, less the mean level: the reference. For the scene's own waves (summed
// directly, direct_waves.h) with their exact wave vectors; for waves sampled from the spectrum, on the
// lattice.
double sines_height(const OceanParams& params, double time_s, double x, double z);

}  // namespace lagoon::ocean
