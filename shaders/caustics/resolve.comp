#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/caustics.h"

// The accumulated fixed-point energy as irradiance relative to a flat sea, one layer per slice; the
// accumulation is cleared for the next frame on the way (no separate fill).
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = LAGOON_CAUSTICS_BIND_ACCUM) buffer Accum { uint energy[]; };
layout(r32f, binding = LAGOON_CAUSTICS_BIND_MAP) writeonly uniform image2DArray caustic_map;

void main() {
  const int n = LAGOON_CAUSTICS_CELLS;
  ivec3 c = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(c.xy, ivec2(n)))) return;
  uint i = uint((c.z * n + c.y) * n + c.x);
  float e = float(energy[i]) / LAGOON_CAUSTICS_ONE;
  energy[i] = 0u;
  imageStore(caustic_map, c, vec4(e));
}
