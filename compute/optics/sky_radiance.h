// The angle-resolved spectral clear sky L(λ, θ, φ) of Belyaev's §5 (Fig. 2): the sky image whose
// cosine-weighted integral is the E_sky of eq. 7 and that tunes the tone map.
//
// The angular shape and its colour across the sky are Preetham, Shirley & Smits (1999) (formulas in
// shared/sky_model.h; the Perez and zenith coefficients, their Appendix A.2, are in sky_radiance.cpp). Its
// spectra come from the CIE daylight basis S0, S1, S2 (data/cie_daylight_basis_10nm.csv, CIE 15:2004
// Table T.2), interpolated linearly onto the 5 nm grid. The absolute level is Bird & Riordan's (sky.h): at
// each wavelength the radiance is scaled so that ∫ L(λ, ω) cos θ dω over the sky is clear_sky's E_sky(λ).
// Preetham's turbidity is their own definition, T = (τ_R + τ_a) / τ_R at 550 nm with Bird's depths, clamped
// to the range [2, 10] their fit covers. Their sky is bluer than Bird's (irradiance x 0.254 against 0.274 at
// the defaults), so every direction's chromaticity is shifted by the same (Δx, Δy) that makes the colour of
// their sky irradiance Bird's. Both lie on the daylight locus, so the shift keeps each direction a daylight
// colour; scaling Preetham's spectra by Bird's instead turned the horizon pink. The per-wavelength scale that
// remains is nearly flat.
//
// Directions are unit vectors with y up; only dir·sun and dir.y matter. Below the horizon the sky is the
// horizon's (the renderer's distant sea haze).
#pragma once
#include <glm/vec3.hpp>

#include "optics/sky.h"
#include "optics/spectrum.h"
#include "shared/sky_model.h"

namespace lagoon::optics {

// S0, S1, S2 of the CIE daylight basis on the 5 nm grid.
struct DaylightBasis {
  Spectrum s[3];
};
const DaylightBasis& daylight_basis();
// S0 + M1 S1 + M2 S2 for chromaticity (x, y) (CIE 15:2004 eq. 3.4), unnormalised (S0(560) = 100).
Spectrum daylight_spectrum(double x, double y);

// Preetham's definition from the optical depths, T = (τ_R(550) + τ_a(550)) / τ_R(550), with Bird's Rayleigh
// and Ångström depths (unclamped).
double sky_turbidity(const SkyParams& params);

class SkyRadiance {
 public:
  // Sun elevation in degrees, clamped to [1, 90] for the shape; the irradiance is clear_sky's at the
  // same clamped elevation.
  explicit SkyRadiance(double sun_elevation_deg, const SkyParams& params = {});

  // Unit vector towards the sun, at azimuth 0 (+x).
  glm::dvec3 sun_direction() const { return sun_; }
  double turbidity() const { return turbidity_; }
  // E_sky(λ) / N(λ): the per-wavelength scale from the colour-shifted Preetham sky to Bird's level.
  const Spectrum& scale() const { return scale_; }
  const SkyIrradiance& irradiance() const { return irradiance_; }
  // The Perez coefficients, the zenith chromaticity and its shift, Y_k in basis*.w; basis*.rgb are left 0
  // (the renderer fills them).
  const gpu::SkyModelGpu& coefficients() const { return model_; }

  // B_k(λ), W m⁻² sr⁻¹ nm⁻¹: L(λ, ω) = Σ_k w_k(ω) B_k(λ), w from shared/sky_model.h.
  const Spectrum& basis_radiance(int k) const { return basis_[k]; }
  // L(λ, ω) in W m⁻² sr⁻¹ nm⁻¹.
  Spectrum radiance(glm::dvec3 dir) const;
  glm::dvec3 weights(glm::dvec3 dir) const;

 private:
  gpu::SkyModelGpu model_{};
  glm::dvec3 sun_{0, 1, 0};
  double turbidity_ = 2;
  SkyIrradiance irradiance_;
  Spectrum basis_[3]{};
  Spectrum scale_{};
};

// ∫ L(λ, ω) cos θ dω over the upper hemisphere by the midpoint rule on an n_theta × 2·n_theta grid of
// (θ, φ): the sky image's irradiance on a horizontal surface, W m⁻² nm⁻¹.
Spectrum sky_image_irradiance(const SkyRadiance& sky, int n_theta);

}  // namespace lagoon::optics
