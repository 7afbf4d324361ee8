// Foam where the floor or an object meets the surface (docs/physics.md, Shore foam): waves break where the
// water is shallower than their height over the breaker index γ = 0.8 (McCowan's 0.78), d_b = H_s / 0.8. The
// band is solid to half that depth and fades out at d_b, so it widens with the waves and on gentle slopes.
// Needs `frame` (FrameUniforms): glint.z = H_s, 0 when shore foam is off.
#ifndef LAGOON_COMMON_SHORE_FOAM_GLSL
#define LAGOON_COMMON_SHORE_FOAM_GLSL

const float kBreakerIndex = 0.8;

// `depth`: of the water under the surface point, to the floor or a submerged object (m).
float shore_foam(float depth) {
  float hs = frame.glint.z;
  if (hs <= 0.0) return 0.0;
  return 1.0 - smoothstep(0.5, 1.0, depth * kBreakerIndex / hs);
}

#endif
