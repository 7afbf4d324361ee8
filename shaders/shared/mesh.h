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
#define LAGOON_MESH_BIND_FRAME 0         // FrameUniforms (shared/frame.h)
#define LAGOON_MESH_BIND_VERTICES 1      // the mesh's vertices (render/gpu_mesh.h MeshVertex)
#define LAGOON_MESH_BIND_INDICES 2       // its 32-bit indices
#define LAGOON_MESH_BIND_ALBEDO 3        // base colour texture (sRGB)
#define LAGOON_MESH_BIND_LIGHTS 4        // PointLightGpu[]
#define LAGOON_MESH_BIND_METAL_ROUGH 5   // metallic-roughness texture (linear: B metallic, G roughness)
#define LAGOON_MESH_BIND_NORMAL 6        // tangent-space normal map (linear)
#define LAGOON_MESH_BIND_OCCLUSION 7     // occlusion texture (linear, R)
#define LAGOON_MESH_BIND_EMISSIVE 8      // emissive texture (sRGB)
#define LAGOON_MESH_BIND_MATERIALS 9     // MaterialGpu[]
#define LAGOON_MESH_BIND_ENVIRONMENT 10  // pre-filtered environment (render/environment_map.h), 2D array
#define LAGOON_MESH_BIND_DFG 11          // directional-albedo table (render/dfg_table.h), RG

// MaterialGpu.flags.x
#define LAGOON_ALPHA_OPAQUE 0u
#define LAGOON_ALPHA_MASK 1u
#define LAGOON_ALPHA_BLEND 2u
// A material's textures, in bit order of flags.y (present) and flags.z (on TEXCOORD_1), and in uv_rows.
#define LAGOON_TEX_BASE 0
#define LAGOON_TEX_METAL_ROUGH 1
#define LAGOON_TEX_NORMAL 2
#define LAGOON_TEX_OCCLUSION 3
#define LAGOON_TEX_EMISSIVE 4
#define LAGOON_TEX_COUNT 5

// The refraction pass's alpha (coverage; above 0.5 = something drawn): 1 for the procedural floor, a height
// field whose point on a refracted ray the fixed point finds alone; less for objects and glTF floors, which a
// ray can meet before what it settles on (common/refracted_hit.glsl).
#define LAGOON_REFRACTION_ALPHA_HEIGHT_FIELD 1.0
#define LAGOON_REFRACTION_ALPHA_OBJECT 0.75

LAGOON_GPU_BEGIN
struct MeshPush {
  mat4 model;           // model to world
  uint material;        // index into MaterialGpu[]
  float texture_scale;  // metres per texture repeat for world-space uv (0 = the mesh's uv)
  uint ground_truth;    // what it is in the ground truth (shared/ground_truth.h LAGOON_GT_*)
  uint height_field;    // 1: the procedural floor, which the refraction pass marks as a height field
};

// A glTF material (gltf/model.h Material) as the mesh shader reads it.
struct MaterialGpu {
  vec4 base_colour;  // linear RGBA factor
  vec4 emissive;     // rgb linear (times KHR_materials_emissive_strength), w = alpha cutoff
  vec4 pbr;          // metallic, roughness, normal scale, occlusion strength
  uvec4 flags;  // x alpha mode, y textures present (bits), z textures on TEXCOORD_1 (bits), w double-sided
  vec4 uv_rows[2 * LAGOON_TEX_COUNT];  // texture i: rows 2i and 2i+1 of its KHR_texture_transform (xyz)
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(MeshPush, 80);
LAGOON_CHECK_OFFSET(MeshPush, texture_scale, 68);
LAGOON_CHECK_SIZE(MaterialGpu, 224);
LAGOON_CHECK_OFFSET(MaterialGpu, uv_rows, 64);
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
