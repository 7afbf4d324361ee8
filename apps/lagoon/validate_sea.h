// The sea-state laws of `lagoon validate` (docs/validation.md): significant height and peak period against
// Pierson–Moskowitz at full development and JONSWAP's fetch laws below it, the cap at full development, TMA's
// depth limitation, Rayleigh-distributed wave heights and Cox–Munk's slopes.
#pragma once
#include <vector>

#include "validate_law.h"
#include "vk/context.h"

namespace lagoon::cli {

std::vector<Law> sea_state_laws(vk::Context& ctx, const ValidateOptions& options);

}  // namespace lagoon::cli
