// The waves' transformation over the floor (shared/shoaling.h; ocean/shoaling.h) where the surface shaders
// sum the water's motion: the floor's row and each direct wave's row at a rest position, interpolated by the
// CPU's own arithmetic (shared/shoaling_math.h). Compiled out (the specialisation constant) when no floor is
// shallow enough to change the sea, which is then the deep sea's code, bit for bit.
// Needs `frame` (FrameUniforms) declared by the includer.
#ifndef LAGOON_COMMON_SHOALING_GLSL
#define LAGOON_COMMON_SHOALING_GLSL
#include "shared/shoaling.h"

// 0: nothing transformed; 1: a profile (one row, straight contours); 2: a grid. A constant, not a branch on
// the frame's uniforms: lavapipe (Mesa 22.3) re-inlines the uniforms a vertex shader branches on at every
// draw and kept each variant (0.17 MiB more resident a frame in `lagoon soak`).
layout(constant_id = LAGOON_SURFACE_SPEC_SHOALING) const int kShoalingMode = 0;
const bool kShoaling = kShoalingMode > 0;
layout(std430, binding = LAGOON_SURFACE_BIND_SHOALING) readonly buffer ShoalingTable { vec4 shoaling_table[]; };

// Sample (u, v) of a layer.
vec4 shoal_texel(int u, int v, int layer) {
  int columns = int(frame.shoaling_grid.y), rows = int(frame.shoaling_grid.z);
  return shoaling_table[(layer * rows + v) * columns + u];
}

#define sh_real float
#define sh_real4 vec4
#include "shared/shoaling_math.h"

struct ShoalPoint {
  ivec4 texels;  // the samples around the point: (u below, u above, v below, v above)
  vec4 at;       // (fraction along u, along v, metres beyond the grid along u, along v)
  vec4 ground;   // layer 0: (depth, the random sea's height scale, the waves' steepness scale, breaking ratio)
};

vec4 shoal_layer(ShoalPoint p, int layer) {
  vec4 a00 = shoal_texel(p.texels.x, p.texels.z, layer);
  vec4 a10 = shoal_texel(p.texels.y, p.texels.z, layer);
  if (kShoalingMode == 1) return a00 + (a10 - a00) * p.at.x;  // one row: contours along v
  vec4 a01 = shoal_texel(p.texels.x, p.texels.w, layer);
  vec4 a11 = shoal_texel(p.texels.y, p.texels.w, layer);
  return sh_bilinear(a00, a10, a01, a11, p.at.x, p.at.y);
}

ShoalPoint shoal_point(vec2 xz) {
  vec2 d = xz - frame.shoaling_axis.xy, u = frame.shoaling_axis.zw;
  vec4 au = sh_locate(dot(d, u), frame.shoaling_grid.x, frame.shoaling_grid.y);
  vec4 av = sh_locate(dot(d, vec2(-u.y, u.x)), frame.shoaling_grid.x, frame.shoaling_grid.z);
  int last_u = int(frame.shoaling_grid.y) - 1, last_v = int(frame.shoaling_grid.z) - 1;
  ShoalPoint p;
  p.texels = ivec4(int(au.x), min(int(au.x) + 1, last_u), int(av.x), min(int(av.x) + 1, last_v));
  p.at = vec4(au.y, av.y, au.z, av.z);
  p.ground = shoal_layer(p, 0);
  return p;
}

// Direct wave `wave` there: (phase offset, amplitude, k along the axis, k across it); k0: its own wavevector.
vec4 shoal_wave(ShoalPoint p, int wave, vec2 k0) {
  vec2 u = frame.shoaling_axis.zw;
  return sh_wave_value(shoal_layer(p, wave + 1), p.at.z, p.at.w, dot(k0, u), dot(k0, vec2(-u.y, u.x)));
}

// The random sea's (the cascades') height scale over the floor at a rest position: 1 in deep water.
float sea_over_floor(vec2 xz) {
  if (!kShoaling) return 1.0;
  return shoal_point(xz).ground.y;
}

#endif
