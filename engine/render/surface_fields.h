// What the surface shaders sample of the water's motion (shared/surface.h): the ocean's cascade textures
// (displacement, normal and Jacobian terms, one array element per cascade, LAGOON_MAX_CASCADES, the last
// repeated) and the wakes' dynamic layer (passes/wakes_pass.h). Shared by every pass that draws or follows
// the surface (from above, from below, its AOVs, the waterline, the caustics), so none of them can leave the
// wakes out. Also whether the water carries sediment clouds (the frame's sediment buffer,
// world/vehicle_sediment.h), which the shaders that look through the water draw.
#pragma once
#include <vector>

#include "ocean/gpu/gpu_ocean.h"
#include "render/passes/wakes_pass.h"
#include "render/samplers.h"
#include "vk/pipeline.h"

namespace lagoon::render {

struct SurfaceFields {
  const ocean::GpuOcean& ocean;
  const WakesPass& wakes;
  bool sediment = false;  // some vehicle can stir the floor: common/sediment.glsl compiled in
};

std::vector<vk::Binding> surface_field_bindings(const SurfaceFields& fields, const Samplers& samplers);

// `own` with the constants the shaders that sum the fields take: the cascade count
// (LAGOON_SPEC_CASCADE_COUNT; 0 when the waves are summed directly), whether they are
// (LAGOON_SPEC_DIRECT_WAVES: how many), whether the wakes are compiled in (LAGOON_SURFACE_SPEC_WAKES) and the
// sediment (LAGOON_SURFACE_SPEC_SEDIMENT; shaders without it ignore the constant).
std::vector<vk::SpecConstant> with_surface_field_specs(std::vector<vk::SpecConstant> own,
                                                       const SurfaceFields& fields);

}  // namespace lagoon::render
