// The dynamic wave layer (issue 14, docs/physics.md "Wakes"): push constants, sources and binding slots of
// its passes (shaders/ocean/dynamic_*.comp, compute/ocean/gpu/dynamic_layer_gpu.*). The physics both sides
// evaluate is in shared/dynamic_layer_math.h.
#ifndef LAGOON_SHARED_DYNAMIC_LAYER_H
#define LAGOON_SHARED_DYNAMIC_LAYER_H
#include "shared/interop.h"

#define LAGOON_DYNAMIC_MAX_SOURCES 16
// Evolution in the spectral domain (dynamic_evolve.comp): the transformed state in, the evolved out.
#define LAGOON_DYNAMIC_BIND_SPECTRUM 0
#define LAGOON_DYNAMIC_BIND_EVOLVED 1
#define LAGOON_DYNAMIC_BIND_SOURCES 2
// Specialisation: the evolution's pass over the Nyquist lines (bool; dynamic_evolve.comp), and whether the
// border's pass writes the renderer's fields image (bool; dynamic_sponge.comp).
#define LAGOON_DYNAMIC_SPEC_NYQUIST 0
#define LAGOON_DYNAMIC_SPEC_FIELDS 1
// The sponge, the foam and the fields (dynamic_sponge.comp): the state after the inverse transform in, the
// damped state, the foam (float per cell; the last step's in, this step's out, ping-pong so the trails can
// spread from their neighbours) and the image (h, dh/dx, dh/dz, foam) out. The
// step's sources are at LAGOON_DYNAMIC_BIND_SOURCES, as in the evolution.
#define LAGOON_DYNAMIC_BIND_RAW 0
#define LAGOON_DYNAMIC_BIND_STATE 1
#define LAGOON_DYNAMIC_BIND_FIELDS 3
#define LAGOON_DYNAMIC_BIND_FOAM 4
#define LAGOON_DYNAMIC_BIND_FOAM_IN 5

LAGOON_GPU_BEGIN
// A pressure patch on the water: a hull's footprint (a Gaussian of its length and beam) moving at
// `velocity` from `centre` at the step's start.
struct DynamicSource {
  vec2 centre;       // world (x, z), m
  vec2 velocity;     // m/s
  vec2 sigma;        // along and across the heading, m
  vec2 along;        // the heading as a unit vector in (x, z), compass::toward
  float depression;  // m: the still-water depression at its centre (pressure / (ρ g))
  float depth;       // m below the surface (0 = at it): its pattern is filtered by exp(-k depth)
  float foam_per_s;  // how fast foam builds behind its stern (and at 0.3 of that at its bow)
  float pad0;
};

struct DynamicPush {
  ivec2 origin;  // the window's first cell (world cell index); cell a holds world x = a · cell
  uint n;        // cells per side
  uint source_count;
  float cell;          // m
  float dt;            // s, this step
  uint substeps;       // the forcing is advanced in this many parts of the step
  float gravity;       // m/s²
  float depth;         // m, of the water (<= 0: deep)
  float decay_per_s;   // damping of every mode
  float sponge_cells;  // width of the absorbing border
  float sponge_per_s;  // its strongest damping rate, at the edge
  uint foam_sources;   // the first this many sources leave foam (foam_per_s > 0), the others none
  float foam_decay;    // the factor the foam keeps over this step
  float foam_spread;   // D dt / cell² of the trails' diffusion (dl_foam_spread)
  uint pad2;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(DynamicSource, 48);
LAGOON_CHECK_SIZE(DynamicPush, 64);
#endif
#endif
