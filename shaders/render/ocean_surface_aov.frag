#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"

// Ground truth of the water surface per pixel, for checks and datasets: the shading normal the surface
// pass uses (common/surface_normal.glsl) and the world point it is evaluated at. Float targets, no
// lighting, no tone map. Where no water is drawn the targets keep their clear value (coverage 0).
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_NORMAL_JACOBIAN) uniform sampler2DArray normal_jacobian[LAGOON_MAX_CASCADES];
layout(binding = LAGOON_SURFACE_BIND_JACOBIAN_TERMS) uniform sampler2DArray jacobian_terms[LAGOON_MAX_CASCADES];

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_rest;
layout(location = 0) out vec4 out_normal_foam;   // xyz unit normal (world), w = foam 0..1
layout(location = 1) out vec4 out_world;         // xyz world point (m), w = 1 (coverage)

#include "common/surface_normal.glsl"

void main() {
  SurfaceSample s = surface_sample(normalize(frame.camera_pos.xyz - v_world));
  out_normal_foam = vec4(s.normal, s.foam);
  out_world = vec4(v_world, 1.0);
  if (s.dry) discard;  // a beach's sand above the water (common/shoaling.glsl), after the derivatives
}
