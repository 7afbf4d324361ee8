#include "ocean/whitecaps.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "ocean/direct_waves.h"
#include "ocean/slope_statistics.h"
#include "ocean/spectral_fields.h"

namespace lagoon::ocean {
namespace {

// Φ⁻¹(p) by bisection on the normal distribution function (p in (0, 1)).
double normal_quantile(double p) {
  double lo = -10, hi = 10;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The whole sea's Jacobian at t = 0 on a 256² grid over the largest patch: each cascade's terms from its
// fields (one CPU FFT per field and cascade) at the nearest texel, summed, as the surface shader sums them.
std::vector<double> jacobian_samples(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra) {
  static constexpr Field kTerms[] = {Field::DxDx, Field::DzDz, Field::DxDz};
  const InverseFft2d fft = cpu_inverse_fft(2);
  std::vector<std::vector<std::vector<double>>> fields;
  for (const CascadeSpectrum& s : spectra) fields.push_back(evaluate_fields(s, 0.0, kTerms, fft));
  constexpr uint32_t kGrid = 256;
  const double side = spectra.front().patch_size_m, lambda = params.choppiness;
  std::vector<double> out;
  out.reserve(size_t{kGrid} * kGrid);
  for (uint32_t j = 0; j < kGrid; ++j)
    for (uint32_t i = 0; i < kGrid; ++i) {
      double a = 0, b = 0, c = 0;
      for (size_t k = 0; k < spectra.size(); ++k) {
        const uint32_t n = spectra[k].resolution;
        const double scale = n / spectra[k].patch_size_m;
        const size_t x = size_t((i + 0.5) * side / kGrid * scale) % n,
                     z = size_t((j + 0.5) * side / kGrid * scale) % n;
        a += fields[k][0][z * n + x], b += fields[k][1][z * n + x], c += fields[k][2][z * n + x];
      }
      out.push_back((1 + lambda * a) * (1 + lambda * b) - lambda * lambda * c * c);
    }
  return out;
}

// The same for waves summed directly (direct_waves.h): eq. 11's Jacobian at the grid's points.
std::vector<double> jacobian_samples(const GerstnerSurface& surface, double side) {
  constexpr uint32_t kGrid = 256;
  std::vector<double> out;
  out.reserve(size_t{kGrid} * kGrid);
  for (uint32_t j = 0; j < kGrid; ++j)
    for (uint32_t i = 0; i < kGrid; ++i)
      out.push_back(surface.at_rest(glm::dvec2(i + 0.5, j + 0.5) * (side / kGrid), 0.0).jacobian);
  return out;
}

}  // namespace

double monahan_coverage(double wind_speed_mps) {
  return 3.84e-6 * std::pow(std::max(wind_speed_mps, 0.0), 3.41);
}

FoamRule foam_rule(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra) {
  if (params.foam.coverage == FoamCoverage::Threshold || params.model == SurfaceModel::Springs ||
      spectra.empty())
    return {params.foam.threshold, 1.0};
  // σ_J² = λ² × the mean square slope; for waves summed directly J - 1 ≈ -Σ Q k A cos θ: Σ (Q k A)²/2.
  double variance = 0;
  std::vector<double> j;
  if (const std::optional<GerstnerParams> direct = direct_wave_params(params)) {
    const GerstnerSurface surface(*direct);
    for (size_t i = 0; i < surface.size(); ++i) {
      const double qka =
          surface.steepness(i) * glm::length(surface.wavevector(i)) * direct->waves[i].amplitude_m;
      variance += 0.5 * qka * qka;
    }
    j = jacobian_samples(surface, spectra.front().patch_size_m);
  } else {
    for (const CascadeSpectrum& s : spectra) variance += mean_square_slope(s);
    variance *= params.choppiness * params.choppiness;
    // J's lower tail is not Gaussian (J = (1 + a)(1 + b) - c²): its quantile is read off the sea itself
    // where the grid holds enough points below it, and taken from the Gaussian only for the calmest seas.
    j = jacobian_samples(params, spectra);
  }
  // A sea that moves only up and down (choppiness 0, the sines) has J = 1 everywhere: nothing squeezes it,
  // and a rule fitted to no spread would whiten all of it.
  if (variance == 0) return {0.0, 1.0};
  const double sigma = std::max(std::sqrt(variance), 1e-3);
  const double coverage = std::clamp(monahan_coverage(params.spectrum.wind_speed_mps), 1e-9, 0.5);
  const size_t below = size_t(coverage * double(j.size()));
  if (below >= 20) {
    std::nth_element(j.begin(), j.begin() + long(below), j.end());
    return {j[below] + 0.5 * sigma, sigma};
  }
  return {1.0 + sigma * normal_quantile(coverage) + 0.5 * sigma, sigma};
}

}  // namespace lagoon::ocean
