// A closed box as a hull for the physics tests: the closed form of its volume, inertia and draught is known.
#pragma once
#include <cstdint>
#include <glm/vec3.hpp>

#include "physics/mass_properties.h"

namespace lagoon::test {

// An axis-aligned box with half-extents `h` centred on `c`, counter-clockwise from outside.
inline physics::TriangleMesh box(glm::dvec3 h, glm::dvec3 c = glm::dvec3(0.0)) {
  physics::TriangleMesh m;
  for (int k = 0; k < 8; ++k)
    m.vertices.push_back(c + glm::dvec3(k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z));
  // Faces as quads (corner bits x + 2y + 4z), wound outward.
  const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  return m;
}

// The same box with every face split into n x n quads (2n² triangles): a finer model of the same solid.
inline physics::TriangleMesh tessellated_box(glm::dvec3 h, int n, glm::dvec3 c = glm::dvec3(0.0)) {
  physics::TriangleMesh m;
  // Each face from a corner along two edges u, v with u × v pointing out of the box.
  auto face = [&](glm::dvec3 corner, glm::dvec3 u, glm::dvec3 v) {
    const uint32_t base = uint32_t(m.vertices.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.vertices.push_back(c + corner + (double(i) / n) * u + (double(j) / n) * v);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, d = a + uint32_t(n + 1), e = d + 1;
        m.indices.insert(m.indices.end(), {a, b, e, a, e, d});
      }
  };
  const glm::dvec3 x(2 * h.x, 0, 0), y(0, 2 * h.y, 0), z(0, 0, 2 * h.z);
  face(-h, x, z);                           // bottom, −y
  face(glm::dvec3(-h.x, h.y, -h.z), z, x);  // top, +y
  face(-h, y, x);                           // −z
  face(glm::dvec3(-h.x, -h.y, h.z), x, y);  // +z
  face(-h, z, y);                           // −x
  face(glm::dvec3(h.x, -h.y, -h.z), y, z);  // +x
  return m;
}

}  // namespace lagoon::test
