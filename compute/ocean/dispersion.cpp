#include "ocean/dispersion.h"

#include <cmath>
#include <numbers>

namespace lagoon::ocean {

DispersionModel dispersion_for(const OceanParams& params) {
  return DispersionModel{params.depth_m, true, params.loop_period_s};
}

namespace {

// tanh(kD) and its derivative factor sech²(kD); beyond kD = 20 tanh is 1 to double precision.
double depth_factor(double kd) {
  return kd > 20.0 ? 1.0 : std::tanh(kd);
}
double sech2(double kd) {
  if (kd > 20.0) return 0.0;
  const double c = std::cosh(kd);
  return 1.0 / (c * c);
}

double omega_unquantised(const DispersionModel& model, double k) {
  if (!(k > 0.0)) return 0.0;
  const double capillary = model.capillary ? 1.0 + k * k / kCapillaryK2 : 1.0;
  return std::sqrt(kGravity * k * depth_factor(k * model.depth_m) * capillary);
}

}  // namespace

double quantise_omega(double omega, double period_s) {
  if (!(period_s > 0.0)) return omega;
  const double step = 2.0 * std::numbers::pi / period_s;
  return std::floor(omega / step) * step;
}

double omega(const DispersionModel& model, double k) {
  return quantise_omega(omega_unquantised(model, k), model.loop_period_s);
}

double domega_dk(const DispersionModel& model, double k) {
  const double d = model.depth_m;
  if (!(k > 0.0)) return std::sqrt(kGravity * d);  // ω -> k sqrt(gD) as k -> 0
  // ω² = g k t c with t = tanh(kD), c = 1 + k²/k_m²:  d(ω²)/dk = g (t c + k D sech²(kD) c + k t 2k/k_m²).
  const double t = depth_factor(k * d);
  const double c = model.capillary ? 1.0 + k * k / kCapillaryK2 : 1.0;
  const double dc = model.capillary ? 2.0 * k / kCapillaryK2 : 0.0;
  const double dw2 = kGravity * (t * c + k * d * sech2(k * d) * c + k * t * dc);
  return dw2 / (2.0 * omega_unquantised(model, k));
}

double omega_deep(double k) {
  return k > 0.0 ? std::sqrt(kGravity * k) : 0.0;
}

double omega_finite_depth(double k, double depth_m) {
  return omega_unquantised(DispersionModel{depth_m, false, 0.0}, k);
}

double omega_capillary(double k) {
  return k > 0.0 ? std::sqrt(kGravity * k * (1.0 + k * k / kCapillaryK2)) : 0.0;
}

}  // namespace lagoon::ocean
