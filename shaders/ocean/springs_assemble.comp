#version 450
// Model springs' picture (compute/ocean/springs.h): the state after step m is the surface at t_m; the
// picture at t_m - behind_s is x - v behind_s (the straight line eq. 5 draws between steps). It goes into the
// first cascade's layer of the ocean's images as the FFT ocean writes them: (0, h, 0, foam), the normal from
// central differences and J = 1 (the nodes only move vertically), so every consumer runs unchanged.
#extension GL_GOOGLE_include_directive : require
#include "shared/springs.h"
#define foam_real float
#include "shared/foam_math.h"
#undef foam_real
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = LAGOON_SPRINGS_BIND_STATE_IN) readonly buffer State { vec2 state[]; };
layout(rgba32f, binding = LAGOON_SPRINGS_BIND_DISPLACEMENT) uniform image2DArray displacement;
layout(rgba32f, binding = LAGOON_SPRINGS_BIND_NORMAL_JACOBIAN) writeonly uniform image2DArray normal_jacobian;
layout(rgba16f, binding = LAGOON_SPRINGS_BIND_JACOBIAN_TERMS) writeonly uniform image2DArray jacobian_terms;
layout(push_constant) uniform Push { SpringsPush p; };

float height(int i, int j) {
  int n = int(p.n);
  vec2 xv = state[((j + n) % n) * n + (i + n) % n];
  return xv.x - xv.y * p.behind_s;
}

void main() {
  int n = int(p.n);
  ivec2 c = ivec2(gl_GlobalInvocationID.xy);
  if (c.x >= n || c.y >= n) return;
  ivec3 texel = ivec3(c, int(p.layer));
  float h = height(c.x, c.y);
  float sx = (height(c.x + 1, c.y) - height(c.x - 1, c.y)) / (2.0 * p.spacing);
  float sz = (height(c.x, c.y + 1) - height(c.x, c.y - 1)) / (2.0 * p.spacing);
  float previous = p.reset_foam != 0u ? 0.0 : imageLoad(displacement, texel).w;
  float foam = foam_after_step(previous, p.foam_decay, foam_made(p.foam_threshold, 1.0, 1.0));
  imageStore(displacement, texel, vec4(0.0, h, 0.0, foam));
  imageStore(normal_jacobian, texel, vec4(normalize(vec3(-sx, 1.0, -sz)), 1.0));
  imageStore(jacobian_terms, texel, vec4(0.0, 0.0, 0.0, foam));
}
