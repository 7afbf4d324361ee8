#include "ocean/perlin.h"

#include <cmath>
#include <complex>
#include <numbers>

#include "fft/cpu_fft.h"
#include "ocean/dispersion.h"

namespace lagoon::ocean {
namespace {

uint32_t mix(uint32_t h) {  // a 32-bit integer hash (lowbias32)
  h ^= h >> 16;
  h *= 0x7feb352dU;
  h ^= h >> 15;
  h *= 0x846ca68bU;
  h ^= h >> 16;
  return h;
}

// The unit gradient at lattice point (i, j) (wrapped into the period).
void gradient(long i, long j, uint32_t period, uint32_t seed, double& gx, double& gz) {
  const long p = long(period);
  const uint32_t a = uint32_t((i % p + p) % p), b = uint32_t((j % p + p) % p);
  const double angle = 2 * std::numbers::pi * (mix(mix(a * 0x9e3779b9U ^ b) ^ seed) >> 8) / double(1u << 24);
  gx = std::cos(angle);
  gz = std::sin(angle);
}

double fade(double t) {
  return t * t * t * (t * (t * 6 - 15) + 10);
}

}  // namespace

double gradient_noise(double x, double z, uint32_t period, uint32_t seed) {
  const double fx = std::floor(x), fz = std::floor(z);
  const long i = long(fx), j = long(fz);
  const double u = x - fx, v = z - fz;
  double corner[2][2];
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a) {
      double gx, gz;
      gradient(i + a, j + b, period, seed, gx, gz);
      corner[b][a] = gx * (u - a) + gz * (v - b);
    }
  const double su = fade(u), sv = fade(v);
  const double bottom = corner[0][0] + su * (corner[0][1] - corner[0][0]);
  const double top = corner[1][0] + su * (corner[1][1] - corner[1][0]);
  return bottom + sv * (top - bottom);
}

double perlin_octave(const OceanParams& params, uint32_t octave, double x, double z) {
  const PerlinParams& p = params.perlin;
  const double patch = params.cascades.front().patch_size_m;
  const uint32_t cells = p.cells * uint32_t(std::pow(double(p.lacunarity), double(octave)));
  const double scale = double(cells) / patch;
  return p.amplitude_m * std::pow(p.persistence, double(octave)) *
         gradient_noise(x * scale, z * scale, cells, params.seed * 0x85ebca6bU + octave);
}

double perlin_height(const OceanParams& params, double x, double z) {
  double h = 0;
  for (uint32_t o = 0; o < params.perlin.octaves; ++o) h += perlin_octave(params, o, x, z);
  return h;
}

CascadeSpectrum perlin_cascade_spectrum(const OceanParams& params, uint32_t cascade) {
  CascadeSpectrum out = empty_cascade_spectrum(params, cascade);
  if (out.resolution == 0 || cascade != 0) return out;  // the noise lives on the first patch
  const uint32_t n = out.resolution;
  const double patch = out.patch_size_m;
  std::vector<std::complex<double>> field(size_t(n) * n);
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i)
      field[size_t(j) * n + i] = perlin_height(params, patch * i / n, patch * j / n);
  fft::CpuFft2d(n, false).transform(field, 1, 2);
  const double dk = 2 * std::numbers::pi / patch;
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      if (i == 0 && j == 0) continue;  // the mean level
      const double mx = i < n / 2 ? double(i) : double(i) - n, mz = j < n / 2 ? double(j) : double(j) - n;
      const size_t c = size_t(j) * n + i;
      // field = Σ F(k) e^{ik·x} / n²; h̃ = h0(k) + conj(h0(-k)) at t = 0, and F is Hermitian: h0 = F / (2 n²).
      out.h0[c] = std::complex<float>(field[c] / (2.0 * n * n));
      out.omega[c] = float(quantise_omega(omega_deep(dk * std::hypot(mx, mz)), params.loop_period_s));
    }
  return out;
}

}  // namespace lagoon::ocean
