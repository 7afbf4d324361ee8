// What Lagoon requires of a device, checked on both paths: choosing one (Context::create) and accepting a
// host's (Context::adopt). The requirements themselves (version, extensions, features) are declared in
// vk/context.h; these are context.cpp's checks of them.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "vk/context.h"

namespace lagoon::vk::detail {

// The queue family that does graphics and compute (and presents, when a surface is given), or -1.
int find_queue_family(VkPhysicalDevice device, VkSurfaceKHR surface);

// Why Context::create() cannot use `device`; "" when it can.
std::string unsuitable_reason(VkPhysicalDevice device, VkSurfaceKHR surface);

// Why Context::adopt() cannot use the host's device, one item per problem; empty when it can.
std::vector<std::string> host_device_shortfalls(const HostDevice& host);

// The core features a host enabled, from what it gave vkCreateDevice.
VkPhysicalDeviceFeatures enabled_core_features(const VkDeviceCreateInfo& info);

}  // namespace lagoon::vk::detail
