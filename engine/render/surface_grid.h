// Parameters and draw ranges of the ocean surface's clipmap mesh (shaders/shared/clipmap.h) for one camera.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lagoon::render {

struct VertexRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

struct SurfaceGrid {
  glm::vec4 grid{0.0f};     // x = spacing of the finest drawn level (m), y = m (cells per half side)
  glm::vec4 clipmap{0.0f};  // x = levels, y = fade of the finest level into the next, z = morph zone (cells)
  std::vector<VertexRange> ranges;  // of the non-indexed draw; blocks outside the view are left out
  uint32_t vertex_count = 0;        // of all the levels, drawn or not
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

// Levels reach at least `reach_m` from the camera (Chebyshev distance) or stop at kClipmapMaxLevels.
// With `view_proj`, blocks whose displaced surface cannot reach the view volume are not drawn.
SurfaceGrid surface_grid(const glm::vec3& camera, float reach_m, const glm::mat4* view_proj = nullptr,
                         DisplacementBound bound = {});

}  // namespace lagoon::render
