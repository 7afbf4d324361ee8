// The light laws of `lagoon validate` (docs/validation.md): Snell's window seen from under a calm sea in a
// render on the device, the diffuse attenuation K_d against Jerlov's measurements, and the Secchi depth
// against Poole & Atkins' 1.7/K_d.
#pragma once
#include <vector>

#include "validate_law.h"
#include "vk/context.h"

namespace lagoon::cli {

std::vector<Law> light_laws(vk::Context& ctx, const ValidateOptions& options);

}  // namespace lagoon::cli
