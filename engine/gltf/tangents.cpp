#include "gltf/tangents.h"

#include <cmath>

namespace lagoon::gltf::detail {
namespace {

// Any unit vector orthogonal to n.
glm::vec3 orthogonal(glm::vec3 n) {
  const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(a, n));
}

float corner_angle(glm::vec3 at, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 u = a - at, v = b - at;
  const float lu = glm::length(u), lv = glm::length(v);
  if (lu == 0.0f || lv == 0.0f) return 0.0f;
  return std::acos(glm::clamp(glm::dot(u, v) / (lu * lv), -1.0f, 1.0f));
}

}  // namespace

std::vector<glm::vec4> generate_tangents(const std::vector<glm::vec3>& positions,
                                         const std::vector<glm::vec3>& normals,
                                         const std::vector<glm::vec2>& uvs,
                                         const std::vector<uint32_t>& indices) {
  const size_t n = positions.size();
  std::vector<glm::vec3> tangent(n, glm::vec3(0)), bitangent(n, glm::vec3(0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
    const glm::vec3 e1 = positions[i[1]] - positions[i[0]], e2 = positions[i[2]] - positions[i[0]];
    const glm::vec2 d1 = uvs[i[1]] - uvs[i[0]], d2 = uvs[i[2]] - uvs[i[0]];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (det == 0.0f || !std::isfinite(det)) continue;  // no uv mapping across this triangle
    // dp/du and dp/dv of the triangle's affine map from uv to position.
    const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) / det;
    for (int c = 0; c < 3; ++c) {
      const float w = corner_angle(positions[i[c]], positions[i[(c + 1) % 3]], positions[i[(c + 2) % 3]]);
      const float lu = glm::length(dpdu), lv = glm::length(dpdv);
      if (lu > 0) tangent[i[c]] += w * dpdu / lu;
      if (lv > 0) bitangent[i[c]] += w * dpdv / lv;
    }
  }
  std::vector<glm::vec4> out(n);
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 nrm = normals[v];
    glm::vec3 t = tangent[v] - nrm * glm::dot(nrm, tangent[v]);  // Gram-Schmidt against the normal
    const float len = glm::length(t);
    if (!(len > 1e-12f)) {
      out[v] = glm::vec4(orthogonal(nrm), 1.0f);
      continue;
    }
    t /= len;
    const float w = glm::dot(glm::cross(nrm, t), bitangent[v]) < 0.0f ? -1.0f : 1.0f;
    out[v] = glm::vec4(t, w);
  }
  return out;
}

}  // namespace lagoon::gltf::detail
