#include "physics/heave_radiation.h"

#include <cmath>
#include <numbers>

namespace lagoon::physics {

HeaveTerms heave_terms(const HeaveRadiation& radiation, double displaced_m3, double density, double gravity) {
  if (!radiation.enabled || !(displaced_m3 > 0)) return {};
  const double radius = std::cbrt(3.0 * displaced_m3 / (2.0 * std::numbers::pi));
  const double omega = std::sqrt(3.0 * gravity / (2.0 * radius * (1.0 + radiation.added_mass)));
  const double water_mass = density * displaced_m3;
  return {radiation.added_mass * water_mass, radiation.damping * water_mass * omega, 0.375 * radius};
}

}  // namespace lagoon::physics
