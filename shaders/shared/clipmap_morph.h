// The displaced position of a clipmap vertex (shared/clipmap.h). The includer defines
//   vec3 clipmap_displacement(vec2 rest, float spacing)
// first: the ocean's displacement at `rest`, filtered for a mesh of that spacing. The shader samples the
// cascades; the C++ tests use analytic fields.
#ifndef LAGOON_SHARED_CLIPMAP_MORPH_H
#define LAGOON_SHARED_CLIPMAP_MORPH_H
#include "shared/clipmap.h"

LAGOON_GPU_BEGIN
LAGOON_FN vec3 clipmap_displaced(ClipmapVertex v) {
  // Filtering follows the morph so that a fully morphed vertex matches the coarser level exactly.
  vec3 p = vec3(v.rest.x, 0.0f, v.rest.y) + clipmap_displacement(v.rest, v.spacing * (1.0f + v.morph));
  if (v.morph > 0.0f && v.coarse_a != v.coarse_b) {
    vec3 a = vec3(v.coarse_a.x, 0.0f, v.coarse_a.y) + clipmap_displacement(v.coarse_a, 2.0f * v.spacing);
    vec3 b = vec3(v.coarse_b.x, 0.0f, v.coarse_b.y) + clipmap_displacement(v.coarse_b, 2.0f * v.spacing);
    p = mix(p, 0.5f * (a + b), v.morph);
  }
  return p;
}
LAGOON_GPU_END

#endif
