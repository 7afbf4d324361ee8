#version 450
// Counts the texels of one cascade (mip 0, one layer of its group's three textures) that hold NaN or Inf
// (compute/ocean/gpu/field_check.h): a long run checks every step without reading the fields back.
#extension GL_GOOGLE_include_directive : require
#include "shared/ocean.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = LAGOON_CHECK_BIND_FIELDS) readonly uniform image2DArray displacement;
layout(rgba32f, binding = LAGOON_CHECK_BIND_FIELDS + 1) readonly uniform image2DArray normal_jacobian;
layout(rgba16f, binding = LAGOON_CHECK_BIND_FIELDS + 2) readonly uniform image2DArray jacobian_terms;
layout(std430, binding = LAGOON_CHECK_BIND_COUNT) buffer Count {
  uint non_finite;
};
layout(push_constant) uniform Push {
  int layer;
};

bool finite(vec4 v) {
  return !any(isnan(v)) && !any(isinf(v));
}

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID.xy, layer);
  ivec3 size = imageSize(displacement);
  if (p.x >= size.x || p.y >= size.y) return;
  if (!finite(imageLoad(displacement, p)) || !finite(imageLoad(normal_jacobian, p)) ||
      !finite(imageLoad(jacobian_terms, p)))
    atomicAdd(non_finite, 1u);
}
