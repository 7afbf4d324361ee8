// CIE 1931 2° standard observer and illuminant D65 on the optics grid (spectrum.h), from the embedded
// tables cie1931_2deg_cmf_5nm.csv and cie_d65_5nm.csv (sources in data/README.md).
#pragma once
#include <glm/glm.hpp>

#include "optics/spectrum.h"

namespace lagoon::optics {

// Colour-matching functions x̄, ȳ, z̄ (dimensionless). ȳ is also V(λ), the photopic luminous efficiency.
const Spectrum& cie_x_bar();
const Spectrum& cie_y_bar();
const Spectrum& cie_z_bar();
// D65 relative spectral power distribution, 100 at 560 nm.
const Spectrum& cie_d65();

// XYZ = Σ f(λ)·(x̄, ȳ, z̄)(λ)·Δλ with Δλ = 5 nm: the rectangle rule on the grid (the CIE's own 5 nm
// summation). No 683 lm/W factor and no normalisation: for f in W m⁻² nm⁻¹, Y is in "W m⁻²
// weighted by V(λ)"; colour code only ever uses ratios of these.
glm::dvec3 spectrum_to_xyz(const Spectrum& f);

// (x, y) = (X, Y) / (X + Y + Z); (0, 0) when X + Y + Z <= 0 (no light).
glm::dvec2 chromaticity(glm::dvec3 xyz);

}  // namespace lagoon::optics
