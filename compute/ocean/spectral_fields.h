// CPU evaluation of a cascade's real fields at time t on its N x N grid: the evolved spectrum
// h̃(k,t) = h0(k)e^{-iωt} + conj(h0(-k))e^{+iωt} times each field's multiplier, two real fields packed per
// complex inverse FFT. The same conventions as the GPU passes (shaders/ocean/evolve_fft.comp).
#pragma once
#include <complex>
#include <functional>
#include <span>
#include <vector>

#include "ocean/initial_spectrum.h"

namespace lagoon::ocean {

enum class Field {
  Dx,
  Height,
  Dz,  // horizontal displacement D (before scaling by λ) and height, metres
  SlopeX,
  SlopeZ,  // ∂h/∂x, ∂h/∂z
  DxDx,
  DzDz,
  DxDz,  // ∂Dx/∂x, ∂Dz/∂z, ∂Dx/∂z (Jacobian terms, before λ)
  VelocityX,
  VelocityY,
  VelocityZ,  // ∂Dx/∂t, ∂h/∂t, ∂Dz/∂t (m/s, before λ for x and z)
};

// In-place unnormalised inverse 2-D FFT of `batches` row-major n x n arrays.
using InverseFft2d =
    std::function<void(std::vector<std::complex<double>>& data, uint32_t n, uint32_t batches)>;

// Our own CPU FFT (fft/cpu_fft.h) on `threads` threads.
InverseFft2d cpu_inverse_fft(unsigned threads = 1);

// result[f][z * N + x] is fields[f] at x = i·L/N, z = j·L/N.
std::vector<std::vector<double>> evaluate_fields(const CascadeSpectrum& spectrum, double time_s,
                                                 std::span<const Field> fields, const InverseFft2d& fft);
// The same at every `stride`-th point along each axis only (stride divides N; M = N / stride):
// result[f][j * M + i] is fields[f] at x = i·stride·L/N, z = j·stride·L/N, exactly: the modes are folded
// onto an M x M spectrum (at those points e^{ikx} cannot tell k from k + 2πM/L), so one M² FFT does.
std::vector<std::vector<double>> evaluate_fields_on_lattice(const CascadeSpectrum& spectrum, double time_s,
                                                            std::span<const Field> fields,
                                                            const InverseFft2d& fft, uint32_t stride);

// What a mode's evaluation at any time is built from: h0(k), conj(h0(-k)), ω and the wave vector.
struct ModeConstants {
  std::complex<double> h0, h0m;
  double omega = 0, kx = 0, kz = 0, inv_k = 0;  // inv_k = 1/|k| (0 for k = 0)
};
ModeConstants mode_constants(const CascadeSpectrum& spectrum, uint32_t ix, uint32_t iz);

// A cascade's modes with any amplitude, listed once with their constants: evaluating a time then visits
// these only, not every cell, and recomputes nothing but the phase (a band-limited spectrum, the bodies' sea,
// fills a quarter of its grid; issue 35).
struct SpectrumModes {
  uint32_t resolution = 0;
  std::vector<uint32_t> index;  // iz * N + ix, in the grid's order
  std::vector<ModeConstants> constants;
};
SpectrumModes list_modes(const CascadeSpectrum& spectrum);
// evaluate_fields(spectrum, ...)'s fields to the bit, from the listed modes.
std::vector<std::vector<double>> evaluate_fields(const SpectrumModes& modes, double time_s,
                                                 std::span<const Field> fields, const InverseFft2d& fft);

// The spectral value of `field` at mode index (ix, iz) and time t (used by the evaluator and by tests).
std::complex<double> field_spectrum(const CascadeSpectrum& spectrum, uint32_t ix, uint32_t iz, double time_s,
                                    Field field);

}  // namespace lagoon::ocean
