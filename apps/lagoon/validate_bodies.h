// The floating-body laws of `lagoon validate` (docs/validation.md): Archimedes' draught, heave of boxes in
// regular waves against quasi-static Froude–Krylov theory, the same motion whatever the tessellation, and
// bodies that rest on the floor or rise from it. All on the CPU: physics/floating_body.h is plain C++.
#pragma once
#include <vector>

#include "validate_law.h"

namespace lagoon::cli {

std::vector<Law> body_laws(const ValidateOptions& options);

}  // namespace lagoon::cli
