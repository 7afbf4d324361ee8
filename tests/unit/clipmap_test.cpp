// The surface mesh (shaders/shared/clipmap.h, compiled here as C++ exactly as the vertex shader runs it):
// vertices rest on world-fixed lattices, the rings tile the plane once, the displaced surface has no cracks
// between rings, and it does not pop as the camera moves and climbs. The displacement is an analytic
// height field whose filtering depends on the mesh spacing, like the cascades' mips.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/surface_grid.h"
#include "shared/clipmap.h"

namespace lagoon::gpu {
// Waves of 0.7 .. 23 m in several directions, each damped like a mip of a texture with texel ~ spacing.
vec3 clipmap_displacement(vec2 rest, float spacing) {
  struct Wave {
    float kx, kz, amplitude, phase;
  };
  static const Wave waves[] = {{0.27f, 0.05f, 0.6f, 0.3f},
                               {-0.9f, 1.4f, 0.25f, 1.1f},
                               {3.1f, -2.2f, 0.08f, 2.0f},
                               {-6.5f, -5.9f, 0.03f, 4.2f}};
  float h = 0.0f;
  for (const Wave& w : waves) {
    const float k2 = w.kx * w.kx + w.kz * w.kz;
    h += w.amplitude * std::exp(-0.5f * k2 * spacing * spacing) *
         std::sin(w.kx * rest.x + w.kz * rest.y + w.phase);
  }
  return vec3(0.0f, h, 0.0f);
}
}  // namespace lagoon::gpu

#include "shared/clipmap_morph.h"

namespace lagoon::test {
namespace {

using gpu::vec2;
using gpu::vec4;

// Largest |∇h| of the field above, for continuity bounds.
constexpr float kMaxSlope = 0.6f * 0.275f + 0.25f * 1.66f + 0.08f * 3.81f + 0.03f * 8.78f;

struct SurfaceSample {
  int claims = 0;  // rings whose visible cells contain the point
  float height = 0.0f;
  int level = -1;
};

// The height of the drawn triangle mesh at `p`, found cell by cell the way the rasteriser would see it.
SurfaceSample surface_at(vec2 p, vec2 camera, const render::SurfaceGrid& g, bool morph = true) {
  SurfaceSample out;
  const int cells = gpu::clipmap_cells_per_side(g.grid);
  const int m = int(g.grid.y);
  for (int level = 0; level < int(g.clipmap.x); ++level) {
    const float s = gpu::clipmap_spacing(level, g.grid);
    const vec2 origin = gpu::clipmap_centre(level, camera, g.grid) - vec2(float(m) * s);
    const vec2 f = (p - origin) / s;
    const glm::ivec2 cell(std::floor(f.x), std::floor(f.y));
    if (cell.x < 0 || cell.y < 0 || cell.x >= cells || cell.y >= cells) continue;
    if (!gpu::clipmap_cell_visible(level, cell, camera, g.grid)) continue;
    ++out.claims;
    out.level = level;
    const vec2 local = f - vec2(cell);
    // Triangles (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1), as render::surface_grid lists them.
    const glm::ivec2 c1 = local.x >= local.y ? glm::ivec2(1, 0) : glm::ivec2(1, 1);
    const glm::ivec2 c2 = local.x >= local.y ? glm::ivec2(1, 1) : glm::ivec2(0, 1);
    auto height = [&](glm::ivec2 corner) {
      gpu::ClipmapVertex v = gpu::clipmap_vertex(level, cell + corner, camera, g.grid, g.clipmap);
      if (!morph) v.morph = 0.0f;
      return gpu::clipmap_displaced(v).y;
    };
    const float h0 = height({0, 0}), h1 = height(c1), h2 = height(c2);
    // Barycentric weights in the right triangle.
    if (local.x >= local.y)
      out.height = h0 + local.x * (h1 - h0) + local.y * (h2 - h1);
    else
      out.height = h0 + local.x * (h1 - h2) + local.y * (h2 - h0);
  }
  return out;
}

TEST(Clipmap, VerticesRestOnWorldFixedLattices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> xz(-5000.0f, 5000.0f), y(-20.0f, 200.0f);
  for (int trial = 0; trial < 50; ++trial) {
    const glm::vec3 cam(xz(rng), y(rng), xz(rng));
    const render::SurfaceGrid g = render::surface_grid(cam, 3000.0f);
    const int cells = gpu::clipmap_cells_per_side(g.grid);
    for (int level = 0; level < int(g.clipmap.x); ++level)
      for (int i = 0; i <= cells; i += 7) {
        const gpu::ClipmapVertex v =
            gpu::clipmap_vertex(level, {i, cells - i}, vec2(cam.x, cam.z), g.grid, g.clipmap);
        // Spacing is the base spacing times a power of two, and the rest position a multiple of it.
        const float octaves = std::log2(v.spacing / render::kClipmapBaseSpacingM);
        EXPECT_EQ(octaves, std::round(octaves));
        EXPECT_EQ(v.rest.x / v.spacing, std::round(v.rest.x / v.spacing));
        EXPECT_EQ(v.rest.y / v.spacing, std::round(v.rest.y / v.spacing));
      }
  }
}

TEST(Clipmap, RingsTileThePlaneExactlyOnceToTheRequestedReach) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (float height : {2.0f, 9.0f, 60.0f}) {
    const glm::vec3 cam(123.4f * unit(rng), height, -88.8f * unit(rng));
    const float reach = 3000.0f;
    const render::SurfaceGrid g = render::surface_grid(cam, reach);
    for (int i = 0; i < 20000; ++i) {
      // Points at every scale: log-uniform distance up to the reach.
      const float r = std::exp(std::log(reach) * (0.5f + 0.5f * unit(rng)) - 0.5f);
      const vec2 p = vec2(cam.x, cam.z) + r * glm::normalize(vec2(unit(rng), unit(rng)) + vec2(1e-6f));
      ASSERT_EQ(surface_at(p, vec2(cam.x, cam.z), g).claims, 1) << "at " << p.x << ", " << p.y;
    }
    EXPECT_LE(g.indices.size(), render::kClipmapMaxIndices);
  }
}

// Largest height jump between neighbouring points along lines that cross every ring.
float largest_step_across_rings(vec2 camera, const render::SurfaceGrid& g, float step, bool morph) {
  float worst = 0.0f;
  for (float angle : {0.0f, 0.3f, 1.1f, 2.5f, 4.0f}) {
    const vec2 dir(std::cos(angle), std::sin(angle));
    float previous = surface_at(camera, camera, g, morph).height;
    for (float t = step; t < 400.0f; t += step) {
      const float h = surface_at(camera + t * dir, camera, g, morph).height;
      worst = std::max(worst, std::abs(h - previous));
      previous = h;
    }
  }
  return worst;
}

TEST(Clipmap, DisplacedSurfaceHasNoCracksBetweenRings) {
  const vec2 camera(3.3f, -1.7f);
  const render::SurfaceGrid g = render::surface_grid({camera.x, 4.0f, camera.y}, 3000.0f);
  const float step = 2e-3f;
  // A continuous piecewise-linear interpolant of the field moves at most a few times its slope per step.
  EXPECT_LT(largest_step_across_rings(camera, g, step, true), 3.0f * kMaxSlope * step);
  // Control: without the morph the rings' edges disagree and the same walk finds the cracks.
  EXPECT_GT(largest_step_across_rings(camera, g, step, false), 10.0f * kMaxSlope * step);
}

// Largest change of the surface at fixed points while the camera flies and climbs in small steps.
float largest_change_while_flying(float step, bool morph) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::vector<vec2> points;
  for (int i = 0; i < 400; ++i) points.push_back(vec2(60.0f * unit(rng), 60.0f * unit(rng)));
  float worst = 0.0f;
  std::vector<float> previous;
  for (int i = 0; i * step < 6.0f; ++i) {
    // Diagonal flight across many snaps of every fine ring, climbing 3 -> 9 m (two changes of the finest
    // ring: 3 m * 1/16 = 2^-2.4 m, 9 m -> 2^-0.8 m).
    const float t = float(i) * step;
    const glm::vec3 cam(0.37f + 3.0f * t, 3.0f + t, -1.1f + 2.1f * t);
    const render::SurfaceGrid g = render::surface_grid_parameters(cam, 3000.0f);
    std::vector<float> heights;
    for (const vec2& p : points) heights.push_back(surface_at(p, vec2(cam.x, cam.z), g, morph).height);
    if (!previous.empty())
      for (size_t k = 0; k < points.size(); ++k) worst = std::max(worst, std::abs(heights[k] - previous[k]));
    previous = std::move(heights);
  }
  return worst;
}

TEST(Clipmap, SurfaceDoesNotPopAsTheCameraMovesAndClimbs) {
  const float step = 1e-3f;
  // Morphing over 8 cells of >= 1/8 m: the surface moves by well under a metre per metre of flight (measured
  // 0.22).
  const float smooth = largest_change_while_flying(step, true);
  const float popping = largest_change_while_flying(step, false);
  EXPECT_LT(smooth, 1.0f * step);
  EXPECT_GT(popping, 20.0f * smooth);
}

TEST(Clipmap, IndicesCoverEveryVisibleCellOnceAsTwoTriangles) {
  const vec2 camera(-7.3f, 12.9f);
  const render::SurfaceGrid g = render::surface_grid({camera.x, 5.0f, camera.y}, 3000.0f);
  ASSERT_EQ(g.indices.size() % 6, 0u);
  std::map<std::pair<int, std::pair<float, float>>, int> quads;  // (level, lowest corner) -> count
  for (size_t q = 0; q < g.indices.size(); q += 6) {
    gpu::ClipmapVertex v[6];
    for (int k = 0; k < 6; ++k)
      v[k] = gpu::clipmap_indexed_vertex(int(g.indices[q + k]), camera, g.grid, g.clipmap);
    const float s = v[0].spacing;
    ASSERT_EQ(v[1].rest, v[0].rest + vec2(s, 0.0f));
    ASSERT_EQ(v[2].rest, v[0].rest + vec2(s));  // the shared (0,0)-(1,1) diagonal
    ASSERT_EQ(v[3].rest, v[0].rest);
    ASSERT_EQ(v[4].rest, v[0].rest + vec2(s));
    ASSERT_EQ(v[5].rest, v[0].rest + vec2(0.0f, s));
    for (const auto& corner : v) ASSERT_EQ(corner.spacing, s);  // one level per quad
    ++quads[{int(std::log2(s / g.grid.x)), {v[0].rest.x, v[0].rest.y}}];
  }
  for (const auto& [key, count] : quads) ASSERT_EQ(count, 1);
  // Level 0 is whole; every other level misses the quarter the finer one draws.
  const int per_level = 4 * render::kClipmapHalfCells * render::kClipmapHalfCells;
  EXPECT_EQ(int(quads.size()), per_level + (int(g.clipmap.x) - 1) * per_level * 3 / 4);
  EXPECT_LE(g.indices.size(), render::kClipmapMaxIndices);
}

TEST(Clipmap, CullingKeepsEveryCellThatCanReachTheView) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const render::DisplacementBound bound{.horizontal_m = 4.0f, .vertical_m = 3.0f};
  for (int trial = 0; trial < 20; ++trial) {
    const glm::vec3 eye(100.0f * unit(rng), 3.0f + 40.0f * (1.0f + unit(rng)), 100.0f * unit(rng));
    const glm::vec3 target = eye + glm::vec3(unit(rng), -0.6f + 0.5f * unit(rng), unit(rng));
    const glm::mat4 view_proj = glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 5000.0f) *
                                glm::lookAt(eye, target, {0, 1, 0});
    const render::SurfaceGrid all = render::surface_grid(eye, 3000.0f);
    const render::SurfaceGrid culled = render::surface_grid(eye, 3000.0f, &view_proj, bound);
    EXPECT_LT(culled.indices.size(), all.indices.size() / 2)
        << "culling should drop most cells of a 60° view";
    std::set<uint32_t> drawn(culled.indices.begin(), culled.indices.end());
    // Any vertex of a drawn cell of the full grid that, displaced anywhere within the bound, lands in the
    // view volume must still be drawn.
    for (uint32_t index : all.indices) {
      const gpu::ClipmapVertex v =
          gpu::clipmap_indexed_vertex(int(index), vec2(eye.x, eye.z), all.grid, all.clipmap);
      const float h = bound.horizontal_m, y = bound.vertical_m;
      for (const glm::vec3 d : {glm::vec3(-h, -y, -h), glm::vec3(h, 0, -h), glm::vec3(0, 0, 0),
                                glm::vec3(-h, y, h), glm::vec3(h, y, h), glm::vec3(0, -y, h)}) {
        const glm::vec4 clip = view_proj * glm::vec4(v.rest.x + d.x, d.y, v.rest.y + d.z, 1.0f);
        const bool inside = clip.w > 0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w &&
                            clip.z >= 0 && clip.z <= clip.w;
        if (inside) {
          ASSERT_TRUE(drawn.count(index)) << "vertex " << index << " of trial " << trial;
        }
      }
    }
  }
}

TEST(Clipmap, FinestSpacingFollowsHeightContinuously) {
  // The fade reaches 1 exactly where the next lattice takes over.
  const render::SurfaceGrid below = render::surface_grid({0, 3.999f, 0}, 3000.0f);
  const render::SurfaceGrid above = render::surface_grid({0, 4.001f, 0}, 3000.0f);
  EXPECT_FLOAT_EQ(below.grid.x, 0.125f);
  EXPECT_NEAR(below.clipmap.y, 1.0f, 1e-3f);
  EXPECT_FLOAT_EQ(above.grid.x, 0.25f);
  EXPECT_NEAR(above.clipmap.y, 0.0f, 1e-3f);
  // Below the surface the mesh follows the depth the same way; near the surface it stops refining.
  EXPECT_EQ(render::surface_grid({0, -8.0f, 0}, 3000.0f).grid.x,
            render::surface_grid({0, 8.0f, 0}, 3000.0f).grid.x);
  EXPECT_EQ(render::surface_grid({0, 0.01f, 0}, 3000.0f).grid.x, render::kClipmapBaseSpacingM * 4.0f);
  // The outermost ring reaches the requested distance.
  const render::SurfaceGrid g = render::surface_grid({0, 2.0f, 0}, 3000.0f);
  EXPECT_GE(gpu::clipmap_spacing(int(g.clipmap.x) - 1, g.grid) * (render::kClipmapHalfCells - 1), 3000.0f);
}

}  // namespace
}  // namespace lagoon::test
