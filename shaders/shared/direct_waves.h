// Waves evaluated directly (docs/models.md, "Evaluated directly"): models gerstner and sines with an explicit
// list of waves. The list as the shaders read it, in the frame's uniforms (shared/frame.h) and in the step's
// buffer (shaders/ocean/direct_waves.comp, compute/ocean/gpu/direct_waves_gpu.*). The sum itself is in
// common/direct_waves.glsl; one wave's profile, shared with the CPU reference, in shared/direct_waves_math.h.
#ifndef LAGOON_SHARED_DIRECT_WAVES_H
#define LAGOON_SHARED_DIRECT_WAVES_H
#include "shared/interop.h"

#define LAGOON_DIRECT_MAX_WAVES 64
// The step (direct_waves.comp): the waves in, the ocean's three images out (the first cascade's layer).
// Specialisation constant of the shaders that include common/direct_waves.glsl: how many waves the sum has
// (0: none; the step says 1 and counts its own). Ids 0-6 are the surface's (shared/surface.h, limits.h,
// sediment.h).
#define LAGOON_SPEC_DIRECT_WAVES 7
#define LAGOON_DIRECT_BIND_WAVES 0
#define LAGOON_DIRECT_BIND_DISPLACEMENT 1
#define LAGOON_DIRECT_BIND_NORMAL_JACOBIAN 2
#define LAGOON_DIRECT_BIND_JACOBIAN_TERMS 3

LAGOON_GPU_BEGIN
// One wave: θ = k·x0 + phase, height A g(θ) (shared/direct_waves_math.h), horizontal shift -Q A (k/|k|) sin
// θ.
struct DirectWaveGpu {
  vec4 wave;  // xy = wave vector k (rad/m, toward where it travels), z = phase (rad), w = amplitude A (m)
  vec4
      shape;  // x = steepness Q, y = power p of the profile (0 = Gerstner's cos θ), z = the profile's mean
              // (left out), w = ω (rad/s; the step turns the phase by -ω t, the frame's phase is at its time)
};

struct DirectWavesPush {
  uint n;      // texels per side of the first cascade
  uint layer;  // its array layer
  uint count;  // waves in the buffer
  uint reset_foam;
  float spacing;  // m between texels
  float time_s;
  float foam_threshold;
  float foam_decay;  // exp(-decay dt): what is left of the last step's foam
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(DirectWaveGpu, 32);
LAGOON_CHECK_SIZE(DirectWavesPush, 32);
#endif
#endif
