// Parameters and draw ranges of the ocean surface's clipmap mesh (shaders/shared/clipmap.h) for one camera.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lagoon::render {

struct SurfaceGrid {
  glm::vec4 grid{0.0f};     // x = spacing of the finest drawn level (m), y = m (cells per half side)
  glm::vec4 clipmap{0.0f};  // x = levels, y = fade of the finest level into the next, z = morph zone (cells)
  // Triangle list over clipmap_indexed_vertex ids: the visible cells of every level, except blocks outside
  // the view. Two triangles per cell, (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
  std::vector<uint32_t> indices;
};

// Cells per half side of a level: a cell spans at most 1/(m/2) of its distance from the camera, 1/12.
inline constexpr int kClipmapHalfCells = 24;
// Width of the zone where a level morphs into the next; at most m/2 - 1.5 so that a level is unmorphed
// where the finer level ends (shared/clipmap.h).
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
