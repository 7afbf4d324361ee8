// Constants and small formulas of the tests' own references (not taken from the code under test).
#pragma once
#include <cmath>
#include <numbers>

namespace lagoon::test {

inline constexpr double kG = 9.81;  // standard gravity (m/s²)

// An angle (rad) brought into [-π, π].
inline double wrap_angle(double a) {
  return a - 2 * std::numbers::pi * std::round(a / (2 * std::numbers::pi));
}

}  // namespace lagoon::test
