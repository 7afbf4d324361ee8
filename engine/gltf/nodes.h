// The node hierarchy flattened into instances. Files are checked to be a forest (one parent per node, no
// cycles) before it is walked, and the walk uses its own stack, so no file can make it recurse forever.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "gltf/model.h"

namespace lagoon::gltf::detail {

// A glTF node as tinygltf parses it; empty arrays mean "absent".
struct NodeDesc {
  std::vector<int> children;
  int mesh = -1;
  std::vector<double> matrix;       // 16, column-major
  std::vector<double> translation;  // 3
  std::vector<double> rotation;     // 4, quaternion x, y, z, w
  std::vector<double> scale;        // 3
  int camera = -1;
  int light = -1;  // KHR_lights_punctual
};

// A node that carries a camera or a light (`index` into the file's cameras or lights), and its world
// transform.
struct AttachedNode {
  int node = -1;
  int index = -1;
  glm::dmat4 world{1.0};
};

// Where flatten_nodes puts the nodes with a camera or a light, and how many the file has (to check indices).
struct Attachments {
  std::vector<AttachedNode> cameras, lights;
  size_t camera_count = 0, light_count = 0;
};

// Deeper hierarchies are refused: no real asset nests a thousand levels, a hostile one could nest 100 000.
constexpr size_t kMaxNodeDepth = 1000;

// Instances of every node with a mesh under `roots` (a scene's node list, named `roots_where` in
// messages), in depth-first order; without roots (a file with no scenes), under every parentless node.
// The nodes with a camera or a light go to `attached` when given (their indices checked).
Result<std::vector<Instance>> flatten_nodes(const std::vector<NodeDesc>& nodes,
                                            const std::optional<std::vector<int>>& roots,
                                            const std::string& roots_where, size_t mesh_count,
                                            Attachments* attached = nullptr);

}  // namespace lagoon::gltf::detail
