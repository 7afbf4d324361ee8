#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"

// A lens cutting the water surface: the frame drawn from above is already in the target; here every pixel
// whose point on the near plane lies below the displaced surface takes the frame drawn from below instead,
// so the image splits along the surface as it crosses the lens, not along a horizontal line. A thin dark
// meniscus (water clinging to the lens) marks the split on the water's side; the pixels the line crosses
// on the water's side blend by how much of them is under it.
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_DISPLACEMENT) uniform sampler2DArray displacement[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_BELOW_COLOR) uniform sampler2D below_colour;
layout(binding = LAGOON_SURFACE_BIND_BELOW_DEPTH) uniform sampler2D below_depth;

#include "common/cascade_uv.glsl"
#include "common/wake_fields.glsl"
#include "common/direct_waves.glsl"

layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_colour;

vec3 displacement_at(vec2 rest, inout ShoalCell floor_cell) {
  vec3 d = vec3(0.0);
  const int count = kCascadeCount;  // compiled out beyond it (shared/limits.h)
  Lattices lattices = lattices_at(rest);  // each cascade read where its lattice has moved over the floor
#define LAGOON_CASCADE(c) \
  if (count > c) d += textureLod(displacement[c], cascade_uvw(lattice_point(rest, lattices, c), c), 0.0).xyz;
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
#undef LAGOON_CASCADE
  d *= sea_over_floor_cached(rest, floor_cell);  // the random sea's depth-limited height (common/shoaling.glsl)
  d += direct_waves_at(rest, 0.0, 0.0).displacement;
  d.y += wake_at(rest).x;
  return d;
}

// The height of the displaced surface above (x, z): the surface point that the waves move there, found by
// fixed-point iteration on the horizontal displacement (as WaveQuery does).
float water_height(vec2 xz) {
  ShoalCell floor_cell;
  floor_cell.texels = ivec4(-1);
  vec2 rest = xz;
  vec3 d = displacement_at(rest, floor_cell);
  for (int i = 0; i < 3; ++i) {
    rest = xz - d.xz;
    d = displacement_at(rest, floor_cell);
  }
  return d.y;
}

void main() {
  vec4 n = frame.inv_view_proj * vec4(v_ndc, 0.0, 1.0);  // on the near plane
  vec3 lens = n.xyz / n.w;
  float below = water_height(lens.xz) - lens.y;  // > 0 under the water
  float pixel = max(length(dFdy(lens)), length(dFdx(lens)));  // a pixel's size on the near plane
  float across = fwidth(below);  // how much `below` changes over a pixel (before any lane discards)
  if (below <= 0.0) discard;
  // The share of the pixel under the water, blended over the frame from above. Only the wet side blends (a
  // pixel whose centre is dry keeps the view from above and its depth), so where two devices round `below`
  // differently a pixel on the line changes by half its contrast at most, not all of it.
  float coverage = clamp(0.5 + below / max(across, 1e-9), 0.5, 1.0);
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec3 colour = texelFetch(below_colour, texel, 0).rgb;
  // The meniscus: 1.5 pixels of darkened water along the line.
  float meniscus = 1.0 - smoothstep(0.5 * pixel, 1.5 * pixel, below);
  out_colour = vec4(colour * (1.0 - 0.6 * meniscus), coverage);
  gl_FragDepth = texelFetch(below_depth, texel, 0).r;
}
