// Parameters and draw ranges of the ocean surface's clipmap mesh (shaders/shared/clipmap.h) for one camera.
#pragma once
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lagoon::render {

struct SurfaceGrid {
  glm::vec4 grid{0.0f};     // x = spacing of the finest drawn level (m), y = m (cells per half side)
  glm::vec4 clipmap{0.0f};  // x = levels, y = fade of the finest level into the next, z = morph zone (cells)
  // Triangle list over clipmap_indexed_vertex ids: the visible cells of every level, except blocks outside
  // the view, as clipmap_patch() triangulates them.
  std::vector<uint32_t> indices;
};

// The triangles that cover one cell of a level, with the cells they cover together. Inside a level: the
// cell alone, as (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1). On the edge of a level that a coarser one
// surrounds (`stitched`), every other vertex of the edge lies on a coarser edge: a T-junction, exact in the
// world but not after the projection's rounding, where the rasteriser leaves pixel-sized holes. There the
// edge's cells go in pairs, three triangles on the straight coarser edge, and each 2 x 2 corner block as a
// fan about its middle vertex, so the finer edge's odd vertices (morphed onto the coarser edge's middle,
// shared/clipmap.h) are not used and every edge of the mesh is shared by two triangles.
struct ClipmapPatch {
  glm::ivec2 first{0};  // the patch's first cell: surface_grid lists it with this cell
  // Lattice vertices of the level, three per triangle, counter-clockwise: at most a corner's six triangles.
  // Held in place, not on the heap: surface_grid asks for every cell of every level each frame.
  std::array<glm::ivec2, 18> corners{};
  uint32_t count = 0;
  std::span<const glm::ivec2> triangles() const { return {corners.data(), count}; }
};
// Cell (i, j) of a level of `cells` x `cells` (2m, even).
ClipmapPatch clipmap_patch(int i, int j, int cells, bool stitched);

// Cells per half side of a level: a cell spans at most 1/(m/2) of its distance from the camera, 1/12.
inline constexpr int kClipmapHalfCells = 24;
// Width of the zone where a level morphs into the next (it ends a cell inside the edge); at most m/2 - 2.5
// so that a level is unmorphed where the finer level ends (shared/clipmap.h).
inline constexpr float kClipmapMorphCells = 6.0f;
// Every level's spacing is this times a power of two, so lattices stay fixed in the world as the camera
// rises and falls; the finest drawn level follows the camera's height above (or below) the mean surface.
inline constexpr float kClipmapBaseSpacingM = 1.0f / 64.0f;
inline constexpr float kClipmapSpacingPerHeight = 1.0f / 16.0f;
inline constexpr float kClipmapMinHeightM = 1.0f;
inline constexpr int kClipmapMaxLevels = 16;

// How far the displaced surface can be from its rest position, for culling blocks against the view.
struct DisplacementBound {
  float horizontal_m = 0.0f;
  float vertical_m = 0.0f;
};

// The most indices a grid can have (all levels, every cell).
inline constexpr size_t kClipmapMaxIndices =
    size_t(kClipmapMaxLevels) * (2 * kClipmapHalfCells) * (2 * kClipmapHalfCells) * 6;

// The grid's parameters only (no indices): levels reach at least `reach_m` from the camera (Chebyshev
// distance) or stop at kClipmapMaxLevels.
SurfaceGrid surface_grid_parameters(const glm::vec3& camera, float reach_m);

// The parameters and the indices of the cells to draw.
// With `view_proj`, blocks whose displaced surface cannot reach the view volume are not drawn.
SurfaceGrid surface_grid(const glm::vec3& camera, float reach_m, const glm::mat4* view_proj = nullptr,
                         DisplacementBound bound = {});

}  // namespace lagoon::render
