// The surface mesh's vertex: the clipmap (shared/clipmap.h) displaced by the cascades. Shared by the surface's
// vertex shaders (render/ocean_surface.vert, and ocean_surface_gouraud.vert which also lights the vertex).
// Needs shared/frame.h and shared/surface.h included first.
//
// The surface mesh is a geometry clipmap (shared/clipmap.h): nested rings on world-fixed lattices whose
// spacing doubles per ring, so triangles keep about the same size on screen, vertices do not swim as the
// camera moves, and morphing at each ring's edge avoids cracks and popping. Each vertex is displaced by
// the sum of the cascades' displacement (λDx, h, λDz), sampled at a mip matching the mesh spacing so waves
// shorter than the spacing fade instead of aliasing.
#ifndef LAGOON_COMMON_SURFACE_VERTEX_GLSL
#define LAGOON_COMMON_SURFACE_VERTEX_GLSL
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_DISPLACEMENT) uniform sampler2DArray displacement[LAGOON_MAX_CASCADES];
#include "common/cascade_uv.glsl"
#include "common/direct_waves.glsl"
#include "common/wake_fields.glsl"

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec2 v_rest;
// The floor under the vertex (common/shoaling.glsl): x = the random sea's height scale, y = the depth (< 0:
// dry sand). Slow over a triangle, so the fragments interpolate it instead of each reading the table.
layout(location = 3) out vec2 v_floor;
// The random sea's lattices over the floor there (common/shoaling.glsl's Lattices): also slow over a
// triangle, and the fragments need them for every cascade they read.
layout(location = 4) out vec4 v_lattice_phase;
layout(location = 5) out vec4 v_lattice_grad01;
layout(location = 6) out vec4 v_lattice_grad23;

// Also writes the lattices' outputs.
vec2 floor_under(vec2 rest) {
  Lattices l = lattices_at(rest);
  v_lattice_phase = l.phase;
  v_lattice_grad01 = l.grad01;
  v_lattice_grad23 = l.grad23;
  if (!kShoaling) return vec2(1.0);
  vec4 ground = shoal_point(rest).ground;
  return vec2(ground.y, ground.x);
}

vec3 clipmap_displacement(vec2 rest, float spacing) {
  // Constant indices into the sampler array (a loop index would be dynamic descriptor indexing). A cascade
  // whose patch is no larger than the spacing would be read at its 1x1 mip, the patch's mean displacement,
  // which is zero (no k = 0 mode): such lookups are skipped (a third of them on a far-reaching clipmap).
  vec3 d = vec3(0.0);
  const int count = kCascadeCount;  // compiled out beyond it (shared/limits.h)
  Lattices lattices = lattices_at(rest);  // each cascade read where its lattice has moved over the floor
#define LAGOON_CASCADE(c)                                                                                  \
  if (count > c && spacing < frame.cascade_patch[c]) {                                                     \
    float lod = max(0.0, log2(spacing / frame.cascade_texel[c]));                                          \
    d += textureLod(displacement[c], cascade_uvw(lattice_point(rest, lattices, c), c), lod).xyz;          \
  }
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
#undef LAGOON_CASCADE
  d *= sea_over_floor(rest);  // the random sea's depth-limited height (common/shoaling.glsl)
  d += direct_waves_at(rest, 0.0, spacing).displacement;  // models with their own waves
  d.y += wake_at(rest).x;  // the wakes, at the rest position (their own motion is vertical)
  return d;
}

#include "shared/clipmap_morph.h"

#endif
