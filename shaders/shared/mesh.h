// Push constants of the mesh pass (render/mesh.vert, mesh.frag): one draw of one mesh instance.
#ifndef LAGOON_SHARED_MESH_H
#define LAGOON_SHARED_MESH_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct MeshPush {
  mat4 model;        // model to world
  vec4 base_colour;  // rgb albedo (linear), a = 1 if the texture is used
  vec4 params;       // x = mode (0 lit above water, 1 albedo for refraction, 2 lit mirrored for reflection),
                     // y = texture scale for world-space uv (0 = mesh uv), zw unused
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(MeshPush, 96);
LAGOON_CHECK_OFFSET(MeshPush, base_colour, 64);
#endif
#endif
