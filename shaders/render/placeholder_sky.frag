#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/placeholder_frame.h"
#include "common/sky.glsl"

layout(std140, binding = 0) uniform Frame { PlaceholderFrame frame; };
layout(location = 0) in vec2 v_ndc;
layout(location = 0) out vec4 out_color;

void main() {
  vec4 far_point = frame.inv_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far_point.xyz / far_point.w - frame.camera_pos.xyz);
  vec3 radiance = sky_radiance(dir, frame.sun_dir.xyz, frame.sun_dir.w, true);
  out_color = vec4(tone_map(radiance, frame.post.x, frame.post.y), 1.0);
}
