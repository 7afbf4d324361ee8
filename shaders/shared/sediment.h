// Sediment stirred up from the floor (issue 14, docs/physics.md "Sediment"): the clouds the frame draws as
// turbidity (compute/physics/sediment.h makes them; shaders/common/sediment.glsl draws them), in a storage
// buffer the host writes each frame. The optics both sides evaluate is in shared/sediment_math.h.
#ifndef LAGOON_SHARED_SEDIMENT_H
#define LAGOON_SHARED_SEDIMENT_H
#include "shared/interop.h"

// Clouds the frame draws: each costs every water pixel a few exponentials, so the host keeps the densest.
#define LAGOON_MAX_SEDIMENT_PUFFS 64
// Grains drawn of one cloud at most (render/sediment_grains.vert).
#define LAGOON_SEDIMENT_MAX_GRAINS 64
// A cloud adds nothing to a ray that passes further than √20 σ from its centre (below e^-10 of its peak,
// shared/sediment_math.h): the square of that reach, in σ².
#define LAGOON_SEDIMENT_REACH2_SIGMA2 20.0
// The clouds are also tested in groups of this many, consecutive in the buffer, each against its own reach
// box: a stream of clouds along a vehicle's track spans the view, while each group is a stretch of it.
#define LAGOON_SEDIMENT_GROUP 8
#define LAGOON_SEDIMENT_GROUPS (LAGOON_MAX_SEDIMENT_PUFFS / LAGOON_SEDIMENT_GROUP)
// The buffer, in the surface shaders' set (shared/surface.h numbering).
#define LAGOON_SURFACE_BIND_SEDIMENT 18
// Specialisation constant of the shaders that include common/sediment.glsl: the clouds compiled in (1) or
// not (nothing in the scene stirs the floor); lavapipe pays for a loop it skips.
#define LAGOON_SURFACE_SPEC_SEDIMENT 5

LAGOON_GPU_BEGIN
// One cloud: an isotropic Gaussian of sediment (physics/sediment.h, SedimentPuff).
struct SedimentPuffGpu {
  vec4 centre_sigma;  // xyz world m, w = standard deviation m
  vec4 strength;  // x = mass x mass-specific attenuation (m²): its optical depth integrated over a plane;
                  // y = grains drawn of it (render/passes/sediment_grains_pass.h), z = its release's id (uint
                  // bits: the same grains each frame), w unused
};

struct SedimentHeader {
  vec4 colour;  // rgb = the particles' albedo (linear), w = number of puffs that follow
  // xyz: a box holding every cloud's reach (centre ± √20 σ): a ray segment that misses it passes every cloud
  // (sed_segment_meets_box), so a pixel far from the clouds skips the loop over them. Empty (lo > hi)
  // without clouds.
  vec4 box_lo, box_hi;
  // The same for clouds LAGOON_SEDIMENT_GROUP g .. g + LAGOON_SEDIMENT_GROUP - 1 (those there are).
  vec4 group_lo[LAGOON_SEDIMENT_GROUPS], group_hi[LAGOON_SEDIMENT_GROUPS];
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(SedimentPuffGpu, 32);
LAGOON_CHECK_SIZE(SedimentHeader, 48 + 32 * LAGOON_SEDIMENT_GROUPS);
#endif
#endif
