#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"

// render.shading's classic modes (ocean_surface_classic.frag): the surface's vertices
// (common/surface_vertex.glsl). For gouraud (seed 001 §2.1) each is lit by Blinn-Phong with the normal at the
// vertex, and the rasteriser interpolates the colour across the triangle.
layout(constant_id = LAGOON_SURFACE_SPEC_SHADING) const int kShading = 1;
#include "common/surface_vertex.glsl"
#include "common/light.glsl"
layout(binding = LAGOON_SURFACE_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(std430, binding = LAGOON_SURFACE_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };
#include "common/classic_light.glsl"

layout(location = 2) out vec3 v_colour;

// The summed cascades' normal at a rest position, filtered to the mesh's spacing as the displacement is.
vec3 vertex_normal(vec2 rest, float spacing) {
  vec2 slope = vec2(0.0);
  const int count = kCascadeCount;
  Lattices lattices = lattices_at(rest);  // each cascade read where its lattice has moved over the floor
#define LAGOON_CASCADE(c)                                                                   \
  if (count > c && spacing < frame.cascade_patch[c]) {                                     \
    float lod = max(0.0, log2(spacing / frame.cascade_texel[c]));                          \
    vec3 cn = textureLod(normal_jacobian[c], cascade_uvw(lattice_point(rest, lattices, c), c), lod).xyz; \
    slope += lattice_slope(-cn.xz / max(cn.y, 0.05), lattices, c);                         \
  }
  LAGOON_CASCADE(0)
  LAGOON_CASCADE(1)
  LAGOON_CASCADE(2)
  LAGOON_CASCADE(3)
#undef LAGOON_CASCADE
  slope *= sea_over_floor(rest);  // the random sea's depth-limited height (common/shoaling.glsl)
  slope += direct_waves_at(rest, 0.0, spacing).slope;
  slope += wake_at(rest).yz;
  return normalize(vec3(-slope.x, 1.0, -slope.y));
}

void main() {
  ClipmapVertex v = clipmap_indexed_vertex(gl_VertexIndex, frame.camera_pos.xz, frame.grid, frame.clipmap);
  v_rest = v.rest;
  v_floor = floor_under(v.rest);
  v_world = clipmap_displaced(v);
  v_colour = vec3(0.0);
  if (kShading == 2)
    v_colour = classic_light(v_world, vertex_normal(v.rest, v.spacing), normalize(frame.camera_pos.xyz - v_world));
  gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
