// The ocean's per-texel math after the inverse FFT, shared by both FFT variants
// (compute/ocean/gpu/ocean_fft_path.h): displacement, normal, Jacobian and foam from the four packed fields
// of common/ocean_fields.glsl. Needs OceanPush (shared/ocean.h) as `p` and the images `displacement`,
// `normal_jacobian` and `jacobian_terms` declared by the includer.
#ifndef LAGOON_COMMON_OCEAN_ASSEMBLE_GLSL
#define LAGOON_COMMON_OCEAN_ASSEMBLE_GLSL
#define foam_real float
#include "shared/foam_math.h"
#undef foam_real

// After the inverse FFT: one texel's displacement (λDx, h, λDz, foam), normal and Jacobian, and Jacobian
// terms. Foam decays from the previous step's (displacement.w) at foam_decay_per_s and builds where the
// Jacobian falls below its cascade's foam_onset (shared/foam_math.h).
struct OceanJacobian {
  float jxx, jzz, jxz, j;
};

// The Jacobian's terms from F2 and F3: one expression for full and foam-only steps, so both give the same foam.
OceanJacobian ocean_jacobian(vec2 f2, vec2 f3) {
  float lambda = p.choppiness;
  OceanJacobian o;
  o.jxx = 1.0 + lambda * f2.y;
  o.jzz = 1.0 + lambda * f3.x;
  o.jxz = lambda * f3.y;
  o.j = o.jxx * o.jzz - o.jxz * o.jxz;
  return o;
}

// The texel's foam after this step: the previous step's (displacement.w), faded, or what J < onset makes.
float ocean_foam(ivec3 texel, float jacobian) {
  float fade = exp(-p.foam_decay_per_s * p.dt_s);
  float previous = p.reset_foam != 0u ? 0.0 : imageLoad(displacement, texel).w;
  float made = p.foam_build * foam_made(p.foam_onset[texel.z], p.foam_width[texel.z], jacobian);
  return foam_after_step(previous, fade, made);
}

// A warm-up step's texel: the foam only; the displacement's other channels and the other images are left for
// the next full step to write.
void ocean_assemble_foam(ivec3 texel, vec2 f2, vec2 f3) {
  imageStore(displacement, texel, vec4(0.0, 0.0, 0.0, ocean_foam(texel, ocean_jacobian(f2, f3).j)));
}

void ocean_assemble(ivec3 texel, vec2 f0, vec2 f1, vec2 f2, vec2 f3) {
  float lambda = p.choppiness;
  float h = f0.y, sx = f1.y, sz = f2.x;
  OceanJacobian jac = ocean_jacobian(f2, f3);
  float jxx = jac.jxx, jzz = jac.jzz, jxz = jac.jxz, jacobian = jac.j;
  float foam = ocean_foam(texel, jacobian);
  imageStore(displacement, texel, vec4(lambda * f0.x, h, lambda * f1.x, foam));
  imageStore(normal_jacobian, texel, vec4(normalize(vec3(-sx, 1.0, -sz)), jacobian));
  // Terms below half precision's smallest normal (6.1e-5) are flushed to 0: stored as subnormal halves they
  // take a slow conversion path on CPU devices (lavapipe), and below 1e-4 they decide no foam.
  vec4 terms = vec4(jxx - 1.0, jzz - 1.0, jxz, foam);
  imageStore(jacobian_terms, texel, mix(terms, vec4(0.0), lessThan(abs(terms), vec4(6.2e-5))));
}

#endif
