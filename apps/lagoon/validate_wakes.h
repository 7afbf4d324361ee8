// The wake laws of `lagoon validate` (issue 33, docs/validation.md "Wakes"): the dynamic wave layer behind a
// hull at constant speed against Kelvin's half-angle, the transverse wavelength and Rabaud & Moisy's
// narrowing at high Froude numbers.
#pragma once
#include <vector>

#include "validate_law.h"

namespace lagoon::cli {

std::vector<Law> wake_laws(const ValidateOptions& options);

}  // namespace lagoon::cli
