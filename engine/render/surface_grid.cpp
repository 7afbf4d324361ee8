#include "render/surface_grid.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shared/clipmap.h"

namespace lagoon::render {
namespace {

static_assert((2 * kClipmapHalfCells) % gpu::kClipmapBlock == 0, "levels must split into whole blocks");
static_assert(kClipmapMorphCells <= kClipmapHalfCells / 2 - 2.5f, "morph zone reaches the finer level");

// Planes a·x + b·y + c·z + d >= 0 of the view volume (0 <= z <= w, Vulkan depth).
std::array<glm::vec4, 6> frustum_planes(const glm::mat4& m) {
  const glm::vec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]),
      r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
  return {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
}

bool box_may_be_visible(const std::array<glm::vec4, 6>& planes, const glm::vec3& lo, const glm::vec3& hi) {
  for (const glm::vec4& p : planes) {
    // The box corner furthest along the plane's normal.
    const glm::vec3 far(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
    if (glm::dot(glm::vec3(p), far) + p.w < 0) return false;
  }
  return true;
}

ClipmapPatch patch(glm::ivec2 first, std::initializer_list<glm::ivec2> corners) {
  ClipmapPatch p{.first = first};
  for (const glm::ivec2& c : corners) p.corners[p.count++] = c;
  return p;
}

// The 2 x 2 corner block at (x0, y0) as a fan about its middle vertex, without the odd vertices of its two
// outer sides.
ClipmapPatch corner_patch(int x0, int y0) {
  const glm::ivec2 ring[8] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const glm::ivec2 skip_x = x0 == 0 ? glm::ivec2(0, 1) : glm::ivec2(2, 1);
  const glm::ivec2 skip_y = y0 == 0 ? glm::ivec2(1, 0) : glm::ivec2(1, 2);
  std::array<glm::ivec2, 6> polygon;
  size_t sides = 0;
  for (const glm::ivec2& v : ring)
    if (v != skip_x && v != skip_y) polygon[sides++] = glm::ivec2(x0, y0) + v;
  ClipmapPatch fan{.first = {x0, y0}};
  const glm::ivec2 middle(x0 + 1, y0 + 1);
  for (size_t k = 0; k < sides; ++k) {
    fan.corners[fan.count++] = polygon[k];
    fan.corners[fan.count++] = polygon[(k + 1) % sides];
    fan.corners[fan.count++] = middle;
  }
  return fan;
}

}  // namespace

ClipmapPatch clipmap_patch(int i, int j, int cells, bool stitched) {
  const int n = cells;
  if (stitched) {
    const bool corner_x = i < 2 || i >= n - 2, corner_y = j < 2 || j >= n - 2;
    if (corner_x && corner_y) return corner_patch(i < 2 ? 0 : n - 2, j < 2 ? 0 : n - 2);
    const int a = i & ~1, b = j & ~1;  // a pair along the edge starts at an even cell
    using V = glm::ivec2;
    if (j == 0)
      return patch({a, 0}, {V(a, 0), V(a + 2, 0), V(a + 1, 1), V(a, 0), V(a + 1, 1), V(a, 1), V(a + 2, 0),
                            V(a + 2, 1), V(a + 1, 1)});
    if (j == n - 1)
      return patch({a, n - 1}, {V(a + 2, n), V(a, n), V(a + 1, n - 1), V(a, n - 1), V(a + 1, n - 1), V(a, n),
                                V(a + 1, n - 1), V(a + 2, n - 1), V(a + 2, n)});
    if (i == 0)
      return patch({0, b}, {V(0, b + 2), V(0, b), V(1, b + 1), V(0, b), V(1, b), V(1, b + 1), V(1, b + 1),
                            V(1, b + 2), V(0, b + 2)});
    if (i == n - 1)
      return patch({n - 1, b}, {V(n, b), V(n, b + 2), V(n - 1, b + 1), V(n - 1, b), V(n, b), V(n - 1, b + 1),
                                V(n - 1, b + 1), V(n, b + 2), V(n - 1, b + 2)});
  }
  return patch({i, j}, {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}});
}

SurfaceGrid surface_grid_parameters(const glm::vec3& camera, float reach_m) {
  // Continuous level of detail b: its integer part picks the finest lattice, its fraction fades that
  // level into the next, so the mesh changes smoothly as the camera climbs.
  const float wanted = std::max(std::abs(camera.y), kClipmapMinHeightM) * kClipmapSpacingPerHeight;
  const float b = std::max(std::log2(wanted / kClipmapBaseSpacingM), 0.0f);
  const float first = std::floor(b);
  const float spacing = std::ldexp(kClipmapBaseSpacingM, int(first));
  int levels = 1;
  // The outermost ring's edge is at least m - 1 of its cells from the camera.
  while (levels < kClipmapMaxLevels && std::ldexp(spacing, levels - 1) * (kClipmapHalfCells - 1) < reach_m)
    ++levels;
  SurfaceGrid g;
  g.grid = glm::vec4(spacing, float(kClipmapHalfCells), 0.0f, 0.0f);
  g.clipmap = glm::vec4(float(levels), b - first, kClipmapMorphCells, 0.0f);
  return g;
}

SurfaceGrid surface_grid(const glm::vec3& camera, float reach_m, const glm::mat4* view_proj,
                         DisplacementBound bound) {
  SurfaceGrid g = surface_grid_parameters(camera, reach_m);
  const int levels = int(g.clipmap.x);
  const int cells = 2 * kClipmapHalfCells;
  const int blocks = cells / gpu::kClipmapBlock;
  const uint32_t side = uint32_t(cells + 1);

  const glm::vec2 cam(camera.x, camera.z);
  const auto planes = view_proj ? frustum_planes(*view_proj) : std::array<glm::vec4, 6>{};
  for (int level = 0; level < levels; ++level) {
    const float s = gpu::clipmap_spacing(level, g.grid);
    const glm::vec2 origin =
        gpu::clipmap_centre(level, cam, g.grid) - glm::vec2(float(kClipmapHalfCells) * s);
    const uint32_t base = uint32_t(level) * side * side;
    for (int block = 0; block < blocks * blocks; ++block) {
      const glm::ivec2 b0 = glm::ivec2(block % blocks, block / blocks) * gpu::kClipmapBlock;
      if (view_proj) {
        const glm::vec2 lo = origin + glm::vec2(b0) * s - bound.horizontal_m;
        const glm::vec2 hi = origin + glm::vec2(b0 + gpu::kClipmapBlock) * s + bound.horizontal_m;
        if (!box_may_be_visible(planes, {lo.x, -bound.vertical_m, lo.y}, {hi.x, bound.vertical_m, hi.y}))
          continue;
      }
      for (int j = b0.y; j < b0.y + gpu::kClipmapBlock; ++j)
        for (int i = b0.x; i < b0.x + gpu::kClipmapBlock; ++i) {
          if (!gpu::clipmap_cell_visible(level, {i, j}, cam, g.grid)) continue;  // the finer level's
          // A patch of several cells is listed once, with its first cell (in the same block: pairs and
          // corners start at even cells).
          const ClipmapPatch patch = clipmap_patch(i, j, cells, level + 1 < levels);
          if (patch.first != glm::ivec2(i, j)) continue;
          for (const glm::ivec2& v : patch.triangles())
            g.indices.push_back(base + uint32_t(v.y) * side + uint32_t(v.x));
        }
    }
  }
  return g;
}

}  // namespace lagoon::render
