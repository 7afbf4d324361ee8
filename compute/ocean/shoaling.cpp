#include "ocean/shoaling.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "ocean/ocean_params.h"

namespace {
using sh_real = double;
using sh_real4 = glm::dvec4;
using std::clamp;
using std::floor;
using std::max;
using std::min;
#define LAGOON_FN inline
#include "shared/shoaling_math.h"
#undef LAGOON_FN

// Depths below this are treated as this for the wavenumber (k ~ 1/sqrt(h) grows without bound at the
// shoreline, where the wave has already broken down to nothing).
constexpr double kShallowestM = 0.02;
}  // namespace

namespace lagoon::ocean {

double Shoaling::wavenumber(double omega, double depth_m) {
  const double deep = omega * omega / kGravity;
  if (!(depth_m > 0)) return HUGE_VAL;
  // Newton on f(k) = g k tanh(k h) - ω², from k0 / sqrt(tanh(k0 h)), within 5 % everywhere.
  double k = deep / std::sqrt(std::tanh(deep * depth_m));
  for (int i = 0; i < 50; ++i) {
    const double t = std::tanh(k * depth_m);
    const double f = kGravity * k * t - omega * omega;
    const double df = kGravity * (t + k * depth_m * (1 - t * t));
    const double step = f / df;
    k -= step;
    if (std::abs(step) < 1e-15 * k) break;
  }
  return k;
}

double Shoaling::group_velocity(double omega, double depth_m) {
  const double k = wavenumber(omega, depth_m);
  const double kh2 = 2 * k * depth_m;
  const double n = 0.5 * (1 + (kh2 > 40 ? 0.0 : kh2 / std::sinh(kh2)));
  return n * omega / k;
}

Shoaling::Shoaling(ShoalingInputs inputs) : inputs_(std::move(inputs)) {
  if (!inputs_.floor || inputs_.floor->depth_m.size() < 2 || !(inputs_.floor->spacing_m > 0))
    throw std::invalid_argument("Shoaling: the depth profile needs two samples or more, > 0 apart");
  const size_t n = samples(), waves = wave_count();
  const std::vector<double>& depth = inputs_.floor->depth_m;
  table_.assign(n * (1 + waves), glm::dvec4(0.0));
  std::vector<double> linear(n, 0.0);  // Σ H_i before breaking
  for (size_t i = 0; i < waves; ++i) build_wave(i, linear);
  double base_steepness = 0;
  for (const ShoalingWave& w : inputs_.waves)
    base_steepness += w.steepness * glm::length(w.k) * w.amplitude_m;
  const double hs = inputs_.sea_significant_height_m, gamma = inputs_.breaker_index;
  for (size_t j = 0; j < n; ++j) {
    const double h = depth[j], cap = gamma * std::max(h, 0.0);
    // The waves' sum breaks too: where their summed height exceeds γ h each is scaled down alike.
    double summed = 0, steep = 0;
    for (size_t i = 0; i < waves; ++i)
      summed += inputs_.waves[i].height_per_amplitude * table_[(1 + i) * n + j].y;
    const double together = summed > cap ? (summed > 0 ? cap / summed : 0.0) : 1.0;
    for (size_t i = 0; i < waves; ++i) {
      glm::dvec4& v = table_[(1 + i) * n + j];
      if (together < 1) v.y *= together;
      const glm::dvec2 k = wavevector(i, v);
      steep += inputs_.waves[i].steepness * glm::length(k) * v.y;
    }
    // Steeper, shorter waves would loop their crests: never more than the waves do in deep water (or 1).
    const double allowed = std::max(1.0, base_steepness);
    const double q = steep > allowed ? allowed / steep : 1.0;
    const double sea = hs > 0 ? std::clamp(kSurfZoneHsPerDepth * h / hs, 0.0, 1.0) : 1.0;
    const double ratio = cap > 0 ? linear[j] / cap : (linear[j] > 0 ? 1e3 : 0.0);
    table_[j] = glm::dvec4(h, sea, q, ratio);
    if (sea < 1 || q < 1) active_ = true;
  }
}

void Shoaling::build_wave(size_t i, std::vector<double>& linear) {
  const ShoalingWave& w = inputs_.waves[i];
  const DepthProfile& floor = *inputs_.floor;
  const size_t n = samples();
  const glm::dvec2 u = floor.axis, v(-u.y, u.x);
  const double k0 = glm::length(w.k), ku0 = glm::dot(w.k, u), kv = glm::dot(w.k, v);
  // Where the wave is its own: half a wavelength down, or the depth a finite-depth wave is given at.
  const double top = std::min(std::numbers::pi / k0, inputs_.reference_depth_m);
  const double k_top = wavenumber(w.omega, top), cg_top = group_velocity(w.omega, top);
  const double cos0 = std::abs(ku0) / k0;
  glm::dvec4* row = &table_[(1 + i) * n];
  for (size_t j = 0; j < n; ++j) {
    const double h = floor.depth_m[j];
    double ku = ku0, a = w.amplitude_m;
    if (h < top) {
      const double he = std::max(h, kShallowestM);
      // Relative to the wave's own k at `top`: continuous there, and exact for a finite-depth wave.
      const double kl = k0 * wavenumber(w.omega, he) / k_top;
      ku = std::copysign(std::sqrt(std::max(kl * kl - kv * kv, 0.0)), ku0 == 0 ? 1.0 : ku0);
      const double cos_theta = std::abs(ku) / kl;
      const double refraction = cos_theta > 0 ? std::sqrt(cos0 / cos_theta) : 1.0;
      a = h > 0 ? w.amplitude_m * std::sqrt(cg_top / group_velocity(w.omega, he)) * refraction : 0.0;
      active_ = true;
    }
    const double capped = std::min(a, inputs_.breaker_index * std::max(h, 0.0) / w.height_per_amplitude);
    row[j] = glm::dvec4(0.0, capped, ku, a);
    linear[j] += w.height_per_amplitude * a;
  }
  // φ(s) = ∫ (k_u - k_u0) ds, 0 at the deepest sample (trapezoids: the shaders interpolate linearly).
  const size_t anchor =
      size_t(std::max_element(floor.depth_m.begin(), floor.depth_m.end()) - floor.depth_m.begin());
  const double half = 0.5 * floor.spacing_m;
  for (size_t j = anchor + 1; j < n; ++j)
    row[j].x = row[j - 1].x + half * (row[j - 1].z + row[j].z - 2 * ku0);
  for (size_t j = anchor; j-- > 0;) row[j].x = row[j + 1].x - half * (row[j + 1].z + row[j].z - 2 * ku0);
}

glm::dvec4 Shoaling::locate(glm::dvec2 xz) const {
  return sh_locate(inputs_.floor->s_of(xz), inputs_.floor->spacing_m, double(samples()));
}

glm::dvec4 Shoaling::ground(glm::dvec2 xz) const {
  const glm::dvec4 at = locate(xz);
  const size_t j = size_t(at.x);
  return sh_value(table_[j], table_[j + 1], at);
}

glm::dvec4 Shoaling::wave(size_t i, glm::dvec2 xz) const {
  const glm::dvec4 at = locate(xz);
  const size_t j = size_t(at.x), n = samples();
  const glm::dvec4* row = &table_[(1 + i) * n];
  return sh_wave_value(row[j], row[j + 1], at, glm::dot(inputs_.waves[i].k, inputs_.floor->axis));
}

glm::dvec2 Shoaling::wavevector(size_t i, const glm::dvec4& value) const {
  const glm::dvec2 u = inputs_.floor->axis, v(-u.y, u.x);
  return value.z * u + glm::dot(inputs_.waves[i].k, v) * v;
}

}  // namespace lagoon::ocean
