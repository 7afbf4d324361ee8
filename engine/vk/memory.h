// Device memory allocation with a failure a user can act on: running out of memory is not a bug but a
// scene too large for the device, so the error says what was being allocated, how much, and how much the
// heap holds (check.h's VulkanError, with the VkResult kept for the apps' advice).
#pragma once
#include <vulkan/vulkan.h>

#include <string>

namespace lagoon::vk {

class Context;

// vkAllocateMemory; on failure throws VulkanError: "out of device memory allocating 256.0 MiB for <what>
// (memory heap 0 holds 23.4 GiB)".
VkDeviceMemory allocate_memory(const Context& ctx, const VkMemoryAllocateInfo& info, const std::string& what);

// "256.0 MiB": byte counts in Vulkan messages.
std::string format_mib(VkDeviceSize bytes);

}  // namespace lagoon::vk
