#version 450
#extension GL_GOOGLE_include_directive : require
// One Stockham pass of a batched 2-D complex FFT over N x N arrays, along rows (x) or columns (z).
// An invocation does two neighbouring butterflies (rows) or the same butterfly of two neighbouring columns,
// for FFT_FIELDS arrays that share twiddles, so every load and store moves two complex values (vec4):
// on lavapipe time follows the number of memory accesses. Twiddles: 3 table loads per butterfly.
#include "shared/fft.h"
#include "common/fft.glsl"

layout(local_size_x_id = LAGOON_FFT_SPEC_GROUP_X, local_size_y_id = LAGOON_FFT_SPEC_GROUP_Y) in;
layout(constant_id = LAGOON_FFT_SPEC_COLUMNS) const bool FFT_COLUMNS = false;
layout(constant_id = LAGOON_FFT_SPEC_FIELDS) const int FFT_FIELDS = 1;  // arrays per batch group (4 for the ocean's packed fields)

layout(std430, binding = LAGOON_FFT_BIND_SRC) readonly buffer Src { vec4 src[]; };  // complex pairs
layout(std430, binding = LAGOON_FFT_BIND_DST) writeonly buffer Dst { vec4 dst[]; };
layout(std430, binding = LAGOON_FFT_BIND_TWIDDLES) readonly buffer Twiddles { vec2 twiddles[]; };  // exp(+2πi q/N), q < N
layout(push_constant) uniform Push { FftPush p; };

void main() {
  const int n = FFT_N, butterflies = n / FFT_RADIX;
  // Rows: x = butterfly pair. Columns: x = column pair.
  int a = int(gl_GlobalInvocationID.x), b = int(gl_GlobalInvocationID.y);
  int group = int(gl_GlobalInvocationID.z);
  if (group >= int(p.batches)) return;
  if (FFT_COLUMNS ? (a >= n / 2 || b >= butterflies) : (a >= butterflies / 2 || b >= n)) return;

  vec2 w0[FFT_RADIX], w1[FFT_RADIX];
  int j0 = FFT_COLUMNS ? b : 2 * a;
  if (FFT_NS > 1) {
    FFT_LOAD_TWIDDLES(twiddles, j0, w0);
    if (FFT_COLUMNS) {
      for (int r = 0; r < FFT_RADIX; ++r) w1[r] = w0[r];
    } else {
      FFT_LOAD_TWIDDLES(twiddles, j0 + 1, w1);
    }
  }
  for (int f = 0; f < FFT_FIELDS; ++f) {
    int plane = (group * FFT_FIELDS + f) * n * n;
    vec2 v0[FFT_RADIX], v1[FFT_RADIX];
    for (int r = 0; r < FFT_RADIX; ++r) {
      // Element index (in complex values); always even, so a vec4 holds it and its neighbour.
      int at = FFT_COLUMNS ? plane + fft_source_index(j0, r) * n + 2 * a : plane + b * n + fft_source_index(j0, r);
      vec4 pair = src[at / 2];
      v0[r] = FFT_NS > 1 ? cmul(pair.xy, w0[r]) : pair.xy;
      v1[r] = FFT_NS > 1 ? cmul(pair.zw, w1[r]) : pair.zw;
    }
    fft_radix(v0);
    fft_radix(v1);
    if (FFT_COLUMNS || FFT_NS > 1) {
      // The two butterflies' outputs are neighbours.
      for (int r = 0; r < FFT_RADIX; ++r) {
        int at = FFT_COLUMNS ? plane + fft_dest_index(j0, r) * n + 2 * a : plane + b * n + fft_dest_index(j0, r);
        dst[at / 2] = vec4(v0[r], v1[r]);
      }
    } else {
      // First row pass (Ns = 1): each butterfly's outputs are contiguous, write them two by two.
      for (int r = 0; r < FFT_RADIX; r += 2) {
        dst[(plane + b * n + fft_dest_index(j0, r)) / 2] = vec4(v0[r], v0[r + 1]);
        dst[(plane + b * n + fft_dest_index(j0 + 1, r)) / 2] = vec4(v1[r], v1[r + 1]);
      }
    }
  }
}
