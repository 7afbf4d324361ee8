#version 450
#extension GL_GOOGLE_include_directive : require
// Evolves the spectrum to time t and transforms it along rows (x), all stages, for the four packed fields
// of every cascade: one pass over memory. With h̃(k,t) = h0(k)e^{-iωt} + conj(h0(-k))e^{+iωt} (waves
// travel along +k) the packed complex fields are, each the spectrum of real_part + i·imag_part:
//   F0 = Dx + i·h,  F1 = Dz + i·∂h/∂x,  F2 = ∂h/∂z + i·∂Dx/∂x,  F3 = ∂Dz/∂z + i·∂Dx/∂z
// with D̃ = i(k/|k|)h̃ (crests sharpen for x' = x + λD) and ∂/∂x ↔ i·kx.
// Workgroup: (FFT_N/16 work items) x (FFT_LINES rows); groups (1, N / FFT_LINES, cascades).
#include "shared/ocean.h"
#include "common/fft_line.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(constant_id = 7) const int FFT_LINES = 4;

layout(std430, binding = 0) readonly buffer Spectrum { vec4 h0_pair[]; };  // (h0(k), conj(h0(-k))) per k
layout(std430, binding = 1) readonly buffer Omega { float omega[]; };      // ω(k), rad/s
layout(std430, binding = 2) readonly buffer Twiddles { vec2 twiddles[]; };
layout(std430, binding = 3) writeonly buffer Dst { vec2 dst[]; };  // [cascade][field][z][x]
layout(push_constant) uniform Push { OceanPush p; };

shared vec2 exchange[FFT_LINES * 4 * FFT_N];  // [line][field][element]

// ω·t reduced to [-π, π] keeping the low bits of the product (exact where fma is fused).
float phase(float w, float t) {
  float hi = w * t;
  float lo = fma(w, t, -hi);
  float q = round(hi * 0.15915494309189535);
  float reduced = fma(-q, 6.2831854820251465, hi);       // 2π rounded to float
  return fma(-q, -1.7484556000744487e-7, reduced) + lo;  // 2π - float(2π)
}

void main() {
  const int n = FFT_N;
  int w = int(gl_LocalInvocationID.x);
  int line = int(gl_LocalInvocationID.y);
  int row = int(gl_WorkGroupID.y) * FFT_LINES + line;
  int cascade = int(gl_WorkGroupID.z);
  float dk = 6.283185307179586 / p.patch_size_m[cascade];
  float kz = dk * float(row < n / 2 ? row : row - n);

  vec2 f0[16], f1[16], f2[16], f3[16];
  int radix = fft_stage_radix(0);
  for (int b = 0; b < 16 / radix; ++b) {
    for (int r = 0; r < radix; ++r) {
      int col = fft_read_index(fft_butterfly(w, b, radix), r, radix);
      int index = (cascade * n + row) * n + col;
      vec4 pair = h0_pair[index];
      float a = phase(omega[index], p.time_s);
      vec2 e = vec2(cos(a), sin(a));
      vec2 h = cmul(pair.xy, cconj(e)) + cmul(pair.zw, e);
      float kx = dk * float(col < n / 2 ? col : col - n);
      float k = sqrt(kx * kx + kz * kz);
      float inv_k = k > 0.0 ? 1.0 / k : 0.0;
      vec2 ih = vec2(-h.y, h.x);  // i·h̃
      vec2 dx = ih * (kx * inv_k), dz = ih * (kz * inv_k);
      vec2 sx = ih * kx, sz = ih * kz;
      vec2 dxdx = h * (-kx * kx * inv_k), dzdz = h * (-kz * kz * inv_k), dxdz = h * (-kx * kz * inv_k);
      int q = b * radix + r;
      // A + i·B for spectra A, B: (A.x - B.y, A.y + B.x).
      f0[q] = vec2(dx.x - h.y, dx.y + h.x);
      f1[q] = vec2(dz.x - sx.y, dz.y + sx.x);
      f2[q] = vec2(sz.x - dxdx.y, sz.y + dxdx.x);
      f3[q] = vec2(dzdz.x - dxdz.y, dzdz.y + dxdz.x);
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
