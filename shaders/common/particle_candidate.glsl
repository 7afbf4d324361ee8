// One candidate of the suspended particles (shared/particles.h): where it is and whether it is drawn. Shared by
// the particles' vertex shader (render/particles.vert) and the tests that check the field against what the
// scene asks (density, drift). Needs common/simplex4.glsl included first.
//
// One candidate per cell of a world-fixed lattice of LAGOON_PARTICLES_SIDE³ cells around the camera, placed in
// its cell by a hash of the cell and the seed, carried by the drift (wrapping within its cell, so every cell
// keeps one candidate), and kept where a second hash falls below the local density from 4-D simplex noise
// over (x, y, z, t), and under the water.
#ifndef LAGOON_COMMON_PARTICLE_CANDIDATE_GLSL
#define LAGOON_COMMON_PARTICLE_CANDIDATE_GLSL
#include "shared/particles.h"

struct ParticleCandidate {
  vec3 position;  // world, metres
  bool kept;
};

ParticleCandidate particle_candidate(int particle, ParticlesPush p) {
  const int n = LAGOON_PARTICLES_SIDE;
  ivec3 cell = ivec3(round(p.lattice.xyz / p.lattice.w)) + ivec3(particle % n, (particle / n) % n, particle / (n * n));
  uint seed = p.seed.x;
  uint h = lagoon_hash4(ivec4(cell, 0), seed);
  uint h1 = lagoon_hash(h), h2 = lagoon_hash(h1), h3 = lagoon_hash(h2);
  float presence = float(h >> 8) / 16777216.0;
  float t = p.drift.w;
  vec3 offset = vec3(float(h1 & 0xffffu), float(h2 & 0xffffu), float(h3 & 0xffffu)) / 65536.0;
  vec3 pos = (vec3(cell) + fract(offset + p.drift.xyz * t / p.lattice.w)) * p.lattice.w;
  // The noise's mean density is 1/2: twice it keeps the scene's mean density.
  if (presence >= 2.0 * p.look.x) return ParticleCandidate(pos, false);
  float density = clamp(0.5 + 0.5 * simplex4(vec4(pos / p.look.z, 0.05 * t), seed), 0.0, 1.0);
  return ParticleCandidate(pos, presence < 2.0 * p.look.x * density && pos.y <= -0.02);
}

#endif
