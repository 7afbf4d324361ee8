// The water surface's shading normal, foam and unresolved slope at a fragment of the clipmap mesh, from
// the cascades' textures. One definition for the surface pass (render/ocean_surface.frag) and its
// ground-truth output (render/ocean_surface_aov.frag), so the check of one against WaveQuery checks both.
// Needs, declared by the includer: `frame` (FrameUniforms), `normal_jacobian[4]` and `jacobian_terms[4]`
// (sampler2DArray), and `v_rest` (the fragment's rest position, metres).
#ifndef LAGOON_COMMON_SURFACE_NORMAL_GLSL
#define LAGOON_COMMON_SURFACE_NORMAL_GLSL
#include "common/cascade_uv.glsl"
#include "common/direct_waves.glsl"
#include "common/wake_fields.glsl"
#define foam_real float
#include "shared/foam_math.h"
#undef foam_real

layout(location = 3) in vec2 v_floor;  // (the random sea's height scale, depth) from the vertices
// The random sea's lattices over the floor from the vertices (common/surface_vertex.glsl).
layout(location = 4) in vec4 v_lattice_phase;
layout(location = 5) in vec4 v_lattice_grad01;
layout(location = 6) in vec4 v_lattice_grad23;

struct SurfaceSample {
  vec3 normal;  // unit, world space, facing the viewer
  float foam;   // 0..1
  float mss;    // mean square slope of the waves the textures do not resolve here (glint width)
  bool dry;     // over a beach's sand above the water: the caller discards the fragment
};

SurfaceSample surface_sample(vec3 to_viewer) {
  // Constant indices into the sampler arrays (a loop index would be dynamic descriptor indexing).
  vec2 slope = vec2(0.0);
  float foam = 0.0;
  vec3 terms = vec3(0.0);  // the Jacobian terms of the whole sea: each cascade's summed
  const int count = kCascadeCount;  // compiled out beyond it (shared/limits.h)
  // Slopes the mips filter away still roughen the surface: their mean square slope widens the glint
  // (Bruneton et al. 2010). Cascade c carries |k| from k_lo to π/(2·texel), with about equal slope variance
  // per octave (saturation range); a mip level `lod` keeps waves up to π/(texel·2^lod), so (lod - 1)
  // octaves of the band are lost.
  float footprint = max(length(dFdx(v_rest)), length(dFdy(v_rest)));
  float mss = frame.glint.x;
  Lattices lattices = Lattices(v_lattice_phase, v_lattice_grad01, v_lattice_grad23);
#define LAGOON_CASCADE(c)                                                                    \
  if (count > c) {                                                                           \
    vec3 uvw = cascade_uvw(lattice_point(v_rest, lattices, c), c);                          \
    vec3 cn = texture(normal_jacobian[c], uvw).xyz;                                          \
    /* the cascade normal is (-sx, 1, -sz); its slope through the lattice's move */          \
    slope += lattice_slope(-cn.xz / max(cn.y, 0.05), lattices, c);                           \
    vec4 jt = texture(jacobian_terms[c], uvw);                                               \
    foam = max(foam, jt.w);                                                                  \
    terms += jt.xyz;                                                                         \
    float k_hi = 1.5707963 / frame.cascade_texel[c];                                         \
    float k_lo = c == 0 ? 6.2831853 / frame.cascade_patch[0] : 1.5707963 / frame.cascade_texel[max(c - 1, 0)]; \
    float octaves = max(log2(k_hi / k_lo), 0.5);                                             \
    float lod = log2(max(footprint, 1e-6) / frame.cascade_texel[c]);                         \
    mss += frame.cascade_mss[c] * clamp((lod - 1.0) / octaves, 0.0, 1.0);                    \
  }
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
#undef LAGOON_CASCADE
  float sea = v_floor.x;  // the random sea's depth-limited height (common/surface_vertex.glsl)
  slope *= sea;
  terms *= sea;
  foam *= min(sea, 1.0);  // the cascades' foam where the floor flattens their waves
  DirectSum direct = direct_waves_at(v_rest, 0.0, footprint);  // models with their own waves
  slope += direct.slope;
  terms += direct.terms;
  // Each cascade keeps its own foam with its decay (the FFT ocean's whitecaps, ocean/whitecaps.h); the whole
  // sea's Jacobian whitens afresh every frame by the threshold rule and for waves summed directly.
  float jacobian = (1.0 + terms.x) * (1.0 + terms.y) - terms.z * terms.z;
  foam = max(foam, foam_made(frame.glint.y, frame.glint.w, jacobian));
  foam = max(foam, direct.breaking);  // waves breaking over the floor
  foam *= frame.whitecaps.x;  // render.effects.foam = false hides the whitecaps
  vec4 wake = wake_at(v_rest);
  slope += wake.yz;
  foam = max(foam, wake_foam(wake.w, v_rest));  // the hulls' trails, drawn as the sea's own foam
  vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));  // slope = (∂h/∂x, ∂h/∂z) summed over cascades
  vec3 v = to_viewer;
  if (dot(n, v) < 0.02) n = normalize(n + v * (0.02 - dot(n, v)));  // back-facing slopes seen at grazing angles
  return SurfaceSample(n, foam, mss, v_floor.y < 0.0);
}

#endif
