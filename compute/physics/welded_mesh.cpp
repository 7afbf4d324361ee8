#include "physics/welded_mesh.h"

#include <bit>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace lagoon::physics {
namespace {

// Exact positions by their bits: a weld by tolerance could join vertices a thin part keeps apart. -0 and +0
// are the same position, so both weld.
struct PositionHash {
  size_t operator()(const glm::dvec3& p) const {
    const auto bits = [](double v) { return std::bit_cast<uint64_t>(v == 0.0 ? 0.0 : v); };
    uint64_t h = bits(p.x);
    h = h * 0x9E3779B97F4A7C15ull ^ bits(p.y);
    h = h * 0x9E3779B97F4A7C15ull ^ bits(p.z);
    return size_t(h ^ (h >> 29));
  }
};

}  // namespace

TriangleMesh welded(const TriangleMesh& mesh) {
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> remap(mesh.vertices.size(), kUnused);
  std::unordered_map<glm::dvec3, uint32_t, PositionHash> first;
  first.reserve(mesh.vertices.size());
  TriangleMesh out;
  out.indices.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const uint32_t* corner = &mesh.indices[t];
    if (corner[0] >= remap.size() || corner[1] >= remap.size() || corner[2] >= remap.size()) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = corner[k];
      if (remap[i] == kUnused) {
        auto [it, fresh] = first.try_emplace(mesh.vertices[i], uint32_t(out.vertices.size()));
        if (fresh) out.vertices.push_back(mesh.vertices[i]);
        remap[i] = it->second;
      }
      out.indices.push_back(remap[i]);
    }
  }
  return out;
}

}  // namespace lagoon::physics
