// The sea floor as the waves feel it (issue 37, docs/ocean.md "Waves over the floor"): the water's depth on a
// grid of samples along two horizontal axes, u and v, held constant beyond the grid's edges. One row (rows =
// 1) is a floor whose depth changes along u only, with straight, parallel contours: the slope floor
// (scene/floor_profile.h); more rows sample any floor (a glTF floor). The waves' transformation over the
// floor (ocean/shoaling.h) is computed on it. Plain data, no Vulkan.
#pragma once
#include <cmath>
#include <cstddef>
#include <glm/vec2.hpp>
#include <vector>

namespace lagoon::ocean {

struct DepthProfile {
  glm::dvec2 origin{0.0};     // world (x, z) of sample (0, 0)
  glm::dvec2 axis{0.0, 1.0};  // u, a unit vector; v = across() = (-u.z, u.x)
  double spacing_m = 1.0;     // between samples along both axes, > 0
  size_t rows = 1;            // samples along v
  // Depth below the mean water level (m; < 0: dry land), rows × columns, row-major: sample (i, j) lies at
  // origin + i·spacing·u + j·spacing·v.
  std::vector<double> depth_m;

  size_t columns() const { return rows == 0 ? 0 : depth_m.size() / rows; }
  glm::dvec2 across() const { return {-axis.y, axis.x}; }
  // (s_u, s_v): metres along u and v from the origin.
  glm::dvec2 local(glm::dvec2 xz) const;
  double depth(size_t i, size_t j) const { return depth_m[j * columns() + i]; }
  double depth_at(glm::dvec2 local) const;  // bilinear between samples
  double shallowest_m() const;
};

}  // namespace lagoon::ocean
