// The spectral -> RGB operator Φ of Belyaev's section 5: CIE XYZ (eq. 14), von Kries chromatic
// adaptation in LMS (eqs. 15-17), XYZ -> linear sRGB, then the tone-mapping operator of eq. 18.
// Scene-referred colours (adapted_linear_srgb) are kept separate from display values (tone_map,
// encode_srgb) because Φ is non-linear (eq. 19): LUTs store the former only where they are mixed later.
#pragma once
#include <glm/glm.hpp>

#include "optics/spectrum.h"

namespace lagoon::optics {

// Hunt–Pointer–Estévez XYZ -> LMS, normalised to D65, from von_kries_xyz_to_lms.csv; lms = M * xyz
// (glm is column-major: the math entry row r, column c is m[c][r]). The seed's eq. 15 prints -0.023 for
// row 1, column 0: a typo for -0.2263 (data/README.md), kept out of here.
const glm::dmat3& xyz_to_lms();
// XYZ -> linear sRGB (D65): the *_exact rows of srgb_xyz_to_linear_rgb_d65.csv, computed from the sRGB
// primaries and white rather than the 4-decimal IEC print.
const glm::dmat3& xyz_to_linear_srgb();
// Its inverse (the *_from_rgb rows); row Y is the luminance of a linear sRGB colour.
const glm::dmat3& linear_srgb_to_xyz();
double linear_srgb_luminance(glm::dvec3 linear_rgb);

// Linear sRGB of spectrum f seen by an observer adapted to `white` (von Kries in LMS):
//   rgb = B⁻¹ · S · M⁻¹ · diag(1 / (M·XYZ(white))) · M · XYZ(f)
// with M = xyz_to_lms(), S = xyz_to_linear_srgb() and B = S·M⁻¹·(1,1,1) a fixed per-channel balance
// (within 2e-5 of 1: it only absorbs the rounding of the published M and S) so that `white` itself maps to
// exactly (1,1,1). Belyaev normalises f and the white to unit luminance (eq. 16) before eq. 17; since every
// step is linear, that normalisation and re-applying the luminance ratio cancel: the result is the
// luminance ratio Y(f)/Y(white) (V(λ) = ȳ) times the chromatic part. Any spectrum proportional to the
// white gives a neutral grey R = G = B = the ratio. Scene-referred: no tone mapping, may exceed 1 or be
// negative outside the sRGB gamut. Returns (0,0,0) if the white has a non-positive cone response
// (no light).
glm::dvec3 adapted_linear_srgb(const Spectrum& f, const Spectrum& white);

// Eq. 18: L_d = m(L_wa)·L_da·(L_w / L_wa)^(γ_w/γ_d), L_df = L_d·(1 + L_d / L_white²) / (1 + L_d).
// The seed lists γ_w and γ_d among the constants but prints only γ_w; we use the Tumblin–Rushmeier
// exponent γ_w/γ_d (Tumblin, Hodgins & Guenter 1999, "revised TR"; as given in Reinhard et al., "High
// Dynamic Range Imaging", ch. on global operators), with
//   γ(L) = 2.655 for L > 100 cd/m², 1.855 + 0.4·log10(L + 2.3e-5) otherwise (L in cd/m²),
//   γ_w = γ(world adaptation in cd/m²), γ_d = γ(L_da in cd/m²),
//   m = sqrt(C_max)^(γ_w/γ_d − 1)   (C_max: the display's maximum contrast).
// L_d is expressed in units of the display adaptation luminance L_da (so the factor L_da is 1), and the
// Reinhard-type step maps L_d = L_white to 1; larger L_d clamps to 1 (a burnt-out highlight).
// With the defaults: γ_w = 2.655, γ_d = 2.4958, exponent 1.0638, m = 1.1581, so input luminance 1 (the
// white the colour was adapted to, e.g. a white surface under the sun + sky) maps to 0.813, and luminance
// above ≈ 1.275 clips. The curve is continuous, strictly increasing below the clip, 0 at 0, and ≤ 1.
struct ToneMapParams {
  double world_adaptation_luminance = 1.0;  // L_wa, in the units of the input luminance (1 = the white)
  double world_adaptation_cd_m2 = 10000.0;  // what L_wa is in cd/m² (a white surface in daylight); only sets
                                            // γ_w, constant above 100 cd/m² (photopic)
  double display_adaptation_cd_m2 = 40.0;   // L_da: half the 80 cd/m² sRGB reference display white
  double display_max_contrast = 100.0;      // C_max, for m(L_wa)
  double white_luminance = 1.5;             // L_white, in units of L_da: L_d at and above it shows as 1
};
double tone_map_luminance(double L_w, const ToneMapParams& params = {});  // L_df, in [0, 1]
// The constants of that curve, for shaders that apply the same operator (L_d = m (L_w/L_wa)^exponent).
struct ToneMapCurve {
  double m, exponent, world_adaptation, white;
};
ToneMapCurve tone_map_curve(const ToneMapParams& params = {});
// Scales the colour by L_df / L (L = linear_srgb_luminance) and clamps each channel to [0, 1]; (0,0,0)
// for L <= 0.
glm::dvec3 tone_map(glm::dvec3 linear_rgb, const ToneMapParams& params = {});

// The sRGB transfer function (IEC 61966-2-1) per channel, input clamped to [0, 1], for 8-bit previews.
glm::dvec3 encode_srgb(glm::dvec3 linear);
// Its inverse, encoded values in [0, 1] to linear light (textures' colours, render/texture_mips.h).
glm::dvec3 decode_srgb(glm::dvec3 encoded);

}  // namespace lagoon::optics
