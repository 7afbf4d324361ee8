// The directional albedo of the glTF specular lobe (shared/pbr.h: GGX, height-correlated Smith, Schlick):
// ∫ f_spec (n·l) dω = f0·A + B, tabulated over n·v and roughness (Karis 2013's split-sum terms, here for
// this lobe rather than fitted: his mobile fit loses 11-19 % too much energy at roughness 0.2-0.6).
// Integrated once, in double, by importance-sampling the GGX normal distribution.
#pragma once
#include <glm/vec2.hpp>

#include <array>

#include "shared/pbr.h"

namespace lagoon::render {

struct DfgTable {
  // Texel (i, j) holds (A, B) at n·v = i/(N − 1), roughness = j/(N − 1); row j after row j − 1.
  std::array<glm::vec2, size_t(LAGOON_DFG_SIZE) * LAGOON_DFG_SIZE> ab{};
  // Bilinear between texel centres, clamped at the edges, as the shaders' sampler reads it.
  glm::vec2 lookup(float n_dot_v, float roughness) const;
};

const DfgTable& dfg_table();

// (A, B) at one (n·v, roughness), by `samples` GGX importance samples (the table's entries).
glm::vec2 integrate_dfg(double n_dot_v, double roughness, int samples);

}  // namespace lagoon::render
