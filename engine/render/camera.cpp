#include "render/camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/compass.h"

namespace lagoon::render {

CameraMatrices camera_matrices(const scene::Camera& camera, float aspect) {
  CameraMatrices m;
  glm::vec3 forward = camera.look_at - camera.position;
  // The camera's up (level unless a glTF camera rolls it); parallel to the view, as when looking straight up
  // or down, another up keeps lookAt defined.
  const glm::vec3 f = glm::normalize(forward), wanted = glm::normalize(camera.up);
  const glm::vec3 up = std::abs(glm::dot(f, wanted)) < 0.999f ? wanted
                       : std::abs(f.y) > 0.999f               ? glm::vec3(0, 0, 1)
                                                              : glm::vec3(0, 1, 0);
  m.view = glm::lookAt(camera.position, camera.look_at, up);
  m.proj = glm::perspective(glm::radians(camera.fov_deg), aspect, camera.near_m, camera.far_m);
  m.view_proj = m.proj * m.view;
  return m;
}

glm::vec3 sun_direction(const scene::Sun& sun) {
  return glm::vec3(compass::direction_deg(sun.azimuth_deg, sun.elevation_deg));
}

}  // namespace lagoon::render
