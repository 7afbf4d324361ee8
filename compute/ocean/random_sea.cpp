#include "ocean/random_sea.h"

#include <cmath>
#include <complex>
#include <glm/geometric.hpp>
#include <numbers>

#include "ocean/direct_waves.h"
#include "ocean/slope_statistics.h"

namespace lagoon::ocean {

ShoalingWave representative_wave(const CascadeSpectrum& spectrum, const OceanParams& params) {
  const uint32_t n = spectrum.resolution;
  if (n == 0 || spectrum.h0.size() != size_t(n) * n) return {};
  const double dk = 2 * std::numbers::pi / spectrum.patch_size_m;
  double weight = 0, k_sum = 0;
  glm::dvec2 toward(0.0);
  for (uint32_t iz = 0; iz < n; ++iz)
    for (uint32_t ix = 0; ix < n; ++ix) {
      const double w = std::norm(std::complex<double>(spectrum.h0[size_t(iz) * n + ix]));
      if (w == 0) continue;
      const auto mode = [n](uint32_t i) { return double(i < n / 2 ? int64_t(i) : int64_t(i) - int64_t(n)); };
      const glm::dvec2 k = dk * glm::dvec2(mode(ix), mode(iz));
      const double length = glm::length(k);
      weight += w;
      k_sum += w * length;
      toward += w * k / length;
    }
  if (!(weight > 0) || !(glm::length(toward) > 0)) return {};
  const double k = k_sum / weight;
  return {.k = k * glm::normalize(toward),
          .omega = std::sqrt(kGravity * k * std::tanh(k * params.depth_m)),
          .amplitude_m = std::sqrt(2 * height_variance(spectrum)),  // a sine of the cascade's variance
          .own_depth_m = params.depth_m};
}

RandomSea random_sea(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra) {
  RandomSea sea{.significant_height_m = sea_significant_height(spectra)};
  // Perlin's octaves are noise, not waves with a dispersion relation: its lattice is not moved.
  for (const CascadeSpectrum& s : spectra)
    sea.lattice.push_back(params.model == SurfaceModel::Perlin ? ShoalingWave{}
                                                               : representative_wave(s, params));
  return sea;
}

}  // namespace lagoon::ocean
