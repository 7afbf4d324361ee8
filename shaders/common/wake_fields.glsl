// The wakes' dynamic layer (engine/render/passes/wakes_pass.h) where the surface shaders sum the water's
// motion: its height and slopes at a world point, added to the cascades'. Compiled out (the specialisation
// constant) when no vehicle makes a wake: on lavapipe even a skipped branch costs its work.
// Needs `frame` (FrameUniforms) declared by the includer.
#ifndef LAGOON_COMMON_WAKE_FIELDS_GLSL
#define LAGOON_COMMON_WAKE_FIELDS_GLSL
#include "shared/surface.h"

layout(constant_id = LAGOON_SURFACE_SPEC_WAKES) const bool kWakes = false;
layout(binding = LAGOON_SURFACE_BIND_WAKES) uniform sampler2D wake_fields;

// (h, dh/dx, dh/dz, foam trail coverage) at world (x, z); zero outside the layer's window, whose border has
// brought it to rest. Cell a holds x = a · cell, and a sampler puts texel i at (i + 0.5) / n: hence the half
// cell.
vec4 wake_at(vec2 xz) {
  if (!kWakes) return vec4(0.0);
  vec2 inside = xz - frame.wakes.xy;
  if (any(lessThan(inside, vec2(0.0))) || any(greaterThanEqual(inside, frame.wakes.zz))) return vec4(0.0);
  return textureLod(wake_fields, (xz + 0.5 * frame.wakes.w) / frame.wakes.z, 0.0);
}

#include "common/simplex4.glsl"

// A trail's coverage as it shows: churned and broken into patches (simplex noise about 1 m across, drifting
// slowly), solid where fresh wash saturates it, patchy as it fades.
float wake_foam(float coverage, vec2 xz) {
  if (!kWakes || coverage <= 0.0) return 0.0;
  float n = simplex4(vec4(xz * 1.1, 0.0, frame.camera_pos.w * 0.25), 7u);
  return smoothstep(0.1, 0.9, coverage * (1.0 + 0.45 * n));
}

#endif
