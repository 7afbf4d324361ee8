// A cascade's spectrum cut to its waves longer than a given length (issue 14: the bodies' buoyancy needs no
// waves shorter than the lattice it samples, and evaluating fewer, longer waves is cheaper): the modes with
// |k| < k_cut, on the smallest grid that still gives each of them 4 texels per wavelength, as the cascades'
// bands do (ocean/initial_spectrum.h). The same band-limited sum, so WaveQuery's interpolation and its bound
// work unchanged on it.
#pragma once
#include "ocean/initial_spectrum.h"

namespace lagoon::ocean {

// An empty spectrum (resolution 0) when the cascade has no wave longer than 2π / k_cut.
CascadeSpectrum band_limited(const CascadeSpectrum& spectrum, double k_cut);

}  // namespace lagoon::ocean
