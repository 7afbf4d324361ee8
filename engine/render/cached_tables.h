// The CPU tables that cost a renderer tens of milliseconds each at start-up, kept between runs through the
// result cache (io/result_cache.h): the PBR lobe's directional-albedo table (dfg_table.h: keyed by the code
// alone), the environment map's layers (environment_map.h: by the sky model and the sun) and the water's
// tables (water_luts.h: by every input of the optics model). Every key starts with the fingerprint of the
// code that computes them (cmake/Fingerprint.cmake), so no build reads the tables of another.
#pragma once
#include <glm/vec3.hpp>

#include <string_view>

#include "io/result_cache.h"
#include "render/environment_map.h"

namespace lagoon::render {

// A key for `kind` that already holds the code's fingerprint; callers add the inputs.
io::ResultKey table_key(std::string_view kind);

// prefilter_environment(sky, sun, width, height), from the cache when an earlier run computed it.
EnvironmentLayers cached_environment(const gpu::SkyModelGpu& sky, glm::vec3 sun_dir, uint32_t width,
                                     uint32_t height);

}  // namespace lagoon::render
