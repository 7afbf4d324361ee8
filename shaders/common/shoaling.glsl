// The waves' transformation over the floor (shared/shoaling.h; ocean/shoaling.h) where the surface shaders
// sum the water's motion: the floor's row and each direct wave's row at a rest position, interpolated by the
// CPU's own arithmetic (shared/shoaling_math.h). Compiled out (the specialisation constant) when no floor is
// shallow enough to change the sea, which is then the deep sea's code, bit for bit.
// Needs `frame` (FrameUniforms) declared by the includer.
#ifndef LAGOON_COMMON_SHOALING_GLSL
#define LAGOON_COMMON_SHOALING_GLSL
#include "shared/shoaling.h"

layout(constant_id = LAGOON_SURFACE_SPEC_SHOALING) const bool kShoaling = false;
layout(binding = LAGOON_SURFACE_BIND_SHOALING) uniform sampler2D shoaling_table;

#define sh_real float
#define sh_real4 vec4
#include "shared/shoaling_math.h"

struct ShoalPoint {
  vec4 at;      // sh_locate's (sample, fraction, s beyond the table)
  vec4 ground;  // row 0: (depth, the random sea's height scale, the waves' steepness scale, breaking ratio)
};

ShoalPoint shoal_point(vec2 xz) {
  float s = dot(xz - frame.shoaling_axis.xy, frame.shoaling_axis.zw);
  vec4 at = sh_locate(s, frame.shoaling_grid.x, frame.shoaling_grid.y);
  ivec2 i = ivec2(int(at.x), 0);
  return ShoalPoint(at, sh_value(texelFetch(shoaling_table, i, 0), texelFetch(shoaling_table, i + ivec2(1, 0), 0), at));
}

// Direct wave `wave` there: (phase offset, amplitude, k along the axis, amplitude before breaking).
vec4 shoal_wave(ShoalPoint p, int wave, float k_u0) {
  ivec2 i = ivec2(int(p.at.x), wave + 1);
  return sh_wave_value(texelFetch(shoaling_table, i, 0), texelFetch(shoaling_table, i + ivec2(1, 0), 0), p.at, k_u0);
}

// The random sea's (the cascades') height scale over the floor at a rest position: 1 in deep water.
float sea_over_floor(vec2 xz) {
  if (!kShoaling) return 1.0;
  return shoal_point(xz).ground.y;
}

#endif
