// A grain of a sediment cloud (seed 002 §3.4's earth-coloured particles; shared/sediment.h): grain j of a
// cloud lies where the cloud's Gaussian puts it, centre + σ g with g three standard normal numbers (Box-Muller)
// from a hash of the cloud's release and j, so the same cloud shows the same grains as it bursts, rises,
// spreads and sinks. Needs common/simplex4.glsl (its integer hash) included first.
#ifndef LAGOON_COMMON_SEDIMENT_GRAIN_GLSL
#define LAGOON_COMMON_SEDIMENT_GRAIN_GLSL
#include "shared/sediment.h"

// A uniform number in (0, 1] from 24 bits of a hash.
float grain_uniform(uint h) {
  return (float(h >> 8) + 1.0) / 16777216.0;
}

// Grain j of `puff`, or w = 0 when the cloud has fewer grains (strength.y of them).
vec4 sediment_grain(SedimentPuffGpu puff, int j) {
  if (float(j) >= puff.strength.y) return vec4(0.0);
  uint h = lagoon_hash(floatBitsToUint(puff.strength.z) ^ lagoon_hash(uint(j) + 0x9e3779b9u));
  uint h1 = lagoon_hash(h), h2 = lagoon_hash(h1), h3 = lagoon_hash(h2);
  float r1 = sqrt(-2.0 * log(grain_uniform(h))), r2 = sqrt(-2.0 * log(grain_uniform(h2)));
  float a1 = 6.2831853 * grain_uniform(h1), a2 = 6.2831853 * grain_uniform(h3);
  vec3 g = vec3(r1 * cos(a1), r1 * sin(a1), r2 * cos(a2));
  return vec4(puff.centre_sigma.xyz + puff.centre_sigma.w * g, 1.0);
}

#endif
