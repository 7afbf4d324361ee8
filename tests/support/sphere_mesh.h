// A UV sphere as a hull for the physics tests (the IEA OES Task 10 sphere is one): its buoyancy, heave
// stiffness and wave force have closed forms or quadratures to check against.
#pragma once
#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <numbers>

#include "physics/mass_properties.h"

namespace lagoon::test {

// A sphere of radius r, `rings` from pole to pole, counter-clockwise from outside.
inline physics::TriangleMesh sphere(double r, int rings) {
  physics::TriangleMesh m;
  const int sectors = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= sectors; ++j) {
      const double theta = std::numbers::pi * i / rings, phi = 2 * std::numbers::pi * j / sectors;
      m.vertices.push_back(
          r * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      const uint32_t a = uint32_t(i * (sectors + 1) + j), b = a + 1, d = a + uint32_t(sectors + 1), c = d + 1;
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  return m;
}

}  // namespace lagoon::test
