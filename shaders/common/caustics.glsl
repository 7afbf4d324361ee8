// The caustic map (shared/caustics.h, engine/render/passes/caustics_pass.h) as a gain on the light falling on
// the floor: the sun's direct share of it is focused by the waves, the diffuse rest is not. Needs, declared
// by the includer: `frame` (FrameUniforms) and `caustic_map` (sampler2DArray).
#ifndef LAGOON_COMMON_CAUSTICS_GLSL
#define LAGOON_COMMON_CAUSTICS_GLSL
#include "shared/caustics.h"

layout(constant_id = LAGOON_SURFACE_SPEC_CAUSTICS) const bool kCaustics = true;

// Irradiance at world (xz, depth) relative to the same light under a flat surface; 1 outside the window,
// fading to 1 over its outer tenth so its edge does not show.
float caustic_gain(vec2 xz, float depth) {
  if (!kCaustics || frame.caustics.w < 0.5 || depth <= 0.0) return 1.0;
  vec2 uv = (xz - frame.caustics.xy) / (frame.caustics.z * frame.caustics.w);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
  // Between slices linearly in depth; above the first towards 1 at the surface (no focusing at depth 0);
  // below the last, the last. Selects, not branches, so only two lookups run (lavapipe runs both sides of a
  // branch).
  vec4 z = frame.caustic_depths;
  int k = depth < z.y ? 0 : depth < z.z ? 1 : depth < z.w ? 2 : 3;
  int next = min(k + 1, 3);
  float f = k == 3 ? 0.0 : clamp((depth - z[k]) / (z[next] - z[k]), 0.0, 1.0);
  // The frame's n x n cells are the map's first (OceanRenderer::set_caustic_cells), its texel centres the
  // window's cells: kept inside them, so a coarser map does not blend in the cells it did not write.
  float n = frame.caustics.w;
  vec2 tc = clamp(uv * n, vec2(0.5), vec2(n - 0.5)) / float(LAGOON_CAUSTICS_CELLS);
  float e = mix(texture(caustic_map, vec3(tc, float(k))).r, texture(caustic_map, vec3(tc, float(next))).r, f);
  e = depth < z.x ? mix(1.0, e, depth / z.x) : e;  // there k = 0 and f = 0: e is the first slice's
  float share = mix(frame.caustic_share[k], frame.caustic_share[next], f);
  vec2 edge = min(uv, 1.0 - uv);
  float fade = smoothstep(0.0, 0.1, min(edge.x, edge.y));
  return 1.0 + fade * share * (e - 1.0);
}

#endif
