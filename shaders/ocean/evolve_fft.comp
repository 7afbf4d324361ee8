#version 450
#extension GL_GOOGLE_include_directive : require
// Evolves the spectrum to time t and runs the first Stockham pass along rows (x), for the four packed
// fields of every cascade, in one pass over memory. With h̃(k,t) = h0(k)e^{-iωt} + conj(h0(-k))e^{+iωt}
// (waves travel along +k) the packed complex fields are, each the spectrum of real_part + i·imag_part:
//   F0 = Dx + i·h,  F1 = Dz + i·∂h/∂x,  F2 = ∂h/∂z + i·∂Dx/∂x,  F3 = ∂Dz/∂z + i·∂Dx/∂z
// with D̃ = i(k/|k|)h̃ (crests sharpen for x' = x + λD), ∂/∂x ↔ i·kx.
#include "shared/ocean.h"
#include "common/fft.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;

layout(std430, binding = 0) readonly buffer Spectrum { vec4 h0_pair[]; };  // (h0(k), conj(h0(-k))) per k
layout(std430, binding = 1) readonly buffer Omega { float omega[]; };      // ω(k), rad/s
layout(std430, binding = 2) writeonly buffer Dst { vec4 dst[]; };  // complex pairs, [cascade][field][z][x]
layout(push_constant) uniform Push { OceanPush p; };

// ω·t reduced to [-π, π] keeping the low bits of the product (exact where fma is fused).
float phase(float w, float t) {
  float hi = w * t;
  float lo = fma(w, t, -hi);
  float q = round(hi * 0.15915494309189535);
  float reduced = fma(-q, 6.2831854820251465, hi);  // 2π rounded to float
  return fma(-q, -1.7484556000744487e-7, reduced) + lo;  // 2π - float(2π)
}

void main() {
  const int n = FFT_N;
  int j = int(gl_GlobalInvocationID.x);
  int row = int(gl_GlobalInvocationID.y);
  int cascade = int(gl_GlobalInvocationID.z);
  if (j >= n / FFT_RADIX || row >= n || cascade >= int(p.cascades)) return;

  float dk = 6.283185307179586 / p.patch_size_m[cascade];
  float kz = dk * float(row < n / 2 ? row : row - n);
  vec2 f0[FFT_RADIX], f1[FFT_RADIX], f2[FFT_RADIX], f3[FFT_RADIX];
  for (int r = 0; r < FFT_RADIX; ++r) {
    int col = fft_source_index(j, r);
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
    // A + i·B for spectra A, B: (A.x - B.y, A.y + B.x).
    f0[r] = vec2(dx.x - h.y, dx.y + h.x);
    f1[r] = vec2(dz.x - sx.y, dz.y + sx.x);
    f2[r] = vec2(sz.x - dxdx.y, sz.y + dxdx.x);
    f3[r] = vec2(dzdz.x - dxdz.y, dzdz.y + dxdz.x);
  }
  // First pass: Ns = 1, so every twiddle is 1.
  fft_radix(f0);
  fft_radix(f1);
  fft_radix(f2);
  fft_radix(f3);
  // Ns = 1: the butterfly's outputs are contiguous; write them two complex values at a time.
  int plane = n * n;
  int base = cascade * 4 * plane + row * n;
  for (int r = 0; r < FFT_RADIX; r += 2) {
    int at = (base + fft_dest_index(j, r)) / 2;
    dst[at] = vec4(f0[r], f0[r + 1]);
    dst[at + plane / 2] = vec4(f1[r], f1[r + 1]);
    dst[at + plane] = vec4(f2[r], f2[r + 1]);
    dst[at + 3 * plane / 2] = vec4(f3[r], f3[r + 1]);
  }
}
