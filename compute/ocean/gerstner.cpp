#include "ocean/gerstner.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/compass.h"
#include "ocean/cascade_lattice.h"
#include "ocean/dispersion.h"
#include "ocean/spectrum.h"
#include "ocean/spreading.h"

namespace {
using dw_real = double;
using dw_real2 = glm::dvec2;
using std::cos;
using std::sin;
#define LAGOON_FN inline
#include "shared/direct_waves_math.h"
#undef LAGOON_FN
}  // namespace

namespace lagoon::ocean {

double sine_profile_mean(uint32_t power) {
  if (power == 0) return 0;
  double mean = 1;
  for (uint32_t j = 1; j <= power; ++j) mean *= double(power + j) / double(j) / 4.0;
  return mean;
}

double gerstner_omega(GerstnerDispersion law, double k, double depth_m) {
  switch (law) {
    case GerstnerDispersion::Deep:
      return omega_deep(k);
    case GerstnerDispersion::FiniteDepth:
      return omega_finite_depth(k, depth_m);
    case GerstnerDispersion::Capillary:
      return omega_capillary(k);
  }
  return 0.0;
}

GerstnerSurface::GerstnerSurface(GerstnerParams params) : params_(std::move(params)) {
  double sum = 0;
  for (const GerstnerWave& w : params_.waves) {
    const double k = 2 * std::numbers::pi / w.wavelength_m;
    k_.push_back(k * compass::toward_deg(w.direction_deg));
    omega_.push_back(
        quantise_omega(gerstner_omega(params_.dispersion, k, params_.depth_m), params_.loop_period_s));
    q_.push_back(w.steepness);
    mean_.push_back(sine_profile_mean(w.power));
    sum += w.steepness * k * w.amplitude_m;
  }
  if (params_.limit_steepness && sum > 1)
    for (double& q : q_) q /= sum;
  if (!params_.floor) return;
  ShoalingInputs in{.floor = params_.floor, .breaker_index = params_.breaker_index, .sea = params_.sea};
  if (params_.dispersion == GerstnerDispersion::FiniteDepth) in.reference_depth_m = params_.depth_m;
  for (size_t i = 0; i < k_.size(); ++i)
    in.waves.push_back({.k = k_[i],
                        .omega = omega_[i],
                        .amplitude_m = params_.waves[i].amplitude_m,
                        .height_per_amplitude = params_.waves[i].power == 0 ? 2.0 : 1.0,
                        .steepness = q_[i]});
  auto shoaling = std::make_shared<Shoaling>(std::move(in));
  if (shoaling->active()) shoaling_ = std::move(shoaling);
}

double GerstnerSurface::steepness_sum() const {
  double sum = 0;
  for (size_t i = 0; i < k_.size(); ++i) sum += q_[i] * glm::length(k_[i]) * params_.waves[i].amplitude_m;
  return sum;
}

GerstnerSurface::Sum GerstnerSurface::sum_at(glm::dvec2 x0, double t) const {
  Sum out;
  // Over the floor each wave has its local wavevector, amplitude and phase offset (ocean/shoaling.h).
  const double q_scale = shoaling_ ? shoaling_->ground(x0).z : 1.0;
  for (size_t i = 0; i < k_.size(); ++i) {
    const GerstnerWave& w = params_.waves[i];
    glm::dvec2 kv = k_[i];
    double a = w.amplitude_m, offset = 0;
    if (shoaling_) {
      const glm::dvec4 local = shoaling_->wave(i, x0);
      kv = shoaling_->wavevector(local);
      a = local.y;
      offset = local.x;
    }
    const double k = glm::length(kv);
    const glm::dvec2 d = kv / k;
    const double theta = glm::dot(k_[i], x0) + offset - omega_[i] * t + w.phase_rad;
    const double s = std::sin(theta), c = std::cos(theta), qa = q_[i] * q_scale * a;
    const glm::dvec2 g = dw_profile(theta, double(w.power), mean_[i]);  // (g, dg/dθ)
    // ∂(x, z)/∂(x0, z0) = I - Σ Q A |k| d dᵀ cos θ; ∂y/∂x0 = Σ A g' k (the amplitude's own change is slow).
    out.shift -= qa * d * s;
    out.y += a * g.x;
    out.vxz += qa * d * c * omega_[i];  // d/dt of -Q A d sin θ, dθ/dt = -ω
    out.vy -= a * g.y * omega_[i];      // d/dt of A g(θ)
    out.jxx -= qa * k * d.x * d.x * c;
    out.jxz -= qa * k * d.x * d.y * c;
    out.jzz -= qa * k * d.y * d.y * c;
    out.dy += a * g.y * kv;
  }
  return out;
}

GerstnerPoint GerstnerSurface::at_rest(glm::dvec2 x0, double t) const {
  const Sum sum = sum_at(x0, t);
  GerstnerPoint p;
  p.position = {x0.x + sum.shift.x, sum.y, x0.y + sum.shift.y};
  p.velocity = {sum.vxz.x, sum.vy, sum.vxz.y};
  p.jacobian = sum.jxx * sum.jzz - sum.jxz * sum.jxz;
  // Tangents along x0 and z0: (jxx, dy.x, jxz) and (jxz, dy.y, jzz); the normal is their cross product, up.
  const glm::dvec3 tx(sum.jxx, sum.dy.x, sum.jxz), tz(sum.jxz, sum.dy.y, sum.jzz);
  const glm::dvec3 n = glm::cross(tz, tx);
  p.normal = glm::length(n) > 0 ? glm::normalize(n.y < 0 ? -n : n) : glm::dvec3(0, 1, 0);
  return p;
}

WaveSample GerstnerSurface::sample(double t, double x, double z) const {
  const glm::dvec2 q(x, z);
  glm::dvec2 p = q;
  bool converged = false;
  for (int iteration = 0; iteration < 64 && !converged; ++iteration) {
    const Sum sum = sum_at(p, t);
    const glm::dvec2 miss = p + sum.shift - q;
    converged = glm::length(miss) < 1e-10;
    if (converged) break;
    // Newton on the horizontal map; where it is nearly singular (a sharp crest) a fixed-point step instead.
    const double jxx = sum.jxx, jxz = sum.jxz, jzz = sum.jzz;
    const double det = jxx * jzz - jxz * jxz;
    if (det > 1e-3)
      p -= glm::dvec2(jzz * miss.x - jxz * miss.y, -jxz * miss.x + jxx * miss.y) / det;
    else
      p -= miss;
  }
  const GerstnerPoint at = at_rest(p, t);
  WaveSample s;
  s.height = at.position.y;
  s.normal = at.normal;
  s.velocity = at.velocity;
  s.rest_position = p;
  s.converged = converged;
  return s;
}

}  // namespace lagoon::ocean

namespace lagoon::ocean {

std::vector<GerstnerWaveSpec> gerstner_wave_specs(const OceanParams& params) {
  const uint32_t n = params.gerstner.spectrum_waves;
  return n == 0 ? params.gerstner.waves : spectrum_wave_specs(params, n);
}

std::vector<GerstnerWaveSpec> spectrum_wave_specs(const OceanParams& params, uint32_t n) {
  const SpectrumParams& spectrum = params.spectrum;
  const double peak = peak_omega(spectrum), lo = 0.6 * peak, hi = 4.0 * peak;
  const double ratio = std::pow(hi / lo, 1.0 / n);
  const SpreadingModel spread = spreading_for(spectrum);
  const double wind = spectrum.wind_direction_deg;
  constexpr int kAngles = 720;
  std::vector<GerstnerWaveSpec> out;
  for (uint32_t i = 0; i < n; ++i) {
    const double w0 = lo * std::pow(ratio, i), w1 = w0 * ratio, w = std::sqrt(w0 * w1);
    // θ from D(ω, θ): the inverse of its cumulative sum at the i-th golden-ratio quantile.
    std::vector<double> cumulative(kAngles + 1, 0.0);
    for (int a = 0; a < kAngles; ++a) {
      const double theta = -std::numbers::pi + (a + 0.5) * 2 * std::numbers::pi / kAngles;
      cumulative[a + 1] = cumulative[a] + spreading(spread, w, theta);
    }
    const double u = std::fmod(0.5 + i * 0.6180339887498949, 1.0) * cumulative.back();
    int a = 0;
    while (a < kAngles - 1 && cumulative[a + 1] < u) ++a;
    const double theta = -180.0 + (a + 0.5) * 360.0 / kAngles;
    const double phase =
        360.0 * std::fmod((params.seed + 1) * 0.7548776662466927 + i * 0.5698402909980532, 1.0);
    out.push_back({.amplitude_m = std::sqrt(2 * frequency_spectrum(spectrum, params.depth_m, w) * (w1 - w0)),
                   .wavelength_m = 2 * std::numbers::pi / (w * w / kGravity),  // deep water k = ω²/g
                   .direction_deg = wind - theta,  // D is even in θ: the sign only picks a side
                   .phase_deg = phase});
  }
  return out;
}

std::vector<GerstnerWave> lattice_gerstner_waves(const OceanParams& params, std::vector<int>* cascade_of) {
  std::vector<GerstnerWave> out;
  if (cascade_of) cascade_of->clear();
  for (const GerstnerWaveSpec& w : gerstner_wave_specs(params)) {
    const LatticeWave l = snap_to_cascades(params, wave_vector(w.wavelength_m, w.direction_deg));
    out.push_back({.amplitude_m = w.amplitude_m,
                   .wavelength_m = 2 * std::numbers::pi / glm::length(l.k),
                   .direction_deg = compass::azimuth_of(l.k) * 180 / std::numbers::pi,
                   .phase_rad = w.phase_deg * std::numbers::pi / 180,
                   .steepness = params.choppiness});
    if (cascade_of) cascade_of->push_back(l.cascade);
  }
  return out;
}

GerstnerParams gerstner_params(const OceanParams& params) {
  return {.waves = lattice_gerstner_waves(params),
          .dispersion = params.gerstner.dispersion,
          .depth_m = params.depth_m,
          .loop_period_s = params.loop_period_s,
          .limit_steepness = false};  // validate() refuses loops; the cascades cannot scale Q per wave
}

CascadeSpectrum gerstner_cascade_spectrum(const OceanParams& params, uint32_t cascade) {
  CascadeSpectrum out = empty_cascade_spectrum(params, cascade);
  if (out.resolution == 0) return out;
  const uint32_t n = out.resolution;
  for (const GerstnerWaveSpec& w : gerstner_wave_specs(params)) {
    // The lattice mode itself, as lattice_gerstner_waves places the wave (not re-derived from its length).
    const LatticeWave l = snap_to_cascades(params, wave_vector(w.wavelength_m, w.direction_deg));
    if (l.cascade != int(cascade)) continue;
    const long mx = l.mode.x, mz = l.mode.y;
    // h̃(k, t) = h0(k) e^{-iωt} + conj(h0(-k)) e^{iωt}: with h0(k) = A/2 e^{iφ} and h0(-k) = 0 the height is
    // A cos(k·x - ωt + φ), eq. 11's y.
    out.h0[mode_index(n, mx, mz)] +=
        std::complex<float>(std::polar(0.5 * w.amplitude_m, w.phase_deg * std::numbers::pi / 180));
    const float omega = float(quantise_omega(
        gerstner_omega(params.gerstner.dispersion, glm::length(l.k), params.depth_m), params.loop_period_s));
    out.omega[mode_index(n, mx, mz)] = omega;
    out.omega[mode_index(n, -mx, -mz)] = omega;
  }
  return out;
}

}  // namespace lagoon::ocean
