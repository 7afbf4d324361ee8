#version 450
#extension GL_GOOGLE_include_directive : require
// common/simplex4.glsl at a list of points.
#include "common/simplex4.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 points[]; };
layout(std430, binding = 1) writeonly buffer Out { float values[]; };
layout(push_constant) uniform Push { uint count; uint seed; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  values[i] = simplex4(points[i], push.seed);
}
