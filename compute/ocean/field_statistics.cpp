#include "ocean/field_statistics.h"

#include <cmath>
#include <complex>
#include <numbers>

#include "fft/cpu_fft.h"
#include "ocean/spectrum.h"

namespace lagoon::ocean {

double HeightGrid::at(glm::dvec2 p) const {
  const double texel = patch_m / n;
  const double u = p.x / texel, v = p.y / texel, fu = std::floor(u), fv = std::floor(v);
  const long mask = long(n) - 1;  // n is a power of two
  const long i = long(fu) & mask, j = long(fv) & mask, i1 = (i + 1) & mask, j1 = (j + 1) & mask;
  const double a = u - fu, b = v - fv;
  auto h = [&](long x, long z) { return height[size_t(z) * n + size_t(x)]; };
  return (1 - b) * ((1 - a) * h(i, j) + a * h(i1, j)) + b * ((1 - a) * h(i, j1) + a * h(i1, j1));
}

double summed_height(std::span<const HeightGrid> cascades, glm::dvec2 p) {
  double sum = 0;
  for (const HeightGrid& g : cascades) sum += g.at(p);
  return sum;
}

namespace {

// The summed field at the grid's points, shifted by `offset`.
std::vector<double> sample_field(std::span<const HeightGrid> cascades, uint32_t samples, glm::dvec2 offset) {
  const double step = cascades.front().patch_m / samples;
  std::vector<double> out(size_t{samples} * samples);
  for (uint32_t j = 0; j < samples; ++j)
    for (uint32_t i = 0; i < samples; ++i)
      out[size_t{j} * samples + i] = summed_height(cascades, glm::dvec2(i + 0.5, j + 0.5) * step + offset);
  return out;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= double(a.size()), mb /= double(b.size());
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : 1.0;
}

}  // namespace

double significant_height(std::span<const HeightGrid> cascades) {
  double variance = 0;
  for (const HeightGrid& g : cascades) {
    double mean = 0, square = 0;
    for (double v : g.height) mean += v, square += v * v;
    mean /= double(g.height.size());
    variance += std::max(square / double(g.height.size()) - mean * mean, 0.0);
  }
  return 4 * std::sqrt(variance);
}

double tiling_correlation(std::span<const HeightGrid> cascades, double lag_m, uint32_t samples) {
  const std::vector<double> here = sample_field(cascades, samples, glm::dvec2(0));
  return 0.5 * (correlation(here, sample_field(cascades, samples, {lag_m, 0})) +
                correlation(here, sample_field(cascades, samples, {0, lag_m})));
}

glm::dvec2 ModeEnergy::wavevector(uint32_t ix, uint32_t iz) const {
  const double dk = 2 * std::numbers::pi / patch_m;
  auto mode = [&](uint32_t i) { return i < n / 2 ? double(i) : double(i) - n; };
  return {dk * mode(ix), dk * mode(iz)};
}

ModeEnergy mode_energy(const HeightGrid& grid) {
  const uint32_t n = grid.n;
  std::vector<std::complex<double>> data(grid.height.begin(), grid.height.end());
  fft::CpuFft2d(n, false).transform(data, 1);
  ModeEnergy e{.n = n, .patch_m = grid.patch_m, .energy = std::vector<double>(data.size())};
  const double scale = 1.0 / (double(n) * n);
  for (size_t i = 0; i < data.size(); ++i) e.energy[i] = std::norm(data[i] * scale);
  e.energy[0] = 0;  // the mean level is no wave
  return e;
}

glm::dvec2 peak_wavevector(const ModeEnergy& e) {
  size_t best = 0;
  for (size_t i = 1; i < e.energy.size(); ++i)
    if (e.energy[i] > e.energy[best]) best = i;
  glm::dvec2 k = e.wavevector(uint32_t(best % e.n), uint32_t(best / e.n));
  if (k.y < 0 || (k.y == 0 && k.x < 0)) k = -k;
  return k;
}

BandEnergies band_energies(const ModeEnergy& e, const OceanParams& target, double k_min, double k_max,
                           uint32_t bands) {
  BandEnergies out;
  for (uint32_t b = 0; b <= bands; ++b)
    out.k_edges.push_back(k_min * std::pow(k_max / k_min, double(b) / bands));
  out.measured.assign(bands, 0);
  out.target.assign(bands, 0);
  const DirectionalSpectrum spectrum(target);
  const double dk = 2 * std::numbers::pi / e.patch_m;
  for (uint32_t iz = 0; iz < e.n; ++iz)
    for (uint32_t ix = 0; ix < e.n; ++ix) {
      const glm::dvec2 k = e.wavevector(ix, iz);
      const double length = std::hypot(k.x, k.y);
      if (length < k_min || length >= k_max) continue;
      const auto band = uint32_t(std::log(length / k_min) / std::log(k_max / k_min) * bands);
      if (band >= bands) continue;
      out.measured[band] += e.energy[size_t{iz} * e.n + ix];
      out.target[band] += spectrum(k.x, k.y) * dk * dk;
    }
  double diff = 0, norm = 0;
  for (uint32_t b = 0; b < bands; ++b) {
    diff += std::pow(out.measured[b] - out.target[b], 2);
    norm += out.target[b] * out.target[b];
  }
  out.relative_error = norm > 0 ? std::sqrt(diff / norm) : 0.0;
  return out;
}

}  // namespace lagoon::ocean
