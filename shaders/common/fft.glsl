// Radix-R Stockham FFT pass, shared by the generic FFT pass and the ocean's fused first/last passes.
// One invocation computes one radix-R butterfly of one line: it reads R elements spaced N/R apart, applies
// the twiddles W^(r·(j mod Ns)·N/(Ns·R)) (table of the N roots of unity), transforms them in registers and
// writes them Ns apart (autosort: no bit reversal pass). log_R(N) passes make a length-N transform.
// Specialisation (IDs in shared/fft.h): FFT_RADIX (2, 4, 8, 16 or 32), FFT_INVERSE (exp(+2πi kn/N), unnormalised),
// FFT_N (length), FFT_NS (this pass's Stockham stride). All compile-time constants: the loops unroll,
// the in-register twiddles fold, and index arithmetic becomes shifts and masks (lavapipe has no vector
// integer division: a division by a run-time value costs a scalar loop over the SIMD lanes).
#ifndef LAGOON_COMMON_FFT_GLSL
#define LAGOON_COMMON_FFT_GLSL
#include "shared/fft.h"

// The largest radix by default: glslang checks the in-register kernels' constant indices against it.
layout(constant_id = LAGOON_FFT_SPEC_RADIX) const int FFT_RADIX = 32;
layout(constant_id = LAGOON_FFT_SPEC_INVERSE) const bool FFT_INVERSE = true;
layout(constant_id = LAGOON_FFT_SPEC_N) const int FFT_N = 256;
layout(constant_id = LAGOON_FFT_SPEC_NS) const int FFT_NS = 1;
const float FFT_SIGN = FFT_INVERSE ? 1.0 : -1.0;

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 cconj(vec2 a) { return vec2(a.x, -a.y); }

#include "common/fft_radix.glsl"

// Index helpers for butterfly j of a line at this pass's stride.
int fft_source_index(int j, int r) { return j + r * (FFT_N / FFT_RADIX); }
int fft_dest_index(int j, int r) { return (j / FFT_NS) * FFT_NS * FFT_RADIX + (j % FFT_NS) + r * FFT_NS; }
// Twiddle of element r of butterfly j from the table of exp(+2πi q/n), conjugated for a forward transform.
vec2 fft_twiddle(vec2 table_entry) { return FFT_INVERSE ? table_entry : cconj(table_entry); }
int fft_twiddle_index(int j, int r) { return (j % FFT_NS) * r * (FFT_N / (FFT_NS * FFT_RADIX)); }

#endif

// The FFT_RADIX twiddles of butterfly j, from 3 table loads (W^m, W^4m, W^8m; W = exp(2πi/N)) and at
// most 2 complex products each: a load per element costs more than the products on lavapipe.
#define FFT_LOAD_TWIDDLES(table, j, w)                                                     \
  {                                                                                        \
    int m_ = ((j) % FFT_NS) * (FFT_N / (FFT_NS * FFT_RADIX));                              \
    w[0] = vec2(1.0, 0.0);                                                                 \
    if (FFT_RADIX > 1) w[1] = fft_twiddle(table[m_]);                                      \
    if (FFT_RADIX > 2) w[2] = cmul(w[1], w[1]);                                            \
    if (FFT_RADIX > 3) w[3] = cmul(w[2], w[1]);                                            \
    if (FFT_RADIX > 4) {                                                                   \
      w[4] = fft_twiddle(table[4 * m_]);                                                   \
      for (int r_ = 5; r_ < 8; ++r_) w[r_] = cmul(w[4], w[r_ - 4]);                        \
    }                                                                                      \
    if (FFT_RADIX > 8) {                                                                   \
      w[8] = fft_twiddle(table[8 * m_]);                                                   \
      for (int r_ = 9; r_ < 16; ++r_) w[r_] = cmul(w[8], w[r_ - 8]);                      \
    }                                                                                      \
    if (FFT_RADIX > 16) {                                                                  \
      w[16] = fft_twiddle(table[16 * m_]);                                                 \
      for (int r_ = 17; r_ < 32; ++r_) w[r_] = cmul(w[16], w[r_ - 16]);                   \
    }                                                                                      \
  }
