// The procedural sea floor of the scene's "seafloor" block (type "slope"): a height field that falls from
// depth_near_m at `near` to depth_far_m at `far` along the line between them, flat beyond both ends.
#pragma once
#include <vector>

#include "render/gpu_mesh.h"
#include "scene/scene.h"
#include "world/slope_depth.h"

namespace lagoon::render {

struct FloorMesh {
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;
};

// A grid of `cells` x `cells` quads covering ±extent_m around `centre`, denser near the centre.
FloorMesh build_slope_floor(const scene::Seafloor& floor, glm::vec2 centre, uint32_t cells = 64);

}  // namespace lagoon::render
