#version 450
#extension GL_GOOGLE_include_directive : require
// The sediment clouds' grains (common/sediment_grain.glsl) as render/sediment_grains.vert places them:
// LAGOON_SEDIMENT_MAX_GRAINS per cloud, (position, 1) or 0 where the cloud has fewer.
#include "common/simplex4.glsl"
#include "common/sediment_grain.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Puffs { SedimentPuffGpu puffs[]; };
layout(std430, binding = 1) writeonly buffer Out { vec4 grains[]; };
layout(push_constant) uniform Push { uint count; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count * uint(LAGOON_SEDIMENT_MAX_GRAINS)) return;
  grains[i] = sediment_grain(puffs[i / uint(LAGOON_SEDIMENT_MAX_GRAINS)], int(i % uint(LAGOON_SEDIMENT_MAX_GRAINS)));
}
