// What a user can do about a Vulkan failure that ends a command: running out of memory and losing the
// device are not bugs in the scene file but limits of the machine, so the message says what to change.
#pragma once
#include <string>

#include "vk/check.h"

namespace lagoon::cli {

// The error's message followed, for out-of-memory and device-lost results, by what to do about it.
std::string explain_vulkan_error(const vk::VulkanError& error);

}  // namespace lagoon::cli
