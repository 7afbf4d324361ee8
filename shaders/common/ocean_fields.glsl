// The ocean's per-texel math before the inverse FFT, shared by both FFT variants
// (compute/ocean/gpu/ocean_fft_path.h): the spectrum evolved to time t and packed into four complex fields.
// common/ocean_assemble.glsl is the other half.
//
// With h̃(k,t) = h0(k)e^{-iωt} + conj(h0(-k))e^{+iωt} (waves travel along +k) the packed complex fields are,
// each the spectrum of real_part + i·imag_part:
//   F0 = Dx + i·h,  F1 = Dz + i·∂h/∂x,  F2 = ∂h/∂z + i·∂Dx/∂x,  F3 = ∂Dz/∂z + i·∂Dx/∂z
// with D̃ = i(k/|k|)h̃ (crests sharpen for x' = x + λD) and ∂/∂x ↔ i·kx.
// Needs cmul and cconj (common/fft.glsl or fft_line.glsl).
#ifndef LAGOON_COMMON_OCEAN_FIELDS_GLSL
#define LAGOON_COMMON_OCEAN_FIELDS_GLSL

// ω·t reduced to [-π, π] keeping the low bits of the product (exact where fma is fused).
float ocean_phase(float w, float t) {
  float hi = w * t;
  float lo = fma(w, t, -hi);
  float q = round(hi * 0.15915494309189535);
  float reduced = fma(-q, 6.2831854820251465, hi);       // 2π rounded to float
  return fma(-q, -1.7484556000744487e-7, reduced) + lo;  // 2π - float(2π)
}

// The wavenumber of FFT index i (0..n-1) on a grid of spacing dk: negative frequencies in the upper half.
float ocean_wavenumber(int i, int n, float dk) {
  return dk * float(i < n / 2 ? i : i - n);
}

struct OceanPacked {
  vec2 f0, f1, f2, f3;
};

// The four packed fields at wave vector (kx, kz) from (h0(k), conj(h0(-k))) and ω(k), at time t.
OceanPacked ocean_pack(vec4 h0_pair, float omega, float t, float kx, float kz) {
  float a = ocean_phase(omega, t);
  vec2 e = vec2(cos(a), sin(a));
  vec2 h = cmul(h0_pair.xy, cconj(e)) + cmul(h0_pair.zw, e);
  float k = sqrt(kx * kx + kz * kz);
  float inv_k = k > 0.0 ? 1.0 / k : 0.0;
  vec2 ih = vec2(-h.y, h.x);  // i·h̃
  vec2 dx = ih * (kx * inv_k), dz = ih * (kz * inv_k);
  vec2 sx = ih * kx, sz = ih * kz;
  vec2 dxdx = h * (-kx * kx * inv_k), dzdz = h * (-kz * kz * inv_k), dxdz = h * (-kx * kz * inv_k);
  // A + i·B for spectra A, B: (A.x - B.y, A.y + B.x).
  OceanPacked o;
  o.f0 = vec2(dx.x - h.y, dx.y + h.x);
  o.f1 = vec2(dz.x - sx.y, dz.y + sx.x);
  o.f2 = vec2(sz.x - dxdx.y, sz.y + dxdx.x);
  o.f3 = vec2(dzdz.x - dxdz.y, dzdz.y + dxdz.x);
  return o;
}

#endif
