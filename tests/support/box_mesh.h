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

}  // namespace lagoon::test
