#include "physics/sphere_mesh.h"

#include <cmath>
#include <numbers>

namespace lagoon::physics {

TriangleMesh uv_sphere(double r, int rings) {
  TriangleMesh m;
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

}  // namespace lagoon::physics
