#version 450
#extension GL_GOOGLE_include_directive : require
// One Stockham pass of a batched 2-D complex FFT over N x N arrays: along rows (contiguous, x) or columns
// (stride N, z), chosen by FFT_COLUMNS. Invocation: (butterfly or line, line or butterfly, batch) arranged
// so that neighbouring invocations touch neighbouring memory in both directions.
#include "shared/fft.h"
#include "common/fft.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(constant_id = 3) const bool FFT_COLUMNS = false;

layout(std430, binding = 0) readonly buffer Src { vec2 src[]; };
layout(std430, binding = 1) writeonly buffer Dst { vec2 dst[]; };
layout(std430, binding = 2) readonly buffer Twiddles { vec2 twiddles[]; };  // exp(+2πi q/N), q < N
layout(push_constant) uniform Push { FftPush p; };

void main() {
  const int n = FFT_N;
  const int butterflies = n / FFT_RADIX;
  int j = int(FFT_COLUMNS ? gl_GlobalInvocationID.y : gl_GlobalInvocationID.x);
  int line = int(FFT_COLUMNS ? gl_GlobalInvocationID.x : gl_GlobalInvocationID.y);
  int batch = int(gl_GlobalInvocationID.z);
  if (j >= butterflies || line >= n || batch >= int(p.batches)) return;

  int base = batch * n * n + (FFT_COLUMNS ? line : line * n);
  int stride = FFT_COLUMNS ? n : 1;
  vec2 v[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    vec2 w = fft_twiddle(twiddles[fft_twiddle_index(j, r)]);
    v[r] = cmul(src[base + fft_source_index(j, r) * stride], w);
  }
  fft_radix(v);
  for (int r = 0; r < FFT_RADIX; ++r) dst[base + fft_dest_index(j, r) * stride] = v[r];
}
