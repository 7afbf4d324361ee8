#version 450
// One mip level of a group's three ocean textures at once: each texel is the mean of its 2x2 parents, what a
// linear blit to exactly half size computes. One dispatch per level instead of three blits, each of which
// lavapipe runs as a draw.
#extension GL_GOOGLE_include_directive : require
#include "shared/ocean.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = LAGOON_MIPS_BIND_SRC + 0) readonly uniform image2DArray src_displacement;
layout(rgba32f, binding = LAGOON_MIPS_BIND_SRC + 1) readonly uniform image2DArray src_normal_jacobian;
layout(rgba16f, binding = LAGOON_MIPS_BIND_SRC + 2) readonly uniform image2DArray src_jacobian_terms;
layout(rgba32f, binding = LAGOON_MIPS_BIND_DST + 0) writeonly uniform image2DArray dst_displacement;
layout(rgba32f, binding = LAGOON_MIPS_BIND_DST + 1) writeonly uniform image2DArray dst_normal_jacobian;
layout(rgba16f, binding = LAGOON_MIPS_BIND_DST + 2) writeonly uniform image2DArray dst_jacobian_terms;

#define LAGOON_MEAN(img)                                                                             \
  (0.25 * (imageLoad(img, s) + imageLoad(img, s + ivec3(1, 0, 0)) + imageLoad(img, s + ivec3(0, 1, 0)) + \
           imageLoad(img, s + ivec3(1, 1, 0))))

void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  ivec3 size = imageSize(dst_displacement);
  if (p.x >= size.x || p.y >= size.y || p.z >= size.z) return;
  ivec3 s = ivec3(p.xy * 2, p.z);
  imageStore(dst_displacement, p, LAGOON_MEAN(src_displacement));
  imageStore(dst_normal_jacobian, p, LAGOON_MEAN(src_normal_jacobian));
  imageStore(dst_jacobian_terms, p, LAGOON_MEAN(src_jacobian_terms));
}
