#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/surface.h"
#include "shared/particles.h"

// Suspended particles (seed 002): the candidates of common/particle_candidate.glsl, each drawn as
// common/particle_quad.glsl's quad with the scene's albedo.
layout(std140, binding = LAGOON_SURFACE_BIND_FRAME) uniform Frame { FrameUniforms frame; };
layout(binding = LAGOON_SURFACE_BIND_UW_TARGET) uniform sampler2D uw_target;
layout(binding = LAGOON_SURFACE_BIND_UW_DOWN) uniform sampler2D uw_down;
layout(binding = LAGOON_SURFACE_BIND_UW_UP) uniform sampler2D uw_up;
layout(push_constant) uniform Push { ParticlesPush p; };

#include "common/simplex4.glsl"
#include "common/particle_candidate.glsl"
#include "common/tonemap.glsl"
#include "common/underwater.glsl"
#include "common/particle_quad.glsl"

void main() {
  ParticleCandidate candidate = particle_candidate(gl_VertexIndex / 6, p);
  if (!candidate.kept) { particle_hide(); return; }
  particle_emit(candidate.position, p.look.y, vec3(p.look.w));
}
