// The waves' transformation over the floor (shared/shoaling.h; ocean/shoaling.h) where the surface shaders
// sum the water's motion: the floor's row and each direct wave's row at a rest position, interpolated by the
// CPU's own arithmetic (shared/shoaling_math.h). Compiled out (the specialisation constant) when no floor is
// shallow enough to change the sea, which is then the deep sea's code, bit for bit.
// Needs `frame` (FrameUniforms) declared by the includer.
#ifndef LAGOON_COMMON_SHOALING_GLSL
#define LAGOON_COMMON_SHOALING_GLSL
#include "shared/shoaling.h"
#include "common/cascade_uv.glsl"

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
#define sh_real2 vec2
#define sh_real4 vec4
#include "shared/shoaling_math.h"

struct ShoalPoint {
  ivec4 texels;  // the samples around the point: (u below, u above, v below, v above)
  vec4 at;       // (fraction along u, along v, metres beyond the grid along u, along v)
  vec4 ground;   // layer 0: (depth, the random sea's height scale, the waves' steepness scale, breaking ratio)
};

// The samples of a layer around a point: one row's two (a00, a10) or the grid's four.
struct ShoalCell {
  ivec4 texels;  // as ShoalPoint's; -1: nothing loaded yet
  vec4 a00, a10, a01, a11;
};

ShoalCell shoal_cell(ivec4 texels, int layer) {
  ShoalCell c;
  c.texels = texels;
  c.a00 = shoal_texel(texels.x, texels.z, layer);
  c.a10 = shoal_texel(texels.y, texels.z, layer);
  c.a01 = c.a11 = vec4(0.0);
  if (kShoalingMode == 2) {
    c.a01 = shoal_texel(texels.x, texels.w, layer);
    c.a11 = shoal_texel(texels.y, texels.w, layer);
  }
  return c;
}

vec4 shoal_value(ShoalCell c, vec4 at) {
  if (kShoalingMode == 1) return c.a00 + (c.a10 - c.a00) * at.x;  // one row: contours along v
  return sh_bilinear(c.a00, c.a10, c.a01, c.a11, at.x, at.y);
}

vec4 shoal_layer(ShoalPoint p, int layer) {
  return shoal_value(shoal_cell(p.texels, layer), p.at);
}

// Where `xz` lies in the table: the samples around it and the fractions (ShoalPoint's texels and at).
void shoal_locate(vec2 xz, out ivec4 texels, out vec4 at) {
  vec2 d = xz - frame.shoaling_axis.xy, u = frame.shoaling_axis.zw;
  vec4 au = sh_locate(dot(d, u), frame.shoaling_grid.x, frame.shoaling_grid.y);
  vec4 av = sh_locate(dot(d, vec2(-u.y, u.x)), frame.shoaling_grid.x, frame.shoaling_grid.z);
  int last_u = int(frame.shoaling_grid.y) - 1, last_v = int(frame.shoaling_grid.z) - 1;
  texels = ivec4(int(au.x), min(int(au.x) + 1, last_u), int(av.x), min(int(av.x) + 1, last_v));
  at = vec4(au.y, av.y, au.z, av.z);
}

ShoalPoint shoal_point(vec2 xz) {
  ShoalPoint p;
  shoal_locate(xz, p.texels, p.at);
  p.ground = shoal_layer(p, 0);
  return p;
}

// Direct wave `wave` there: (phase offset, amplitude, k along the axis, k across it); k0: its own wavevector.
vec4 shoal_wave(ShoalPoint p, int wave, vec2 k0) {
  vec2 u = frame.shoaling_axis.zw;
  return sh_wave_value(shoal_layer(p, wave + 1), p.at.z, p.at.w, dot(k0, u), dot(k0, vec2(-u.y, u.x)));
}

// The random sea's lattices over the floor at a rest position (shared/shoaling_math.h): each cascade's phase
// offset φ (phase[c]) and ∇φ (grad01: cascades 0 and 1, grad23: 2 and 3). All vec4 so that the surface's
// vertices can hand them to its fragments.
struct Lattices {
  vec4 phase;
  vec4 grad01, grad23;
};

Lattices lattices_at(vec2 rest) {
  Lattices l = Lattices(vec4(0.0), vec4(0.0), vec4(0.0));
  if (!kShoaling) return l;
  ivec4 texels;
  vec4 at;
  shoal_locate(rest, texels, at);
  vec2 u = frame.shoaling_axis.zw, v = vec2(-u.y, u.x);
  int base = int(frame.shoaling_grid.w);
  vec2 grad[4] = vec2[4](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
  for (int c = 0; c < kCascadeCount; ++c) {
    vec2 k0 = frame.shoaling_lattice[c].xy;
    vec4 s = sh_wave_value(shoal_value(shoal_cell(texels, base + c), at), at.z, at.w, dot(k0, u), dot(k0, v));
    l.phase[c] = s.x;
    grad[c] = s.z * u + s.w * v - k0;  // zeros for a cascade not moved (its layer is zeros)
  }
  l.grad01 = vec4(grad[0], grad[1]);
  l.grad23 = vec4(grad[2], grad[3]);
  return l;
}

// Where cascade c's textures are read for the rest position.
vec2 lattice_point(vec2 rest, Lattices l, int c) {
  if (!kShoaling) return rest;
  return sh_lattice_point(rest, l.phase[c], frame.shoaling_lattice[c]);
}

// A slope of cascade c read at its moved point, as the surface's at the rest position.
vec2 lattice_slope(vec2 slope, Lattices l, int c) {
  if (!kShoaling) return slope;
  vec2 grad = c == 0 ? l.grad01.xy : c == 1 ? l.grad01.zw : c == 2 ? l.grad23.xy : l.grad23.zw;
  return sh_lattice_slope(slope, grad, frame.shoaling_lattice[c]);
}

// The random sea's (the cascades') height scale over the floor at a rest position: 1 in deep water.
float sea_over_floor(vec2 xz) {
  if (!kShoaling) return 1.0;
  return shoal_point(xz).ground.y;
}

// The same for lookups that mostly stay in one cell of the table (the waterline's fixed point, four at a
// pixel within a metre): the cell's samples are read again only when the point leaves it, in a loop rather
// than an `if` because lavapipe skips a loop no lane enters but runs both sides of an `if`. The value is
// sea_over_floor()'s, bit for bit. Start with `cell.texels = ivec4(-1)`.
float sea_over_floor_cached(vec2 xz, inout ShoalCell cell) {
  if (!kShoaling) return 1.0;
  ivec4 texels;
  vec4 at;
  shoal_locate(xz, texels, at);
  for (int load = any(notEqual(texels, cell.texels)) ? 1 : 0; load > 0; --load) cell = shoal_cell(texels, 0);
  return shoal_value(cell, at).y;
}

#endif
