// Push constants of the mesh pass (render/mesh.vert, mesh.frag): one draw of one mesh instance.
#ifndef LAGOON_SHARED_MESH_H
#define LAGOON_SHARED_MESH_H
#include "shared/interop.h"

// Which pass draws the mesh: a specialisation constant (LAGOON_MESH_SPEC_MODE), one pipeline per mode, so
// each compiles only its own code (lavapipe runs a masked branch at full cost: the window mode's path
// bisection ran in every mesh's vertex shader).
#define LAGOON_MESH_SPEC_MODE 0
#define LAGOON_MESH_LIT 0u         // lit and tone-mapped, above the water, into the displayed frame
#define LAGOON_MESH_REFRACTION 1u  // albedo of what is under the water, into the refraction target
#define LAGOON_MESH_MIRRORED 2u    // lit, mirrored about the mean water level, into the reflection target
#define LAGOON_MESH_WINDOW \
  3u  // lit, above the water, as seen from below through a flat surface
      // (common/snell_window.glsl), into the Snell's window target

// Binding slots of mesh.vert and mesh.frag.
#define LAGOON_MESH_BIND_FRAME 0     // FrameUniforms (shared/frame.h)
#define LAGOON_MESH_BIND_VERTICES 1  // the mesh's vertices (render/gpu_mesh.h MeshVertex)
#define LAGOON_MESH_BIND_INDICES 2   // its 32-bit indices
#define LAGOON_MESH_BIND_ALBEDO 3    // albedo texture (sRGB)
#define LAGOON_MESH_BIND_LIGHTS 4    // PointLightGpu[]

LAGOON_GPU_BEGIN
struct MeshPush {
  mat4 model;           // model to world
  vec4 base_colour;     // rgb albedo (linear), a = 1 if the texture is used
  float texture_scale;  // metres per texture repeat for world-space uv (0 = the mesh's uv)
  uint pad0;
  uint pad1;
  uint pad2;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(MeshPush, 96);
LAGOON_CHECK_OFFSET(MeshPush, base_colour, 64);
LAGOON_CHECK_OFFSET(MeshPush, texture_scale, 80);
namespace lagoon::gpu {
enum class MeshMode : uint32_t {
  Lit = LAGOON_MESH_LIT,
  Refraction = LAGOON_MESH_REFRACTION,
  Mirrored = LAGOON_MESH_MIRRORED,
  Window = LAGOON_MESH_WINDOW
};
}
#endif
#endif
