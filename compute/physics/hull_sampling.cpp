#include "physics/hull_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <unordered_map>

namespace lagoon::physics {
namespace {

// Splits triangles of one mesh along their longest edges; midpoints are shared through the edge they split.
class Splitter {
 public:
  Splitter(const TriangleMesh& hull, double spacing) : spacing2_(spacing * spacing) {
    out_.vertices = hull.vertices;
  }

  // Triangle (a, b, c) split until no edge is longer than the spacing; false once the mesh has more than
  // `cap` triangles (the caller then tries a coarser spacing).
  bool split(uint32_t a, uint32_t b, uint32_t c, size_t cap) {
    if (out_.indices.size() / 3 >= cap) return false;
    const std::array<uint32_t, 3> v{a, b, c};
    int longest = 0;
    double most = 0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 e = out_.vertices[v[(k + 1) % 3]] - out_.vertices[v[k]];
      if (glm::dot(e, e) > most) most = glm::dot(e, e), longest = k;
    }
    if (most <= spacing2_) {
      out_.indices.insert(out_.indices.end(), {a, b, c});
      return true;
    }
    // The longest edge p -> q, opposite r: (p, m, r) and (m, q, r) keep the winding.
    const uint32_t p = v[longest], q = v[(longest + 1) % 3], r = v[(longest + 2) % 3];
    const uint32_t m = midpoint(p, q);
    return split(p, m, r, cap) && split(m, q, r, cap);
  }

  TriangleMesh take() { return std::move(out_); }

 private:
  uint32_t midpoint(uint32_t p, uint32_t q) {
    const uint64_t key = (uint64_t(std::min(p, q)) << 32) | std::max(p, q);
    auto [it, fresh] = midpoints_.try_emplace(key, uint32_t(out_.vertices.size()));
    if (fresh) out_.vertices.push_back(0.5 * (out_.vertices[p] + out_.vertices[q]));
    return it->second;
  }

  double spacing2_;
  TriangleMesh out_;
  std::unordered_map<uint64_t, uint32_t> midpoints_;
};

}  // namespace

double sample_spacing(const TriangleMesh& hull, const HullSampling& sampling) {
  if (sampling.spacing_m != 0) return sampling.spacing_m;
  if (hull.vertices.empty()) return -1;
  glm::dvec3 lo = hull.vertices[0], hi = lo;
  for (const glm::dvec3& v : hull.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const glm::dvec3 size = hi - lo;
  const double extent = std::max({size.x, size.y, size.z});
  return std::max(extent / HullSampling::kDivisions, sampling.min_spacing_m);
}

TriangleMesh refine_hull(const TriangleMesh& hull, const HullSampling& sampling) {
  double spacing = sample_spacing(hull, sampling);
  if (!(spacing > 0)) return hull;
  // The mesh's own triangles count against the cap too: a model finer than the cap is used as it is.
  const size_t cap = std::max(sampling.max_triangles, hull.indices.size() / 3);
  for (;;) {
    Splitter splitter(hull, spacing);
    bool fits = true;
    for (size_t t = 0; fits && t + 2 < hull.indices.size(); t += 3)
      fits = splitter.split(hull.indices[t], hull.indices[t + 1], hull.indices[t + 2], cap);
    if (fits) return splitter.take();
    spacing *= 1.25;
  }
}

}  // namespace lagoon::physics
