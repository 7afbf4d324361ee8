#include "world/floor_height.h"

#include <memory>

#include "gltf/gltf_loader.h"
#include "physics/mesh_floor.h"
#include "world/slope_depth.h"

namespace lagoon::world {
namespace {

// The floor model's triangles where SceneObjects draws them (identity transform, its nodes' own).
Result<std::shared_ptr<const physics::MeshFloor>> load_mesh_floor(const std::string& file) {
  auto model = gltf::load_gltf(file);
  if (!model) return make_error("seafloor.file: " + model.error().message);
  std::vector<glm::dvec3> vertices;
  std::vector<uint32_t> indices;
  for (const gltf::Instance& instance : model->instances)
    for (const gltf::Primitive& p : model->meshes[instance.mesh].primitives) {
      const uint32_t base = uint32_t(vertices.size());
      for (const glm::vec3& v : p.positions)
        vertices.push_back(glm::dvec3(instance.world * glm::vec4(v, 1.0f)));
      for (uint32_t i : p.indices) indices.push_back(base + i);
    }
  return std::make_shared<const physics::MeshFloor>(std::move(vertices), std::move(indices));
}

}  // namespace

Result<physics::FloorHeight> floor_height(const scene::Scene& scene) {
  const scene::Seafloor& floor = scene.seafloor;
  switch (floor.type) {
    case scene::SeafloorType::Slope:
      return physics::FloorHeight(
          [floor](double x, double z) { return -double(slope_depth(floor, glm::vec2(float(x), float(z)))); });
    case scene::SeafloorType::Gltf: {
      auto mesh = load_mesh_floor(floor.file);
      if (!mesh) return mesh.error();
      return physics::FloorHeight([mesh = *mesh](double x, double z) { return mesh->height(x, z); });
    }
    case scene::SeafloorType::None:
      break;
  }
  const double depth = scene.ocean.depth_m;
  return physics::FloorHeight([depth](double, double) { return -depth; });
}

}  // namespace lagoon::world
