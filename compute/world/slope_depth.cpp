#include "world/slope_depth.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace lagoon::world {

float slope_depth(const scene::Seafloor& floor, glm::vec2 xz) {
  const glm::vec2 axis = floor.far - floor.near;
  const float t = std::clamp(glm::dot(xz - floor.near, axis) / glm::dot(axis, axis), 0.0f, 1.0f);
  return floor.depth_near_m + (floor.depth_far_m - floor.depth_near_m) * t;
}

}  // namespace lagoon::world
