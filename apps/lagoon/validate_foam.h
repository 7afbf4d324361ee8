// The foam laws of `lagoon validate` beyond its coverage (issue 33, docs/validation.md "Foam"): how long the
// foam Lagoon draws lasts where it forms, and whether its patches streak down-wind.
#pragma once
#include <vector>

#include "validate_law.h"
#include "vk/context.h"

namespace lagoon::cli {

std::vector<Law> foam_laws(vk::Context& ctx, const ValidateOptions& options);

}  // namespace lagoon::cli
