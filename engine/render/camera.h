// Camera and sun conventions shared by every pass: y up, mean water level y = 0, -z north, +x east.
// Projection maps depth to [0, 1] (GLM_FORCE_DEPTH_ZERO_TO_ONE) with clip-space y up; the viewport flips y.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace lagoon::render {

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  glm::mat4 view_proj{1.0f};
};

CameraMatrices camera_matrices(const scene::Camera& camera, float aspect);

// Unit vector from the surface towards the sun.
glm::vec3 sun_direction(const scene::Sun& sun);

}  // namespace lagoon::render
