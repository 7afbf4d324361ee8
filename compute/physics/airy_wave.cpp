#include "physics/airy_wave.h"

#include <algorithm>
#include <cmath>

namespace lagoon::physics {

double AiryWave::angular_frequency() const {
  const double kd = wavenumber * depth;
  return std::sqrt(gravity * wavenumber * (std::isfinite(kd) ? std::tanh(kd) : 1.0));
}

double AiryWave::height(double x, double z, double t) const {
  return amplitude * std::cos(wavenumber * (x * direction.x + z * direction.y) - angular_frequency() * t);
}

double AiryWave::pressure_head(double x, double y, double z, double t) const {
  const double eta = height(x, z, t);
  if (!std::isfinite(depth)) return eta * std::exp(wavenumber * std::min(y - eta, 0.0));
  const double stretched = std::min((y - eta) * depth / (depth + eta), 0.0);
  // cosh(k(s + d)) / cosh(k·d), written so that it does not overflow for deep water (k·d in the hundreds).
  const double k = wavenumber;
  return eta * (std::exp(k * stretched) + std::exp(-k * (stretched + 2 * depth))) /
         (1 + std::exp(-2 * k * depth));
}

}  // namespace lagoon::physics
