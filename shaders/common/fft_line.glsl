// Whole-line FFTs inside one workgroup. A line of FFT_N elements is split among FFT_N/16 invocations
// ("work items") holding 16 complex values each in registers. The transform runs in Stockham stages of
// radix 16 (plus one of radix 2, 4 or 8 when log2 N is not a multiple of 4); between stages the values are
// exchanged through shared memory with a barrier, so a 2-D transform is one dispatch per axis: for
// N = 256 two stages and one barrier. In a stage of radix R a work item does 16/R butterflies.
// Specialisation: 4 = FFT_INVERSE, 5 = FFT_N (64..1024). All index arithmetic folds to shifts and masks.
#ifndef LAGOON_COMMON_FFT_LINE_GLSL
#define LAGOON_COMMON_FFT_LINE_GLSL

layout(constant_id = 4) const bool FFT_INVERSE = true;
layout(constant_id = 5) const int FFT_N = 256;
const float FFT_SIGN = FFT_INVERSE ? 1.0 : -1.0;
const int FFT_WORK = FFT_N / 16;  // work items per line
const int FFT_LOG2N = FFT_N == 64 ? 6 : FFT_N == 128 ? 7 : FFT_N == 256 ? 8 : FFT_N == 512 ? 9 : 10;
const int FFT_STAGES16 = FFT_LOG2N / 4;
const int FFT_REMAINDER = 1 << (FFT_LOG2N % 4);
const int FFT_STAGES = FFT_STAGES16 + (FFT_REMAINDER > 1 ? 1 : 0);

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 cconj(vec2 a) { return vec2(a.x, -a.y); }

int fft_stage_radix(int stage) { return stage < FFT_STAGES16 ? 16 : FFT_REMAINDER; }
int fft_stage_stride(int stage) { return 1 << (4 * stage); }

// Butterfly b of work item w in a stage of radix `radix`: its index among the line's N/radix butterflies.
int fft_butterfly(int w, int b, int radix) { return w * (16 / radix) + b; }
// Element r of butterfly j: where it is read, where the stage writes it, and its twiddle's table index.
int fft_read_index(int j, int r, int radix) { return j + r * (FFT_N / radix); }
int fft_write_index(int j, int r, int radix, int ns) { return (j / ns) * ns * radix + (j % ns) + r * ns; }
int fft_twiddle_index(int j, int r, int radix, int ns) { return (j % ns) * r * (FFT_N / (ns * radix)); }
// Table entries are exp(+2πi q/N); a forward transform uses their conjugates.
vec2 fft_twiddle(vec2 table_entry) { return FFT_INVERSE ? table_entry : cconj(table_entry); }

// In-register DFT of v[base .. base + radix) as a radix-2 network with compile-time twiddles.
void fft_butterfly_registers(inout vec2 v[16], int base, int radix) {
  int log2_radix = radix == 16 ? 4 : radix == 8 ? 3 : radix == 4 ? 2 : 1;
  for (int i = 0; i < radix; ++i) {
    int j = int(bitfieldReverse(uint(i)) >> uint(32 - log2_radix));
    if (i < j) {
      vec2 t = v[base + i];
      v[base + i] = v[base + j];
      v[base + j] = t;
    }
  }
  for (int len = 2; len <= radix; len <<= 1) {
    int half_len = len >> 1;
    for (int i = 0; i < radix; i += len) {
      for (int k = 0; k < half_len; ++k) {
        float angle = FFT_SIGN * 6.283185307179586 * float(k) / float(len);
        vec2 a = v[base + i + k];
        vec2 b = cmul(v[base + i + k + half_len], vec2(cos(angle), sin(angle)));
        v[base + i + k] = a + b;
        v[base + i + k + half_len] = a - b;
      }
    }
  }
}

// All butterflies of one stage on one work item's registers.
void fft_stage_registers(inout vec2 v[16], int radix) {
  for (int b = 0; b < 16 / radix; ++b) fft_butterfly_registers(v, b * radix, radix);
}

#endif
