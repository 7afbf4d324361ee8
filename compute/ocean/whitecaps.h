// Where the whole sea's surface whitens (issue 33): foam = clamp((onset - J) / width, 0, 1) where its
// Jacobian J (1 on undisturbed water, < 1 where it is squeezed, <= 0 where it folds) falls below the onset.
// The surface shader applies it to the sum of the cascades' Jacobian terms at each point, every frame
// (shaders/common/surface_normal.glsl), beside each cascade's own persisting foam (foam.threshold), so it
// depends on the frame's time alone, not on how the frames were stepped.
//
// foam.coverage "monahan" (the default) makes the whitecaps cover the share of the sea Monahan &
// O'Muircheartaigh (1980) observed, W = 3.84e-6 U10^3.41: J is close to Gaussian about 1 with σ_J² = λ² ×
// the cascades' mean square slope (J - 1 ≈ λ Σ |k| h), so foam of at least ½ (J < onset - width/2) covers
// Φ((onset - width/2 - 1)/σ_J) of the area; the onset solves that for W, with width σ_J (a crest whitens
// over one standard deviation of squeezing, not in a hard edge). J's lower tail is heavier than a
// Gaussian's, so the quantile is read off the sea's own Jacobian at t = 0 (CPU FFTs of its terms, ~50 ms
// for 3 x 256²) wherever the share is large enough to count. "threshold" is the rule of the seed's foam:
// onset = foam.threshold, width 1.
#pragma once
#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"

namespace lagoon::ocean {

// Monahan & O'Muircheartaigh (1980), eq. 3: whitecap coverage (a fraction of the area) at U10 m/s.
double monahan_coverage(double wind_speed_mps);

struct FoamRule {
  double onset = 0.5;  // J below which foam builds
  double width = 1.0;  // how much further J must fall for foam to reach 1; > 0
};

// The rule for a sea made of `spectra` (one per cascade, as make_cascade_spectra gives them).
FoamRule foam_rule(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra);

}  // namespace lagoon::ocean
