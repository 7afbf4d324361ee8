#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/caustics.h"

// The accumulated fixed-point energy as irradiance relative to a flat sea, blurred along x by the slice's
// spread (common/caustic_blur.glsl); resolve.comp blurs it along z into the map and clears the
// accumulation for the next frame's splat.
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = LAGOON_CAUSTICS_BIND_ACCUM) readonly buffer Accum { uint energy[]; };
layout(std430, binding = LAGOON_CAUSTICS_BIND_ROWS) writeonly buffer Rows { float rows[]; };
layout(push_constant) uniform Push { CausticsBlurPush p; };

float caustic_in(int slice, int x, int z) {
  int n = int(p.cells.x);
  return float(energy[(slice * n + z) * n + x]) / LAGOON_CAUSTICS_ONE;
}
#include "common/caustic_blur.glsl"

// An invocation is a run of cells along a row: x = the run, y = the row, z = the slice.
void main() {
  int n = int(p.cells.x);  // this frame's cells per side: the map's first n x n
  ivec3 g = ivec3(gl_GlobalInvocationID);
  if (g.x >= n / LAGOON_CAUSTICS_RUN || g.y >= n) return;
  ivec2 start = ivec2(g.x * LAGOON_CAUSTICS_RUN, g.y);
  float run[LAGOON_CAUSTICS_RUN];
  caustic_blur_run(n, g.z, start, ivec2(1, 0), p.sigma_cells[g.z], run);
  for (int j = 0; j < LAGOON_CAUSTICS_RUN; ++j) rows[(g.z * n + start.y) * n + start.x + j] = run[j];
}
