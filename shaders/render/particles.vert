#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"
#include "shared/particles.h"

// Suspended particles (seed 002): the candidates of common/particle_candidate.glsl. Six vertices per
// candidate make a quad facing the camera, at least 1.5 pixels across, its alpha the particle's share of it. Lit as a white target of the
// particle's albedo at its depth and seen through the water (common/underwater.glsl); tone-mapped here.
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(push_constant) uniform Push { ParticlesPush p; };

#include "common/simplex4.glsl"
#include "common/particle_candidate.glsl"
#include "common/tonemap.glsl"
#include "common/underwater.glsl"

layout(location = 0) out vec3 v_colour;  // display-encoded
layout(location = 1) out float v_alpha;
layout(location = 2) out vec2 v_corner;  // -1..1 across the quad

const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void hide() {
  gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped
  v_colour = vec3(0.0);
  v_alpha = 0.0;
  v_corner = vec2(0.0);
}

void main() {
  ParticleCandidate candidate = particle_candidate(gl_VertexIndex / 6, p);
  if (!candidate.kept) { hide(); return; }
  vec3 pos = candidate.position;

  vec3 eye = frame.camera_pos.xyz;
  vec4 clip = frame.view_proj * vec4(pos, 1.0);
  if (clip.w <= 1e-3) { hide(); return; }
  vec3 dir = normalize(pos - eye);
  vec3 side = normalize(abs(dir.y) < 0.99 ? cross(dir, vec3(0.0, 1.0, 0.0)) : cross(dir, vec3(1.0, 0.0, 0.0)));
  vec4 edge = frame.view_proj * vec4(pos + side * p.look.y, 1.0);
  float size_px = length(edge.xy / edge.w - clip.xy / clip.w) * 0.5 * frame.screen.x;
  float radius_px = max(0.5 * size_px, 0.75);
  v_alpha = min(1.0, (0.5 * size_px / radius_px) * (0.5 * size_px / radius_px));

  float d = length(pos - eye);
  float depth = -pos.y, camera_depth = max(-eye.y, 0.0);
  vec3 radiance = (p.look.w * underwater_target(d, depth).rgb + underwater_added(d, 0.5 * (camera_depth + depth), dir.y)) *
                  frame.lut.w;
  v_colour = display_encode(frame, radiance);
  v_corner = kCorners[gl_VertexIndex % 6];
  clip.xy += v_corner * radius_px * 2.0 * frame.screen.zw * clip.w;
  gl_Position = clip;
}
