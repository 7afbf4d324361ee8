// 4-D simplex noise (Perlin 2001; Gustavson, "Simplex noise demystified", 2005): the density field of the
// suspended particles, as seed 002 uses it, over (x, y, z, t). Gradients come from an integer hash of the
// lattice point and a seed (no sin() hashing, whose results differ between devices), so the same seed gives
// the same field on every device. Range about [-1, 1].
#ifndef LAGOON_COMMON_SIMPLEX4_GLSL
#define LAGOON_COMMON_SIMPLEX4_GLSL

uint lagoon_hash(uint x) {  // a 32-bit integer mixer (lowbias32)
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

uint lagoon_hash4(ivec4 c, uint seed) {
  uint h = lagoon_hash(uint(c.x) ^ lagoon_hash(seed));
  h = lagoon_hash(h ^ uint(c.y));
  h = lagoon_hash(h ^ uint(c.z));
  return lagoon_hash(h ^ uint(c.w));
}

// One of the 32 gradients (0, ±1, ±1, ±1) in every arrangement of the zero.
vec4 simplex4_gradient(uint h) {
  vec3 s = vec3(float((h >> 2) & 1u), float((h >> 3) & 1u), float((h >> 4) & 1u)) * 2.0 - 1.0;
  uint zero = h & 3u;
  if (zero == 0u) return vec4(0.0, s);
  if (zero == 1u) return vec4(s.x, 0.0, s.yz);
  if (zero == 2u) return vec4(s.xy, 0.0, s.z);
  return vec4(s, 0.0);
}

float simplex4_corner(vec4 x, ivec4 cell, uint seed) {
  float t = 0.6 - dot(x, x);
  if (t <= 0.0) return 0.0;
  t *= t;
  return t * t * dot(simplex4_gradient(lagoon_hash4(cell, seed)), x);
}

float simplex4(vec4 p, uint seed) {
  const float F4 = 0.309016994374947451;  // (sqrt(5) - 1) / 4: skews to the hypercubic lattice
  const float G4 = 0.138196601125010504;  // (5 - sqrt(5)) / 20: and back
  vec4 i = floor(p + dot(p, vec4(F4)));
  vec4 x0 = p - i + dot(i, vec4(G4));
  // Which of the 24 simplices of the hypercube: rank the coordinates (Gustavson's ordering).
  vec4 rank;
  vec3 is_x = step(x0.yzw, x0.xxx);
  vec3 is_yz = step(x0.zww, x0.yyz);
  rank.x = is_x.x + is_x.y + is_x.z;
  rank.yzw = 1.0 - is_x;
  rank.y += is_yz.x + is_yz.y;
  rank.zw += 1.0 - is_yz.xy;
  rank.z += is_yz.z;
  rank.w += 1.0 - is_yz.z;
  vec4 i1 = clamp(rank - 2.0, 0.0, 1.0), i2 = clamp(rank - 1.0, 0.0, 1.0), i3 = clamp(rank, 0.0, 1.0);
  ivec4 c = ivec4(i);
  float n = simplex4_corner(x0, c, seed);
  n += simplex4_corner(x0 - i1 + G4, c + ivec4(i1), seed);
  n += simplex4_corner(x0 - i2 + 2.0 * G4, c + ivec4(i2), seed);
  n += simplex4_corner(x0 - i3 + 3.0 * G4, c + ivec4(i3), seed);
  n += simplex4_corner(x0 - 1.0 + 4.0 * G4, c + ivec4(1), seed);
  return 27.0 * n;
}

#endif
