// Perlin noise as a surface model (issue 15; seed 001 §1.1.1): octaves of 2-D gradient noise on the first
// cascade's patch, each with a whole number of lattice cells across it, so the field tiles. The field on the
// cascade's grid is a finite sum of the grid's modes (its DFT); put into that cascade's spectrum
// (h0 = half of each mode) it runs through the FFT ocean's pipeline unchanged. In time each mode turns at the
// deep-water ω = sqrt(g k): the noise moves like linear water waves instead of the document's undefined
// animation, and stays tileable and loopable. The mean is left out (zero mean level).
#pragma once
#include <vector>

#include "ocean/initial_spectrum.h"

namespace lagoon::ocean {

// 2-D gradient noise (quintic fade) at p in lattice units, periodic with `period` cells along both axes;
// `seed` picks the gradients. Zero at every lattice point.
double gradient_noise(double x, double z, uint32_t period, uint32_t seed);
// Octave o alone (o = 0 .. octaves - 1) at world (x, z): amplitude · persistence^o · noise.
double perlin_octave(const OceanParams& params, uint32_t octave, double x, double z);
// The sum of the octaves at (x, z), t = 0, before the mean is taken out.
double perlin_height(const OceanParams& params, double x, double z);

CascadeSpectrum perlin_cascade_spectrum(const OceanParams& params, uint32_t cascade);

}  // namespace lagoon::ocean
