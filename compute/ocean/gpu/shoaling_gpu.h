// The waves' transformation over the floor (ocean/shoaling.h) as the surface shaders read it: its table in a
// storage buffer of vec4, a layer for the floor and one per wave (shared/shoaling.h), and where the grid
// lies, for the frame's uniforms. One texel when nothing is transformed, so every pass can bind it.
#pragma once
#include <glm/vec4.hpp>
#include <vector>

#include "ocean/shoaling.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace lagoon::ocean {

class ShoalingGpu {
 public:
  // `shoaling` may be null (nothing transformed).
  ShoalingGpu(vk::Context& ctx, const Shoaling* shoaling);

  bool active() const { return active_; }
  // The shaders' LAGOON_SURFACE_SPEC_SHOALING: 0 nothing transformed, 1 a profile (one row), 2 a grid.
  uint32_t mode() const { return active_ ? (grid_.z > 1.5f ? 2u : 1u) : 0u; }
  const vk::Buffer& table() const { return table_; }
  // For the frame (shared/frame.h): xy = the profile's origin (world xz), zw = its axis.
  glm::vec4 axis() const { return axis_; }
  // x = spacing m, y = samples along the axis (columns), z = across it (rows), w = cascade 0's lattice layer.
  glm::vec4 grid() const { return grid_; }
  // Cascade c's representative wave (k0, k0/|k0|²), zeros when it is not moved.
  glm::vec4 lattice(size_t c) const { return c < lattice_.size() ? lattice_[c] : glm::vec4(0.0f); }

 private:
  bool active_ = false;
  vk::Buffer table_;
  glm::vec4 axis_{0.0f}, grid_{1.0f, 1.0f, 1.0f, 0.0f};
  std::vector<glm::vec4> lattice_;
};

}  // namespace lagoon::ocean
