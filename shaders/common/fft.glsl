// Radix-R Stockham FFT pass, shared by the generic FFT pass and the ocean's fused first/last passes.
// One invocation computes one radix-R butterfly of one line: it reads R elements spaced N/R apart, applies
// the twiddles W^(r·(j mod Ns)·N/(Ns·R)) (table of the N roots of unity), transforms them in registers and
// writes them Ns apart (autosort: no bit reversal pass). log_R(N) passes make a length-N transform.
// Specialisation: constant_id 2 = FFT_RADIX (2, 4, 8 or 16), 4 = FFT_INVERSE (exp(+2πi kn/N), unnormalised),
// 5 = FFT_N (length), 6 = FFT_NS (this pass's Stockham stride). All compile-time constants: the loops unroll,
// the in-register twiddles fold, and index arithmetic becomes shifts and masks (lavapipe has no vector
// integer division: a division by a run-time value costs a scalar loop over the SIMD lanes).
#ifndef LAGOON_COMMON_FFT_GLSL
#define LAGOON_COMMON_FFT_GLSL

layout(constant_id = 2) const int FFT_RADIX = 16;
layout(constant_id = 4) const bool FFT_INVERSE = true;
layout(constant_id = 5) const int FFT_N = 256;
layout(constant_id = 6) const int FFT_NS = 1;
const float FFT_SIGN = FFT_INVERSE ? 1.0 : -1.0;

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 cconj(vec2 a) { return vec2(a.x, -a.y); }

// In-register DFT of FFT_RADIX values as a radix-2 network with compile-time twiddles.
void fft_radix(inout vec2 v[FFT_RADIX]) {
  // Bit-reversal permutation; indices are constants once the loop is unrolled.
  const int log2_radix = findMSB(FFT_RADIX);
  for (int i = 0; i < FFT_RADIX; ++i) {
    int j = int(bitfieldReverse(uint(i)) >> uint(32 - log2_radix));
    if (i < j) {
      vec2 t = v[i];
      v[i] = v[j];
      v[j] = t;
    }
  }
  for (int len = 2; len <= FFT_RADIX; len <<= 1) {
    int half_len = len >> 1;
    for (int i = 0; i < FFT_RADIX; i += len) {
      for (int k = 0; k < half_len; ++k) {
        float angle = FFT_SIGN * 6.283185307179586 * float(k) / float(len);
        vec2 w = vec2(cos(angle), sin(angle));
        vec2 a = v[i + k];
        vec2 b = cmul(v[i + k + half_len], w);
        v[i + k] = a + b;
        v[i + k + half_len] = a - b;
      }
    }
  }
}

// Index helpers for butterfly j of a line at this pass's stride.
int fft_source_index(int j, int r) { return j + r * (FFT_N / FFT_RADIX); }
int fft_dest_index(int j, int r) { return (j / FFT_NS) * FFT_NS * FFT_RADIX + (j % FFT_NS) + r * FFT_NS; }
// Twiddle of element r of butterfly j from the table of exp(+2πi q/n), conjugated for a forward transform.
vec2 fft_twiddle(vec2 table_entry) { return FFT_INVERSE ? table_entry : cconj(table_entry); }
int fft_twiddle_index(int j, int r) { return (j % FFT_NS) * r * (FFT_N / (FFT_NS * FFT_RADIX)); }

#endif
