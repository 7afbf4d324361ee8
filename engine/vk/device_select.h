// Which physical device to use: a pure function of what the driver reports, so it is unit-tested without
// Vulkan. Preference discrete > integrated > virtual > CPU; LAGOON_DEVICE=<index or name substring>
// overrides.
#pragma once
#include <vulkan/vulkan.h>

#include <string>
#include <string_view>
#include <vector>

#include "vk/result.h"

namespace lagoon::vk {

struct DeviceCandidate {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::string unsuitable_reason;  // empty when the device has everything Lagoon needs
};

const char* device_type_name(VkPhysicalDeviceType type);

// Returns the index of the device to use. `override_spec` is LAGOON_DEVICE's value ("" = automatic).
Result<size_t> choose_device(const std::vector<DeviceCandidate>& devices, std::string_view override_spec);

}  // namespace lagoon::vk
