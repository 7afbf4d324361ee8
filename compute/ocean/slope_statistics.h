// Mean square slope of the sea surface, E[(∂h/∂x)² + (∂h/∂z)²]: what the renderer adds to the sun glint's
// width for the waves a pixel cannot resolve (those filtered away by the cascades' mips and those shorter
// than the last cascade carries), as in Bruneton, Neyret & Holzschuch 2010, "Real-time realistic ocean
// lighting using seamless transitions from geometry to BRDF".
#pragma once
#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"

namespace lagoon::ocean {

// The cascade's own mean square slope averaged over time: Σ_k |k|² E_t|h̃(k,t)|² = 2 Σ_k |k|² |h0(k)|²
// (h̃ = h0(k)e^{-iωt} + conj(h0(-k))e^{iωt}). Exact for the sampled amplitudes, not the expected spectrum.
double mean_square_slope(const CascadeSpectrum& spectrum);

// The cascade's height variance averaged over time, 2 Σ_k |h0(k)|² (as above without |k|²). With choppiness
// λ each horizontal component has at most λ² times this (|k̂_x| <= 1); the renderer culls with 6σ bounds.
double height_variance(const CascadeSpectrum& spectrum);

// ∫ k² Ψ_omni(k) dk over [k_from, k_to] rad/m from the continuous spectrum (no sampling): the slopes of
// waves no cascade carries. 0 when k_to <= k_from.
double spectrum_mean_square_slope(const OceanParams& params, double k_from, double k_to);

// E[s sᵀ] of the slopes s = (∂h/∂x, ∂h/∂z): the roughness the water colour's surface coefficients average
// over (optics/rough_surface.h, seed 000 eq. 10). xx + zz is the mean square slope.
struct SlopeMoments {
  double xx = 0, zz = 0, xz = 0;
};
// The cascade's, averaged over time, from its sampled amplitudes (as mean_square_slope); only its modes with
// |k| >= k_from.
SlopeMoments slope_moments(const CascadeSpectrum& spectrum, double k_from = 0);
// The continuous directional spectrum's over k_from <= |k| < k_to (no sampling).
SlopeMoments spectrum_slope_moments(const OceanParams& params, double k_from, double k_to);
// The whole sea's: every cascade's, plus for the FFT ocean the capillary-gravity waves beyond the last
// cascade's band (ocean/short_waves.h, Elfouhaily et al. 1997: the waves the glint also counts; the other
// models have no waves beyond their cascades).
SlopeMoments sea_slope_moments(const OceanParams& params);
// The same from cascade spectra already built for `params` (make_cascade_spectra), without building them
// again.
SlopeMoments sea_slope_moments(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra);
// What a field sampled every π/k_from metres does not resolve: the first `drawn` cascades' modes with
// |k| >= k_from, plus the waves beyond the last drawn one down to 1 cm (kCapillaryCutoffK), as the glint
// counts them (Elfouhaily's short waves for the FFT ocean, the spectrum's own tail for the other models).
SlopeMoments unresolved_slope_moments(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra,
                                      size_t drawn, double k_from);

// Shortest wave the glint model counts, 1 cm (k = 2π/0.01): below it capillary damping dominates and the
// gravity-wave spectra used here no longer hold (Cox & Munk's glitter slopes end about here).
inline constexpr double kCapillaryCutoffK = 628.3;

}  // namespace lagoon::ocean
