// The ocean's cascade textures as the surface shaders bind them (shared/surface.h): displacement, normal and
// Jacobian terms, one array element per cascade (LAGOON_MAX_CASCADES, the last cascade repeated). Shared by
// every pass that draws the surface mesh (from above, from below, its AOVs).
#pragma once
#include <vector>

#include "ocean/gpu/gpu_ocean.h"
#include "render/samplers.h"
#include "vk/pipeline.h"

namespace lagoon::render {

std::vector<vk::Binding> cascade_bindings(const ocean::GpuOcean& ocean, const Samplers& samplers);

// The cascade count as the shaders that sum the cascades take it (LAGOON_SPEC_CASCADE_COUNT).
vk::SpecConstant cascade_count_spec(const ocean::GpuOcean& ocean);

}  // namespace lagoon::render
