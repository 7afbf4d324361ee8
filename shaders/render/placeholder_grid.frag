#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/placeholder_frame.h"
#include "common/sky.glsl"

layout(std140, binding = 0) uniform Frame { PlaceholderFrame frame; };
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 out_color;

void main() {
  vec3 n = normalize(v_normal);
  vec3 v = normalize(frame.camera_pos.xyz - v_world);
  vec3 l = frame.sun_dir.xyz;
  float cos_v = max(dot(n, v), 0.0);
  // Schlick's Fresnel for water (F0 = 0.02).
  float fresnel = 0.02 + 0.98 * pow(1.0 - cos_v, 5.0);
  vec3 reflected = sky_radiance(reflect(-v, n), l, frame.sun_dir.w, false);
  vec3 water = vec3(0.01, 0.05, 0.08) * frame.sun_dir.w * (0.3 + 0.7 * max(dot(n, l), 0.0));
  vec3 h = normalize(l + v);
  vec3 specular = vec3(1.0, 0.9, 0.75) * 6.0 * frame.sun_dir.w * pow(max(dot(n, h), 0.0), 400.0);
  vec3 radiance = mix(water, reflected, fresnel) + specular * fresnel;
  // Fade to the sky at the horizon so the grid's far edge does not show.
  float dist = length(v_world.xz - frame.camera_pos.xz);
  float fog = smoothstep(0.5, 1.0, dist / frame.grid.x);
  radiance = mix(radiance, sky_radiance(-v, l, frame.sun_dir.w, false), fog);
  out_color = vec4(tone_map(radiance, frame.post.x, frame.post.y), 1.0);
}
