// A particle in the water drawn as a quad facing the camera (the suspended particles, render/particles.vert;
// the sediment's grains, render/sediment_grains.vert): at least 1.5 pixels across, its alpha the particle's
// share of it, lit as a target of the particle's albedo at its depth and seen through the water
// (common/underwater.glsl), tone-mapped here. Six vertices per particle; render/particles.frag draws the spot.
// Needs `frame` (FrameUniforms), common/tonemap.glsl and common/underwater.glsl included first.
#ifndef LAGOON_COMMON_PARTICLE_QUAD_GLSL
#define LAGOON_COMMON_PARTICLE_QUAD_GLSL

layout(location = 0) out vec3 v_colour;  // display-encoded
layout(location = 1) out float v_alpha;
layout(location = 2) out vec2 v_corner;  // -1..1 across the quad

const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void particle_hide() {
  gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped
  v_colour = vec3(0.0);
  v_alpha = 0.0;
  v_corner = vec2(0.0);
}

// This vertex (gl_VertexIndex % 6) of the quad of a particle of `diameter` m at `pos` with `albedo`.
void particle_emit(vec3 pos, float diameter, vec3 albedo) {
  vec3 eye = frame.camera_pos.xyz;
  vec4 clip = frame.view_proj * vec4(pos, 1.0);
  if (clip.w <= 1e-3) { particle_hide(); return; }
  vec3 dir = normalize(pos - eye);
  // The diameter measured along the camera's right axis (clip x's row: at right angles to the view axis), so
  // the edge lies at the particle's own view depth and the quad is the pinhole's D f / z across. A side
  // across the line of sight instead tilts toward the view axis for a particle off to the side: near the
  // camera's plane its edge crossed it and the quad grew to cover the frame (tests/render/
  // particles_render_test.cpp).
  mat4 m = frame.view_proj;
  vec3 side = normalize(vec3(m[0][0], m[1][0], m[2][0]));
  vec4 edge = frame.view_proj * vec4(pos + side * diameter, 1.0);
  float size_px = length(edge.xy / edge.w - clip.xy / clip.w) * 0.5 * frame.screen.x;
  float radius_px = max(0.5 * size_px, 0.75);
  v_alpha = min(1.0, (0.5 * size_px / radius_px) * (0.5 * size_px / radius_px));

  float d = length(pos - eye);
  float depth = -pos.y, camera_depth = max(-eye.y, 0.0);
  vec3 radiance = (albedo * underwater_target(d, depth).rgb + underwater_added(d, 0.5 * (camera_depth + depth), dir.y)) *
                  frame.lut.w;
  v_colour = display_encode(frame, radiance);
  v_corner = kCorners[gl_VertexIndex % 6];
  clip.xy += v_corner * radius_px * 2.0 * frame.screen.zw * clip.w;
  gl_Position = clip;
}

#endif
