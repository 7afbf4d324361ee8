// Checks OceanParams before anything is built from them. Every error message starts with the JSON path of
// the offending field under "ocean." and says how to fix it; all problems are reported, one per line.
#pragma once
#include "core/result.h"
#include "ocean/ocean_params.h"
#include "shared/limits.h"

namespace lagoon::ocean {

inline constexpr uint32_t kMinResolution = 64, kMaxResolution = 1024;
inline constexpr size_t kMaxCascades = LAGOON_MAX_CASCADES;  // the renderer binds this many

Result<void> validate(const OceanParams& params);

}  // namespace lagoon::ocean
