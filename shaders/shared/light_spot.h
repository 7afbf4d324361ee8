// A spot light's cone, as KHR_lights_punctual's reference implementation has it: the irradiance is scaled by
// clamp(cos(angle from the axis)·scale + offset, 0, 1)², with scale = 1 / (cos inner − cos outer) and
// offset = −cos outer · scale; full inside the inner cone, none outside the outer. A point light has scale 0
// and offset 1. Shared by the shaders (common/light.glsl) and the C++ that fills the lights
// (render/frame_uniforms.cpp) and checks them.
#ifndef LAGOON_SHARED_LIGHT_SPOT_H
#define LAGOON_SHARED_LIGHT_SPOT_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
// `from_light`: unit vector from the light to the lit point.
LAGOON_FN float spot_attenuation(vec3 axis, float scale, float offset, vec3 from_light) {
  float t = clamp(dot(axis, from_light) * scale + offset, 0.0f, 1.0f);
  return t * t;
}

// (scale, offset) of a cone between `cos_inner` and `cos_outer` (cos_inner > cos_outer).
LAGOON_FN vec2 spot_cone(float cos_inner, float cos_outer) {
  float scale = 1.0f / max(cos_inner - cos_outer, 1e-3f);
  return vec2(scale, -cos_outer * scale);
}
LAGOON_GPU_END

#endif
