// The procedural sea floor of the scene's "seafloor" block (type "slope"): a height field that falls from
// depth_near_m at `near` to depth_far_m at `far` along the line between them, flat beyond both ends. The
// renderer draws it (render/seafloor.h) and the world's bodies rest on it (world/floor_height.h).
#pragma once
#include <glm/vec2.hpp>

#include "scene/scene.h"

namespace lagoon::world {

// Depth below the mean water level (m, > 0 under water) of the slope floor at (x, z).
float slope_depth(const scene::Seafloor& floor, glm::vec2 xz);

}  // namespace lagoon::world
