// Frame constants of the foundation's placeholder scene (sky + displaced, lit grid). Uniform buffer.
#ifndef LAGOON_SHARED_PLACEHOLDER_FRAME_H
#define LAGOON_SHARED_PLACEHOLDER_FRAME_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct PlaceholderFrame {
  mat4 view_proj;
  mat4 inv_view_proj;
  vec4 camera_pos;  // xyz metres, w unused
  vec4 sun_dir;     // xyz unit vector towards the sun, w = sun intensity
  vec4 grid;        // x = half extent (m), y = vertices per side, z = time (s), w = unused
  vec4 post;        // x = exposure, y = gamma, zw unused
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(PlaceholderFrame, 192);
LAGOON_CHECK_OFFSET(PlaceholderFrame, inv_view_proj, 64);
LAGOON_CHECK_OFFSET(PlaceholderFrame, camera_pos, 128);
LAGOON_CHECK_OFFSET(PlaceholderFrame, sun_dir, 144);
LAGOON_CHECK_OFFSET(PlaceholderFrame, grid, 160);
LAGOON_CHECK_OFFSET(PlaceholderFrame, post, 176);
#endif
#endif
