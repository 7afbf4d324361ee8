// The model's diffuse attenuation of downwelling light, K_d = −d ln(G+ + F+)/dz between 5 and 10 m in deep
// water, as Jerlov measured it (Marine Optics, 1976, Table XXVII): the check of the four-flow model against
// measurements (docs/optics.md, "Against measurements"), for either diffuse path-length factor.
#pragma once
#include "optics/lut.h"

namespace lagoon::optics {

// At grid wavelength i, with the "mixed" phase function of the inputs' water and the sun of their sky.
double model_kd(const LutInputs& inputs, int i, double diffuse_path_factor);

// The irradiance reflectance just below the surface, E_u/E_d = (G− + F−)/(G+ + F+) at depth 0, of the same
// deep water (the water's own colour, against which a Secchi disk is seen).
double model_reflectance(const LutInputs& inputs, int i, double diffuse_path_factor);

}  // namespace lagoon::optics
