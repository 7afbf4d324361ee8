// The suspended particles' candidates as the particles' vertex shader places them (common/
// particle_candidate.glsl, through tests/shaders/gpu/particles_eval.comp), for the push the particles' pass
// builds from `scene`: (position, 1 if drawn else 0) per candidate of the LAGOON_PARTICLES_SIDE³ lattice.
#pragma once
#include <glm/vec4.hpp>
#include <vector>

#include "scene/scene.h"
#include "shared/particles.h"
#include "vk/context.h"

namespace lagoon::test {

inline constexpr uint32_t kParticleCandidates =
    LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE * LAGOON_PARTICLES_SIDE;

std::vector<glm::vec4> particle_candidates(vk::Context& ctx, const scene::Scene& scene);

}  // namespace lagoon::test
