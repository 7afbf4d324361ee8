// Where the sea whitens (issue 33). Foam builds where the Jacobian J of the horizontal displacement (1 on
// undisturbed water, < 1 where it is squeezed, <= 0 where it folds) falls below an onset, as
// clamp((onset - J) / width, 0, 1), and persists, fading as exp(-foam.decay_per_s · t).
//
// foam.coverage "monahan" (the default) makes the foam cover the share of the sea Monahan &
// O'Muircheartaigh (1980) observed, W = 3.84e-6 U10^3.41. For the FFT ocean the foam is each cascade's own
// (its J, in the ocean step, kept from step to step): it stays where a crest folded the surface while the
// crest moves on, so it lasts a second or two at a point, as field whitecaps' foam does (Callaghan et al.
// 2012: 0.5-8 s). Each cascade whitens an equal share of the sea, the shares together W, so that the long
// waves' crests break in patches metres wide and the short waves' in specks. Foam that lasts covers more
// than the instants of folding (a point is white now if J fell far enough below the onset within the last
// ln2/decay seconds), so each cascade's onset is read off its own J stepped as the ocean steps it (10 Hz, as
// a still frame's warm-up) on a lattice of up to 128² of its texels over 3-5 s: CPU FFTs, ~0.3 s at
// 3 x 256², on another thread while the device is set up (gpu/gpu_ocean.h). For waves summed directly
// (gerstner, sines) the whole sea's J is applied afresh every frame by the surface shader, the onset being
// the quantile of J below which W lies. "threshold" is the rule of the seed: onset = foam.threshold, width
// 1, for each cascade and for the whole sea's J in the surface shader.
#pragma once
#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"

namespace lagoon::ocean {

// Monahan & O'Muircheartaigh (1980), eq. 3: whitecap coverage (a fraction of the area) at U10 m/s.
double monahan_coverage(double wind_speed_mps);

// How long foam lasts at most after it is made, ln(1 + 1/c)/decay (shared/foam_math.h's fade; infinite for
// decay 0).
double foam_memory_s(double decay_per_s);

struct FoamRamp {
  double onset = 0.5;  // J below which foam builds
  double width = 1.0;  // how much further J must fall for foam to reach 1; > 0
};

// A ramp that never whitens (onset far below any J a sea reaches).
inline constexpr FoamRamp kNoFoam{-1e6, 1.0};

struct FoamRule {
  FoamRamp whole;                  // the whole sea's J, applied every frame by the surface shader
  std::vector<FoamRamp> cascades;  // each cascade's own J, persisting in the ocean step; one per cascade
};

// The rule for a sea made of `spectra` (one per cascade, as make_cascade_spectra gives them).
FoamRule foam_rule(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra);

}  // namespace lagoon::ocean
