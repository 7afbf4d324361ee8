#include "gltf/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace lagoon::gltf::detail {

std::vector<uint32_t> strip_to_list(const std::vector<uint32_t>& strip) {
  std::vector<uint32_t> list;
  if (strip.size() < 3) return list;
  list.reserve((strip.size() - 2) * 3);
  for (size_t i = 0; i + 2 < strip.size(); ++i) {
    // Every other triangle of a strip is wound the other way round; swapping its first two vertices
    // gives all triangles the winding of the first.
    const bool odd = i % 2 == 1;
    list.insert(list.end(), {strip[odd ? i + 1 : i], strip[odd ? i : i + 1], strip[i + 2]});
  }
  return list;
}

std::vector<uint32_t> fan_to_list(const std::vector<uint32_t>& fan) {
  std::vector<uint32_t> list;
  if (fan.size() < 3) return list;
  list.reserve((fan.size() - 2) * 3);
  for (size_t i = 1; i + 1 < fan.size(); ++i) list.insert(list.end(), {fan[0], fan[i], fan[i + 1]});
  return list;
}

std::vector<glm::vec3> area_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<uint32_t>& indices) {
  // Accumulated in double: large flat meshes sum many similar vectors.
  std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::dvec3 a = positions[indices[t]], b = positions[indices[t + 1]], c = positions[indices[t + 2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);  // length = twice the area: the weight comes for free
    for (size_t k = 0; k < 3; ++k) sum[indices[t + k]] += n;
  }
  std::vector<glm::vec3> normals(positions.size());
  for (size_t i = 0; i < sum.size(); ++i) {
    const double length = glm::length(sum[i]);
    normals[i] = length > 0.0 && std::isfinite(length) ? glm::vec3(sum[i] / length) : glm::vec3(0, 1, 0);
  }
  return normals;
}

void compute_bounds(Model& model, size_t budget) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  auto add = [&](const glm::mat4& world, const glm::vec3& p) {
    const glm::vec3 w = glm::vec3(world * glm::vec4(p, 1.0f));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  };
  // Per-mesh boxes for the instances past the budget.
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes(model.meshes.size(), {lo, hi});
  std::vector<size_t> vertices(model.meshes.size(), 0);
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    for (const Primitive& prim : model.meshes[m].primitives) {
      vertices[m] += prim.positions.size();
      for (const glm::vec3& p : prim.positions) {
        boxes[m].first = glm::min(boxes[m].first, p);
        boxes[m].second = glm::max(boxes[m].second, p);
      }
    }
  }
  size_t spent = 0;
  bool any = false;
  for (const Instance& instance : model.instances) {
    if (instance.mesh >= model.meshes.size() || vertices[instance.mesh] == 0) continue;
    any = true;
    if (spent + vertices[instance.mesh] <= budget) {
      spent += vertices[instance.mesh];
      for (const Primitive& prim : model.meshes[instance.mesh].primitives) {
        for (const glm::vec3& p : prim.positions) add(instance.world, p);
      }
      continue;
    }
    const auto& [bmin, bmax] = boxes[instance.mesh];
    for (int corner = 0; corner < 8; ++corner) {
      add(instance.world, glm::vec3(corner & 1 ? bmax.x : bmin.x, corner & 2 ? bmax.y : bmin.y,
                                    corner & 4 ? bmax.z : bmin.z));
    }
  }
  model.bounds_min = any ? lo : glm::vec3(0);
  model.bounds_max = any ? hi : glm::vec3(0);
}

}  // namespace lagoon::gltf::detail
