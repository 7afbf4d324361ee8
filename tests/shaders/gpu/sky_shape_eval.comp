#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates shared/sky_shape.h, the formula C++ also compiles, for a list of (direction, sun) pairs.
#include "shared/sky_shape.h"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 dir_sun[]; };  // pairs: direction, sun
layout(std430, binding = 1) writeonly buffer Out { float shape[]; };
layout(push_constant) uniform Push { uint count; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  shape[i] = sky_shape(dir_sun[2 * i].xyz, dir_sun[2 * i + 1].xyz);
}
