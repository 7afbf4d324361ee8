// One regular wave of linear (Airy) theory, with what a hull feels of it below the surface: the
// dynamic pressure fades with depth as e^{k·y} (deep water) or cosh(k(y + d))/cosh(k·d) (depth d), so a
// hull as deep as the wave is long feels less of it than the quasi-static approximation says (issue 33,
// the Task 10 sphere). Above the mean level the pressure is Wheeler-stretched (y → (y − η)·d/(d + η)), so
// that it is zero at the surface itself. The validation's regular waves and the tests are made of it.
#pragma once
#include <glm/vec2.hpp>
#include <limits>

namespace lagoon::physics {

struct AiryWave {
  double amplitude = 0;                                    // m
  double wavenumber = 0;                                   // rad/m
  glm::dvec2 direction{1.0, 0.0};                          // (x, z), unit: where the crests travel
  double depth = std::numeric_limits<double>::infinity();  // m of still water
  double gravity = 9.81;                                   // m/s²

  // ω² = g·k·tanh(k·d).
  double angular_frequency() const;
  // η(x, z, t) = a·cos(k·(x, z)·dir − ω·t).
  double height(double x, double z, double t) const;
  // The pressure head H with p = ρ·g·(H − y) (physics/hydrostatics.h's PressureHead), y from the mean level.
  double pressure_head(double x, double y, double z, double t) const;
};

}  // namespace lagoon::physics
