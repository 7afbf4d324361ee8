#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/caustics.h"

// One ray per invocation, LAGOON_CAUSTICS_RAYS² per source cell of the sea's surface: the sun's ray through
// the displaced surface there, refracted by its normal, carries its share of the flat-surface irradiance
// down to each slice's depth, where it is splatted bilinearly (fixed point, atomics). Every ray carries the
// same energy, so what arrives over the window is what left the surface: under a flat sea each destination
// cell gets exactly 1.
layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = LAGOON_CAUSTICS_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_CAUSTICS_BIND_DISPLACEMENT) uniform sampler2DArray displacement[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_CAUSTICS_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(std430, binding = LAGOON_CAUSTICS_BIND_ACCUM) buffer Accum { uint energy[]; };
layout(push_constant) uniform Push { CausticsPush p; };

#include "common/cascade_uv.glsl"
#include "common/wake_fields.glsl"
#include "common/direct_waves.glsl"

void splat(int slice, ivec2 cell, uint amount) {
  int n = int(frame.caustics.w);  // this frame's cells per side: the map's first n x n
  if (amount == 0u || any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(n)))) return;
  atomicAdd(energy[(slice * n + cell.y) * n + cell.x], amount);
}

void main() {
  ivec2 s = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(s, ivec2(p.source.zw) * LAGOON_CAUSTICS_RAYS))) return;
  float cell = frame.caustics.z;
  vec2 rest = p.source.xy + (vec2(s) + 0.5) * (cell / float(LAGOON_CAUSTICS_RAYS));
  // The cascades filtered to the cell size: shorter waves would alias into the pattern.
  vec3 d = vec3(0.0);
  vec2 slope = vec2(0.0);
  const int count = kCascadeCount;  // compiled out beyond it (shared/limits.h)
  Lattices lattices = lattices_at(rest);  // each cascade read where its lattice has moved over the floor
#define LAGOON_CASCADE(c)                                                         \
  if (count > c && cell < frame.cascade_patch[c]) {                               \
    float lod = max(0.0, log2(cell / frame.cascade_texel[c]));                    \
    vec3 uvw = cascade_uvw(lattice_point(rest, lattices, c), c);                  \
    d += textureLod(displacement[c], uvw, lod).xyz;                               \
    vec3 cn = textureLod(normal_jacobian[c], uvw, lod).xyz;                       \
    slope += lattice_slope(-cn.xz / max(cn.y, 0.05), lattices, c);                \
  }
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
#undef LAGOON_CASCADE
  float sea = sea_over_floor(rest);  // the random sea's depth-limited height (common/shoaling.glsl)
  d *= sea;
  slope *= sea;
  DirectSum direct = direct_waves_at(rest, 0.0, cell);
  d += direct.displacement;
  slope += direct.slope;
  vec3 wake = wake_at(rest).xyz;
  d.y += wake.x;
  slope += wake.yz;
  vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
  vec3 t = refract(-frame.sun_dir.xyz, n, 1.0 / frame.sun_dir.w);
  if (t.y > -1e-3) return;  // the sun at or below this facet's horizon
  for (int slice = 0; slice < LAGOON_CAUSTICS_SLICES; ++slice) {
    vec2 hit = rest + d.xz + t.xz * ((frame.caustic_depths[slice] + d.y) / -t.y);
    vec2 f = (hit - frame.caustics.xy) / cell - 0.5;  // cell centres at integers
    ivec2 c0 = ivec2(floor(f));
    vec2 w = f - vec2(c0);
    // Weights in fixed point that add up to exactly one ray (1/RAYS² of a source cell).
    const uint one = uint(LAGOON_CAUSTICS_ONE) / uint(LAGOON_CAUSTICS_RAYS * LAGOON_CAUSTICS_RAYS);
    uint w00 = uint((1.0 - w.x) * (1.0 - w.y) * float(one));
    uint w10 = uint(w.x * (1.0 - w.y) * float(one));
    uint w01 = uint((1.0 - w.x) * w.y * float(one));
    uint w11 = one - min(w00 + w10 + w01, one);
    splat(slice, c0, w00);
    splat(slice, c0 + ivec2(1, 0), w10);
    splat(slice, c0 + ivec2(0, 1), w01);
    splat(slice, c0 + ivec2(1, 1), w11);
  }
}
