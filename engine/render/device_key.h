// What a result the device computed depends on besides its inputs, for the result cache's keys
// (io/result_cache.h): the foam's warm-up (render/foam_cache.h), the wakes' history (render/wakes_cache.h)
// and the pipelines a scene used (render/pipeline_memory.h).
#pragma once
#include "io/result_cache.h"
#include "vk/context.h"

namespace lagoon::render {

// Adds the device, its driver and version, and on a CPU device the host's instruction set (LLVM generates
// code for it, so another CPU may round differently).
void add_device(io::ResultKey& key, const vk::Context& ctx);

}  // namespace lagoon::render
