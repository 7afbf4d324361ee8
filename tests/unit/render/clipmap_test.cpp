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
    // The triangle of the level's mesh under the point, as render::surface_grid lists them.
    const bool stitched = level + 1 < int(g.clipmap.x);
    const render::ClipmapPatch patch = render::clipmap_patch(cell.x, cell.y, cells, stitched);
    auto height = [&](glm::ivec2 vertex) {
      gpu::ClipmapVertex v = gpu::clipmap_vertex(level, vertex, camera, g.grid, g.clipmap);
      if (!morph) v.morph = 0.0f;
      return gpu::clipmap_displaced(v).y;
    };
    for (size_t t = 0; t < patch.triangles().size(); t += 3) {
      const vec2 a(patch.triangles()[t]), b(patch.triangles()[t + 1]), c(patch.triangles()[t + 2]);
      const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
      const float wb = ((f.x - a.x) * (c.y - a.y) - (f.y - a.y) * (c.x - a.x)) / area;
      const float wc = ((b.x - a.x) * (f.y - a.y) - (b.y - a.y) * (f.x - a.x)) / area;
      const float wa = 1.0f - wb - wc;
      if (wa < -1e-5f || wb < -1e-5f || wc < -1e-5f) continue;
      out.height = wa * height(patch.triangles()[t]) + wb * height(patch.triangles()[t + 1]) +
                   wc * height(patch.triangles()[t + 2]);
      break;
    }
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

// The index list is a closed mesh up to the outermost edge: every edge of a triangle, taken by the world
// rest positions of its ends, is an edge of exactly one other triangle, run the other way; only the last
// level's outer edge is not. A T-junction (a finer ring's edge vertex on a coarser edge) breaks this: the
// rasteriser leaves pixel-sized holes there (the highlight test of tests/render/classic_shading_test.cpp
// found two in a 320 x 180 frame). And the triangles cover every visible cell once: each level's area is
// its visible cells' (the whole square at level 0, three quarters further out).
TEST(Clipmap, IndicesTileEveryVisibleCellAndShareEveryInnerEdge) {
  const vec2 camera(-7.3f, 12.9f);
  const render::SurfaceGrid g = render::surface_grid({camera.x, 5.0f, camera.y}, 3000.0f);
  ASSERT_EQ(g.indices.size() % 3, 0u);
  const int levels = int(g.clipmap.x);
  using Point = std::pair<float, float>;
  std::map<std::pair<Point, Point>, int> directed;
  std::vector<double> area(size_t(levels), 0.0);
  for (size_t t = 0; t < g.indices.size(); t += 3) {
    gpu::ClipmapVertex v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = gpu::clipmap_indexed_vertex(int(g.indices[t + k]), camera, g.grid, g.clipmap);
    ASSERT_TRUE(v[0].spacing == v[1].spacing && v[1].spacing == v[2].spacing) << "one level per triangle";
    const double twice = (double(v[1].rest.x) - v[0].rest.x) * (double(v[2].rest.y) - v[0].rest.y) -
                         (double(v[1].rest.y) - v[0].rest.y) * (double(v[2].rest.x) - v[0].rest.x);
    ASSERT_GT(twice, 0.0) << "counter-clockwise and not degenerate";
    area[size_t(std::lround(std::log2(v[0].spacing / g.grid.x)))] += 0.5 * twice;
    for (int k = 0; k < 3; ++k)
      ++directed[{{v[k].rest.x, v[k].rest.y}, {v[(k + 1) % 3].rest.x, v[(k + 1) % 3].rest.y}}];
  }
  // The outermost level's square.
  const float s_last = gpu::clipmap_spacing(levels - 1, g.grid);
  const vec2 lo =
      gpu::clipmap_centre(levels - 1, camera, g.grid) - vec2(float(render::kClipmapHalfCells) * s_last);
  const vec2 hi = lo + vec2(float(2 * render::kClipmapHalfCells) * s_last);
  auto on_outer_edge = [&](Point p) {
    return p.first == lo.x || p.first == hi.x || p.second == lo.y || p.second == hi.y;
  };
  int unmatched = 0;
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "an edge drawn twice the same way";
    const bool outer = on_outer_edge(edge.first) && on_outer_edge(edge.second) &&
                       (edge.first.first == edge.second.first || edge.first.second == edge.second.second);
    if (outer) continue;
    if (!directed.count({edge.second, edge.first})) ++unmatched;
  }
  EXPECT_EQ(unmatched, 0) << "edges with no neighbour across them: cracks";
  const double per_level = 4.0 * render::kClipmapHalfCells * render::kClipmapHalfCells;
  for (int level = 0; level < levels; ++level) {
    const double s = gpu::clipmap_spacing(level, g.grid);
    EXPECT_NEAR(area[size_t(level)] / (s * s), level == 0 ? per_level : 0.75 * per_level, 1e-6) << level;
  }
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
