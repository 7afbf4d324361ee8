#include "ocean/direct_waves.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "ocean/slope_statistics.h"

namespace lagoon::ocean {
namespace {

constexpr double kRadians = std::numbers::pi / 180;

// A Gerstner wave as the scene states it; without its own steepness, the sea's choppiness.
GerstnerWave gerstner_wave(const GerstnerWaveSpec& w, double choppiness) {
  return {.amplitude_m = w.amplitude_m,
          .wavelength_m = w.wavelength_m,
          .direction_deg = w.direction_deg,
          .phase_rad = w.phase_deg * kRadians,
          .steepness = w.steepness.value_or(choppiness)};
}

}  // namespace

std::optional<GerstnerParams> direct_wave_params(const OceanParams& params) {
  GerstnerParams out{
      .depth_m = params.depth_m, .loop_period_s = params.loop_period_s, .limit_steepness = false};
  if (params.shoaling) out.floor = params.floor;
  out.breaker_index = params.breaker_index;
  if (params.model == SurfaceModel::Gerstner && params.gerstner.spectrum_waves == 0) {
    out.dispersion = params.gerstner.dispersion;
    for (const GerstnerWaveSpec& w : params.gerstner.waves)
      out.waves.push_back(gerstner_wave(w, params.choppiness));
    return out;
  }
  if (params.model == SurfaceModel::Sines && params.sines.spectrum_waves == 0) {
    out.dispersion = params.sines.dispersion;
    for (const SineWaveSpec& w : params.sines.waves)
      out.waves.push_back({.amplitude_m = w.amplitude_m,
                           .wavelength_m = w.wavelength_m,
                           .direction_deg = w.direction_deg,
                           .phase_rad = w.phase_deg * kRadians,
                           .steepness = 0,  // eqs. 1-3 move the surface only up and down
                           .power = w.steepness});
    return out;
  }
  return std::nullopt;
}

std::optional<GerstnerParams> swell_wave_params(const OceanParams& params, const RandomSea& sea) {
  if (params.swell_waves.empty() || evaluated_directly(params) || params.model == SurfaceModel::Springs)
    return std::nullopt;
  GerstnerParams out{.dispersion = GerstnerDispersion::Deep,
                     .depth_m = params.depth_m,
                     .loop_period_s = params.loop_period_s,
                     .limit_steepness = false,
                     .breaker_index = params.breaker_index,
                     .sea = sea};
  if (params.shoaling) out.floor = params.floor;
  for (const GerstnerWaveSpec& w : params.swell_waves)
    out.waves.push_back(gerstner_wave(w, params.choppiness));
  return out;
}

double sea_significant_height(const std::vector<CascadeSpectrum>& spectra) {
  double variance = 0;
  for (const CascadeSpectrum& s : spectra) variance += height_variance(s);
  return 4 * std::sqrt(variance);
}

std::shared_ptr<const Shoaling> sea_over_floor(const OceanParams& params, const RandomSea& sea) {
  if (!params.floor || !params.shoaling || params.model == SurfaceModel::Springs) return nullptr;
  auto over = std::make_shared<Shoaling>(
      ShoalingInputs{.floor = params.floor, .breaker_index = params.breaker_index, .sea = sea});
  return over->active() ? over : nullptr;
}

std::optional<GerstnerParams> summed_wave_params(const OceanParams& params, const RandomSea& sea) {
  if (std::optional<GerstnerParams> own = direct_wave_params(params)) return own;
  return swell_wave_params(params, sea);
}

std::vector<gpu::DirectWaveGpu> direct_waves_gpu(const GerstnerSurface& surface,
                                                 std::optional<double> at_time) {
  std::vector<gpu::DirectWaveGpu> out;
  for (size_t i = 0; i < surface.size(); ++i) {
    const GerstnerWave& w = surface.params().waves[i];
    double phase = w.phase_rad;
    if (at_time) phase = std::remainder(phase - surface.omega(i) * *at_time, 2 * std::numbers::pi);
    const glm::dvec2 k = surface.wavevector(i);
    out.push_back({.wave = glm::vec4(float(k.x), float(k.y), float(phase), float(w.amplitude_m)),
                   .shape = glm::vec4(float(surface.steepness(i)), float(w.power),
                                      float(surface.profile_mean(i)), float(surface.omega(i)))});
  }
  return out;
}

}  // namespace lagoon::ocean
