#version 450
// The step of models gerstner and sines with their own waves (compute/ocean/gpu/direct_waves_gpu.h): the sum
// of common/direct_waves.glsl at every texel of the first cascade's grid (x0 = i L/N), written as the FFT
// ocean writes its layer: (Dx, h, Dz, foam), (normal, J) and the Jacobian terms, foam by the same law. The
// renderer draws the sum itself; this layer is what export, the field statistics and the read-backs see.
#extension GL_GOOGLE_include_directive : require
#include "shared/direct_waves.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std430, binding = LAGOON_DIRECT_BIND_WAVES) readonly buffer Waves {
  DirectWaveGpu waves[];
};
layout(rgba32f, binding = LAGOON_DIRECT_BIND_DISPLACEMENT) uniform image2DArray displacement;
layout(rgba32f, binding = LAGOON_DIRECT_BIND_NORMAL_JACOBIAN) writeonly uniform image2DArray normal_jacobian;
layout(rgba16f, binding = LAGOON_DIRECT_BIND_JACOBIAN_TERMS) writeonly uniform image2DArray jacobian_terms;
layout(push_constant) uniform Push { DirectWavesPush p; };

#define LAGOON_DIRECT_WAVE(i) waves[i]
#define LAGOON_DIRECT_COUNT p.count
#include "common/direct_waves.glsl"
#define foam_real float
#include "shared/foam_math.h"
#undef foam_real

void main() {
  int n = int(p.n);
  ivec2 c = ivec2(gl_GlobalInvocationID.xy);
  if (c.x >= n || c.y >= n) return;
  ivec3 texel = ivec3(c, int(p.layer));
  DirectSum s = direct_waves_at(vec2(c) * p.spacing, p.time_s, 0.0);
  float jacobian = (1.0 + s.terms.x) * (1.0 + s.terms.y) - s.terms.z * s.terms.z;
  float previous = p.reset_foam != 0u ? 0.0 : imageLoad(displacement, texel).w;
  float foam = foam_after_step(previous, p.foam_decay, foam_made(p.foam_threshold, 1.0, jacobian));
  imageStore(displacement, texel, vec4(s.displacement, foam));
  imageStore(normal_jacobian, texel, vec4(normalize(vec3(-s.slope.x, 1.0, -s.slope.y)), jacobian));
  // Terms below half precision's smallest normal flushed to 0, as common/ocean_assemble.glsl does.
  vec3 terms = mix(s.terms, vec3(0.0), lessThan(abs(s.terms), vec3(6.1e-5)));
  imageStore(jacobian_terms, texel, vec4(terms, foam));
}
