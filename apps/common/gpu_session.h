// The Vulkan context of one CLI run, created from the environment, with a uniform exit-code policy for
// validation failures (checked before any output file is committed).
#pragma once
#include <memory>

#include "vk/context.h"

namespace lagoon::cli {

// Prints the reason and returns null when no usable device exists.
std::unique_ptr<vk::Context> open_context();

// kExitOk, or kExitValidation after printing how many validation errors the run had.
int validation_status(vk::Context& ctx);

}  // namespace lagoon::cli
