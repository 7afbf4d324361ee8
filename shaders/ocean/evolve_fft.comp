#version 450
#extension GL_GOOGLE_include_directive : require
// Evolves the spectrum to time t and runs the first Stockham pass along rows (x), for the four packed
// fields of every cascade (common/ocean_fields.glsl), in one pass over memory; a foam-only step (warm-ups)
// does F2 and F3 alone, stored as fields 0 and 1 of two per cascade.
#include "shared/ocean.h"
#include "common/fft.glsl"
#include "common/ocean_fields.glsl"

layout(local_size_x_id = LAGOON_FFT_SPEC_GROUP_X, local_size_y_id = LAGOON_FFT_SPEC_GROUP_Y) in;

layout(std430, binding = LAGOON_OCEAN_BIND_SPECTRUM) readonly buffer Spectrum { vec4 h0_pair[]; };  // (h0(k), conj(h0(-k))) per k
layout(std430, binding = LAGOON_OCEAN_BIND_OMEGA) readonly buffer Omega { float omega[]; };      // ω(k), rad/s
layout(std430, binding = LAGOON_OCEAN_BIND_EVOLVED) writeonly buffer Dst { vec4 dst[]; };  // complex pairs, [cascade][field][z][x]
layout(push_constant) uniform Push { OceanPush p; };
layout(constant_id = LAGOON_OCEAN_SPEC_FOAM_ONLY) const bool kFoamOnly = false;  // F2, F3 only, as fields 0, 1

void main() {
  const int n = FFT_N;
  int j = int(gl_GlobalInvocationID.x);
  int row = int(gl_GlobalInvocationID.y);
  int cascade = int(gl_GlobalInvocationID.z);
  if (j >= n / FFT_RADIX || row >= n || cascade >= int(p.cascades)) return;

  float dk = 6.283185307179586 / p.patch_size_m[cascade];
  float kz = ocean_wavenumber(row, n, dk);
  vec2 f0[FFT_RADIX], f1[FFT_RADIX], f2[FFT_RADIX], f3[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    int col = fft_source_index(j, r);
    int index = (cascade * n + row) * n + col;
    OceanPacked o = ocean_pack(h0_pair[index], omega[index], p.time_s, ocean_wavenumber(col, n, dk), kz);
    f0[r] = kFoamOnly ? o.f2 : o.f0;
    f1[r] = kFoamOnly ? o.f3 : o.f1;
    f2[r] = o.f2;
    f3[r] = o.f3;
  }
  // First pass: Ns = 1, so every twiddle is 1.
  fft_radix(f0);
  fft_radix(f1);
  if (!kFoamOnly) {
    fft_radix(f2);
    fft_radix(f3);
  }
  // Ns = 1: the butterfly's outputs are contiguous; write them two complex values at a time.
  int plane = n * n;
  int base = cascade * (kFoamOnly ? 2 : 4) * plane + row * n;
  for (int r = 0; r < FFT_RADIX; r += 2) {
    int at = (base + fft_dest_index(j, r)) / 2;
    dst[at] = vec4(f0[r], f0[r + 1]);
    dst[at + plane / 2] = vec4(f1[r], f1[r + 1]);
    if (!kFoamOnly) {
      dst[at + plane] = vec4(f2[r], f2[r + 1]);
      dst[at + 3 * plane / 2] = vec4(f3[r], f3[r + 1]);
    }
  }
}
