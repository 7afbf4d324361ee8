// The random sea (the cascades' FFT ocean) as the waves' transformation over the floor takes it
// (ocean/shoaling.h): its significant height, which the depth limits, and per cascade one representative
// wave whose phase over the floor moves the cascade's lattice (docs/ocean.md "Waves over the floor").
#pragma once
#include <vector>

#include "ocean/initial_spectrum.h"
#include "ocean/ocean_params.h"
#include "ocean/shoaling.h"

namespace lagoon::ocean {

// A cascade's representative wave: its modes' wavenumber and direction weighted by their variance |h0|²
// (the waves that carry its height), with the sea's dispersion at ocean.depth_m, and the amplitude of a sine
// of the cascade's height variance: its shoaling weighs the cascades by their share of the sea's energy.
// k = 0 for a cascade without waves.
ShoalingWave representative_wave(const CascadeSpectrum& spectrum, const OceanParams& params);

// The random sea of these spectra: its significant height, 4σ over all of them, and each cascade's
// representative wave, in cascade order (none for model perlin, whose octaves are noise, not waves).
RandomSea random_sea(const OceanParams& params, const std::vector<CascadeSpectrum>& spectra);

}  // namespace lagoon::ocean
