#include "ocean/short_waves.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/compass.h"
#include "ocean/spectrum.h"

namespace lagoon::ocean {
namespace {

constexpr double kCm = 0.23, kKm = 370.0;  // minimum phase speed (m/s) and its wavenumber (rad/m)

double phase_speed(double k) {
  return std::sqrt(kGravity / k * (1.0 + (k / kKm) * (k / kKm)));
}

}  // namespace

double friction_velocity(double wind_speed_mps) {
  return std::sqrt((0.8 + 0.065 * wind_speed_mps) * 1e-3) * wind_speed_mps;
}

double short_wave_curvature(const OceanParams& params, double k) {
  if (!(k > 0)) return 0;
  const double u_star = friction_velocity(params.spectrum.wind_speed_mps), r = u_star / kCm;
  const double alpha_m = 0.01 * (u_star <= kCm ? 1.0 + std::log(r) : 1.0 + 3.0 * std::log(r));  // eq. 44
  if (alpha_m <= 0) return 0;
  const double wp = peak_omega(params.spectrum), kp = wp * wp / kGravity;
  // F_m = L_PM J_p exp(-¼ (k/k_m - 1)²) (eq. 41), γ and σ of the peak as the long waves' (eq. 3, 27).
  const double l_pm = std::exp(-1.25 * (kp / k) * (kp / k));
  const double inverse_age = wp * params.spectrum.wind_speed_mps / kGravity;  // Ω_c = U10/c_p
  const double sigma = 0.08 * (1.0 + 4.0 * std::pow(inverse_age, -3));
  const double jp =
      std::pow(params.spectrum.gamma, std::exp(-std::pow(std::sqrt(k / kp) - 1.0, 2) / (2 * sigma * sigma)));
  const double fm = l_pm * jp * std::exp(-0.25 * std::pow(k / kKm - 1.0, 2));
  return 0.5 * alpha_m * kCm / phase_speed(k) * fm;
}

double short_wave_spreading(const OceanParams& params, double k) {
  const double u_star = friction_velocity(params.spectrum.wind_speed_mps);
  const double cp = kGravity / peak_omega(params.spectrum), c = phase_speed(k);
  const double a0 = std::log(2.0) / 4.0, ap = 4.0, am = 0.13 * u_star / kCm;  // eqs. 57, 59
  return std::tanh(a0 + ap * std::pow(c / cp, 2.5) + am * std::pow(kCm / c, 2.5));
}

SlopeMoments short_wave_slope_moments(const OceanParams& params, double k_from) {
  SlopeMoments m;
  const double k_to = 10.0 * kKm;
  if (!(k_from > 0) || k_from >= k_to) return m;
  // Slope variance per ln k is B(k) (∫ k² Ψ k dk dφ = ∫ B dk/k); along the wind it carries
  // ∫ cos²φ (1 + Δ cos 2φ) dφ/2π = ½ + Δ/4, across it ½ - Δ/4. Trapezoid in ln k.
  constexpr int kSteps = 400;
  const double a = std::log(k_from), step = (std::log(k_to) - a) / kSteps;
  double along = 0, across = 0;
  for (int i = 0; i <= kSteps; ++i) {
    const double k = std::exp(a + i * step), w = (i == 0 || i == kSteps ? 0.5 : 1.0) * step;
    const double b = short_wave_curvature(params, k), d = short_wave_spreading(params, k);
    along += w * b * (0.5 + 0.25 * d), across += w * b * (0.5 - 0.25 * d);
  }
  // Rotate from (along, across) the wind into (x, z): the wind blows toward (wx, wz).
  const glm::dvec2 wind = compass::toward_deg(params.spectrum.wind_direction_deg);
  const double wx = wind.x, wz = wind.y;
  m.xx = along * wx * wx + across * wz * wz;
  m.zz = along * wz * wz + across * wx * wx;
  m.xz = (along - across) * wx * wz;
  return m;
}

}  // namespace lagoon::ocean
