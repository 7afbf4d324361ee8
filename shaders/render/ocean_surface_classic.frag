#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

// render.shading's classic modes (seed 001 §2.1), for comparing surface models the way the document draws
// them: Blinn-Phong with the sun, the scene's point lights and the sky's ambient light; no reflection,
// refraction, foam or haze. blinn-phong lights every pixel with the cascades' normal (Phong's interpolated
// normal), gouraud takes the colour lit at the vertices (ocean_surface_classic.vert), flat lights each
// triangle with its own face normal.
layout(constant_id = LAGOON_SURFACE_SPEC_SHADING) const int kShading = 1;
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_JACOBIAN_TERMS) uniform sampler2DArray jacobian_terms[LAGOON_MAX_CASCADES];
layout(std430, binding = LAGOON_SURFACE_BIND_LIGHTS) readonly buffer Lights { PointLightGpu point_lights[]; };
#include "common/classic_light.glsl"

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_rest;
layout(location = 2) in vec3 v_colour;  // lit at the vertices (gouraud only)
layout(location = 0) out vec4 out_colour;

#include "common/surface_normal.glsl"

void main() {
  vec3 v = normalize(frame.camera_pos.xyz - v_world);
  vec3 colour;
  if (kShading == 2) {
    colour = v_colour;
  } else if (kShading == 3) {
    // v_world is linear across a triangle: its screen derivatives span the triangle's plane.
    vec3 n = normalize(cross(dFdy(v_world), dFdx(v_world)));
    if (dot(n, v) < 0.0) n = -n;
    colour = classic_light(v_world, n, v);
  } else {
    colour = classic_light(v_world, surface_sample(v).normal, v);
  }
  out_colour = vec4(display_encode(frame, colour), 1.0);
}
