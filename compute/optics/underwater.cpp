#include "optics/underwater.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/common.hpp>

#include "optics/colour.h"

namespace lagoon::optics {
namespace {

// Deep enough that the bottom is invisible at every wavelength (τ0 > 40 even for pure water at 400 nm);
// as the LUT's deep-water colour.
constexpr double kBottomlessDepthM = 1e4;
constexpr double kKdDepthM = 10.0;

// Per wavelength: the bottomless column's flows and the coefficients a view ray needs.
struct Medium {
  std::vector<FourFlowSolution> flows;  // one per grid wavelength
  Spectrum model_epsilon{};             // χ + σ' of the flows (τ = ε'z)
  Spectrum absorption{}, scattering{};  // χ, σ (true, not similarity-scaled)
  Spectrum forward{};                   // f = g²: the phase function's forward peak (delta-Eddington)
  // Φ is linear in the spectrum for a fixed white (colour.h), so Φ(f) = Σ f(λ_i)·phi[i]: 81 multiply-adds
  // per colour instead of a CIE integration and an adaptation.
  std::array<glm::dvec3, kSamples> phi{};
};

glm::dvec3 apply_phi(const Medium& m, const Spectrum& f) {
  glm::dvec3 rgb(0.0);
  for (int i = 0; i < kSamples; ++i) rgb += f[i] * m.phi[i];
  return rgb;
}

Result<Medium> medium_of(const LutInputs& in) {
  Medium m;
  const Spectrum white = downwelling_white(in.sky);
  for (int i = 0; i < kSamples; ++i) {
    Spectrum line{};
    line[i] = 1.0;
    m.phi[i] = adapted_linear_srgb(line, white);
  }
  for (int i = 0; i < kSamples; ++i) {
    auto s = solve_wavelength(in, i, kBottomlessDepthM);
    if (!s) return s.error();
    m.flows.push_back(*s);
    const double chi = in.water.absorption_per_m[i], sigma = in.water.scattering_per_m[i];
    const double g = phase_x1_at(in, i) / 3.0;
    m.absorption[i] = chi;
    m.scattering[i] = sigma;
    m.forward[i] = g * g;
    m.model_epsilon[i] = chi + similarity_scaled(sigma, phase_x1_at(in, i)).scattering_per_m;
  }
  return m;
}

// The flows at one depth, per wavelength: all a row of the table needs (the distance only enters through α).
struct Depth {
  Spectrum e_d{};     // G+ + F+: the light falling on a target
  Spectrum direct{};  // G+: its direct (sun) part
  Spectrum down{};    // F−: the water's light seen looking down
  Spectrum up{};      // the scattered part of F+, seen looking up
};

Depth depth_of(const Medium& m, double z_m) {
  Depth d;
  for (int i = 0; i < kSamples; ++i) {
    const FourFlowSolution& f = m.flows[i];
    const double tau = m.model_epsilon[i] * z_m;
    d.e_d[i] = f.g_plus(tau) + f.f_plus(tau);
    d.direct[i] = f.g_plus(tau);
    d.down[i] = f.f_minus(tau);
    // Looking up, the diffuse light that came through the surface unscattered, F+(0)·e^{−τ}, is the surface
    // itself (drawn through Snell's window), not light the water adds: only the scattered rest is.
    d.up[i] = std::max(f.f_plus(tau) - f.f_plus(0.0) * std::exp(-tau), 0.0);
  }
  return d;
}

UnderwaterSample sample(const Medium& m, const Depth& at, double d_m) {
  Spectrum received{}, sharp{}, down{}, up{};
  for (int i = 0; i < kSamples; ++i) {
    const double alpha = std::exp(-(m.absorption[i] + m.scattering[i] * (1.0 - m.forward[i])) * d_m);
    const double alpha_sharp = std::exp(-(m.absorption[i] + m.scattering[i]) * d_m);
    received[i] = alpha * at.e_d[i];
    sharp[i] = alpha_sharp * at.e_d[i];
    down[i] = (1.0 - alpha) * at.down[i];
    up[i] = (1.0 - alpha) * at.up[i];
  }
  UnderwaterSample s;
  // Spectral blue-greens lie outside the sRGB gamut (a small negative red); clip as the LUTs do.
  const glm::dvec3 all = apply_phi(m, received);
  s.target = glm::max(all, glm::dvec3(0.0));
  s.water_down = glm::max(apply_phi(m, down), glm::dvec3(0.0));
  s.water_up = glm::max(apply_phi(m, up), glm::dvec3(0.0));
  const double y_all = linear_srgb_luminance(all), y_sharp = linear_srgb_luminance(apply_phi(m, sharp));
  s.blur = y_all > 1e-12 ? std::clamp(1.0 - y_sharp / y_all, 0.0, 1.0) : 1.0;
  const double y_e_d = linear_srgb_luminance(apply_phi(m, at.e_d));
  s.direct_share =
      y_e_d > 1e-12 ? std::clamp(linear_srgb_luminance(apply_phi(m, at.direct)) / y_e_d, 0.0, 1.0) : 0.0;
  return s;
}

// Y(E_d(z)) relative to the white above the water (unclipped, unlike the RGB).
double downwelling_luminance(const Medium& m, double z_m) {
  return linear_srgb_luminance(apply_phi(m, depth_of(m, z_m).e_d));
}

std::vector<double> squared_axis(uint32_t count, double max) {
  std::vector<double> axis;
  for (uint32_t i = 0; i < count; ++i) {
    const double u = double(i) / (count - 1);
    axis.push_back(max * u * u);  // denser near 0, where the colour changes fastest
  }
  return axis;
}

void store(const UnderwaterSample& s, float* target, float* down, float* up) {
  for (int c = 0; c < 3; ++c) {
    target[c] = float(s.target[c]);
    down[c] = float(s.water_down[c]);
    up[c] = float(s.water_up[c]);
  }
  target[3] = float(s.blur);
}

}  // namespace

Result<UnderwaterSample> underwater_sample(const LutInputs& inputs, double d_m, double z_m) {
  if (!(d_m >= 0) || !(z_m >= 0) || !std::isfinite(d_m) || !std::isfinite(z_m))
    return make_error("underwater sample: distance and depth must be finite and >= 0 metres");
  auto m = medium_of(inputs);
  if (!m) return m.error();
  return sample(*m, depth_of(*m, z_m), d_m);
}

Result<UnderwaterTable> build_underwater_table(const LutInputs& inputs, const UnderwaterAxes& axes) {
  if (axes.d_count < 2 || axes.z_count < 2)
    return make_error("underwater table: need at least 2 samples along distance and depth");
  if (!(axes.d_max_m > 0) || !(axes.z_max_m > 0) || !std::isfinite(axes.d_max_m) ||
      !std::isfinite(axes.z_max_m))
    return make_error("underwater table: the largest distance and depth must be finite and > 0 metres");
  const auto start = std::chrono::steady_clock::now();
  auto m = medium_of(inputs);
  if (!m) return m.error();
  UnderwaterTable t;
  t.d_count = axes.d_count;
  t.z_count = axes.z_count;
  t.d_m = squared_axis(t.d_count, axes.d_max_m);
  t.z_m = squared_axis(t.z_count, axes.z_max_m);
  const size_t entries = size_t{t.d_count} * t.z_count;
  t.target.resize(entries * 4);
  t.water_down.resize(entries * 3);
  t.water_up.resize(entries * 3);
  for (uint32_t j = 0; j < t.z_count; ++j) {
    const Depth at = depth_of(*m, t.z_m[j]);
    for (uint32_t i = 0; i < t.d_count; ++i) {
      const size_t e = size_t{i} * t.z_count + j;
      store(sample(*m, at, t.d_m[i]), &t.target[e * 4], &t.water_down[e * 3], &t.water_up[e * 3]);
    }
  }
  t.kd_luminance_per_m =
      -std::log(downwelling_luminance(*m, kKdDepthM) / downwelling_luminance(*m, 0)) / kKdDepthM;
  t.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace lagoon::optics
