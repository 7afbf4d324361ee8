// The clear sky's radiance across the sky, shared by the sky and water shaders (common/light.glsl), the CPU
// spectral model (compute/optics/sky_radiance.h) and the renderer that fills the coefficients
// (render/sky_light.cpp), so one formula gives every pixel of sky, its reflection and the LUTs' E_sky.
//
// Preetham, Shirley & Smits (1999), "A practical analytic model for daylight" (SIGGRAPH 99): luminance Y and
// chromaticity x, y each vary over the sky as a Perez function of the view zenith angle θ and the angle γ to
// the sun, F(θ, γ) = (1 + A e^{B / cos θ}) (1 + C e^{D γ} + E cos² γ), and x(θ, γ) = x_z F_x(θ, γ) / F_x(0,
// θ_s) + Δx, Δx the shift to the irradiance model's sky colour (optics/sky_radiance.h); likewise y.
// Each chromaticity has the CIE daylight spectrum S0 + M1 S1 + M2 S2 (CIE 15:2004 §3.1) with
//   M1 = (−1.3515 − 1.7703 x + 5.9114 y) / (0.0241 + 0.2562 x − 0.7341 y),
//   M2 = (0.0300 − 31.4424 x + 30.0717 y) / (0.0241 + 0.2562 x − 0.7341 y),
// scaled to the direction's relative luminance: per direction the weights (w0, w1, w2) = F_Y · (1, M1, M2) /
// (Y0 + M1 Y1 + M2 Y2), where Y_k = ∫ ȳ S_k. The radiance is Σ_k w_k B_k, where the B_k fold in the
// per-wavelength scale that makes the sky's irradiance the irradiance model's E_sky (optics/sky_radiance.h).
#ifndef LAGOON_SHARED_SKY_MODEL_H
#define LAGOON_SHARED_SKY_MODEL_H
#include "shared/interop.h"

LAGOON_GPU_BEGIN
struct SkyModelGpu {
  vec4 perez_lum;  // A, B, C, D of the luminance's Perez function
  vec4 perez_x;    // A, B, C, D of chromaticity x
  vec4 perez_y;    // A, B, C, D of chromaticity y
  vec4 perez_e;    // x, y, z = E of luminance, x, y; w unused
  vec4 zenith;     // x = x_z / F_x(0, θ_s), y = y_z / F_y(0, θ_s), zw = the shift (Δx, Δy) of every
                   // direction's chromaticity (optics/sky_radiance.h)
  vec4 basis0;     // rgb = B_0 (white units, render/sky_light.h), w = Y_0 = ∫ ȳ S_0
  vec4 basis1;     // rgb = B_1, w = Y_1
  vec4 basis2;     // rgb = B_2, w = Y_2
};

LAGOON_FN float sky_perez(vec4 abcd, float e, float cos_theta, float gamma, float cos_gamma) {
  return (1.0f + abcd.x * exp(abcd.y / cos_theta)) *
         (1.0f + abcd.z * exp(abcd.w * gamma) + e * cos_gamma * cos_gamma);
}

// (w0, w1, w2) for the direction `dir` (unit, y up) with the sun towards `sun`. Below the horizon the
// horizon's values (distant sea haze).
LAGOON_FN vec3 sky_daylight_weights(SkyModelGpu m, vec3 dir, vec3 sun) {
  float cos_theta = max(dir.y, 0.01f);
  float cos_gamma = clamp(dot(normalize(vec3(dir.x, cos_theta, dir.z)), sun), -1.0f, 1.0f);
  float gamma = acos(cos_gamma);
  float lum = sky_perez(m.perez_lum, m.perez_e.x, cos_theta, gamma, cos_gamma);
  float x = m.zenith.x * sky_perez(m.perez_x, m.perez_e.y, cos_theta, gamma, cos_gamma) + m.zenith.z;
  float y = m.zenith.y * sky_perez(m.perez_y, m.perez_e.z, cos_theta, gamma, cos_gamma) + m.zenith.w;
  float den = 0.0241f + 0.2562f * x - 0.7341f * y;
  float m1 = (-1.3515f - 1.7703f * x + 5.9114f * y) / den;
  float m2 = (0.0300f - 31.4424f * x + 30.0717f * y) / den;
  return lum / (m.basis0.w + m1 * m.basis1.w + m2 * m.basis2.w) * vec3(1.0f, m1, m2);
}

LAGOON_FN vec3 sky_model_rgb(SkyModelGpu m, vec3 dir, vec3 sun) {
  vec3 w = sky_daylight_weights(m, dir, sun);
  return w.x * vec3(m.basis0) + w.y * vec3(m.basis1) + w.z * vec3(m.basis2);
}
LAGOON_GPU_END

#ifdef __cplusplus
LAGOON_CHECK_SIZE(SkyModelGpu, 128);
#endif
#endif
