// Push constants of the ocean's fused FFT passes (shaders/ocean/evolve_fft.comp, fft_assemble.comp).
#ifndef LAGOON_SHARED_OCEAN_H
#define LAGOON_SHARED_OCEAN_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct OceanPush {
  vec4 patch_size_m;  // per cascade of this resolution group (up to 4)
  uint cascades;      // cascades in the group (N and the pass's stride are specialisation constants)
  uint pad3;
  uint pad4;
  uint reset_foam;       // 1: previous foam is undefined (first step or new parameters)
  float time_s;          // simulation time of the step
  float dt_s;            // time since the previous step (foam decay)
  float choppiness;      // λ
  float foam_threshold;  // foam builds where J < threshold
  float foam_decay_per_s;
  float pad0;
  float pad1;
  float pad2;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(OceanPush, 64);
LAGOON_CHECK_OFFSET(OceanPush, cascades, 16);
LAGOON_CHECK_OFFSET(OceanPush, time_s, 32);
LAGOON_CHECK_OFFSET(OceanPush, foam_decay_per_s, 48);
#endif
#endif
