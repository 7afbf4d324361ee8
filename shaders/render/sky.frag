#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "common/light.glsl"
#include "common/tonemap.glsl"

layout(std140, binding = LAGOON_SKY_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_colour;  // tone-mapped for display

void main() {
  vec4 far_point = frame.inv_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far_point.xyz / far_point.w - frame.camera_pos.xyz);
  out_colour = vec4(display_encode(frame, sky_radiance(frame, dir, true)), 1.0);
}
