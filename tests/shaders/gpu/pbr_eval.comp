#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates shared/pbr.h, the BRDF C++ also compiles, for a list of cases: n (w roughness), v (w A),
// l (w B), base colour (w metallic). Out: the BRDF·cos, and the environment term for a fixed environment.
#include "shared/pbr.h"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In {
  vec4 cases[];
};
layout(std430, binding = 1) writeonly buffer Out {
  vec4 results[];
};
layout(push_constant) uniform Push {
  uint count;
}
push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  vec4 n = cases[4 * i], v = cases[4 * i + 1], l = cases[4 * i + 2], base = cases[4 * i + 3];
  vec2 ab = vec2(v.w, l.w);
  results[2 * i] = vec4(pbr_brdf_cos(n.xyz, v.xyz, l.xyz, base.rgb, base.w, n.w, ab), 0.0);
  results[2 * i + 1] = vec4(pbr_environment(ab, base.rgb, base.w, vec3(0.7, 0.8, 0.9), vec3(0.5, 0.6, 0.7)), 0.0);
}
