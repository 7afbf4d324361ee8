// The camera the renderer draws with, as a pinhole camera in OpenCV's convention (docs/datasets.md): K from
// the vertical field of view and the image size, pixel centres at integer coordinates, and the optical frame
// (x right, y down, z forward) in the world. Datasets state it per frame; the ground truth casts its rays.
#pragma once
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace lagoon::dataset {

struct Pinhole {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  glm::dmat3 world_from_camera{1.0};  // columns: the optical axes x, y, z in the world
  glm::dvec3 position{0.0};

  // The unit world direction through pixel (u, v) (u right, v down, centres at integers).
  glm::dvec3 ray(double u, double v) const;
  glm::dvec3 forward() const { return world_from_camera[2]; }
};

Pinhole pinhole(const scene::Camera& camera, uint32_t width, uint32_t height);

}  // namespace lagoon::dataset
