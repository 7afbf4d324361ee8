// The waves' transformation over the floor (ocean/shoaling.h) as the surface shaders read it: its table in an
// RGBA32F array texture, a layer for the floor and one per wave (shared/shoaling.h), and where the grid lies,
// for the frame's uniforms. A 1 x 1 texture when nothing is transformed, so every pass can bind it.
#pragma once
#include <glm/vec4.hpp>

#include "ocean/shoaling.h"
#include "vk/context.h"
#include "vk/image.h"

namespace lagoon::ocean {

class ShoalingGpu {
 public:
  // `shoaling` may be null (nothing transformed).
  ShoalingGpu(vk::Context& ctx, const Shoaling* shoaling);

  bool active() const { return active_; }
  const vk::Image& table() const { return table_; }
  // For the frame (shared/frame.h): xy = the profile's origin (world xz), zw = its axis.
  glm::vec4 axis() const { return axis_; }
  // x = spacing m, y = samples along the axis (columns), z = across it (rows), w unused.
  glm::vec4 grid() const { return grid_; }

 private:
  bool active_ = false;
  vk::Image table_;
  glm::vec4 axis_{0.0f}, grid_{1.0f, 1.0f, 0.0f, 0.0f};
};

}  // namespace lagoon::ocean
