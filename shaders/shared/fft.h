// Push constants of the batched Stockham FFT passes (shaders/fft/*.comp, shaders/ocean/*.comp).
#ifndef LAGOON_SHARED_FFT_H
#define LAGOON_SHARED_FFT_H
#include "shared/interop.h"

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
