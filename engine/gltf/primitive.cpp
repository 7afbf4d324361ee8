#include "gltf/primitive.h"

#include <cmath>
#include <numeric>

#include "gltf/checks.h"
#include "gltf/geometry.h"

namespace lagoon::gltf::detail {
namespace {

enum Mode : int { kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6 };

// The accessor behind an attribute, checked to be of an allowed type and (when `count` is set) to have as
// many elements as POSITION.
Result<const AccessorDesc*> attribute(const Accessors& a, int index, const std::string& where,
                                      const char* allowed, bool (*ok)(const AccessorDesc&),
                                      std::optional<size_t> count) {
  if (!valid_index(index, a.accessors.size())) {
    return make_error(where + ": accessors[" + std::to_string(index) + "] does not exist");
  }
  const AccessorDesc& d = a.accessors[static_cast<size_t>(index)];
  const std::string name = at("accessors", index);
  if (!ok(d)) return make_error(where + ": " + name + " is " + describe(d) + "; it must be " + allowed);
  if (count && d.count != *count) {
    return make_error(where + ": " + name + " has " + std::to_string(d.count) +
                      " elements but POSITION has " + std::to_string(*count));
  }
  return &d;
}

bool is_vec3_float(const AccessorDesc& d) {
  return d.components == 3 && d.component_type == kFloat;
}

bool is_texcoord(const AccessorDesc& d) {
  return d.components == 2 &&
         (d.component_type == kFloat ||
          (d.normalized && (d.component_type == kUnsignedByte || d.component_type == kUnsignedShort)));
}

bool is_index(const AccessorDesc& d) {
  return d.components == 1 && (d.component_type == kUnsignedByte || d.component_type == kUnsignedShort ||
                               d.component_type == kUnsignedInt);
}

Result<void> spend(size_t& used, size_t amount, size_t limit, const std::string& where, const char* what) {
  if (amount > limit || used > limit - amount) {
    return make_error(where + ": " + std::to_string(amount) + " " + what +
                      " would take the model past the limit of " + std::to_string(limit) + " " + what);
  }
  used += amount;
  return {};
}

template <typename Vec>
std::vector<Vec> to_vectors(const std::vector<float>& flat) {
  constexpr auto n = static_cast<size_t>(Vec::length());
  std::vector<Vec> out(flat.size() / n);
  for (size_t i = 0; i < out.size(); ++i) {
    for (size_t c = 0; c < n; ++c) out[i][static_cast<int>(c)] = flat[i * n + c];
  }
  return out;
}

Result<std::vector<uint32_t>> read_indices(const PrimitiveDesc& desc, const std::string& where,
                                           const Accessors& a, size_t vertex_count, Budget& budget) {
  if (desc.indices == -1) {  // non-indexed: vertices in order
    if (Result<void> r = spend(budget.indices, vertex_count, budget.max_indices, where, "indices"); !r) {
      return r.error();
    }
    std::vector<uint32_t> indices(vertex_count);
    std::iota(indices.begin(), indices.end(), 0u);
    return indices;
  }
  Result<const AccessorDesc*> d =
      attribute(a, desc.indices, where + ".indices", "SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT",
                is_index, std::nullopt);
  if (!d) return d.error();
  if (Result<void> r = spend(budget.indices, (*d)->count, budget.max_indices, where + ".indices", "indices");
      !r) {
    return r.error();
  }
  Result<std::vector<uint32_t>> indices = read_uints(a, desc.indices);
  if (!indices) return indices.error();
  for (size_t k = 0; k < indices->size(); ++k) {
    if ((*indices)[k] >= vertex_count) {
      return make_error(where + ".indices: " + at("accessors", desc.indices) + " element " +
                        std::to_string(k) + " is " + std::to_string((*indices)[k]) + ", out of range for " +
                        std::to_string(vertex_count) + " vertices");
    }
  }
  return indices;
}

// POSITION: required, VEC3 FLOAT, finite, and charged to the vertex budget before it is read.
Result<std::vector<glm::vec3>> read_positions(const PrimitiveDesc& desc, const std::string& where,
                                              const Accessors& a, Budget& budget) {
  const auto position = desc.attributes.find("POSITION");
  if (position == desc.attributes.end()) return make_error(where + ".attributes: POSITION is missing");
  Result<const AccessorDesc*> pd = attribute(a, position->second, where + ".attributes.POSITION",
                                             "VEC3 FLOAT", is_vec3_float, std::nullopt);
  if (!pd) return pd.error();
  if (Result<void> r = spend(budget.vertices, (*pd)->count, budget.max_vertices,
                             where + ".attributes.POSITION", "vertices");
      !r) {
    return r.error();
  }
  Result<std::vector<float>> positions = read_floats(a, position->second);
  if (!positions) return positions.error();
  for (size_t i = 0; i < positions->size(); ++i) {
    if (!std::isfinite((*positions)[i])) {
      return make_error(where + ".attributes.POSITION: " + at("accessors", position->second) + " vertex " +
                        std::to_string(i / 3) + " is not finite");
    }
  }
  return to_vectors<glm::vec3>(*positions);
}

// NORMAL and TEXCOORD_0, each with one element per vertex. A missing NORMAL stays empty (computed once the
// triangles are known); missing UVs are zero.
Result<void> read_normals_and_uvs(const PrimitiveDesc& desc, const std::string& where, const Accessors& a,
                                  size_t n, Primitive& prim) {
  if (auto it = desc.attributes.find("NORMAL"); it != desc.attributes.end()) {
    Result<const AccessorDesc*> d =
        attribute(a, it->second, where + ".attributes.NORMAL", "VEC3 FLOAT", is_vec3_float, n);
    if (!d) return d.error();
    Result<std::vector<float>> normals = read_floats(a, it->second);
    if (!normals) return normals.error();
    prim.normals = to_vectors<glm::vec3>(*normals);
  }
  if (auto it = desc.attributes.find("TEXCOORD_0"); it != desc.attributes.end()) {
    Result<const AccessorDesc*> d = attribute(
        a, it->second, where + ".attributes.TEXCOORD_0",
        "VEC2 FLOAT, VEC2 normalized UNSIGNED_BYTE or VEC2 normalized UNSIGNED_SHORT", is_texcoord, n);
    if (!d) return d.error();
    Result<std::vector<float>> uvs = read_floats(a, it->second);
    if (!uvs) return uvs.error();
    prim.uvs = to_vectors<glm::vec2>(*uvs);
  } else {
    prim.uvs.assign(n, glm::vec2(0.0f));
  }
  return {};
}

// The indices as a triangle list (strips and fans converted); empty when a strip or fan has no triangle.
Result<std::vector<uint32_t>> triangle_list(int mode, std::vector<uint32_t> indices, const std::string& where,
                                            Budget& budget) {
  if (mode == kTriangles) {
    if (indices.size() % 3 != 0) {
      return make_error(where + ": " + std::to_string(indices.size()) +
                        " indices (or vertices) is not a multiple of 3, as TRIANGLES needs");
    }
    return indices;
  }
  // A list has at most 3x the indices of its strip or fan; charge the difference before building it.
  const size_t extra = indices.size() < 3 ? 0 : 2 * indices.size() - 6;
  if (Result<void> r = spend(budget.indices, extra, budget.max_indices, where + ".indices", "indices"); !r) {
    return r.error();
  }
  return mode == kTriangleStrip ? strip_to_list(indices) : fan_to_list(indices);
}

}  // namespace

Result<std::optional<Primitive>> convert_primitive(const PrimitiveDesc& desc, const std::string& where,
                                                   const Accessors& a, size_t material_count, Budget& budget,
                                                   std::vector<std::string>& warnings) {
  if (desc.mode >= 0 && desc.mode < kTriangles) {
    warn_once(warnings, "point and line primitives are not supported; skipped");
    return std::optional<Primitive>();
  }
  if (desc.mode != kTriangles && desc.mode != kTriangleStrip && desc.mode != kTriangleFan) {
    return make_error(where + ".mode: " + std::to_string(desc.mode) + " is not a glTF primitive mode (0-6)");
  }
  if (desc.has_targets) warn_once(warnings, "morph targets are not supported; drawn with the base geometry");
  if (desc.material != -1 && !valid_index(desc.material, material_count)) {
    return make_error(where + ".material: materials[" + std::to_string(desc.material) + "] does not exist");
  }

  Primitive prim;
  prim.material = desc.material;
  Result<std::vector<glm::vec3>> positions = read_positions(desc, where, a, budget);
  if (!positions) return positions.error();
  prim.positions = std::move(*positions);
  const size_t n = prim.positions.size();
  if (Result<void> r = read_normals_and_uvs(desc, where, a, n, prim); !r) return r.error();

  Result<std::vector<uint32_t>> indices = read_indices(desc, where, a, n, budget);
  if (!indices) return indices.error();
  Result<std::vector<uint32_t>> list = triangle_list(desc.mode, std::move(*indices), where, budget);
  if (!list) return list.error();
  prim.indices = std::move(*list);
  if (prim.indices.empty() && desc.mode != kTriangles) {
    warn_once(warnings, "triangle strips and fans with fewer than 3 vertices were skipped");
    return std::optional<Primitive>();
  }
  if (prim.normals.empty()) prim.normals = area_weighted_normals(prim.positions, prim.indices);
  return std::optional<Primitive>(std::move(prim));
}

}  // namespace lagoon::gltf::detail
