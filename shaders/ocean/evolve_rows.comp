#version 450
#extension GL_GOOGLE_include_directive : require
// Evolves the spectrum to time t and transforms it along rows (x), all stages, for the four packed fields
// of every cascade (common/ocean_fields.glsl): one pass over memory.
// Workgroup: (FFT_N/16 work items) x (FFT_LINES rows); groups (1, N / FFT_LINES, cascades).
#include "shared/ocean.h"
#include "common/fft_line.glsl"
#include "common/ocean_fields.glsl"

layout(local_size_x_id = LAGOON_FFT_SPEC_GROUP_X, local_size_y_id = LAGOON_FFT_SPEC_GROUP_Y) in;
layout(constant_id = LAGOON_FFT_SPEC_LINES) const int FFT_LINES = 4;

layout(std430, binding = LAGOON_OCEAN_BIND_SPECTRUM) readonly buffer Spectrum { vec4 h0_pair[]; };  // (h0(k), conj(h0(-k))) per k
layout(std430, binding = LAGOON_OCEAN_BIND_OMEGA) readonly buffer Omega { float omega[]; };      // ω(k), rad/s
layout(std430, binding = LAGOON_OCEAN_BIND_ROW_TWIDDLES) readonly buffer Twiddles { vec2 twiddles[]; };
layout(std430, binding = LAGOON_OCEAN_BIND_ROWS) writeonly buffer Dst { vec2 dst[]; };  // [cascade][field][z][x]
layout(push_constant) uniform Push { OceanPush p; };

shared vec2 exchange[FFT_LINES * 4 * FFT_N];  // [line][field][element]

void main() {
  const int n = FFT_N;
  int w = int(gl_LocalInvocationID.x);
  int line = int(gl_LocalInvocationID.y);
  int row = int(gl_WorkGroupID.y) * FFT_LINES + line;
  int cascade = int(gl_WorkGroupID.z);
  float dk = 6.283185307179586 / p.patch_size_m[cascade];
  float kz = ocean_wavenumber(row, n, dk);

  vec2 f0[16], f1[16], f2[16], f3[16];
  int radix = fft_stage_radix(0);
  for (int b = 0; b < 16 / radix; ++b) {
    for (int r = 0; r < radix; ++r) {
      int col = fft_read_index(fft_butterfly(w, b, radix), r, radix);
      int index = (cascade * n + row) * n + col;
      OceanPacked o = ocean_pack(h0_pair[index], omega[index], p.time_s, ocean_wavenumber(col, n, dk), kz);
      int q = b * radix + r;
      f0[q] = o.f0;
      f1[q] = o.f1;
      f2[q] = o.f2;
      f3[q] = o.f3;
    }
  }
  int base = line * 4 * n;
  for (int stage = 0; stage < FFT_STAGES; ++stage) {
    radix = fft_stage_radix(stage);
    int ns = fft_stage_stride(stage);
    if (stage > 0) {
      barrier();  // the previous stage's writes are visible
      for (int b = 0; b < 16 / radix; ++b) {
        for (int r = 0; r < radix; ++r) {
          int j = fft_butterfly(w, b, radix), at = base + fft_read_index(j, r, radix), q = b * radix + r;
          vec2 tw = fft_twiddle(twiddles[fft_twiddle_index(j, r, radix, ns)]);
          f0[q] = cmul(exchange[at], tw);
          f1[q] = cmul(exchange[at + n], tw);
          f2[q] = cmul(exchange[at + 2 * n], tw);
          f3[q] = cmul(exchange[at + 3 * n], tw);
        }
      }
      if (stage + 1 < FFT_STAGES) barrier();  // everyone has read before the stage overwrites
    }
    fft_stage_registers(f0, radix);
    fft_stage_registers(f1, radix);
    fft_stage_registers(f2, radix);
    fft_stage_registers(f3, radix);
    bool last = stage + 1 == FFT_STAGES;
    int plane = n * n, out_base = cascade * 4 * plane + row * n;
    for (int b = 0; b < 16 / radix; ++b) {
      for (int r = 0; r < radix; ++r) {
        int at = fft_write_index(fft_butterfly(w, b, radix), r, radix, ns), q = b * radix + r;
        if (last) {
          dst[out_base + at] = f0[q];
          dst[out_base + plane + at] = f1[q];
          dst[out_base + 2 * plane + at] = f2[q];
          dst[out_base + 3 * plane + at] = f3[q];
        } else {
          exchange[base + at] = f0[q];
          exchange[base + n + at] = f1[q];
          exchange[base + 2 * n + at] = f2[q];
          exchange[base + 3 * n + at] = f3[q];
        }
      }
    }
  }
}
