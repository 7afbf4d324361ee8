#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/caustics.h"

// The map, one layer per slice: blur_rows.comp's irradiance (relative to a flat sea, blurred along x)
// blurred along z by the slice's spread (common/caustic_blur.glsl). The accumulation, which blur_rows.comp
// has read, is cleared on the way for the next frame's splat (no separate fill).
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = LAGOON_CAUSTICS_BIND_ACCUM) writeonly buffer Accum { uint energy[]; };
layout(std430, binding = LAGOON_CAUSTICS_BIND_ROWS) readonly buffer Rows { float rows[]; };
layout(r32f, binding = LAGOON_CAUSTICS_BIND_MAP) writeonly uniform image2DArray caustic_map;
layout(push_constant) uniform Push { CausticsBlurPush p; };

float caustic_in(int slice, int x, int z) {
  int n = int(p.cells.x);
  return rows[(slice * n + z) * n + x];
}
#include "common/caustic_blur.glsl"

// An invocation is a run of cells along a column: x = the run, y = the column, z = the slice.
void main() {
  int n = int(p.cells.x);  // this frame's cells per side: the map's first n x n
  ivec3 g = ivec3(gl_GlobalInvocationID);
  if (g.x >= n / LAGOON_CAUSTICS_RUN || g.y >= n) return;
  ivec2 start = ivec2(g.y, g.x * LAGOON_CAUSTICS_RUN);
  float run[LAGOON_CAUSTICS_RUN];
  caustic_blur_run(n, g.z, start, ivec2(0, 1), p.sigma_cells[g.z], run);
  for (int j = 0; j < LAGOON_CAUSTICS_RUN; ++j) {
    imageStore(caustic_map, ivec3(start.x, start.y + j, g.z), vec4(run[j]));
    energy[(g.z * n + start.y + j) * n + start.x] = 0u;
  }
}
