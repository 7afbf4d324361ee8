// Suspended particles (engine/render/passes/particles_pass.cpp, shaders/render/particles.*): one candidate
// particle per cell of a world-fixed lattice around the camera, kept or not by a hash and the local density
// from 4-D simplex noise; drawn as camera-facing quads, lit by the underwater tables.
#ifndef LAGOON_SHARED_PARTICLES_H
#define LAGOON_SHARED_PARTICLES_H
#include "shared/interop.h"

#define LAGOON_PARTICLES_SIDE 32  // lattice cells per side around the camera (32³ candidates)

LAGOON_GPU_BEGIN
struct ParticlesPush {
  vec4 lattice;  // xyz = world position of cell (0, 0, 0)'s corner, w = cell size m
  vec4 drift;    // xyz = drift m/s, w = time s
  vec4 look;     // x = share of cells that hold a particle (density · cell³, <= 1), y = diameter m,
                 // z = noise scale m, w = albedo
  uvec4 seed;    // x = seed, yzw unused
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(ParticlesPush, 64);
#endif
#endif
