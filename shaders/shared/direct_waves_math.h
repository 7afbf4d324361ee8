// One directly evaluated wave's profile (shared/direct_waves.h), written once for the GPU (float;
// common/direct_waves.glsl) and the CPU reference (double; compute/ocean/gerstner.cpp). No include guard: the
// includer defines dw_real and dw_real2 and makes sin and cos visible.
//
// The height is A g(θ) with g(θ) = cos θ for a Gerstner wave (seed 001 eq. 11) and
// g(θ) = ((1 + sin θ)/2)^p - mean for a wave of the sum of sines (eqs. 2-3; the mean C(2p, p)/4^p is left
// out, so the sea's mean level stays 0). Returns (g, dg/dθ).
LAGOON_FN dw_real2 dw_profile(dw_real theta, dw_real power, dw_real mean) {
  if (power < dw_real(0.5)) return dw_real2(cos(theta), -sin(theta));
  dw_real base = dw_real(0.5) * (dw_real(1) + sin(theta));
  int p = int(power + dw_real(0.5));
  dw_real lower = dw_real(1);  // base^(p-1), by multiplication: pow(0, 0) is undefined in GLSL
  for (int i = 1; i < p; ++i) lower *= base;
  return dw_real2(lower * base - mean, dw_real(0.5) * dw_real(p) * lower * cos(theta));
}
