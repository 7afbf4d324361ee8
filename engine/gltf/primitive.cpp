#include "gltf/primitive.h"

#include <cmath>
#include <numeric>

#include "gltf/checks.h"
#include "gltf/geometry.h"
#include "gltf/tangents.h"

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

bool is_vec4_float(const AccessorDesc& d) {
  return d.components == 4 && d.component_type == kFloat;
}

// KHR_mesh_quantization's wider choices (its "Extending Mesh Attributes" table).
bool is_int_type(const AccessorDesc& d) {
  return d.component_type == kByte || d.component_type == kUnsignedByte || d.component_type == kShort ||
         d.component_type == kUnsignedShort;
}
bool is_signed_normalized(const AccessorDesc& d) {
  return d.normalized && (d.component_type == kByte || d.component_type == kShort);
}
bool is_quantized_position(const AccessorDesc& d) {
  return d.components == 3 && (d.component_type == kFloat || is_int_type(d));
}
bool is_quantized_normal(const AccessorDesc& d) {
  return d.components == 3 && (d.component_type == kFloat || is_signed_normalized(d));
}
bool is_quantized_tangent(const AccessorDesc& d) {
  return d.components == 4 && (d.component_type == kFloat || is_signed_normalized(d));
}
bool is_quantized_texcoord(const AccessorDesc& d) {
  return d.components == 2 && (d.component_type == kFloat || is_int_type(d));
}

constexpr const char* kQuantizedTypes =
    "FLOAT, or (KHR_mesh_quantization) BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT";

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
  Result<const AccessorDesc*> pd =
      desc.quantized
          ? attribute(a, position->second, where + ".attributes.POSITION",
                      (std::string("VEC3 ") + kQuantizedTypes).c_str(), is_quantized_position, std::nullopt)
          : attribute(a, position->second, where + ".attributes.POSITION", "VEC3 FLOAT", is_vec3_float,
                      std::nullopt);
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

// An optional attribute with one element per vertex, as floats (normalized integers mapped to [0,1] or
// [-1,1]); empty when the file does not have it.
Result<std::vector<float>> optional_attribute(const PrimitiveDesc& desc, const char* name,
                                              const std::string& where, const Accessors& a, size_t n,
                                              const char* allowed, bool (*ok)(const AccessorDesc&)) {
  const auto it = desc.attributes.find(name);
  if (it == desc.attributes.end()) return std::vector<float>();
  Result<const AccessorDesc*> d = attribute(a, it->second, where + ".attributes." + name, allowed, ok, n);
  if (!d) return d.error();
  return read_floats(a, it->second);
}

// NORMAL, TANGENT, TEXCOORD_0 and TEXCOORD_1, each with one element per vertex. A missing NORMAL or TANGENT
// stays empty (computed once the triangles are known); missing UVs are zero, a missing TEXCOORD_1 copies
// TEXCOORD_0.
Result<void> read_normals_and_uvs(const PrimitiveDesc& desc, const std::string& where, const Accessors& a,
                                  size_t n, Primitive& prim) {
  const std::string q =
      desc.quantized ? std::string(", or with KHR_mesh_quantization normalized BYTE or SHORT") : "";
  const std::string texcoords =
      desc.quantized ? std::string("VEC2 ") + kQuantizedTypes
                     : "VEC2 FLOAT, VEC2 normalized UNSIGNED_BYTE or VEC2 normalized UNSIGNED_SHORT";
  Result<std::vector<float>> normals =
      optional_attribute(desc, "NORMAL", where, a, n, ("VEC3 FLOAT" + q).c_str(),
                         desc.quantized ? is_quantized_normal : is_vec3_float);
  if (!normals) return normals.error();
  Result<std::vector<float>> tangents =
      optional_attribute(desc, "TANGENT", where, a, n, ("VEC4 FLOAT" + q).c_str(),
                         desc.quantized ? is_quantized_tangent : is_vec4_float);
  if (!tangents) return tangents.error();
  auto uv_ok = desc.quantized ? is_quantized_texcoord : is_texcoord;
  Result<std::vector<float>> uv0 =
      optional_attribute(desc, "TEXCOORD_0", where, a, n, texcoords.c_str(), uv_ok);
  if (!uv0) return uv0.error();
  Result<std::vector<float>> uv1 =
      optional_attribute(desc, "TEXCOORD_1", where, a, n, texcoords.c_str(), uv_ok);
  if (!uv1) return uv1.error();
  prim.normals = to_vectors<glm::vec3>(*normals);
  for (glm::vec3& v : prim.normals) {  // quantized normals are only nearly unit length
    const float len = glm::length(v);
    v = std::isfinite(len) && len > 0 ? v / len : glm::vec3(0, 1, 0);
  }
  prim.tangents = to_vectors<glm::vec4>(*tangents);
  for (glm::vec4& t : prim.tangents) {
    const float len = glm::length(glm::vec3(t));
    t = std::isfinite(len) && len > 0 ? glm::vec4(glm::vec3(t) / len, t.w < 0 ? -1.0f : 1.0f)
                                      : glm::vec4(1, 0, 0, 1);
  }
  prim.uvs = uv0->empty() ? std::vector<glm::vec2>(n, glm::vec2(0.0f)) : to_vectors<glm::vec2>(*uv0);
  prim.uvs1 = uv1->empty() ? prim.uvs : to_vectors<glm::vec2>(*uv1);
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
  if (prim.tangents.empty())
    prim.tangents = generate_tangents(prim.positions, prim.normals, prim.uvs, prim.indices);
  return std::optional<Primitive>(std::move(prim));
}

}  // namespace lagoon::gltf::detail
