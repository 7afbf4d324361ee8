// Whole-line FFTs inside one workgroup. A line of FFT_N elements is split among FFT_N/16 invocations
// ("work items") holding 16 complex values each in registers. The transform runs in Stockham stages of
// radix 16 (plus one of radix 2, 4 or 8 when log2 N is not a multiple of 4); between stages the values are
// exchanged through shared memory with a barrier, so a 2-D transform is one dispatch per axis: for
// N = 256 two stages and one barrier. In a stage of radix R a work item does 16/R butterflies.
// Specialisation (IDs in shared/fft.h): FFT_INVERSE, FFT_N (64..1024). All index arithmetic folds to shifts and masks.
#ifndef LAGOON_COMMON_FFT_LINE_GLSL
#define LAGOON_COMMON_FFT_LINE_GLSL
#include "shared/fft.h"

layout(constant_id = LAGOON_FFT_SPEC_INVERSE) const bool FFT_INVERSE = true;
layout(constant_id = LAGOON_FFT_SPEC_N) const int FFT_N = 256;
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

#include "common/fft_stage16.glsl"

#endif
