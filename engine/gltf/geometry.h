// Geometry the file may leave out, computed the way most glTF viewers do.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "gltf/model.h"

namespace lagoon::gltf::detail {

// Triangle lists from TRIANGLE_STRIP / TRIANGLE_FAN index sequences, keeping the winding of the first
// triangle (glTF spec, section 3.7.2.1). Fewer than 3 indices give no triangles.
std::vector<uint32_t> strip_to_list(const std::vector<uint32_t>& strip);
std::vector<uint32_t> fan_to_list(const std::vector<uint32_t>& fan);

// Smooth normals: each vertex gets the sum of its triangles' face normals weighted by their areas,
// normalised. Vertices of no (or only degenerate) triangles get +Y. Indices must be in range.
std::vector<glm::vec3> area_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<uint32_t>& indices);

// World-space bounds of all instances into model.bounds_min/max (zero when nothing is drawn). Exact
// (every vertex transformed) while the work stays under `budget` vertex transforms, so the call cannot
// take minutes on a file with 100 000 instances of a large mesh; past it, each further instance adds its
// mesh's box transformed, which can only be larger.
void compute_bounds(Model& model, size_t budget = size_t{1} << 26);

}  // namespace lagoon::gltf::detail
