// The foam laws of `lagoon validate` beyond its coverage (issue 33, docs/validation.md "Foam"): how long the
// foam Lagoon draws lasts where it forms, and whether its patches streak down-wind.
#pragma once
#include <cstdint>
#include <vector>

#include "ocean/gpu/gpu_ocean.h"
#include "validate_law.h"
#include "vk/context.h"

namespace lagoon::cli {

// Where the foam Lagoon draws is at least 0.5 (1) or not (0) on grid² points over `side` metres from the
// origin, after the ocean's last step: per point the largest cascade foam and the whole sea's Jacobian's
// through the foam rule, as shaders/common/surface_normal.glsl combines them (nearest texel of each
// cascade). Reads the cascades back.
std::vector<uint8_t> drawn_foam(const ocean::GpuOcean& gpu, const ocean::OceanParams& p, uint32_t grid,
                                double side);

std::vector<Law> foam_laws(vk::Context& ctx, const ValidateOptions& options);

}  // namespace lagoon::cli
