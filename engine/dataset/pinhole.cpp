#include "dataset/pinhole.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/trigonometric.hpp>

#include "render/camera.h"

namespace lagoon::dataset {

Pinhole pinhole(const scene::Camera& camera, uint32_t width, uint32_t height) {
  const double w = width, h = height;
  // The view the renderer draws: GLM's right-handed look-at (camera x right, y up, z backwards), the image's
  // y flipped by the viewport (render/camera.h).
  const glm::dmat3 view(render::camera_matrices(camera, float(w / h)).view);
  const glm::dvec3 right = glm::row(view, 0), up = glm::row(view, 1), back = glm::row(view, 2);
  Pinhole p;
  p.fy = p.fx = 0.5 * h / std::tan(0.5 * glm::radians(double(camera.fov_deg)));
  p.cx = 0.5 * (w - 1);
  p.cy = 0.5 * (h - 1);
  p.world_from_camera = glm::dmat3(right, -up, -back);
  p.position = glm::dvec3(camera.position);
  return p;
}

glm::dvec3 Pinhole::ray(double u, double v) const {
  return glm::normalize(world_from_camera * glm::dvec3((u - cx) / fx, (v - cy) / fy, 1.0));
}

}  // namespace lagoon::dataset
