// Tangents for normal mapping when the file gives none, as glTF asks (MikkTSpace): per triangle, the
// direction of increasing u in the surface, accumulated at each corner weighted by the corner's angle,
// then made orthogonal to the vertex normal; w = ±1 is the handedness (bitangent = w · normal × tangent).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lagoon::gltf::detail {

// What this matches of MikkTSpace: the same per-triangle tangent frames, the same angle weighting and the
// same orthogonalisation, so a mesh whose vertices are not shared across UV seams or mirrored halves gets
// MikkTSpace's tangents. MikkTSpace would also split a vertex whose triangles disagree in handedness; here
// the majority wins. Vertices of no triangle with a usable uv mapping get any unit vector orthogonal to the
// normal and w = 1. Indices must be in range; uvs and normals one per position.
std::vector<glm::vec4> generate_tangents(const std::vector<glm::vec3>& positions,
                                         const std::vector<glm::vec3>& normals,
                                         const std::vector<glm::vec2>& uvs,
                                         const std::vector<uint32_t>& indices);

}  // namespace lagoon::gltf::detail
