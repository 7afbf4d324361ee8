// One glTF mesh primitive into a Primitive: attribute types checked, indices checked against the vertex
// count, strips and fans turned into lists, missing normals and UVs filled in.
#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "gltf/accessor.h"
#include "gltf/model.h"

namespace lagoon::gltf::detail {

struct PrimitiveDesc {  // as tinygltf parses it
  std::map<std::string, int> attributes;
  int indices = -1;
  int mode = 4;
  int material = -1;
  bool has_targets = false;
  bool quantized = false;  // KHR_mesh_quantization is used: integer POSITION, NORMAL, TANGENT, TEXCOORD
};

// Vertices and indices of the whole model so far, against the limits: checked before anything is read, so
// a file cannot make us allocate more than the limits allow.
struct Budget {
  size_t max_vertices = 0, max_indices = 0;
  size_t vertices = 0, indices = 0;
};

// `where` is "meshes[m].primitives[p]". Returns no primitive (and adds a warning) for point and line
// primitives, which are skipped.
Result<std::optional<Primitive>> convert_primitive(const PrimitiveDesc& desc, const std::string& where,
                                                   const Accessors& accessors, size_t material_count,
                                                   Budget& budget, std::vector<std::string>& warnings);

}  // namespace lagoon::gltf::detail
