// The shore laws of `lagoon validate` (issue 37, docs/validation.md "Waves over the floor"): a monochromatic
// swell over a planar beach, as WaveQuery, probes and the bodies see it (ocean/gerstner.h over
// ocean/shoaling.h; the renderer draws the same table), against linear wave theory: the finite-depth
// dispersion relation, Snell's law over straight depth contours, shoaling and refraction of the energy flux,
// and McCowan's breaker index.
#pragma once
#include <vector>

#include "validate_law.h"

namespace lagoon::cli {

std::vector<Law> shore_laws(const ValidateOptions& options);

}  // namespace lagoon::cli
