#include "gltf/nodes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "gltf/checks.h"

namespace lagoon::gltf::detail {
namespace {

std::string node(int64_t index) {
  return at("nodes", index);
}

// Each node's parent (-1 for roots), or an error when a node is listed twice or out of range.
Result<std::vector<int>> parents(const std::vector<NodeDesc>& nodes) {
  std::vector<int> parent(nodes.size(), -1);
  for (size_t n = 0; n < nodes.size(); ++n) {
    for (size_t k = 0; k < nodes[n].children.size(); ++k) {
      const int c = nodes[n].children[k];
      const std::string where = node(static_cast<int64_t>(n)) + ".children[" + std::to_string(k) + "]";
      if (!valid_index(c, nodes.size())) return make_error(where + ": " + node(c) + " does not exist");
      if (static_cast<size_t>(c) == n) return make_error(where + ": the node lists itself as its child");
      if (parent[c] != -1) {
        return make_error(where + ": " + node(c) + " is a child of both " + node(parent[c]) + " and " +
                          node(static_cast<int64_t>(n)) + "; a node can have only one parent");
      }
      parent[c] = static_cast<int>(n);
    }
  }
  return parent;
}

// With one parent per node, a cycle is a parent chain that comes back to where it started.
Result<void> check_cycles(const std::vector<int>& parent) {
  enum : uint8_t { kNew, kOnPath, kDone };
  std::vector<uint8_t> state(parent.size(), kNew);
  std::vector<int> path;
  for (size_t start = 0; start < parent.size(); ++start) {
    path.clear();
    int n = static_cast<int>(start);
    while (n != -1 && state[n] == kNew) {
      state[n] = kOnPath;
      path.push_back(n);
      n = parent[n];
    }
    if (n != -1 && state[n] == kOnPath) {
      std::string chain = node(n);
      int m = parent[n];
      for (int shown = 0; m != n && shown < 8; ++shown, m = parent[m]) chain += " -> " + node(m);
      chain += m == n ? " -> " + node(n) : " -> ...";
      return make_error(node(n) + ": the hierarchy has a cycle (" + chain + ", following parents)");
    }
    for (int p : path) state[p] = kDone;
  }
  return {};
}

bool finite(const std::vector<double>& values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

Result<glm::dmat4> local_transform(const NodeDesc& n, const std::string& where) {
  struct Field {
    const char* name;
    const std::vector<double>& values;
    size_t size;
  };
  for (const Field& f : {Field{"matrix", n.matrix, 16}, Field{"translation", n.translation, 3},
                         Field{"rotation", n.rotation, 4}, Field{"scale", n.scale, 3}}) {
    if (f.values.empty()) continue;
    if (f.values.size() != f.size) {
      return make_error(where + "." + f.name + ": expected " + std::to_string(f.size) + " numbers, got " +
                        std::to_string(f.values.size()));
    }
    if (!finite(f.values)) return make_error(where + "." + f.name + ": contains a non-finite number");
  }
  if (!n.matrix.empty()) return glm::make_mat4(n.matrix.data());  // column-major in glTF and glm
  glm::dmat4 m(1.0);
  if (!n.translation.empty()) m = glm::translate(m, glm::make_vec3(n.translation.data()));
  if (!n.rotation.empty()) {
    glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glm: w first
    const double length = glm::length(q);
    // Exporters write quaternions rounded to a few digits; renormalising keeps them rotations.
    if (!(length > 1e-6)) return make_error(where + ".rotation: zero quaternion is not a rotation");
    m *= glm::mat4_cast(q / length);
  }
  if (!n.scale.empty()) m = glm::scale(m, glm::make_vec3(n.scale.data()));
  return m;
}

// The nodes the walk starts from: `roots` checked to be distinct parentless nodes, or without roots every
// parentless node.
Result<std::vector<int>> start_nodes(const std::vector<NodeDesc>& nodes,
                                     const std::optional<std::vector<int>>& roots,
                                     const std::string& roots_where, const std::vector<int>& parent) {
  std::vector<int> start;
  if (!roots) {
    for (size_t n = 0; n < nodes.size(); ++n) {
      if (parent[n] == -1) start.push_back(static_cast<int>(n));
    }
    return start;
  }
  std::vector<bool> listed(nodes.size(), false);
  for (size_t k = 0; k < roots->size(); ++k) {
    const int r = (*roots)[k];
    const std::string where = roots_where + "[" + std::to_string(k) + "]";
    if (!valid_index(r, nodes.size())) return make_error(where + ": " + node(r) + " does not exist");
    if (parent[r] != -1) {
      return make_error(where + ": " + node(r) + " is a child of " + node(parent[r]) + ", not a root node");
    }
    if (listed[r]) return make_error(where + ": " + node(r) + " is listed twice");
    listed[r] = true;
    start.push_back(r);
  }
  return start;
}

// The instance of a node's mesh at `world`; the renderer takes single-precision matrices.
Result<Instance> mesh_instance(const NodeDesc& n, const glm::dmat4& world, const std::string& where,
                               size_t mesh_count) {
  if (!valid_index(n.mesh, mesh_count)) {
    return make_error(where + ".mesh: meshes[" + std::to_string(n.mesh) + "] does not exist");
  }
  const glm::mat4 world_f(world);
  const float* values = glm::value_ptr(world_f);
  if (!std::all_of(values, values + 16, [](float v) { return std::isfinite(v); })) {
    return make_error(where + ": the world transform overflows single precision");
  }
  return Instance{static_cast<uint32_t>(n.mesh), world_f};
}

}  // namespace

Result<std::vector<Instance>> flatten_nodes(const std::vector<NodeDesc>& nodes,
                                            const std::optional<std::vector<int>>& roots,
                                            const std::string& roots_where, size_t mesh_count,
                                            Attachments* attached) {
  Result<std::vector<int>> parent = parents(nodes);
  if (!parent) return parent.error();
  if (Result<void> r = check_cycles(*parent); !r) return r.error();
  Result<std::vector<int>> start = start_nodes(nodes, roots, roots_where, *parent);
  if (!start) return start.error();

  struct Pending {
    int node;
    glm::dmat4 parent_world;
    size_t depth;
  };
  std::vector<Instance> instances;
  std::vector<Pending> stack;
  for (auto it = start->rbegin(); it != start->rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), 1});
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    const std::string where = node(p.node);
    if (p.depth > kMaxNodeDepth) {
      return make_error(where + ": nested deeper than " + std::to_string(kMaxNodeDepth) + " levels");
    }
    const NodeDesc& n = nodes[p.node];
    Result<glm::dmat4> local = local_transform(n, where);
    if (!local) return local.error();
    const glm::dmat4 world = p.parent_world * *local;
    if (n.mesh != -1) {
      Result<Instance> instance = mesh_instance(n, world, where, mesh_count);
      if (!instance) return instance.error();
      instances.push_back(*instance);
    }
    if (attached && n.camera != -1) {
      if (!valid_index(n.camera, attached->camera_count)) {
        return make_error(where + ".camera: cameras[" + std::to_string(n.camera) + "] does not exist");
      }
      attached->cameras.push_back({p.node, n.camera, world});
    }
    if (attached && n.light != -1) {
      if (!valid_index(n.light, attached->light_count)) {
        return make_error(where + ".extensions.KHR_lights_punctual.light: lights[" + std::to_string(n.light) +
                          "] does not exist");
      }
      attached->lights.push_back({p.node, n.light, world});
    }
    for (auto it = n.children.rbegin(); it != n.children.rend(); ++it)
      stack.push_back({*it, world, p.depth + 1});
  }
  return instances;
}

}  // namespace lagoon::gltf::detail
