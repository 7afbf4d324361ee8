#include "render/seafloor.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lagoon::render {

FloorMesh build_slope_floor(const scene::Seafloor& floor, glm::vec2 centre, uint32_t cells) {
  FloorMesh mesh;
  const uint32_t n = cells + 1;
  auto position = [&](uint32_t i, uint32_t j) {
    // u -> sign(u)·u²: fine cells near the centre (the camera), coarse far away.
    const float u = 2.0f * float(i) / float(cells) - 1.0f, v = 2.0f * float(j) / float(cells) - 1.0f;
    const glm::vec2 xz =
        centre + floor.extent_m * glm::vec2(std::copysign(u * u, u), std::copysign(v * v, v));
    return glm::vec3(xz.x, -world::slope_depth(floor, xz), xz.y);
  };
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const glm::vec3 p = position(i, j);
      // Normal from neighbouring samples (the slope is planar between its ends).
      const glm::vec3 dx = position(std::min(i + 1, cells), j) - position(i > 0 ? i - 1 : 0, j);
      const glm::vec3 dz = position(i, std::min(j + 1, cells)) - position(i, j > 0 ? j - 1 : 0);
      glm::vec3 normal = glm::normalize(glm::cross(dz, dx));
      if (normal.y < 0) normal = -normal;
      mesh.vertices.push_back({p, normal, glm::vec2(p.x, p.z)});
    }
  for (uint32_t j = 0; j < cells; ++j)
    for (uint32_t i = 0; i < cells; ++i) {
      const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  return mesh;
}

}  // namespace lagoon::render
