// Push constants of the batched Stockham FFT passes (shaders/fft/*.comp, shaders/ocean/*.comp).
#ifndef LAGOON_SHARED_FFT_H
#define LAGOON_SHARED_FFT_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct FftPush {
  uint n;        // transform length N (power of two, 64..1024); arrays are N x N
  uint ns;       // Stockham stride: product of the radices of the passes already done (1 for the first)
  uint batches;  // number of N x N arrays
  uint pad;      // keeps the block 16 bytes; the direction is a specialisation constant (FFT_INVERSE)
};
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(FftPush, 16);
#endif
#endif
