#version 450
#extension GL_GOOGLE_include_directive : require
// The suspended particles' candidates (common/particle_candidate.glsl) as the particles' vertex shader places
// them: (position, kept) per candidate, for the push the pass builds.
#include "common/simplex4.glsl"
#include "common/particle_candidate.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Out { vec4 candidates[]; };
layout(push_constant) uniform Push { ParticlesPush p; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE)) return;
  ParticleCandidate c = particle_candidate(int(i), p);
  candidates[i] = vec4(c.position, c.kept ? 1.0 : 0.0);
}
