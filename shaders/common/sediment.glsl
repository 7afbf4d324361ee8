// Sediment clouds (shared/sediment.h, docs/physics.md "Sediment") along a view ray through the water: they
// dim what lies behind them and add the light their particles scatter, those lit like a white target at the
// clouds' depth seen from their distance (the underwater tables), times the particles' albedo. Compiled out
// (the specialisation constant) when nothing in the scene stirs the floor.
// Needs `frame` (FrameUniforms) and common/underwater.glsl included first.
#ifndef LAGOON_COMMON_SEDIMENT_GLSL
#define LAGOON_COMMON_SEDIMENT_GLSL
#include "shared/sediment.h"

layout(constant_id = LAGOON_SURFACE_SPEC_SEDIMENT) const bool kSediment = false;
layout(std430, binding = LAGOON_SURFACE_BIND_SEDIMENT) readonly buffer Sediment {
  SedimentHeader sediment;
  SedimentPuffGpu sediment_puffs[];
};

#define sed_real float
#define sed_real2 vec2
#define sed_real3 vec3
#include "shared/sediment_math.h"
#undef sed_real
#undef sed_real2
#undef sed_real3

// The clouds along `len` metres of the ray: the light they add (rgb, white units scaled by frame.lut.w) and the
// share of the light from behind them they let through (a). `volume`: the water's own attenuation is drawn
// (render.effects.underwater).
vec4 sediment_veil_terms(vec3 origin, vec3 dir, float len, bool volume) {
  if (!kSediment) return vec4(0.0, 0.0, 0.0, 1.0);
  // Every cloud culled at once, then a group at a time (the loop would add only zeros for them, so the sum
  // has the same bits): most pixels' rays pass far from the clouds.
  if (!sed_segment_meets_box(origin, dir, len, sediment.box_lo.xyz, sediment.box_hi.xyz))
    return vec4(0.0, 0.0, 0.0, 1.0);
  vec2 sum = vec2(0.0);
  int count = int(sediment.colour.w);
  for (int g = 0; g * LAGOON_SEDIMENT_GROUP < count; ++g) {
    if (!sed_segment_meets_box(origin, dir, len, sediment.group_lo[g].xyz, sediment.group_hi[g].xyz)) continue;
    for (int i = g * LAGOON_SEDIMENT_GROUP; i < min(count, (g + 1) * LAGOON_SEDIMENT_GROUP); ++i) {
      vec4 c = sediment_puffs[i].centre_sigma;
      sum += sed_ray(origin, dir, len, c.xyz, c.w, sediment_puffs[i].strength.x);
    }
  }
  if (sum.x <= 0.0) return vec4(0.0, 0.0, 0.0, 1.0);
  float t = sum.y / sum.x;  // where along the ray the clouds' light comes from
  float depth = max(-(origin.y + dir.y * t), 0.0);
  vec3 lit = underwater_target(volume ? t : 0.0, depth).rgb * frame.lut.w;
  float transmitted = exp(-sum.x);
  return vec4((1.0 - transmitted) * sediment.colour.rgb * lit, transmitted);
}

// `behind`: the radiance arriving from `len` metres along the ray (white units, scaled by frame.lut.w where
// the caller's are), seen through the clouds.
vec3 sediment_veil(vec3 behind, vec3 origin, vec3 dir, float len, bool volume) {
  if (!kSediment) return behind;
  vec4 veil = sediment_veil_terms(origin, dir, len, volume);
  return behind * veil.a + veil.rgb;
}

#endif
