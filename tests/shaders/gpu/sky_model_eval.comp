#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates shared/sky_model.h, the formula C++ also compiles, for a list of (direction, sun) pairs.
#include "shared/sky_model.h"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In {
  vec4 dir_sun[];
};  // pairs: direction, sun
layout(std430, binding = 1) readonly buffer Model {
  SkyModelGpu model;
};
layout(std430, binding = 2) writeonly buffer Out {
  vec4 rgb[];
};
layout(push_constant) uniform Push {
  uint count;
}
push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  rgb[i] = vec4(sky_model_rgb(model, dir_sun[2 * i].xyz, dir_sun[2 * i + 1].xyz), 0.0);
}
