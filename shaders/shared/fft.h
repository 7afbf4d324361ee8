// Push constants of the batched Stockham FFT passes (shaders/fft/*.comp, shaders/ocean/*.comp).
#ifndef LAGOON_SHARED_FFT_H
#define LAGOON_SHARED_FFT_H
#include "shared/interop.h"

// Specialisation-constant IDs of the FFT shaders (common/fft.glsl, fft_line.glsl, fft/fft_pass.comp and the
// ocean's fused passes); compute/fft/gpu_fft.cpp and compute/ocean/gpu/ocean_fft_path.cpp set them.
#define LAGOON_FFT_SPEC_GROUP_X 0  // workgroup size x (local_size_x_id)
#define LAGOON_FFT_SPEC_GROUP_Y 1  // workgroup size y (local_size_y_id)
#define LAGOON_FFT_SPEC_RADIX 2    // 2, 4, 8, 16 or 32
#define LAGOON_FFT_SPEC_COLUMNS 3  // bool: the pass runs along columns
#define LAGOON_FFT_SPEC_INVERSE 4  // bool: exp(+2πi kn/N), unnormalised
#define LAGOON_FFT_SPEC_N 5        // transform size
#define LAGOON_FFT_SPEC_NS 6       // Stockham stride of the pass
#define LAGOON_FFT_SPEC_LINES 7    // lines per workgroup (the ocean's workgroup path)
#define LAGOON_FFT_SPEC_FIELDS 8   // arrays per batch group (4 for the ocean's packed fields)

// Binding slots of fft/fft_pass.comp.
#define LAGOON_FFT_BIND_SRC 0
#define LAGOON_FFT_BIND_DST 1
#define LAGOON_FFT_BIND_TWIDDLES 2

LAGOON_GPU_BEGIN
// N, the Stockham stride, the radix and the direction are specialisation constants (common/fft.glsl).
struct FftPush {
  uint batches;  // number of N x N arrays
  uint pad0;
  uint pad1;
  uint pad2;
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(FftPush, 16);
#endif
#endif
