// Push constants of the ocean's fused FFT passes (shaders/ocean/evolve_fft.comp, fft_assemble.comp).
#ifndef LAGOON_SHARED_OCEAN_H
#define LAGOON_SHARED_OCEAN_H
#include "shared/interop.h"

// Binding slots of the ocean step's shaders (shaders/ocean/*.comp) and compute/ocean/gpu.
// Evolution (evolve_fft.comp, evolve_rows.comp):
#define LAGOON_OCEAN_BIND_SPECTRUM 0      // vec4 (h0(k), conj(h0(-k))) per k, cascade after cascade
#define LAGOON_OCEAN_BIND_OMEGA 1         // float ω(k)
#define LAGOON_OCEAN_BIND_EVOLVED 2       // evolve_fft.comp: the first pass's output
#define LAGOON_OCEAN_BIND_ROW_TWIDDLES 2  // evolve_rows.comp: the roots of unity
#define LAGOON_OCEAN_BIND_ROWS 3          // evolve_rows.comp: the rows' output
// Assembly (fft_assemble.comp, columns_assemble.comp):
#define LAGOON_OCEAN_BIND_FIELDS 0           // the packed fields before the last pass
#define LAGOON_OCEAN_BIND_TWIDDLES 1         // the roots of unity
#define LAGOON_OCEAN_BIND_DISPLACEMENT 2     // image2DArray (λDx, h, λDz, foam)
#define LAGOON_OCEAN_BIND_NORMAL_JACOBIAN 3  // image2DArray (n, J)
#define LAGOON_OCEAN_BIND_JACOBIAN_TERMS 4   // image2DArray (λ∂Dx/∂x, λ∂Dz/∂z, λ∂Dx/∂z, foam)
// The fused passes of a warm-up step bring only the foam to the step's time (compute/ocean/gpu/gpu_ocean.h,
// Outputs::FoamOnly): the two packed fields the Jacobian needs instead of four (specialisation constant,
// after the FFT's own IDs in shared/fft.h).
#define LAGOON_OCEAN_SPEC_FOAM_ONLY 9

// A mip level from the one above (mips.comp): three sources, then the three destinations.
#define LAGOON_MIPS_BIND_SRC 0  // + 0, 1, 2: displacement, normal_jacobian, jacobian_terms
#define LAGOON_MIPS_BIND_DST 3  // + 0, 1, 2
// The NaN/Inf count (field_check.comp, compute/ocean/gpu/field_check.h).
#define LAGOON_CHECK_BIND_FIELDS 0  // + 0, 1, 2: displacement, normal_jacobian, jacobian_terms
#define LAGOON_CHECK_BIND_COUNT 3

LAGOON_GPU_BEGIN
struct OceanPush {
  vec4 patch_size_m;  // per cascade of this resolution group (up to 4)
  uint cascades;      // cascades in the group (N and the pass's stride are specialisation constants)
  uint pad3;
  uint pad4;
  uint reset_foam;   // 1: previous foam is undefined (first step or new parameters)
  float time_s;      // simulation time of the step
  float dt_s;        // time since the previous step (foam decay)
  float choppiness;  // λ
  float foam_build;  // 1: the step makes foam where J is low; 0: it only fades (OceanStepPass's ticks)
  float foam_decay_per_s;
  float pad0;
  float pad1;
  float pad2;
  // Per cascade of the group: its foam builds where J < onset and reaches 1 `width` further below
  // (ocean/whitecaps.h's FoamRule::cascades).
  vec4 foam_onset;
  vec4 foam_width;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(OceanPush, 96);
LAGOON_CHECK_OFFSET(OceanPush, cascades, 16);
LAGOON_CHECK_OFFSET(OceanPush, time_s, 32);
LAGOON_CHECK_OFFSET(OceanPush, foam_decay_per_s, 48);
LAGOON_CHECK_OFFSET(OceanPush, foam_onset, 64);
LAGOON_CHECK_OFFSET(OceanPush, foam_width, 80);
#endif
#endif
