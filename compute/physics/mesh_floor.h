// A floor given as triangles (a glTF sea floor's meshes): its height under a point by a vertical ray cast
// against them, through a grid of cells over the (x, z) plane that lists the triangles over each cell, so
// a lookup tests the few triangles of one cell. The floor is the highest triangle over (x, z) (an overhang
// counts as floor), -infinity outside the mesh.
#pragma once
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace lagoon::physics {

class MeshFloor {
 public:
  // `vertices` in world coordinates (y up), `indices` three per triangle; the winding does not matter.
  MeshFloor(std::vector<glm::dvec3> vertices, std::vector<uint32_t> indices);

  // World y of the floor at (x, z), or -infinity where no triangle is over or under it.
  double height(double x, double z) const;
  bool empty() const { return indices_.empty(); }

 private:
  const std::vector<uint32_t>& cell(int i, int j) const {
    return cells_[size_t(j) * size_t(nx_) + size_t(i)];
  }

  std::vector<glm::dvec3> vertices_;
  std::vector<uint32_t> indices_;
  glm::dvec2 origin_{0.0};  // (x, z) of the grid's corner
  double cell_m_ = 1;
  int nx_ = 0, nz_ = 0;
  std::vector<std::vector<uint32_t>> cells_;  // first index of each triangle over the cell
};

}  // namespace lagoon::physics
